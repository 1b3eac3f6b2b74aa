// Shared by the light passes: the light's values and its visible fraction. Built with SHADOWED for
// lights with hulls in range (see the chunk shadow-visibility). The light's values come from the
// vertex stage (light.vert.glsl) as flat varyings rather than uniforms read per fragment.
#ifdef SHADOWED
#include "shadow-visibility"
#endif

in vec2 v_fromLight; // from the light's position to the pixel, in ranges
in vec2 v_uv;
flat in vec3 v_color;
out vec4 o_light;

flat in vec2 v_falloff; // the curve's code (FALLOFF_LINEAR, …: src/passes/lightLayout.ts), the inverse-square core in ranges

// The light's strength by distance (Falloff in src/scene/lights.ts, and falloffAt there on the
// CPU): 1 at the centre, 0 from the range on. A branch on a value the whole draw shares.
float distanceFalloff() {
  float t = length(v_fromLight);
  int curve = int(v_falloff.x);
  if (curve == FALLOFF_SMOOTH) {
    float window = max(0.0, 1.0 - t * t);
    return window * window;
  }
  if (curve == FALLOFF_INVERSE_SQUARE) {
    float t2 = t * t, window = max(0.0, 1.0 - t2 * t2), core2 = v_falloff.y * v_falloff.y;
    return window * window * core2 / (core2 + t2);
  }
  return max(0.0, 1.0 - t);
}

#ifdef SHADOWED
flat in vec3 v_shadowKept;
#endif

// Writes colour × strength × what passes: the visible fraction of the disk, and of the rest the
// fraction the light's shadows keep (0 by default: mix(0, 1, v) is v exactly). Alpha is 0 so
// additive blending leaves the lightmap's alpha untouched.
void writeLight(float strength) {
#ifdef SHADOWED
  vec3 passes = mix(v_shadowKept, vec3(1.0), strength > 0.0 ? shadowVisibility() : 0.0);
#else
  vec3 passes = vec3(1.0);
#endif
#if defined(SHADOW_STATISTICS)
  // The benchmark's statistics build: per light pixel 1, the records visited, 1 when none was, and 1
  // when the quadrature takes the pixel.
#ifdef SHADOWED
  float visited = float(visitedRecords), past = sweptPixel ? 1.0 : 0.0;
#else
  float visited = 0.0, past = 0.0;
#endif
  o_light = strength > 0.0 ? vec4(1.0, visited, visited == 0.0 ? 1.0 : 0.0, past) : vec4(0.0);
#else
  o_light = vec4(v_color * (strength * passes), 0.0);
#endif
}
