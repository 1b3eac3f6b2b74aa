#version 300 es
// A flat colour: the debug pass's wireframes (light quads, shadow geometry), and the hull mask's
// coverage (1 in its single channel).
precision mediump float;

uniform vec4 u_color;
out vec4 o_color;

void main() {
  o_color = u_color;
}
