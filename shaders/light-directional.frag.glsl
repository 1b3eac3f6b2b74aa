#version 300 es
// Directional light pass: adds colour × the visible fraction of its disk at infinity, over the
// whole view (no falloff). Shadows come from the strips of the light's row (see the chunk
// shadow-visibility, built with DIRECTIONAL).
precision highp float;
precision highp sampler2D;
#define DIRECTIONAL
#include "light-common"

void main() {
  writeLight(1.0);
}
