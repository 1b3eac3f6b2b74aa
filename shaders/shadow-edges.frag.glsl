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
vec4 maskOfAnyHull() {
  vec2 highest = vec2(axis.y, -axis.x); // -90°: below every point ahead
  vec2 lowest = vec2(-axis.y, axis.x);  // +90°: above every point ahead
  bool highBehind = false;
  bool lowBehind = false;
  bool anyAhead = false;
  int width = textureSize(u_hullPoints, 0).x;
  ivec2 texel = ivec2(v_hull.x % width, v_hull.x / width);
  for (int i = 0; i < v_hull.y; i++) {
    vec2 toPoint = pointOffset(texel);
    texel = nextTexel(texel, width);
    float across = cross2(axis, toPoint);
    if (dot(axis, toPoint) <= 0.0) {
      highBehind = highBehind || across >= 0.0;
      lowBehind = lowBehind || across < 0.0;
      continue;
    }
    anyAhead = true;
    if (cross2(highest, toPoint) > 0.0) highest = toPoint;
    if (cross2(lowest, toPoint) < 0.0) lowest = toPoint;
  }
  // A hull wholly behind the pixel hides nothing: every segment to the disk leaves ahead.
  vec4 mask = maskBetween(lowBehind ? PAST_LOW : chordHeight(lowest), highBehind ? PAST_HIGH : chordHeight(highest));
  return anyAhead ? mask : vec4(0.0);
}

void main() {
  seeFromPixel();
  o_mask = maskOfAnyHull();
}
