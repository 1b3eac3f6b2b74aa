#version 300 es
// Composite pass: writes scene colour × lightmap × exposure, tone-mapped and dithered as the
// renderer's options say, into the host's framebuffer (alpha from the scene). With the defaults
// (exposure 1, no curve, no dithering) the result is scene × lightmap exactly. Built with NORMALS
// for a renderer with normals: (scene × (lightmap + emissive) + highlights) × exposure, the emissive
// from the material (docs/normal-maps.md).
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

in vec2 v_uv;
out vec4 o_color;

const int BAYER[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);

vec3 toneMap(vec3 c) {
  if (u_toneMapping == TONE_REINHARD) return c / (1.0 + c);
  if (u_toneMapping == TONE_ACES) return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
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

void main() {
  vec4 scene = texture(u_scene, v_uv);
#ifdef NORMALS
  vec4 material = texture(u_material, u_flipSurface ? vec2(v_uv.x, 1.0 - v_uv.y) : v_uv);
  float emissive = material.a > 0.0 ? material.b / material.a : 0.0;
  vec3 lit = scene.rgb * (texture(u_lightmap, v_uv).rgb + emissive) + texture(u_specular, v_uv).rgb;
  vec3 color = toneMap(lit * u_exposure);
#else
  vec3 color = toneMap(scene.rgb * texture(u_lightmap, v_uv).rgb * u_exposure);
#endif
  // Shifts the value by less than half an 8-bit step either way, so rounding to 8 bits moves it
  // by at most one step, and the average over neighbours follows the exact value.
  if (u_dithering != 0) color += (ditherThreshold() - 0.5) / 255.0;
  o_color = vec4(color, scene.a);
}
