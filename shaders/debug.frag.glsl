#version 300 es
// Debug pass: draws wireframes (light quads, shadow geometry) in a flat colour.
precision mediump float;

uniform vec4 u_color;
out vec4 o_color;

void main() {
  o_color = u_color;
}
