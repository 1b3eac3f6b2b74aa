// Shared by the light passes: light uniforms and the shadow mask lookup.
uniform vec3 u_lightColor; // colour × intensity
uniform vec3 u_light; // position xy, range
uniform bool u_hasShadowMask;
uniform sampler2D u_shadowMask;

in vec2 v_world;
in vec2 v_uv;
out vec4 o_light;

// Fraction of the light disk visible from this pixel, from the shadow-mask pass.
float lightVisibility() {
  if (!u_hasShadowMask) return 1.0;
  vec3 hidden = texelFetch(u_shadowMask, ivec2(gl_FragCoord.xy), 0).rgb;
  return 1.0 - min(1.0, hidden.r + hidden.g + hidden.b);
}

// Linear falloff: 1 at the centre, 0 at the range.
float distanceFalloff() {
  return max(0.0, 1.0 - length(v_world - u_light.xy) / u_light.z);
}

// Alpha is 0 so additive blending leaves the lightmap's alpha untouched.
void writeLight(float strength) {
  o_light = vec4(u_lightColor * (strength * lightVisibility()), 0.0);
}
