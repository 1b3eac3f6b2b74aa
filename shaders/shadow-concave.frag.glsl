#version 300 es
// Shadow mask of any hull's region, fragment stage: writes which part of the light disk the hull,
// convex or not, hides from the pixel (see the chunk shadow-common for the channels).
precision highp float;
precision highp int;
precision highp sampler2D;
#include "shadow-common"

const float TURN = 6.28318530717959;

// The part of the disk hidden by the directions [low, high], measured like `centre` (the light's
// direction), when they overlap the disk's angular width around it.
vec4 maskOfDirections(float low, float high, float centre, float halfWidth) {
  float from = max(low, centre - halfWidth);
  float to = min(high, centre + halfWidth);
  vec4 mask = maskBetween(scale * sin(from - centre), scale * sin(to - centre));
  return from < to ? mask : vec4(0.0);
}

// Walking the outline, the direction to the points turns back and forth; the extremes of the
// accumulated turn bound the one interval of directions the hull covers, also when it spans more
// than 180° (from inside a cavity) and wraps behind the pixel. Measured from the first point.
vec4 maskOfAnyHullRegion() {
  int width = textureSize(u_hullPoints, 0).x;
  ivec2 texel = ivec2(v_hull.x % width, v_hull.x / width);
  vec2 first = pointOffset(texel);
  vec2 previous = first;
  float turn = 0.0;
  float lowest = 0.0;
  float highest = 0.0;
  for (int i = 1; i < v_hull.y; i++) {
    texel = nextTexel(texel, width);
    vec2 toPoint = pointOffset(texel);
    turn += atan(cross2(previous, toPoint), dot(previous, toPoint));
    lowest = min(lowest, turn);
    highest = max(highest, turn);
    previous = toPoint;
  }
  float centre = atan(cross2(first, axis), dot(first, axis));
  float halfWidth = fastAsin(min(1.0 / scale, 1.0));
  // The interval is under a full turn and the disk under half of one: the disk meets it at most
  // twice, once from each side, in the light's direction or a turn either way.
  return max(maskOfDirections(lowest, highest, centre, halfWidth),
             max(maskOfDirections(lowest, highest, centre - TURN, halfWidth),
                 maskOfDirections(lowest, highest, centre + TURN, halfWidth)));
}

void main() {
  seeFromPixel();
  o_mask = maskOfAnyHullRegion();
}
