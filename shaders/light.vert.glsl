#version 300 es
// Light pass, vertex stage: maps the unit square of a light shape (LightShapes) onto the light's
// world-space quad.
precision highp float;

layout(location = 0) in vec2 a_corner; // unit quad, 0..1

uniform mat4 u_viewProjection;
uniform vec2 u_quad[3]; // the light's quad: a corner and the two edge vectors (Light.writeQuad)

out vec2 v_world;
out vec2 v_uv;

void main() {
  v_world = u_quad[0] + a_corner.x * u_quad[1] + a_corner.y * u_quad[2];
  v_uv = a_corner;
  gl_Position = u_viewProjection * vec4(v_world, 0.0, 1.0);
#ifdef NEAREST_DEPTH
  // The shadow mask's range cut-out: as near as the umbrae, so the shadow quads behind it fail the
  // depth test (see ShadowMaskPass).
  gl_Position.z = -gl_Position.w;
#endif
}
