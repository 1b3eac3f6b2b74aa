#version 300 es
// Point light pass: adds colour × distance falloff (the light's curve) × visible fraction of the disk.
precision highp float;
precision highp sampler2D;
#include "light-common"

void main() {
  writeLight(distanceFalloff());
}
