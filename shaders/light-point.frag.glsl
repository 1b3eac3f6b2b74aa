#version 300 es
// Point light pass: adds colour × linear distance falloff × visible fraction of the disk.
precision highp float;
precision highp sampler2D;
#include "light-common"

void main() {
  writeLight(distanceFalloff());
}
