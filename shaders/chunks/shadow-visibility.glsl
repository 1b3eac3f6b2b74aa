// Shared by the light passes built with SHADOWED: the fraction of the light's disk visible from the
// pixel (SPEC §6), computed in the light's own fragment from the hulls in the pixel's angular bin
// (see src/geometry/shadowLayout.ts for the textures, ShadowBins for what a bin holds).
//
// Seen from a pixel p outside the disk, the line through p in direction d passes the centre c at
// the signed distance cross(c − p, d) / |d|; over the radius r this is the chord height t in
// [−1, 1], and the disk area between the chords at heights a and b is G(b) − G(a) with
// G(t) = 1/2 + (asin t + t √(1 − t²)) / π. A convex record spans less than 180° from p, so its
// silhouette points bound one interval of chord heights. When the part of the disk inside that
// wedge lies wholly beyond the record (the record is "in front"), the record hides exactly that
// interval, and several such records hide exactly the union of their intervals, kept here as a
// cover anchored at each side of the disk plus up to MAX_MIDDLES floating intervals: no max, no sum.
//
// A record whose wedge holds disk points nearer to p than the record itself (the disk overlaps it,
// or p looks past it at the disk, or p is inside the disk) hides only the far part of each wedge.
// Per direction the union of such parts is the one beyond the nearest record, so the hidden area is
// an integral over the directions outside the union of the records in front; a second pass over
// the bin evaluates it by Gauss–Legendre quadrature on pieces whose ends are the directions where
// the integrand is not smooth (the records' points, their edges' crossings with the rim, the
// union's ends).
//
// Accuracy: exact (to float rounding and G's polynomial, 2.2e-4) for pixels whose records are all
// in front, with at most MAX_MIDDLES disjoint middle intervals (beyond that the last one widens:
// darker, never lighter). Where records are seen past, the quadrature is exact between breaks up to
// its order; the random-scene test holds it to the reference limits (max error 0.035 of full light
// over 240 scenes, at the kinks where two records seen past cross).
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
float distanceInRadii;

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

// What a record does to the pixel's view of the disk.
const int HIDES_NOTHING = 0;
const int IN_FRONT = 1;    // hides the whole chords in [low, high]
const int SEEN_PAST = 2;   // hides the far part of chords in [low, high] (all directions inside the disk)
const int HOLDS_PIXEL = 3;

bool insideDisk;

// Classifies the loaded record; sets low and high for IN_FRONT and SEEN_PAST.
int classifyRecord(out float low, out float high) {
  low = -1.0;
  high = 1.0;
  if (pixelInsideRecord()) return HOLDS_PIXEL;
  if (insideDisk) return SEEN_PAST;
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
  if (!lowAhead && !highAhead) return HIDES_NOTHING;
  if (lowAhead) low = max(chordHeight(lowEnd), -1.0);
  if (highAhead) high = min(chordHeight(highEnd), 1.0);
  if (low >= high) return HIDES_NOTHING;
  return diskBeyond(lowEnd, highEnd) ? IN_FRONT : SEEN_PAST;
}

// The quadrature over the records seen past, in the angle φ of directions from the pixel: the area
// hidden along the thin wedge at φ is ½ (far² − max(near, nearest)²) dφ, with near and far where
// the direction enters and leaves the disk and nearest where it first meets a record. The integrand
// is smooth between "breaks": the directions of the records' points (where the nearest edge
// changes), of their edges' crossings with the disk's rim, and of the union's ends (where the
// records in front take over). The sweep goes from break to break (pieces wider than MAX_STEP are
// cut), skips the pieces the union covers, and gives each piece two Gauss–Legendre nodes. It keeps
// no arrays (they cost every fragment, even where unused): it scans the pixel's bin again for each
// next break and each node. Directions in a piece outside the union miss every record in front, so
// the scans need not tell records apart.
const int MAX_PIECES = 64;
const float MAX_STEP = PI / 16.0;
const float NO_BREAK = 1e9;

// The light's bin for this pixel: its first entry and count.
int binFirst;
int binCount;
// The angle of the direction to the disk's centre, and half the disk's angular width (π inside it).
float axisAngle;
float halfSpan;

// Angle from the axis of the direction `d`, in (−π, π].
float angleOf(vec2 d) {
  float angle = atan(d.y, d.x) - axisAngle;
  return angle > PI ? angle - 2.0 * PI : (angle <= -PI ? angle + 2.0 * PI : angle);
}

// The smallest of `next` and the loaded record's breaks after `after`.
float nextRecordBreak(float after, float next) {
  vec2 c = centre - pixel;
  for (int k = 0; k < RECORD_TEXELS * 2; k++) {
    if (k >= pointCount) break;
    vec2 a = points[k], edge = points[k + 1 == pointCount ? 0 : k + 1] - a;
    float angle = angleOf(a);
    if (angle > after) next = min(next, angle);
    // |a + u·edge − c|² = r²: u² |edge|² + 2u edge·(a − c) + |a − c|² − r² = 0.
    float length2 = dot(edge, edge), halfB = dot(edge, a - c), constant = dot(a - c, a - c) - radius * radius;
    float discriminant = halfB * halfB - length2 * constant;
    if (length2 <= 0.0 || discriminant <= 0.0) continue;
    float root = sqrt(discriminant);
    for (int end = 0; end < 2; end++) {
      float u = (-halfB + (end == 0 ? -root : root)) / length2;
      float crossing = angleOf(a + u * edge);
      if (u > 0.0 && u < 1.0 && crossing > after) next = min(next, crossing);
    }
  }
  return next;
}

// The smallest of `next` and the union's ends after `after` (chord height t is at asin(t / distance)).
float nextUnionBreak(float after, float next) {
  float scale = 1.0 / distanceInRadii;
  float lowEnd = asin(clamp(lowCover * scale, -1.0, 1.0)), highEnd = asin(clamp(highCover * scale, -1.0, 1.0));
  if (lowEnd > after) next = min(next, lowEnd);
  if (highEnd > after) next = min(next, highEnd);
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    float low = asin(middles[k].x * scale), high = asin(middles[k].y * scale);
    if (low > after) next = min(next, low);
    if (high > after) next = min(next, high);
  }
  return next;
}

// Whether the direction at `angle` off the axis lies in the union of the records in front.
bool inUnion(float angle) {
  float t = sin(angle) * distanceInRadii;
  if (t <= lowCover || t >= highCover) return true;
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    if (t >= middles[k].x && t <= middles[k].y) return true;
  }
  return false;
}

// The records of entry `i` of the pixel's bin, first and last; (-1, -1) when that hull and all after
// it are farther from the centre than the pixel: they hide nothing.
ivec2 recordsOfEntry(int i) {
  int e = binFirst + i;
  vec4 two = texelAt(u_entries, e / 2);
  vec2 entry = e % 2 == 0 ? two.xy : two.zw;
  if (distanceToLight < entry.y) return ivec2(-1);
  int code = int(entry.x);
  int first = code / ENTRY_MAX_RECORDS;
  return ivec2(first, first + code % ENTRY_MAX_RECORDS);
}

// The next break after `after`, at most `limit`.
float nextBreak(float after, float limit) {
  float next = nextUnionBreak(after, limit);
  for (int i = 0; i < binCount; i++) {
    ivec2 records = recordsOfEntry(i);
    if (records.x < 0) break;
    for (int record = records.x; record <= records.y; record++) {
      loadRecord(record);
      next = nextRecordBreak(after, next);
    }
  }
  return min(next, limit);
}

// ½ (far² − max(near, nearest)²) along the direction at `angle` off the axis.
float hiddenAlong(float angle) {
  vec2 axis = toLight / distanceInRadii;
  float cosine = cos(angle), sine = sin(angle);
  vec2 direction = vec2(axis.x * cosine - axis.y * sine, axis.x * sine + axis.y * cosine);
  vec2 c = centre - pixel;
  float along = dot(c, direction), off = cross2(c, direction);
  float halfChord = sqrt(max(0.0, radius * radius - off * off));
  float far = max(0.0, along + halfChord), nearest = far;
  for (int i = 0; i < binCount; i++) {
    ivec2 records = recordsOfEntry(i);
    if (records.x < 0) break;
    for (int record = records.x; record <= records.y; record++) {
      loadRecord(record);
      nearest = min(nearest, entryDistance(direction));
    }
  }
  nearest = max(nearest, max(0.0, along - halfChord));
  return 0.5 * max(0.0, far * far - nearest * nearest);
}

// The disk area (fraction) the records seen past hide outside the union.
float hiddenPast() {
  const float offset = 0.28867513; // 1 / (2√3): Gauss–Legendre's two nodes on a unit piece
  float hidden = 0.0, from = -halfSpan;
  for (int piece = 0; piece < MAX_PIECES; piece++) {
    if (from >= halfSpan) break;
    // The last piece allowed takes the rest of the domain.
    float to = piece == MAX_PIECES - 1 ? halfSpan : nextBreak(from, min(halfSpan, from + MAX_STEP));
    float middle = 0.5 * (from + to), step = to - from;
    if (insideDisk || !inUnion(middle)) {
      hidden += 0.5 * step * (hiddenAlong(middle - offset * step) + hiddenAlong(middle + offset * step));
    }
    from = to;
  }
  return hidden / (PI * radius * radius);
}

// Pseudo-angle of a direction, in [0, 4), as `pseudoAngle` in src/geometry/shadowLayout.ts.
float pseudoAngle(vec2 d) {
  float p = d.y / (abs(d.x) + abs(d.y));
  return d.x < 0.0 ? 2.0 - p : (d.y < 0.0 ? 4.0 + p : p);
}

#ifdef SHADOW_STATISTICS
// Records the first pass visited, for the benchmark's statistics build (see light-common).
int visitedRecords = 0;
bool seenPastRecords = false;
#endif

// A pass over the pixel's bin, stopping at the first hull farther from the light than the pixel:
// merges the records in front into the union and counts the records seen past; only where there
// are some (a loop of no trips elsewhere: SwiftShader runs both sides of a branch, but leaves a loop
// that no pixel of the quad is in), the quadrature adds what they hide.
float shadowVisibility() {
  pixel = v_world;
  centre = v_shadow.xy;
  radius = max(v_shadow.z, MIN_RADIUS);
  vec2 c = centre - pixel;
  distanceToLight = length(c);
  toLight = c / radius;
  distanceInRadii = distanceToLight / radius;
  insideDisk = distanceInRadii <= 1.0;
  bool illuminated = v_illuminated > 0.5;
  lowCover = -1.0;
  highCover = 1.0;
  middleCount = 0;
  int pastCount = 0;

  int bin = min(int(pseudoAngle(-c) * (float(BIN_COUNT) / 4.0)), BIN_COUNT - 1);
  vec4 binEntries = texelFetch(u_bins, ivec2(bin, int(v_shadow.w)), 0);
  binFirst = int(binEntries.x);
  binCount = int(binEntries.y);
  for (int i = 0; i < binCount; i++) {
    ivec2 records = recordsOfEntry(i);
    if (records.x < 0) break;
    for (int record = records.x; record <= records.y; record++) {
#ifdef SHADOW_STATISTICS
      visitedRecords++;
#endif
      loadRecord(record);
      float low, high;
      int kind = classifyRecord(low, high);
      if (kind == HOLDS_PIXEL) return illuminated ? 1.0 : 0.0;
      if (kind == IN_FRONT) insertInterval(low, high);
      if (kind == SEEN_PAST) pastCount++;
#ifdef SHADOW_STATISTICS
      seenPastRecords = pastCount > 0;
#endif
    }
    // Whole: only an Illuminated light's hull pixels are left to find.
    if (coverIsWhole() && !illuminated) return 0.0;
  }
  if (coverIsWhole()) return 0.0;
  float hidden = insideDisk ? 0.0 : coveredBetween(-1.0, 1.0);
  for (int once = 0; once < (pastCount > 0 ? 1 : 0); once++) {
    axisAngle = atan(c.y, c.x);
    halfSpan = insideDisk ? PI : asin(1.0 / distanceInRadii);
    hidden += hiddenPast();
  }
  return clamp(1.0 - hidden, 0.0, 1.0);
}
