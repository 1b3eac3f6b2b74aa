#version 300 es
// Shadow mask of edge quads, fragment stage: writes which part of the light disk the quad's hull,
// convex or not, hides from the pixel (see the chunk shadow-common for the channels).
precision highp float;
precision highp int;
precision highp sampler2D;
#include "shadow-common"

// Any hull, convex or not, seen from the pixel. Points ahead of the pixel (towards the light) lie in
// one half-plane, so a cross product orders their angles: no square root or division per point.
// Points behind the pixel stand for directions past ±90°, beyond any chord of the disk.
vec2 highest;
vec2 lowest;
bool highBehind;
bool lowBehind;
bool anyAhead;

void visitPoint(vec2 toPoint) {
  float across = cross2(toLight, toPoint);
  bool ahead = dot(toLight, toPoint) > 0.0;
  highBehind = highBehind || (!ahead && across >= 0.0);
  lowBehind = lowBehind || (!ahead && across < 0.0);
  anyAhead = anyAhead || ahead;
  if (ahead && cross2(highest, toPoint) > 0.0) highest = toPoint;
  if (ahead && cross2(lowest, toPoint) < 0.0) lowest = toPoint;
}

vec4 maskOfAnyHull() {
  highest = vec2(toLight.y, -toLight.x); // -90°: below every point ahead
  lowest = vec2(-toLight.y, toLight.x);  // +90°: above every point ahead
  highBehind = lowBehind = anyAhead = false;
  visitHullPoints();
  // A hull wholly behind the pixel hides nothing: every segment to the disk leaves ahead.
  vec4 mask = maskBetween(lowBehind ? PAST_LOW : chordHeight(lowest), highBehind ? PAST_HIGH : chordHeight(highest));
  return anyAhead ? mask : vec4(0.0);
}

void main() {
  seeFromPixel();
  o_mask = maskOfAnyHull();
}
