#version 300 es
// Shadow mask of a concave hull's cavities, fragment stage, drawn over the hull's bounding box:
// writes which part of the light disk the hull hides from the pixel (see the chunk shadow-common
// for the channels). Exact anywhere, but costlier than the region stage, which leaves it the pixels
// inside the convex hull of the points.
precision highp float;
precision highp int;
precision highp sampler2D;
#include "shadow-common"

const float PI = 3.14159265358979;
const float TURN = 6.28318530717959;

// asin within 5e-5 (Abramowitz & Stegun 4.4.45): SwiftShader's own costs several times more.
float fastAsin(float x) {
  float a = abs(x);
  float fromRightAngle = sqrt(1.0 - a) * (1.5707288 + a * (-0.2121144 + a * (0.0742610 + a * -0.0187293)));
  return sign(x) * (PI / 2.0 - fromRightAngle);
}

// atan(y, x) within 1e-5: SwiftShader's own costs several times more, once per point.
float fastAtan(float y, float x) {
  float ax = abs(x), ay = abs(y);
  float ratio = min(ax, ay) / max(max(ax, ay), 1e-30);
  float square = ratio * ratio;
  float angle = ratio + ratio * square * (-0.327622764 + square * (0.15931422 + square * -0.0464964749));
  angle = ay > ax ? PI / 2.0 - angle : angle;
  angle = x < 0.0 ? PI - angle : angle;
  return y < 0.0 ? -angle : angle;
}

// The part of the disk hidden by the directions [low, high], measured like `centre` (the light's
// direction), when they overlap the disk's angular width around it.
// `distance` is the pixel's from the light, in radii.
vec4 maskOfDirections(float low, float high, float centre, float halfWidth, float distance) {
  float from = max(low, centre - halfWidth);
  float to = min(high, centre + halfWidth);
  vec4 mask = maskBetween(distance * sin(from - centre), distance * sin(to - centre));
  return from < to ? mask : vec4(0.0);
}

// Walking the outline, the direction to the points turns back and forth; the extremes of the
// accumulated turn bound the one interval of directions the hull covers, also when it spans more
// than 180° (from inside a cavity) and wraps behind the pixel. Measured from the first point.
vec2 previous;
float turn;
float lowest;
float highest;

void visitPoint(vec2 toPoint) {
  turn += fastAtan(cross2(previous, toPoint), dot(previous, toPoint));
  lowest = min(lowest, turn);
  highest = max(highest, turn);
  previous = toPoint;
}

vec4 maskOfAnyHull() {
  vec2 first = firstPointOffset();
  previous = first;
  turn = lowest = highest = 0.0;
  visitHullPoints();
  float centre = fastAtan(cross2(first, toLight), dot(first, toLight));
  float inverseDistance = inversesqrt(max(dot(toLight, toLight), 1e-12));
  float halfWidth = fastAsin(min(inverseDistance, 1.0));
  float distance = 1.0 / inverseDistance;
  // The interval is under a full turn and the disk under half of one: the disk meets it at most
  // twice, once from each side, in the light's direction or a turn either way.
  return max(maskOfDirections(lowest, highest, centre, halfWidth, distance),
             max(maskOfDirections(lowest, highest, centre - TURN, halfWidth, distance),
                 maskOfDirections(lowest, highest, centre + TURN, halfWidth, distance)));
}

void main() {
  seeFromPixel();
  o_mask = maskOfAnyHull();
}
