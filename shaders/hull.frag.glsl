#version 300 es
// Hull pass, fragment stage: writes the shadow mask inside hulls: fully hidden (1) for Solid
// lights, cleared (0) for Illuminated ones.
precision mediump float;

uniform vec4 u_maskValue;
out vec4 o_mask;

void main() {
  o_mask = u_maskValue;
}
