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
out vec4 o_mask;

const float PI = 3.14159265358979;
const float TOUCH = 1.0 / 1024.0;

// Fraction of a unit disk lying below the chord at signed height t.
float diskAreaBelow(float t) {
  t = clamp(t, -1.0, 1.0);
  return 0.5 + (asin(t) + t * sqrt(1.0 - t * t)) / PI;
}

void main() {
  vec2 ndc = gl_FragCoord.xy / u_targetSize * 2.0 - 1.0;
  vec2 pixel = (u_clipToWorld * vec4(ndc, 0.0, 1.0)).xy;
  vec2 toLight = u_lightPosition - pixel;
  float distance = max(length(toLight), 1e-6);
  vec2 axis = toLight / distance;
  // The hull's extreme directions seen from the pixel. Points ahead of the pixel (towards the light)
  // lie in one half-plane, so a cross product orders their angles: no square root or division per
  // point. Points behind the pixel stand for directions past ±90°, beyond any chord of the disk.
  vec2 highest = vec2(axis.y, -axis.x); // -90°: below every point ahead
  vec2 lowest = vec2(-axis.y, axis.x);  // +90°: above every point ahead
  bool highBehind = false;
  bool lowBehind = false;
  int width = textureSize(u_hullPoints, 0).x;
  // Step through the texels instead of dividing the index by the width for every point.
  ivec2 texel = ivec2(v_hull.x % width, v_hull.x / width);
  for (int i = 0; i < v_hull.y; i++) {
    vec2 toPoint = texelFetch(u_hullPoints, texel, 0).xy - pixel;
    texel.x++;
    if (texel.x == width) texel = ivec2(0, texel.y + 1);
    float across = axis.x * toPoint.y - axis.y * toPoint.x;
    if (dot(axis, toPoint) <= 0.0) {
      highBehind = highBehind || across >= 0.0;
      lowBehind = lowBehind || across < 0.0;
      continue;
    }
    if (highest.x * toPoint.y - highest.y * toPoint.x > 0.0) highest = toPoint;
    if (lowest.x * toPoint.y - lowest.y * toPoint.x < 0.0) lowest = toPoint;
  }
  // A ray at angle θ off the axis passes the light centre at distance·sin(θ); over the radius it is
  // the height of the chord that splits the disk.
  float scale = distance / max(u_lightRadius, 1e-4);
  float high = highBehind ? 2.0 : scale * (axis.x * highest.y - axis.y * highest.x) / length(highest);
  float low = lowBehind ? -2.0 : scale * (axis.x * lowest.y - axis.y * lowest.x) / length(lowest);
  float lowArea = diskAreaBelow(low);
  float highArea = diskAreaBelow(high);
  bool fromFirstSide = lowArea <= TOUCH;
  bool fromOtherSide = highArea >= 1.0 - TOUCH;
  if (fromFirstSide && fromOtherSide) {
    o_mask = vec4(1.0, 0.0, 0.0, 0.0);
  } else if (fromFirstSide) {
    o_mask = vec4(highArea, 0.0, 0.0, 0.0);
  } else if (fromOtherSide) {
    o_mask = vec4(0.0, 1.0 - lowArea, 0.0, 0.0);
  } else {
    o_mask = vec4(0.0, 0.0, highArea - lowArea, 0.0);
  }
}
