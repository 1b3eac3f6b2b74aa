// Shared by the light passes: the light's values and its visible fraction. Built with SHADOWED for
// lights with hulls in range (see the chunk shadow-visibility), and with NORMALS for a renderer with
// normals: then it also writes the highlights at location 1 and weights the light by the surface's
// normal (docs/normal-maps.md). The light's values are uniforms, the pixel's come from the vertex
// stage (light.vert.glsl).
in vec2 v_world; // the pixel's world position
#ifdef SHADOWED
#include "shadow-visibility"
#endif

in vec2 v_fromLight; // from the light's position to the pixel, in ranges
in vec2 v_uv;
uniform vec3 u_lightColor; // colour × intensity
layout(location = 0) out vec4 o_light;

uniform vec2 u_falloff; // the curve's code (FALLOFF_LINEAR, …: src/passes/lightLayout.ts), the inverse-square core in ranges

// The light's strength by distance (Falloff in src/scene/falloff.ts, and falloffAt there on the
// CPU): 1 at the centre, 0 from the range on. A branch on a value the whole draw shares.
float distanceFalloff() {
  float t = length(v_fromLight);
  int curve = int(u_falloff.x);
  if (curve == FALLOFF_SMOOTH) {
    float window = max(0.0, 1.0 - t * t);
    return window * window;
  }
  if (curve == FALLOFF_INVERSE_SQUARE) {
    float t2 = t * t, window = max(0.0, 1.0 - t2 * t2), core2 = u_falloff.y * u_falloff.y;
    return window * window * core2 / (core2 + t2);
  }
  return max(0.0, 1.0 - t);
}

#ifdef SHADOWED
uniform vec3 u_shadowKept; // the fraction of each channel a pixel in full shadow keeps (Light.writeShadowKept)
#endif

#ifdef NORMALS
layout(location = 1) out vec4 o_specular;
uniform sampler2D u_normals;  // the scene's normals, premultiplied by coverage (src/passes/surfaceLayout.ts)
uniform sampler2D u_material; // specular, shininess code, emissive, coverage, premultiplied
uniform vec3 u_surfaceFrame;  // 1 / lightmap width, 1 / lightmap height, 1 when the surface's row 0 is the top of the view
// Positional lights: position xy and height, w 0. Directional: the unit vector towards the light, w 1.
uniform vec4 u_towardsLight;

// The surface's texel under this lightmap pixel: the surface covers the same view at its own size
// (the renderer's), so with lightmapScale below 1 one surface pixel stands for several. Fetched
// unfiltered: the scene target is nearest-sampled anyway.
ivec2 surfaceTexel(highp sampler2D surface) {
  ivec2 size = textureSize(surface, 0);
  ivec2 texel = min(ivec2(gl_FragCoord.xy * u_surfaceFrame.xy * vec2(size)), size - 1);
  return u_surfaceFrame.z > 0.5 ? ivec2(texel.x, size.y - 1 - texel.y) : texel;
}

// Writes the light, already weighted by what its shadows let pass, through the surface: diffuse
// mix(1, N·L, coverage) at location 0, the Blinn-Phong highlight (viewer straight above) at 1.
// Where no normal was written (coverage 0) that is the light as without normals and no highlight.
void writeThroughSurface(vec3 light) {
  ivec2 texel = surfaceTexel(u_normals);
  vec4 encodedNormal = texelFetch(u_normals, texel, 0);
  float coverage = encodedNormal.a;
  vec3 normal = coverage > 0.0 ? encodedNormal.rgb / coverage * 2.0 - 1.0 : vec3(0.0, 0.0, 1.0);
  float normalLength = length(normal);
  normal = normalLength > 1e-4 ? normal / normalLength : vec3(0.0, 0.0, 1.0);
  vec3 towardsLight = u_towardsLight.w > 0.5 ? u_towardsLight.xyz : normalize(vec3(u_towardsLight.xy - v_world, u_towardsLight.z));
  float diffuse = max(dot(normal, towardsLight), 0.0);
  o_light = vec4(light * mix(1.0, diffuse, coverage), 0.0);
  float highlight = 0.0;
  // The material only where a highlight can be: a surface facing the light.
  if (coverage > 0.0 && diffuse > 0.0) {
    vec4 material = texelFetch(u_material, texel, 0);
    if (material.a > 0.0) {
      float shininess = exp2(material.g / material.a * PENUMBRA_SHININESS_LOG2_MAX);
      vec3 halfway = normalize(towardsLight + vec3(0.0, 0.0, 1.0));
      highlight = coverage * material.r / material.a * pow(max(dot(normal, halfway), 0.0), shininess);
    }
  }
  o_specular = vec4(light * highlight, 0.0);
}
#endif

// Writes colour × strength × what passes: the visible fraction of the disk, and of the rest the
// fraction the light's shadows keep (0 by default: mix(0, 1, v) is v exactly). Alpha is 0 so
// additive blending leaves the lightmap's alpha untouched.
void writeLight(float strength) {
#ifdef SHADOWED
  vec3 passes = mix(u_shadowKept, vec3(1.0), strength > 0.0 ? shadowVisibility() : 0.0);
#else
  vec3 passes = vec3(1.0);
#endif
#if defined(SHADOW_STATISTICS)
  // The benchmark's statistics build: per light pixel 1, the records visited, 1 when none was, and 1
  // when the quadrature takes the pixel; and, 1024 times each (a texel sums fewer than 1024 lights),
  // 1 in the channels of the held, lean and general programs.
  const float PROGRAM = 1024.0;
#ifdef SHADOWED
  float visited = float(visitedRecords), past = sweptPixel ? 1.0 : 0.0;
#else
  float visited = 0.0, past = 0.0;
#endif
#if defined(HELD_SHADOW)
  vec3 program = vec3(PROGRAM, 0.0, 0.0);
#elif defined(LEAN_SHADOW)
  vec3 program = vec3(0.0, PROGRAM, 0.0);
#elif defined(SHADOWED)
  vec3 program = vec3(0.0, 0.0, PROGRAM);
#else
  vec3 program = vec3(0.0);
#endif
  o_light = strength > 0.0 ? vec4(1.0, visited, visited == 0.0 ? 1.0 : 0.0, past) + vec4(program.x, 0.0, program.yz) : vec4(0.0);
#elif defined(NORMALS)
  writeThroughSurface(u_lightColor * (strength * passes));
#else
  o_light = vec4(u_lightColor * (strength * passes), 0.0);
#endif
}
