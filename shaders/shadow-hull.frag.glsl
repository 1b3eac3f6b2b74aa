#version 300 es
// Shadow mask of a hull's region, fragment stage: writes which part of the light disk the hull
// hides from the pixel (see the chunk shadow-common for the channels). Built with CONCAVE_HULL for
// concave hulls: then it writes nothing hidden inside the convex hull of the points, where the
// cavity stage (shadow-cavity.frag.glsl) takes over.
precision highp float;
precision highp int;
precision highp sampler2D;
#include "shadow-common"

// Seen from outside the convex hull of its points, a hull (convex or not) spans less than 180°, so
// a cross product orders the directions of all its points (not only those ahead): the two extremes
// bound its interval exactly, also when it wraps behind the pixel and hides the disk from both
// sides, clear of its middle.
vec2 lowEnd;
vec2 highEnd;
#ifdef CONCAVE_HULL
// Inside the convex hull the points surround the pixel: some point lies beyond both extremes, or
// the extremes end up 180° or more apart.
bool surrounded = false;
#endif

void visitPoint(vec2 toPoint) {
  bool beyondHigh = cross2(highEnd, toPoint) > 0.0;
  bool beyondLow = cross2(lowEnd, toPoint) < 0.0;
  if (beyondHigh) highEnd = toPoint;
  if (beyondLow) lowEnd = toPoint;
#ifdef CONCAVE_HULL
  surrounded = surrounded || (beyondHigh && beyondLow) || cross2(lowEnd, highEnd) < 0.0;
#endif
}

vec4 maskOfRegion() {
  lowEnd = highEnd = firstPointOffset();
  visitHullPoints();
  bool wrapsBehind = cross2(lowEnd, -toLight) > 0.0 && cross2(-toLight, highEnd) > 0.0;
  vec4 mask = maskOfAreas(diskAreaBelow(chordHeight(lowEnd)), diskAreaBelow(chordHeight(highEnd)), wrapsBehind);
#ifdef CONCAVE_HULL
  // Under #ifdef: SwiftShader keeps even a select on a constant.
  if (surrounded) mask = vec4(0.0);
#endif
  return mask;
}

void main() {
  seeFromPixel();
  o_mask = maskOfRegion();
}
