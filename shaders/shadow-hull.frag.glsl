#version 300 es
// Shadow mask of a convex hull's region, fragment stage: writes which part of the light disk the
// hull hides from the pixel (see the chunk shadow-common for the channels).
precision highp float;
precision highp int;
precision highp sampler2D;
#include "shadow-common"

// A convex hull seen from outside spans less than 180°, so a cross product orders the directions
// of all its points (not only those ahead): the two extremes bound its interval exactly, also
// when it wraps behind the pixel and hides the disk from both sides, clear of its middle.
vec2 lowEnd;
vec2 highEnd;

void visitPoint(vec2 toPoint) {
  if (cross2(highEnd, toPoint) > 0.0) highEnd = toPoint;
  if (cross2(lowEnd, toPoint) < 0.0) lowEnd = toPoint;
}

vec4 maskOfConvexHull() {
  lowEnd = highEnd = firstPointOffset();
  visitHullPoints();
  bool wrapsBehind = cross2(lowEnd, -axis) > 0.0 && cross2(-axis, highEnd) > 0.0;
  return maskOfAreas(diskAreaBelow(chordHeight(lowEnd)), diskAreaBelow(chordHeight(highEnd)), wrapsBehind);
}

void main() {
  seeFromPixel();
  o_mask = maskOfConvexHull();
}
