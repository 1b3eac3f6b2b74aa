#version 300 es
// Light pass, vertex stage: maps the unit square of a light shape (LightShapes) onto the light's
// world-space quad, and hands the fragment stage the light's values (see the chunk light-common).
precision highp float;

layout(location = 0) in vec2 a_corner; // unit quad, 0..1

uniform mat4 u_viewProjection;
uniform vec2 u_quad[3]; // the light's quad: a corner and the two edge vectors (Light.writeQuad)
// The light pass's light; the debug outline leaves them unset and ignores the varyings they feed.
uniform vec3 u_light; // position xy, range
uniform vec3 u_lightColor; // colour × intensity
uniform vec4 u_shadow; // position xy, disk radius, row of the light's shadow bins
uniform float u_shadowType; // how the light treats the inside of hulls: SHADOW_SOLID, … (src/geometry/shadowLayout.ts)
uniform vec3 u_shadowKept; // the fraction of each channel a pixel in full shadow keeps (Light.writeShadowKept)
uniform vec4 u_binning; // how the shadow bins were filed: centre xy, disk radius and distance bucket width; a directional light's strips: perpBase, width, alongBase, bucketWidth (DirectionalStrips)
uniform vec2 u_falloff; // the falloff's code and inverse-square core (see the chunk light-common)
#ifdef NORMALS
uniform vec4 u_towardsLight; // position xy and height, w 0; a directional light's unit vector towards it, w 1
flat out vec4 v_towardsLight;
#endif

out vec2 v_fromLight;
out vec2 v_uv;
out vec2 v_world;
flat out vec3 v_color;
flat out vec4 v_shadow;
flat out float v_shadowType;
flat out vec3 v_shadowKept;
flat out vec4 v_binning;
flat out vec2 v_falloff;

void main() {
  vec2 world = u_quad[0] + a_corner.x * u_quad[1] + a_corner.y * u_quad[2];
  v_fromLight = (world - u_light.xy) / u_light.z;
  v_uv = a_corner;
  v_world = world;
  v_color = u_lightColor;
  v_shadow = u_shadow;
  v_shadowType = u_shadowType;
  v_shadowKept = u_shadowKept;
  v_binning = u_binning;
  v_falloff = u_falloff;
#ifdef NORMALS
  v_towardsLight = u_towardsLight;
#endif
  gl_Position = u_viewProjection * vec4(world, 0.0, 1.0);
  // Depth ½ whatever the view: the quadrature pass tests it against the main pass's marks (LightPass).
  gl_Position.z = 0.0;
}
