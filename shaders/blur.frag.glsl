#version 300 es
// Lightmap blur, one axis: writes the Gaussian-weighted sum of the source texels within u_radius
// texels along u_step (taps past the edge read the edge texel). Two runs, across then down, blur
// the lightmap in both directions (see BlurPass).
precision highp float;
precision highp sampler2D;

uniform sampler2D u_source;
uniform vec2 u_step; // one texel along the axis, in texture coordinates
uniform int u_radius; // ≤ MAX_BLUR_RADIUS (src/passes/BlurPass.ts)
uniform float u_weights[MAX_BLUR_RADIUS + 1]; // u_weights[k] for the taps at ±k, summing to 1 over −u_radius..u_radius

in vec2 v_uv;
out vec4 o_color;

void main() {
  vec4 sum = texture(u_source, v_uv) * u_weights[0];
  for (int k = 1; k <= MAX_BLUR_RADIUS; k++) {
    if (k > u_radius) break;
    vec2 offset = u_step * float(k);
    sum += (texture(u_source, v_uv - offset) + texture(u_source, v_uv + offset)) * u_weights[k];
  }
  o_color = sum;
}
