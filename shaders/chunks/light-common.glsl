// Shared by the light passes: the light's values and the shadow mask lookup. Built with SHADOWED
// for lights with a shadow mask. The light's values come from the vertex stage (light.vert.glsl):
// SwiftShader pays for a uniform read per fragment, and these varyings took S2's frame 6% lower.
#ifdef SHADOWED
uniform sampler2D u_shadowMask;
#endif

in vec2 v_fromLight; // from the light's position to the pixel, in ranges
in vec2 v_uv;
flat in vec3 v_color;
out vec4 o_light;

// Fraction of the light disk visible from this pixel, from the shadow-mask pass.
float lightVisibility() {
#ifdef SHADOWED
  vec3 hidden = texelFetch(u_shadowMask, ivec2(gl_FragCoord.xy), 0).rgb;
  return 1.0 - min(1.0, hidden.r + hidden.g + hidden.b);
#else
  return 1.0;
#endif
}

// Linear falloff: 1 at the centre, 0 at the range.
float distanceFalloff() {
  return max(0.0, 1.0 - length(v_fromLight));
}

// Alpha is 0 so additive blending leaves the lightmap's alpha untouched.
void writeLight(float strength) {
  o_light = vec4(v_color * (strength * lightVisibility()), 0.0);
}
