#version 300 es
// Spotlight pass: adds colour × distance falloff × cone falloff × visible fraction of the disk.
// Cone falloff at angle θ off the axis: (1 − θ / halfAngle) ^ coneDecay inside the cone, 0 outside.
precision highp float;
precision highp sampler2D;
#include "light-common"

uniform vec2 u_direction;
uniform float u_coneHalfAngle;
uniform float u_coneDecay;

void main() {
  float distance = length(v_fromLight);
  float angle = distance > 0.0 ? acos(clamp(dot(v_fromLight / distance, u_direction), -1.0, 1.0)) : 0.0;
  float inside = 1.0 - angle / max(u_coneHalfAngle, 1e-6);
  float cone = inside < 0.0 ? 0.0 : (u_coneDecay == 0.0 ? 1.0 : pow(inside, u_coneDecay));
  writeLight(distanceFalloff() * cone);
}
