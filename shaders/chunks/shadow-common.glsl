// Shared by the shadow-mask fragment stages: the light uniforms, the hull's points (in varyings for
// the builds with VARYING_POINTS, else from the points texture), the pixel seen from the light,
// and the disk areas cut off by chords.
//
// Seen from the pixel, a hull (convex or not) hides one interval of directions; measured in disk
// area from one side of the disk it is [low, high]. It is written as R = high when it reaches the
// first side, G = 1 - low when it reaches the other side, and B = high - low when it touches
// neither. With MAX blending, R + G + B is then the exact union for hulls that hide the disk from
// its sides (the common case). Of several middle slices only the largest counts, and a middle
// slice is added whole even where a hull hiding a side covers part of it.
uniform vec4 u_light; // position xy, disk radius, reach (see shadow-mask.vert.glsl)

in vec2 v_world; // the pixel's world position, interpolated across the caster's quad

out vec4 o_mask;

const float TOUCH = 1.0 / 1024.0;
// Chord heights past either side of the disk, for directions 90° or more off the light.
const float PAST_HIGH = 2.0;
const float PAST_LOW = -2.0;

vec2 pixel;
vec2 toLight; // from the pixel to the light centre, in light radii

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Fraction of a unit disk lying below the chord at signed height t, 1/2 + (asin t + t √(1 − t²)) / π,
// as an odd polynomial fitted for this library: within 2.2e-4 (an eighteenth of a mask step),
// increasing, exactly 0 and 1 at the sides. With asin and two square roots instead, S3's frame
// took 2–3% longer on SwiftShader.
float diskAreaBelow(float t) {
  t = clamp(t, -1.0, 1.0);
  float t2 = t * t;
  return 0.5 + t * (0.63451936 + t2 * (-0.07441131 + t2 * (-0.14561180 + t2 * (0.19324319 + t2 * -0.10773944))));
}

// A ray at angle θ off the direction to the light passes the light centre at distance·sin(θ); over
// the radius it is the height of the chord that splits the disk.
float chordHeight(vec2 direction) {
  float across = cross2(toLight, direction);
  float ahead = across * inversesqrt(dot(direction, direction));
  return dot(toLight, direction) > 0.0 ? ahead : (across >= 0.0 ? PAST_HIGH : PAST_LOW);
}

// The mask of a hull hiding the part of the disk between the areas low and high measured from its
// first side, or (wrapping behind the pixel) all but that part. Products of 0/1 flags: SwiftShader
// runs both sides of a branch, and the same logic as selects cost it a tenth more of the stage.
vec4 maskOfAreas(float lowArea, float highArea, bool wraps) {
  float wrapping = wraps ? 1.0 : 0.0;
  float fromFirstSide = max(wrapping, step(lowArea, TOUCH));
  float fromOtherSide = max(wrapping, step(1.0 - TOUCH, highArea));
  float whole = fromFirstSide * fromOtherSide * (1.0 - wrapping);
  return vec4(fromFirstSide * mix(highArea, 1.0, whole),
              fromOtherSide * (1.0 - whole) * (1.0 - lowArea),
              (1.0 - fromFirstSide) * (1.0 - fromOtherSide) * (highArea - lowArea),
              0.0);
}

// The mask of a hull hiding the directions between the chords at heights low and high.
vec4 maskBetween(float low, float high) {
  return maskOfAreas(diskAreaBelow(low), diskAreaBelow(high), false);
}

// Each stage defines what it does with the offset from the pixel to one of the hull's points.
void visitPoint(vec2 toPoint);

#ifdef VARYING_POINTS
#if VARYING_POINTS != 4 && VARYING_POINTS != 8
#error visitHullPoints visits four or eight points
#endif
// The hull's points, two per vector, padded with its last point (see shadow-mask.vert.glsl).
flat in vec4 v_points[VARYING_POINTS / 2];

vec2 firstPointOffset() {
  return v_points[0].xy - pixel;
}

// Visits every point in order, the padding too: repeating the last point changes no stage's result.
// Unrolled by hand: in a loop, SwiftShader indexes the varyings in memory, slower than fetching.
void visitHullPoints() {
  visitPoint(v_points[0].xy - pixel);
  visitPoint(v_points[0].zw - pixel);
  visitPoint(v_points[1].xy - pixel);
  visitPoint(v_points[1].zw - pixel);
#if VARYING_POINTS == 8
  visitPoint(v_points[2].xy - pixel);
  visitPoint(v_points[2].zw - pixel);
  visitPoint(v_points[3].xy - pixel);
  visitPoint(v_points[3].zw - pixel);
#endif
}
#else
uniform sampler2D u_hullPoints; // one world point per texel (xy)
flat in ivec2 v_hull;           // the hull's first point and point count

ivec2 firstTexel() {
  int width = textureSize(u_hullPoints, 0).x;
  return ivec2(v_hull.x % width, v_hull.x / width);
}

vec2 firstPointOffset() {
  return texelFetch(u_hullPoints, firstTexel(), 0).xy - pixel;
}

// Visits every point in order. Steps to the next texel rather than dividing each index by the width.
void visitHullPoints() {
  int width = textureSize(u_hullPoints, 0).x;
  ivec2 texel = firstTexel();
  for (int i = 0; i < v_hull.y; i++) {
    visitPoint(texelFetch(u_hullPoints, texel, 0).xy - pixel);
    texel.x++;
    if (texel.x == width) texel = ivec2(0, texel.y + 1);
  }
}
#endif

// Sets pixel and toLight for this fragment. Measured in radii, the offset to the light gives chord
// heights with no square root or division per fragment; the stages only compare or normalize the
// offsets to the points, so those stay in world units.
void seeFromPixel() {
  pixel = v_world;
  toLight = (u_light.xy - pixel) / max(u_light.z, 1e-4);
}
