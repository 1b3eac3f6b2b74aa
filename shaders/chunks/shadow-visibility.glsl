// Shared by the light passes built with SHADOWED: the fraction of the light's disk visible from the
// pixel (SPEC §6), computed in the light's own fragment from the records in the pixel's angular bin
// (see src/geometry/shadowLayout.ts for the textures, ShadowBins for what a bin holds).
//
// Seen from a pixel p outside the disk, the line through p in direction d passes the centre c at
// the signed distance cross(c − p, d) / |d|; over the radius r this is the chord height t in
// [−1, 1], and the disk area between the chords at heights a and b is G(b) − G(a) with
// G(t) = 1/2 + (asin t + t √(1 − t²)) / π. A convex record spans less than 180° from p, so its
// silhouette points bound one interval of chord heights. When the part of the disk inside that
// wedge lies wholly beyond the record (the record is "in front"), the record hides exactly that
// interval, and several such records hide exactly the union of their intervals, kept here as a
// cover anchored at each side of the disk plus up to MAX_MIDDLES floating intervals. The union is
// exact: no max, no sum.
//
// A record whose wedge holds disk points nearer to p than the record itself (the disk overlaps it,
// or p looks past it at the disk) hides only the far part of each chord. Per chord, the union of
// such parts is the one beyond the nearest hit, so the hidden area is the integral over t of the
// largest hidden fraction of the chord: evaluated outside the front records' union, over the span
// of those records, by the midpoint rule on PARTIAL_CELLS cells. The cells' ends sit on the span's
// ends, where the hidden fraction jumps; inside, it varies smoothly except where another record's
// silhouette begins. A pixel inside the disk integrates over the full turn of directions instead.
//
// Accuracy: exact (to float rounding and G's polynomial, 2.2e-4) for pixels whose records are all
// in front with at most MAX_MIDDLES disjoint middle intervals; the quadrature's error is measured
// by the reference tests. Beyond MAX_MIDDLES middles, or MAX_PARTIALS records seen past, the
// excess counts as hiding its whole interval (darker, never lighter).
//
// Needs: v_world (the pixel's world position), v_shadow (light centre xy, disk radius, bin row) and
// v_illuminated (1: hulls themselves are lit, 0: dark).
uniform highp sampler2D u_records;
uniform highp sampler2D u_entries;
uniform highp sampler2D u_bins;

in vec2 v_world;
flat in vec4 v_shadow;
flat in float v_illuminated;

const float PI = 3.14159265;
const int MAX_MIDDLES = 4;
const int MAX_PARTIALS = 4;
const int PARTIAL_CELLS = 12;
const int TURN_CELLS = 32;
// A radius of 0 (hard shadows) is taken as this, a thousandth of a world unit: chord heights stay
// finite and the visible fraction is 0 or 1 but within that distance of a hull's edge.
const float MIN_RADIUS = 1e-3;

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// G(t): the fraction of a unit disk below the chord at height t, as an odd polynomial fitted for this
// library: within 2.2e-4, increasing, exactly 0 and 1 at the sides.
float diskAreaBelow(float t) {
  t = clamp(t, -1.0, 1.0);
  float t2 = t * t;
  return 0.5 + t * (0.63451936 + t2 * (-0.07441131 + t2 * (-0.14561180 + t2 * (0.19324319 + t2 * -0.10773944))));
}

vec4 texelAt(sampler2D source, int index) {
  return texelFetch(source, ivec2(index % TEXTURE_WIDTH, index / TEXTURE_WIDTH), 0);
}

// The pixel and light, set by shadowVisibility().
vec2 pixel;
vec2 centre;
float radius;
vec2 toLight;  // from the pixel to the centre, in radii
float distanceToLight; // in world units

// A record's points, as offsets from the pixel.
vec2 points[RECORD_TEXELS * 2];
int pointCount;

// Loads a record's points. Unused slots repeat the last point, so a texel of two repeats ends the
// record; an odd count keeps one repeat, which changes no result (an edge of no length).
void loadRecord(int record) {
  int first = record * RECORD_TEXELS;
  vec4 two = texelAt(u_records, first);
  points[0] = two.xy - pixel;
  points[1] = two.zw - pixel;
  pointCount = 2;
  for (int i = 1; i < RECORD_TEXELS; i++) {
    vec4 next = texelAt(u_records, first + i);
    if (next.xy == two.zw && next.zw == two.zw) break;
    two = next;
    points[2 * i] = two.xy - pixel;
    points[2 * i + 1] = two.zw - pixel;
    pointCount += 2;
  }
}

// Chord height of the line from the pixel along `direction`, for a direction less than 90° off the
// light's (larger ones meet no chord).
float chordHeight(vec2 direction) {
  return cross2(toLight, direction) * inversesqrt(dot(direction, direction));
}

bool isAhead(vec2 direction) {
  return dot(toLight, direction) > 0.0;
}

// Squared distance from `point` to the segment a–b.
float segmentDistance2(vec2 point, vec2 a, vec2 b) {
  vec2 edge = b - a;
  float along = clamp(dot(point - a, edge) / max(dot(edge, edge), 1e-20), 0.0, 1.0);
  vec2 off = point - a - along * edge;
  return dot(off, off);
}

// Whether the disk misses the triangle between the pixel and the silhouette points a and b (offsets
// from the pixel): then every disk point in the wedge lies beyond the record, which lies inside
// that triangle's far part. First the cheap test: the disk wholly beyond the line a–b.
bool diskBeyond(vec2 a, vec2 b) {
  vec2 c = centre - pixel;
  vec2 edge = b - a;
  float beyond = cross2(edge, c - a) * inversesqrt(max(dot(edge, edge), 1e-20));
  // The pixel is on the side where cross2(edge, -a) has its sign.
  if (cross2(edge, -a) * beyond < 0.0 && abs(beyond) >= radius) return true;
  float r2 = radius * radius;
  bool inside = cross2(a, c) * cross2(a, b) > 0.0 && cross2(b, c) * cross2(b, a) > 0.0 && cross2(edge, c - a) * cross2(edge, -a) > 0.0;
  return !inside && segmentDistance2(c, vec2(0.0), a) >= r2 && segmentDistance2(c, vec2(0.0), b) >= r2 && segmentDistance2(c, a, b) >= r2;
}

// The union of the front records' intervals: [-1, lowCover] ∪ [highCover, 1] ∪ middles.
float lowCover;
float highCover;
vec2 middles[MAX_MIDDLES];
int middleCount;

void insertInterval(float low, float high) {
  // Merge every middle that overlaps or touches [low, high] into it. Middles lie strictly between
  // the covers, so after this, growing a cover to high (or low) can reach no other middle.
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    if (middles[k].x <= high && middles[k].y >= low) {
      low = min(low, middles[k].x);
      high = max(high, middles[k].y);
      middles[k] = middles[middleCount - 1];
      middleCount--;
      k--;
    }
  }
  if (low <= lowCover) lowCover = max(lowCover, high);
  else if (high >= highCover) highCover = min(highCover, low);
  else if (middleCount < MAX_MIDDLES) middles[middleCount++] = vec2(low, high);
  else middles[MAX_MIDDLES - 1] = vec2(min(low, middles[MAX_MIDDLES - 1].x), max(high, middles[MAX_MIDDLES - 1].y));
}

bool coverIsWhole() {
  return lowCover >= highCover;
}

// Disk area (fraction) of the union within the chord heights [low, high].
float coveredBetween(float low, float high) {
  float covered = max(0.0, diskAreaBelow(min(high, lowCover)) - diskAreaBelow(low))
                + max(0.0, diskAreaBelow(high) - diskAreaBelow(max(low, highCover)));
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    covered += max(0.0, diskAreaBelow(min(high, middles[k].y)) - diskAreaBelow(max(low, middles[k].x)));
  }
  return covered;
}

// The records seen past: their numbers.
int partials[MAX_PARTIALS];
int partialCount;
float partialLow;
float partialHigh;

// Distance along the unit `direction` from the pixel to where it enters the loaded record (which has
// positive area and does not hold the pixel), or a huge value when it misses.
float entryDistance(vec2 direction) {
  float enter = 0.0, leave = 1e30;
  for (int i = 0; i < RECORD_TEXELS * 2; i++) {
    if (i >= pointCount) break;
    vec2 a = points[i], b = points[i + 1 == pointCount ? 0 : i + 1];
    vec2 normal = vec2(b.y - a.y, a.x - b.x); // outward
    float toward = dot(normal, direction), room = dot(normal, a);
    if (toward < 0.0) enter = max(enter, room / toward);
    else if (toward > 0.0) leave = min(leave, room / toward);
    else if (room < 0.0) return 1e30;
  }
  return enter <= leave ? enter : 1e30;
}

// The largest part of the chord along the unit `direction`, between nearEnd and farEnd from the
// pixel, that a record seen past hides, weighted by area (the polar area element grows with distance).
float hiddenPartOfChord(vec2 direction, float nearEnd, float farEnd) {
  float nearest = farEnd;
  for (int k = 0; k < MAX_PARTIALS; k++) {
    if (k >= partialCount) break;
    loadRecord(partials[k]);
    nearest = min(nearest, entryDistance(direction));
  }
  nearest = max(nearest, nearEnd);
  return (farEnd * farEnd - nearest * nearest) / max(farEnd * farEnd - nearEnd * nearEnd, 1e-20);
}

// The unit direction from the pixel whose line has chord height t.
vec2 directionAtHeight(float t, float distanceInRadii) {
  float sine = t / distanceInRadii, cosine = sqrt(max(0.0, 1.0 - sine * sine));
  vec2 axis = toLight / distanceInRadii;
  return vec2(axis.x * cosine - axis.y * sine, axis.x * sine + axis.y * cosine);
}

// Hidden disk area (fraction) from the records seen past, outside the union, over their span.
float hiddenByPartials(float distanceInRadii) {
  float low = max(partialLow, -1.0), high = min(partialHigh, 1.0);
  float hidden = 0.0;
  for (int j = 0; j < PARTIAL_CELLS; j++) {
    float from = mix(low, high, float(j) / float(PARTIAL_CELLS));
    float to = mix(low, high, float(j + 1) / float(PARTIAL_CELLS));
    float open = diskAreaBelow(to) - diskAreaBelow(from) - coveredBetween(from, to);
    if (open <= 0.0) continue;
    float t = 0.5 * (from + to);
    vec2 direction = directionAtHeight(t, distanceInRadii);
    float along = distanceToLight * dot(direction, toLight) / distanceInRadii;
    float halfChord = radius * sqrt(max(0.0, 1.0 - t * t));
    hidden += open * hiddenPartOfChord(direction, along - halfChord, along + halfChord);
  }
  return hidden;
}

// Visible fraction for a pixel inside the disk: over the full turn of directions, the area from the
// pixel to the nearest of the disk's rim and the records.
float visibleFromInside() {
  float visible = 0.0;
  vec2 c = centre - pixel;
  for (int j = 0; j < TURN_CELLS; j++) {
    float angle = (float(j) + 0.5) * (2.0 * PI / float(TURN_CELLS));
    vec2 direction = vec2(cos(angle), sin(angle));
    float along = dot(c, direction), off = cross2(c, direction);
    float rim = along + sqrt(max(0.0, radius * radius - off * off));
    float nearest = rim;
    for (int k = 0; k < MAX_PARTIALS; k++) {
      if (k >= partialCount) break;
      loadRecord(partials[k]);
      nearest = min(nearest, entryDistance(direction));
    }
    visible += nearest * nearest;
  }
  return visible * (0.5 * 2.0 * PI / float(TURN_CELLS)) / (PI * radius * radius);
}

// Whether the pixel lies inside the loaded record or on its outline (left of or on every edge).
bool pixelInsideRecord() {
  bool inside = true;
  for (int i = 0; i < RECORD_TEXELS * 2; i++) {
    if (i >= pointCount) break;
    vec2 a = points[i], b = points[i + 1 == pointCount ? 0 : i + 1];
    inside = inside && cross2(b - a, -a) >= 0.0;
  }
  return inside;
}

// Pseudo-angle of a direction, in [0, 4), as `pseudoAngle` in src/geometry/shadowLayout.ts.
float pseudoAngle(vec2 d) {
  float p = d.y / (abs(d.x) + abs(d.y));
  return d.x < 0.0 ? 2.0 - p : (d.y < 0.0 ? 4.0 + p : p);
}

bool illuminated;
bool insideDisk;
// Set when the pixel lies inside a record: then its visibility is decided (dark, or lit whole).
bool insideHull;

#ifdef SHADOW_STATISTICS
// Records the main loop visited, for the benchmark's statistics build (see light-common).
int visitedRecords = 0;
#endif

// Visits one record: inside test, then its interval into the union or onto the partials.
void visitRecord(int record) {
#ifdef SHADOW_STATISTICS
  visitedRecords++;
#endif
  loadRecord(record);
  if (pixelInsideRecord()) {
    insideHull = true;
    return;
  }
  if (coverIsWhole()) return; // only an Illuminated light's hull pixels are left to find
  // The silhouette: the extreme directions, ordered by cross products (the record spans < 180°).
  vec2 lowEnd = points[0], highEnd = points[0];
  for (int k = 1; k < RECORD_TEXELS * 2; k++) {
    if (k >= pointCount) break;
    if (cross2(highEnd, points[k]) > 0.0) highEnd = points[k];
    if (cross2(lowEnd, points[k]) < 0.0) lowEnd = points[k];
  }
  // A silhouette direction 90° or more off the light was reached by turning from the other end:
  // clockwise past -90° for the low end, counter-clockwise past +90° for the high end. With both
  // ends there, the record lies behind the pixel (it spans less than 180°).
  bool lowAhead = isAhead(lowEnd), highAhead = isAhead(highEnd);
  if (!lowAhead && !highAhead && !insideDisk) return;
  float low = lowAhead ? max(chordHeight(lowEnd), -1.0) : -1.0;
  float high = highAhead ? min(chordHeight(highEnd), 1.0) : 1.0;
  if (low >= high && !insideDisk) return;
  if (!insideDisk && diskBeyond(lowEnd, highEnd)) {
    insertInterval(low, high);
  } else if (partialCount < MAX_PARTIALS) {
    partials[partialCount++] = record;
    partialLow = min(partialLow, low);
    partialHigh = max(partialHigh, high);
  } else {
    insertInterval(low, high);
  }
}

float shadowVisibility() {
  pixel = v_world;
  centre = v_shadow.xy;
  radius = max(v_shadow.z, MIN_RADIUS);
  vec2 c = centre - pixel;
  distanceToLight = length(c);
  toLight = c / radius;
  float distanceInRadii = distanceToLight / radius;
  insideDisk = distanceInRadii <= 1.0;
  illuminated = v_illuminated > 0.5;
  insideHull = false;
  lowCover = -1.0;
  highCover = 1.0;
  middleCount = 0;
  partialCount = 0;
  partialLow = 2.0;
  partialHigh = -2.0;

  int bin = min(int(pseudoAngle(-c) * (float(BIN_COUNT) / 4.0)), BIN_COUNT - 1);
  vec4 binEntries = texelFetch(u_bins, ivec2(bin, int(v_shadow.w)), 0);
  int first = int(binEntries.x), count = int(binEntries.y);
  for (int i = 0; i < count; i++) {
    int e = first + i;
    vec4 two = texelAt(u_entries, e / 2);
    vec2 entry = e % 2 == 0 ? two.xy : two.zw;
    // This hull and all after it are farther from the centre than the pixel: they hide nothing.
    if (distanceToLight < entry.y) break;
    int code = int(entry.x);
    int firstRecord = code / ENTRY_MAX_RECORDS, lastRecord = firstRecord + code % ENTRY_MAX_RECORDS;
    for (int record = firstRecord; record <= lastRecord; record++) {
      visitRecord(record);
      if (insideHull) return illuminated ? 1.0 : 0.0;
    }
    if (coverIsWhole() && !illuminated) return 0.0;
  }
  if (insideDisk) return partialCount == 0 ? 1.0 : visibleFromInside();
  if (coverIsWhole()) return 0.0;
  float hidden = coveredBetween(-1.0, 1.0);
  if (partialCount > 0) hidden += hiddenByPartials(distanceInRadii);
  return clamp(1.0 - hidden, 0.0, 1.0);
}
