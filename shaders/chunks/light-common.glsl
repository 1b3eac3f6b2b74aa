// Shared by the light passes: the light's values and its visible fraction. Built with SHADOWED for
// lights with hulls in range (see the chunk shadow-visibility). The light's values come from the
// vertex stage (light.vert.glsl): SwiftShader pays for a uniform read per fragment, and these
// varyings took S2's frame 6% lower.
#ifdef SHADOWED
#include "shadow-visibility"
#endif

in vec2 v_fromLight; // from the light's position to the pixel, in ranges
in vec2 v_uv;
flat in vec3 v_color;
out vec4 o_light;

// Fraction of the light disk visible from this pixel.
float lightVisibility() {
#ifdef SHADOWED
  return shadowVisibility();
#else
  return 1.0;
#endif
}

// Linear falloff: 1 at the centre, 0 at the range.
float distanceFalloff() {
  return max(0.0, 1.0 - length(v_fromLight));
}

// Alpha is 0 so additive blending leaves the lightmap's alpha untouched.
// The shadow is computed only where the light adds something.
void writeLight(float strength) {
#ifdef SHADOW_STATISTICS
  // The benchmark's statistics build: per light pixel 1, the records visited, 1 when none was, and 1
  // when it sees records past (the quadrature's pixels).
  lightVisibility();
#ifdef SHADOWED
  float visited = float(visitedRecords), past = seenPastRecords ? 1.0 : 0.0;
#else
  float visited = 0.0, past = 0.0;
#endif
  o_light = strength > 0.0 ? vec4(1.0, visited, visited == 0.0 ? 1.0 : 0.0, past) : vec4(0.0);
#else
  o_light = vec4(v_color * (strength > 0.0 ? strength * lightVisibility() : 0.0), 0.0);
#endif
}
