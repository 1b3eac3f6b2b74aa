#version 300 es
// Composite pass: writes scene colour × lightmap × exposure, tone-mapped and dithered as the
// renderer's options say, into the host's framebuffer (alpha from the scene). With the defaults
// (exposure 1, no curve, no dithering) the result is scene × lightmap exactly. Built with NORMALS
// for a renderer with normals: (scene × (lightmap + emissive) + highlights) × exposure, the emissive
// from the material (docs/normal-maps.md). Built with EDGE_AWARE for a lightmap smaller than the
// scene: the lightmap is upsampled without smearing it across hull outlines (see lightAt).
precision highp float;
precision highp sampler2D;

uniform sampler2D u_scene;
uniform sampler2D u_lightmap;
uniform float u_exposure;
uniform int u_toneMapping; // 0 or TONE_REINHARD or TONE_ACES (src/passes/compositeLayout.ts)
uniform int u_dithering;   // 0 or DITHER_ORDERED or DITHER_NOISE
#ifdef NORMALS
uniform sampler2D u_specular; // the light pass's highlights
uniform sampler2D u_material; // specular, shininess code, emissive, coverage, premultiplied (src/passes/surfaceLayout.ts)
uniform bool u_flipSurface;   // whether the material's row 0 is the top of the view
#endif

#ifdef EDGE_AWARE
uniform sampler2D u_hullMask;         // 1 inside a hull, at the scene's resolution (src/passes/HullMaskPass.ts)
uniform sampler2D u_lightmapHullMask; // the same at the lightmap's (linear filtering): whether each texel's sample lies in a hull
#endif
in vec2 v_uv;
out vec4 o_color;

const int BAYER[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);

// Where the curves stop changing in float32, as their inputs are capped: Reinhard's c / (1 + c) is 1
// from 2^24 on, and the ACES fit reaches 1 at c ≈ 7.24 (clamped above). Capped, a huge c (a huge
// exposure, up to ∞) cannot overflow c² or make ∞ / ∞: the curves give 1 there, not NaN.
const float REINHARD_FLAT = 16777216.0;
const float ACES_FLAT = 16.0;

vec3 toneMap(vec3 c) {
  if (u_toneMapping == TONE_REINHARD) {
    c = min(c, vec3(REINHARD_FLAT));
    return c / (1.0 + c);
  }
  if (u_toneMapping == TONE_ACES) {
    c = min(c, vec3(ACES_FLAT));
    return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
  }
  return c;
}

// The pixel's dithering threshold, in (0, 1): uniform over a 4 × 4 tile, or over the screen.
float ditherThreshold() {
  if (u_dithering == DITHER_ORDERED) {
    ivec2 p = ivec2(gl_FragCoord.xy) & 3;
    return (float(BAYER[p.x + 4 * p.y]) + 0.5) / 16.0;
  }
  return fract(52.9829189 * fract(dot(floor(gl_FragCoord.xy), vec2(0.06711056, 0.00583715))));
}

#ifdef EDGE_AWARE
// The lightmap is smooth but across hull outlines, where a light's value jumps (dark inside a Solid
// hull; lit inside an Illuminated one, beside the dark floor behind it). Bilinear upsampling smears
// that jump a lightmap texel into the other side: a dark rim on the lit floor, a lit seam on the
// shadow. So where the four texels around the pixel are not all on one side of the outlines, only
// those on the pixel's side count, with their bilinear weights (floored, so that one on the pixel's
// side always counts). With none on its side (a hull thinner than a texel), plain bilinear.
// Accuracy: the pixel takes the light of the nearest samples on its side, up to a texel away.
ivec2 lightmapCorner;    // the texel below and left of the pixel
ivec2 lightmapLast;      // the lightmap's last texel, where the corners are clamped
vec4 cornerWeights;      // for the texels (0, 0), (1, 0), (0, 1), (1, 1) from lightmapCorner; 0: bilinear
bool besideOutline;

// Texel `offset` from lightmapCorner of `source` (at the lightmap's resolution), clamped to it.
vec4 texelAround(sampler2D source, ivec2 offset) {
  return texelFetch(source, clamp(lightmapCorner + offset, ivec2(0), lightmapLast), 0);
}

void chooseLightmapTexels() {
  besideOutline = false;
  // One filtered read tells whether the four texels are all on one side: 0 or 1 (the common case).
  float mixed = texture(u_lightmapHullMask, v_uv).r;
  if (mixed == 0.0 || mixed == 1.0) return;
  vec2 position = v_uv * vec2(textureSize(u_lightmap, 0)) - 0.5;
  vec2 corner = floor(position), f = position - corner;
  lightmapCorner = ivec2(corner);
  lightmapLast = textureSize(u_lightmap, 0) - 1;
  vec4 inside = vec4(texelAround(u_lightmapHullMask, ivec2(0, 0)).r, texelAround(u_lightmapHullMask, ivec2(1, 0)).r,
                     texelAround(u_lightmapHullMask, ivec2(0, 1)).r, texelAround(u_lightmapHullMask, ivec2(1, 1)).r);
  float here = texelFetch(u_hullMask, ivec2(v_uv * vec2(textureSize(u_hullMask, 0))), 0).r;
  vec4 bilinear = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  cornerWeights = max(bilinear, 1e-3) * vec4(equal(inside, vec4(here)));
  float total = cornerWeights.x + cornerWeights.y + cornerWeights.z + cornerWeights.w;
  besideOutline = total > 0.0;
  cornerWeights /= max(total, 1e-6);
}

vec3 lightAt(sampler2D lightmap) {
  if (!besideOutline) return texture(lightmap, v_uv).rgb;
  return texelAround(lightmap, ivec2(0, 0)).rgb * cornerWeights.x + texelAround(lightmap, ivec2(1, 0)).rgb * cornerWeights.y
       + texelAround(lightmap, ivec2(0, 1)).rgb * cornerWeights.z + texelAround(lightmap, ivec2(1, 1)).rgb * cornerWeights.w;
}
#else
void chooseLightmapTexels() {}

vec3 lightAt(sampler2D lightmap) {
  return texture(lightmap, v_uv).rgb;
}
#endif

void main() {
  vec4 scene = texture(u_scene, v_uv);
  chooseLightmapTexels();
#ifdef NORMALS
  vec4 material = texture(u_material, u_flipSurface ? vec2(v_uv.x, 1.0 - v_uv.y) : v_uv);
  float emissive = material.a > 0.0 ? material.b / material.a : 0.0;
  vec3 lit = scene.rgb * (lightAt(u_lightmap) + emissive) + lightAt(u_specular);
  vec3 color = toneMap(lit * u_exposure);
#else
  vec3 color = toneMap(scene.rgb * lightAt(u_lightmap) * u_exposure);
#endif
  // Shifts the value by less than half an 8-bit step either way, so rounding to 8 bits moves it
  // by at most one step, and the average over neighbours follows the exact value.
  if (u_dithering != 0) color += (ditherThreshold() - 0.5) / 255.0;
  o_color = vec4(color, scene.a);
}
