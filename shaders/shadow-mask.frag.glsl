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
  // A ray from the pixel at angle θ off the axis passes the light centre at distance·sin(θ);
  // divided by the radius it is the chord height that splits the disk.
  float scale = distance / max(u_lightRadius, 1e-4);
  float low = 2.0;
  float high = -2.0;
  int width = textureSize(u_hullPoints, 0).x;
  for (int i = 0; i < v_hull.y; i++) {
    int index = v_hull.x + i;
    vec2 toPoint = texelFetch(u_hullPoints, ivec2(index % width, index / width), 0).xy - pixel;
    float across = axis.x * toPoint.y - axis.y * toPoint.x;
    float t = dot(axis, toPoint) > 0.0 ? scale * across / length(toPoint) : (across >= 0.0 ? 2.0 : -2.0);
    low = min(low, t);
    high = max(high, t);
  }
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
