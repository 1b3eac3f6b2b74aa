#version 300 es
// Shadow mask, fragment stage: writes which part of the light disk this fragment's hull hides from
// the pixel, as a fraction of the disk's area. Seen from the pixel, a hull (convex or not) hides one
// interval of directions; measured in disk area from one side of the disk it is [low, high]. It is
// written as R = high when it reaches the first side, G = 1 - low when it reaches the other side, and
// B = high - low when it touches neither. With MAX blending, R + G + B is then the exact union for
// hulls that hide the disk from its sides (the common case) and the largest interval for the rest.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D u_hullPoints; // one world point per texel (xy)
uniform vec2 u_lightPosition;
uniform float u_lightRadius;
uniform mat4 u_clipToWorld;
uniform vec2 u_targetSize;

flat in ivec2 v_hull;
flat in int v_wholeHull; // 1 when the quad is a convex hull's whole region, 0 for an edge's quad

out vec4 o_mask;

const float PI = 3.14159265358979;
const float TOUCH = 1.0 / 1024.0;
// Chord heights past either side of the disk, for directions 90° or more off the light.
const float PAST_HIGH = 2.0;
const float PAST_LOW = -2.0;

vec2 pixel;
vec2 axis;      // unit vector from the pixel to the light centre
float scale;    // distance to the light over its radius

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Fraction of a unit disk lying below the chord at signed height t.
float diskAreaBelow(float t) {
  t = clamp(t, -1.0, 1.0);
  return 0.5 + (asin(t) + t * sqrt(1.0 - t * t)) / PI;
}

// A ray at angle θ off the axis passes the light centre at distance·sin(θ); over the radius it is
// the height of the chord that splits the disk.
float chordHeight(vec2 direction) {
  float across = cross2(axis, direction);
  if (dot(axis, direction) <= 0.0) return across >= 0.0 ? PAST_HIGH : PAST_LOW;
  return scale * across / length(direction);
}

// The mask of a hull hiding the directions between the chords at heights low and high.
vec4 maskBetween(float low, float high) {
  float lowArea = diskAreaBelow(low);
  float highArea = diskAreaBelow(high);
  bool fromFirstSide = lowArea <= TOUCH;
  bool fromOtherSide = highArea >= 1.0 - TOUCH;
  if (fromFirstSide && fromOtherSide) return vec4(1.0, 0.0, 0.0, 0.0);
  if (fromFirstSide) return vec4(highArea, 0.0, 0.0, 0.0);
  if (fromOtherSide) return vec4(0.0, 1.0 - lowArea, 0.0, 0.0);
  return vec4(0.0, 0.0, highArea - lowArea, 0.0);
}

vec2 pointOffset(ivec2 texel) {
  return texelFetch(u_hullPoints, texel, 0).xy - pixel;
}

// Steps to the next point's texel instead of dividing the index by the width for every point.
ivec2 nextTexel(ivec2 texel, int width) {
  texel.x++;
  return texel.x == width ? ivec2(0, texel.y + 1) : texel;
}

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
  if (!anyAhead) return vec4(0.0);
  return maskBetween(lowBehind ? PAST_LOW : chordHeight(lowest), highBehind ? PAST_HIGH : chordHeight(highest));
}

// A convex hull seen from outside spans less than 180°, so a cross product orders the directions
// of all its points (not only those ahead): the two extremes bound its interval exactly, also
// when it wraps behind the pixel and hides the disk from both sides, clear of its middle.
vec4 maskOfConvexHull() {
  int width = textureSize(u_hullPoints, 0).x;
  ivec2 texel = ivec2(v_hull.x % width, v_hull.x / width);
  vec2 lowEnd = pointOffset(texel);
  vec2 highEnd = lowEnd;
  for (int i = 1; i < v_hull.y; i++) {
    texel = nextTexel(texel, width);
    vec2 toPoint = pointOffset(texel);
    if (cross2(highEnd, toPoint) > 0.0) highEnd = toPoint;
    if (cross2(lowEnd, toPoint) < 0.0) lowEnd = toPoint;
  }
  bool wrapsBehind = cross2(lowEnd, -axis) > 0.0 && cross2(-axis, highEnd) > 0.0;
  if (!wrapsBehind) return maskBetween(chordHeight(lowEnd), chordHeight(highEnd));
  // From the first side up to the high end, and from the low end up to the other side.
  return vec4(diskAreaBelow(chordHeight(highEnd)), 1.0 - diskAreaBelow(chordHeight(lowEnd)), 0.0, 0.0);
}

void main() {
  vec2 ndc = gl_FragCoord.xy / u_targetSize * 2.0 - 1.0;
  pixel = (u_clipToWorld * vec4(ndc, 0.0, 1.0)).xy;
  vec2 toLight = u_lightPosition - pixel;
  float distance = max(length(toLight), 1e-6);
  axis = toLight / distance;
  scale = distance / max(u_lightRadius, 1e-4);
  o_mask = v_wholeHull == 1 ? maskOfConvexHull() : maskOfAnyHull();
}
