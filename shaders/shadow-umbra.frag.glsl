#version 300 es
// Shadow mask of a hull's umbra, fragment stage: the whole disk is hidden there. Also writes
// depth (nearer than the other shadow quads), so their costly fragments are skipped there.
precision mediump float;

out vec4 o_mask;

void main() {
  o_mask = vec4(1.0, 0.0, 0.0, 0.0);
}
