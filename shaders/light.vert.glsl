#version 300 es
// Light pass, vertex stage: maps the unit square of a light shape (LightShapes) onto the light's
// world-space quad, and hands the fragment stage the light's values (see the chunk light-common).
precision highp float;

layout(location = 0) in vec2 a_corner; // unit quad, 0..1

uniform mat4 u_viewProjection;
uniform vec2 u_quad[3]; // the light's quad: a corner and the two edge vectors (Light.writeQuad)
// The light pass's light; the range cut-out and the debug outline leave them unset and ignore the
// varyings they feed.
uniform vec3 u_light; // position xy, range
uniform vec3 u_lightColor; // colour × intensity

out vec2 v_fromLight;
out vec2 v_uv;
flat out vec3 v_color;

void main() {
  vec2 world = u_quad[0] + a_corner.x * u_quad[1] + a_corner.y * u_quad[2];
  v_fromLight = (world - u_light.xy) / u_light.z;
  v_uv = a_corner;
  v_color = u_lightColor;
  gl_Position = u_viewProjection * vec4(world, 0.0, 1.0);
#ifdef NEAREST_DEPTH
  // The shadow mask's range cut-out: as near as the umbrae, so the shadow quads behind it fail the
  // depth test (see ShadowMaskPass).
  gl_Position.z = -gl_Position.w;
#endif
}
