// Shared by the light passes built with SHADOWED: the fraction of the light's disk whose segments to
// the pixel meet no hull (docs/shadows.md), computed in the light's own fragment from the hulls in
// the pixel's angular bin (see src/shadow/shadowLayout.ts for the textures, ShadowBins for what a
// bin holds).
//
// Seen from a pixel p outside the disk, the line through p in direction d passes the centre c at
// the signed distance cross(c − p, d) / |d|; over the radius r this is the chord height t in
// [−1, 1], and the disk area between the chords at heights a and b is G(b) − G(a) with
// G(t) = 1/2 + (asin t + t √(1 − t²)) / π. A convex record spans less than 180° from p, so its
// points' chord heights bound one interval. When the part of the disk inside that wedge lies wholly
// beyond the record (the record is "in front"), the record hides exactly that interval, and several
// such records hide exactly the union of their intervals, kept here as a cover anchored at each
// side of the disk plus up to MAX_MIDDLES floating intervals: no max, no sum.
//
// A record the pixel sees past hides only the far part of each wedge. Only a record that reaches
// into the disk can be: from a pixel outside the disk, a record apart from it hides nothing unless
// the disk lies wholly beyond it in its wedge (it is then in front), and from a pixel inside the
// disk only records reaching into it hide anything. When the records seen past are one record or
// one convex hull's fan, what they hide in the directions outside the union is a circle–polygon
// area in closed form (the chunk shadow-behind), taken over each gap between the union's intervals;
// otherwise the hidden area is an integral over those directions of the part beyond the nearest
// record (the chunk shadow-quadrature).
//
// An interval that finds MAX_MIDDLES middles taken stays out of the union (which then covers less
// than the records do) and marks it overflowed: the pixel then walks the union's intervals by a
// sweep over the bin (visibleFraction), or, with several hulls seen past, the quadrature covers the
// left-out intervals' directions too. Either way a row of posts before a wide disk is exact.
//
// Accuracy: exact (to float rounding and G's polynomial, 2.2e-4) for pixels whose records are all
// in front, however many disjoint intervals they hide, and for the closed form; the quadrature is
// exact between breaks up to its order (worst error of the random-scene test, 1,020 scenes: 0.084
// at one pixel, 0.003 at p99).
//
// A pixel inside a hull is dark for a Solid light and lit for an Illuminated one. For an Occluded
// light it takes a second pass, lit as from inside every hull that holds it (its holders): of every
// record, only its outline edges facing the pixel hide anything (see seenFromHolders).
//
// Built with LEAN_SHADOW, the lean program: for pixels whose records that hide anything are all in
// front and none of which holds the pixel for an Occluded light (the lean tiles of
// src/shadow/LightTiles.ts: no record meets the disk), it leaves out what only the others need,
// the records seen past (they hide nothing there), the closed form, the quadrature and the holder
// pass, and is as exact as the general program.
//
// Built with LEAN_SHADOW and LISTED_TILES, the listed program: the lean program for the listed
// tiles (src/shadow/TileRecordLists.ts), whose pixel reads its tile's mask of the light's listed
// records (every record whose shadow region or box touches the tile or a neighbour, nearest first)
// and walks those instead of its bin.
//
// Built with CLOSED_SHADOW, the closed program: the general program without the quadrature and the
// holder pass, for the tiles of a light that is not Occluded and whose records reaching into its
// (filed) disk are one record or one convex hull's fan (LightTiles), so that no pixel sees several
// hulls past.
//
// Built with HELD_SHADOW, the held program: for an Illuminated light's pixels that lie in one
// record's umbra unless inside a hull (its held tiles), 1 inside a hull of the bin and 0 elsewhere.
//
// Needs: v_world (the pixel's world position), u_shadow (light centre xy, disk radius, bin row),
// u_binning (how the bins were filed, below) and u_shadowType (SHADOW_SOLID, SHADOW_ILLUMINATED or
// SHADOW_OCCLUDED).
uniform highp sampler2D u_records;
uniform highp sampler2D u_recordTags;
uniform highp sampler2D u_entries;
uniform highp sampler2D u_bins;

uniform vec4 u_shadow; // position xy, disk radius, row of the light's shadow bins (and of its tile records)
uniform float u_shadowType; // how the light treats the inside of hulls: SHADOW_SOLID, … (src/shadow/shadowLayout.ts)
// A light's bins were filed for a disk of radius u_binning.z ≥ r around u_binning.xy, which holds
// the light's disk (a moving light keeps its filing while its disk stays inside, see ShadowCache): bins
// and distance buckets (u_binning.w wide) are taken from that centre, the shadows from the light's
// own disk.
uniform vec4 u_binning;
#ifdef DIRECTIONAL
// A directional light: u_shadow holds the unit direction it travels, sin α (α its angular radius)
// and its row; u_binning its strips (DirectionalStrips in src/shadow/ShadowBins.ts): the least
// coordinate across the travel, a strip's width, where the first distance bucket starts along it,
// and a bucket's width.
vec2 travel;
#endif

const float PI = 3.14159265;
// One middle: a pixel whose records in front hide more disjoint intervals (rare) sums them by the
// sweep, as exactly (or, with several hulls seen past, leaves their directions to the quadrature).
// More middles cost every pixel registers and code for the few that need them.
const int MAX_MIDDLES = 1;
// A radius of 0 (hard shadows) is taken as this, a thousandth of a world unit: chord heights stay
// finite and the visible fraction is 0 or 1 but within that distance of a hull's edge.
const float MIN_RADIUS = 1e-3;
// A directional light's sin α of 0 (hard shadows) is taken as this: a millionth of a radian.
const float MIN_SINE = 1e-6;

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

// Texel `index` (≥ 0) of a texture TEXTURE_WIDTH wide, row by row (see shadowLayout for why shifts).
ivec2 texelOf(int index) {
  return ivec2(index & (TEXTURE_WIDTH - 1), index >> TEXTURE_WIDTH_BITS);
}

vec4 texelAt(sampler2D source, int index) {
  return texelFetch(source, texelOf(index), 0);
}

// The pixel and light, set by shadowVisibility().
vec2 pixel;
vec2 centre;
float radius;
vec2 toLight;  // from the pixel to the centre, in radii
float distanceToLight; // in world units
float distanceInRadii;
bool insideDisk;

// The loaded record's four points as offsets from the pixel, x and y each in a vector, and the same
// rotated by one (each point's successor), so that per-point and per-edge work is vector work.
vec4 xs;
vec4 ys;
vec4 nextXs;
vec4 nextYs;

void loadRecordPoints(int record) {
  vec4 first = texelAt(u_records, record * 2) - vec4(pixel, pixel);
  vec4 second = texelAt(u_records, record * 2 + 1) - vec4(pixel, pixel);
  xs = vec4(first.x, first.z, second.x, second.z);
  ys = vec4(first.y, first.w, second.y, second.w);
  nextXs = xs.yzwx;
  nextYs = ys.yzwx;
}

// The record's tag (src/shadow/shadowLayout.ts, recordTag): its hull's first record and its
// outline edges.
int tagOf(int record) {
  return int(texelFetch(u_recordTags, ivec2(record & (RECORDS_PER_ROW - 1), record >> RECORDS_PER_ROW_BITS), 0).x);
}

// A box around the segment a–b (offsets from the pixel) is what the segment hides: at least 2^-10
// world units wide (as ShadowGeometry's boxes of open hulls) and 2^-19 of the coordinates'
// magnitude, so that rounding cannot close it (a record must have an inside).
void loadSegmentBox(vec2 a, vec2 b) {
  vec2 along = b - a;
  vec2 magnitude = abs(pixel) + max(abs(a), abs(b));
  float halfWidth = max(0.0009765625, max(magnitude.x, magnitude.y) * 1.9073486e-6);
  vec2 normal = vec2(-along.y, along.x) * (halfWidth * inversesqrt(max(dot(along, along), 1e-30)));
  xs = vec4(a.x - normal.x, b.x - normal.x, b.x + normal.x, a.x + normal.x);
  ys = vec4(a.y - normal.y, b.y - normal.y, b.y + normal.y, a.y + normal.y);
  nextXs = xs.yzwx;
  nextYs = ys.yzwx;
}

// For an Occluded light: whether the pixel is inside a hull, and is lit as from inside every hull
// that holds it (the second pass).
bool held = false;

// Whether the last entry recordsOfEntry read holds a whole convex hull's fan of records (set too
// before the closed form and the quadrature read the records seen past).
bool entryIsFan;

// What a loaded record hides from a pixel that hulls hold: what its outline edges facing the pixel
// hide. A segment from the pixel leaves each hull holding it once; crossing such an edge it enters
// one again, and what lies beyond is hidden. A segment from the pixel meets a hull that does not
// hold it first through such an edge too, and what the hull hides past an inner diagonal it hid at
// that edge already. So this rule holds for every closed hull and no record needs to know whether
// its hull holds the pixel: a record hides nothing (false) when it faces no outline edge; it stays
// whole when every edge it faces is on the outline, or when it is a convex hull's (a convex hull
// that faces the pixel with an outline edge does not hold it; kept whole, a fan keeps its closed
// form); a concave hull's triangle facing an outline edge and an inner diagonal (a triangle faces
// at most two) becomes a box around that outline edge. An open hull's boxes, which have no outline
// edges, stay whole: an open hull holds no pixel.
bool seenFromHolders(int record) {
  int edges = tagOf(record) & ((1 << TAG_EDGE_BITS) - 1);
  // A concave hull's triangle repeats its last point (ShadowGeometry), an open hull's box does not.
  bool triangle = xs.w == xs.z && ys.w == ys.z;
  if (edges == 0 && !triangle) return true;
  bvec4 outline = notEqual(ivec4(edges) & ivec4(1, 2, 4, 8), ivec4(0));
  bvec4 facing = lessThan(xs * nextYs - ys * nextXs, vec4(0.0));
  bvec4 hiding = bvec4(vec4(facing) * vec4(outline));
  if (!any(hiding)) return false;
  if (hiding == facing || !triangle || entryIsFan) return true;
  int k = hiding.x ? 0 : (hiding.y ? 1 : (hiding.z ? 2 : 3));
  loadSegmentBox(vec2(xs[k], ys[k]), vec2(nextXs[k], nextYs[k]));
  return true;
}

// Loads record `record` as it hides the disk from the pixel (the points as offsets from the
// pixel); false when it hides nothing (see seenFromHolders).
bool loadRecord(int record) {
  loadRecordPoints(record);
#if defined(LEAN_SHADOW) || defined(CLOSED_SHADOW)
  return true;
#else
  return !held || seenFromHolders(record);
#endif
}

// Whether the pixel lies inside the loaded record or on its outline: left of or on every edge
// (a repeated point makes an edge of no length, which every pixel is on).
bool pixelInsideRecord() {
  return all(greaterThanEqual(xs * nextYs - ys * nextXs, vec4(0.0)));
}

#ifdef LISTED_TILES
uniform highp usampler2D u_tileRecords;
uniform int u_listedRecords[LISTED_RECORDS]; // the light's listed records, nearest first
in vec2 v_tile; // the pixel in tile units of the light's grid (light.vert.glsl)
// The pixel's tile's mask of listed records, and what the current walk has left of it.
uint tileMask;
uint walkMask;
#endif

// The light's bin for this pixel: two lists, each ordered nearest first (the hulls that stood
// still, then those that moved lately; see src/shadow/shadowLayout.ts), walked as one of binCount
// entries: entry i < stillCount is the still list's i-th, from binFirst, and the others the moving
// list's, from movingFirst.
int binFirst;
int stillCount;
int movingFirst;
int binCount;
// The pixel's distance from the centre its light's bins were filed around (u_binning.xy).
float distanceToBinOrigin;

// Set once the union hides the whole disk (Illuminated lights only): then only hulls that may hold
// the pixel are left to find.
bool seekingHolders;

#ifndef DIRECTIONAL
// Whether the hull of `entry` and all after it in its list are farther from the filing's centre
// than the pixel. A segment between two points within ρ ≥ r' of that centre stays within ρ: a hull
// farther than the pixel and the filed disk (radius r') cannot reach a segment between them. The
// list is ordered by distance buckets from that centre (ShadowBins), so one bucket beyond the
// pixel, all the rest are too.
bool beyondPixel(vec4 entry) {
  float filedNearest = length(entry.yz - u_binning.xy) - entry.w, bucketWidth = u_binning.w;
  return filedNearest > u_binning.z + bucketWidth && distanceToBinOrigin < (floor(filedNearest / bucketWidth) - 1.0) * bucketWidth;
}
#endif

// Entry `i` of the pixel's bin (see above).
vec4 entryAt(int i) {
  return texelAt(u_entries, i < stillCount ? binFirst + i : movingFirst + i);
}

// Moves `i` to the last entry of its list, so that a walk's next step leaves the list.
void leaveList(inout int i) {
  i = i < stillCount ? stillCount - 1 : binCount - 1;
}

// The first and last record of `entry`; sets entryIsFan.
ivec2 recordsOf(vec4 entry) {
  int code = int(entry.x);
  entryIsFan = (code & 1) == 1;
  int records = code >> 1;
  int first = records >> ENTRY_RECORD_BITS;
  return ivec2(first, first + (records & (ENTRY_MAX_RECORDS - 1)));
}

// The records of entry `i` of the pixel's bin, first and last, or (0, -1) when this hull cannot hide
// anything from the pixel. When it and all after it in its list are farther from the centre than the
// pixel, moves `i` to the last entry of that list, so that a walk's next step leaves the list.
ivec2 recordsOfEntry(inout int i) {
#ifdef LISTED_TILES
  // The listed program: entry i is the tile's i-th listed record, its lowest bit left in a walk.
  if (i == 0) walkMask = tileMask;
  uint lowest = walkMask & (0u - walkMask);
  walkMask ^= lowest;
  return ivec2(u_listedRecords[int(round(log2(float(lowest))))]);
#else
  vec4 entry = entryAt(i);
  vec2 hull = entry.yz - pixel, toCentre = centre - pixel;
  float hullRadius = entry.w, bucketWidth = u_binning.w;
  bool farther;
#ifdef DIRECTIONAL
  // The strip's list is ordered by buckets of where each hull starts along the travel: one bucket
  // beyond the pixel, this hull and all after it lie wholly downstream of it.
  float hullStart = dot(entry.yz, travel) - hullRadius - u_binning.z, pixelAlong = dot(pixel, travel) - u_binning.z;
  farther = pixelAlong < (floor(hullStart / bucketWidth) - 1.0) * bucketWidth;
  // The hull must meet the wedge of directions within α of the light's, upstream of the pixel:
  // within its radius of the axis widened by tan α per unit upstream (ρ / cos α ≤ ρ (1 + tan α)).
  float upstream = -dot(hull, travel), tangent = radius * inversesqrt(max(1.0 - radius * radius, 1e-12));
  bool between = upstream > -hullRadius
    && abs(cross2(travel, hull)) <= hullRadius * (1.0 + tangent) + max(upstream + hullRadius, 0.0) * tangent + 1e-3;
#else
  farther = beyondPixel(entry);
  float nearest = length(entry.yz - centre) - hullRadius;
  // The hull must meet the region between the pixel and the disk, which lies within r of the
  // segment from the pixel to the centre and nearer to the pixel than the disk's far side.
  float along = clamp(dot(hull, toCentre) / max(dot(toCentre, toCentre), 1e-20), 0.0, 1.0);
  bool between = length(hull - along * toCentre) < hullRadius + radius
    && length(hull) - hullRadius < distanceToLight + radius
    && (nearest <= radius || distanceToLight >= nearest);
#endif
  if (seekingHolders) between = length(hull) <= hullRadius;
  if (farther) {
    leaveList(i);
    between = false;
  }
  ivec2 records = recordsOf(entry);
  return between ? records : ivec2(0, -1);
#endif
}

// What a record does to the pixel's view of the disk.
const int HIDES_NOTHING = 0;
const int IN_FRONT = 1;    // hides the whole chords in [low, high]
const int SEEN_PAST = 2;   // hides the far part of some wedges (all directions inside the disk)
const int HOLDS_PIXEL = 3;

// Squared distance from `point` to the segment a–b.
float segmentDistance2(vec2 point, vec2 a, vec2 b) {
  vec2 edge = b - a;
  float along = clamp(dot(point - a, edge) / max(dot(edge, edge), 1e-20), 0.0, 1.0);
  vec2 off = point - a - along * edge;
  return dot(off, off);
}

// Whether the disk misses the triangle between the pixel and the silhouette points a and b (offsets
// from the pixel): then every disk point in the wedge lies beyond the record, whose side facing the
// pixel lies inside that triangle. First the common case: the disk wholly beyond the line a–b.
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

#ifdef LEAN_SHADOW
// diskBeyond for a record apart from the disk, seen from a pixel outside it (every record of the
// lean program's tiles), along one ray: the ray at chord height t (inside the record's interval,
// so it meets the disk and the segment a–b) meets the disk no nearer than that segment. A line
// separates the record from the disk; a pixel on the record's side sees the disk wholly beyond
// the record in its wedge (beyond a–b too, as the far side of the record lies beyond a–b), one on
// the disk's side sees every ray meet the disk first (before a–b, as the near side of the
// record lies before it). Either way every ray of the wedge that meets the disk, this one too,
// tells which.
bool diskBeyondAlongRay(vec2 a, vec2 b, float t) {
  float sine = t / distanceInRadii, cosine = sqrt(max(1.0 - sine * sine, 0.0));
  vec2 axis = toLight / distanceInRadii;
  vec2 ray = cosine * axis + sine * vec2(-axis.y, axis.x);
  float diskEntry = distanceToLight * cosine - radius * sqrt(max(1.0 - t * t, 0.0));
  return diskEntry * cross2(ray, b - a) >= cross2(a, b);
}
#endif

// Whether the loaded record reaches into the disk: the centre within a radius of one of its edges,
// or inside it (left of every edge).
bool recordMeetsDisk() {
  vec2 c = centre - pixel;
  vec4 ex = nextXs - xs, ey = nextYs - ys, cx = c.x - xs, cy = c.y - ys;
  vec4 along = clamp((cx * ex + cy * ey) / max(ex * ex + ey * ey, vec4(1e-20)), 0.0, 1.0);
  vec4 offX = cx - along * ex, offY = cy - along * ey;
  return any(lessThan(offX * offX + offY * offY, vec4(radius * radius))) || all(greaterThanEqual(ex * cy - ey * cx, vec4(0.0)));
}

// The directions the records seen past cover, as angles from the direction to the centre: what
// the quadrature sweeps.
float pastFrom;
float pastTo;

void addPastSpan(vec2 lowEnd, vec2 highEnd) {
  float from = atan(cross2(toLight, lowEnd), dot(toLight, lowEnd));
  float to = atan(cross2(toLight, highEnd), dot(toLight, highEnd));
  // Turning counter-clockwise from the low end to the high end passes ±π: the whole turn.
  if (to < from) {
    from = -PI;
    to = PI;
  }
  pastFrom = min(pastFrom, from);
  pastTo = max(pastTo, to);
}

// Widens the silhouette lowEnd (clockwise-most) .. highEnd (counter-clockwise-most) to the loaded
// record's points, by cross products: everything it covers spans less than 180° from the pixel.
void widenSilhouette(inout vec2 lowEnd, inout vec2 highEnd) {
  for (int k = 0; k < 4; k++) {
    vec2 point = vec2(xs[k], ys[k]);
    if (cross2(highEnd, point) > 0.0) highEnd = point;
    if (cross2(lowEnd, point) < 0.0) lowEnd = point;
  }
}

// SEEN_PAST, adding the silhouette's directions to those seen past, when the loaded record reaches
// into the disk; else HIDES_NOTHING. The lean program leaves the test out: in its tiles no record
// reaches into the (filed) disk.
int recordSeenPast(vec2 lowEnd, vec2 highEnd) {
#ifndef LEAN_SHADOW
  if (recordMeetsDisk()) {
    addPastSpan(lowEnd, highEnd);
    return SEEN_PAST;
  }
#endif
  return HIDES_NOTHING;
}

// Classifies the loaded record; sets low and high for IN_FRONT.
int classifyRecord(out float low, out float high) {
  low = -1.0;
  high = 1.0;
  if (pixelInsideRecord()) return HOLDS_PIXEL;
  vec2 lowEnd = vec2(xs.x, ys.x), highEnd = lowEnd;
  widenSilhouette(lowEnd, highEnd);
  // From inside the disk, segments to the disk stay in it: only a record reaching into it hides
  // (none does in the lean program's tiles).
  if (insideDisk) return recordSeenPast(lowEnd, highEnd);
  // A silhouette direction 90° or more off the light was reached by turning from the other end:
  // clockwise past −90° for the low end, counter-clockwise past +90° for the high end. With both
  // ends there, the record lies behind the pixel (it spans less than 180°).
  bool lowAhead = dot(toLight, lowEnd) > 0.0, highAhead = dot(toLight, highEnd) > 0.0;
  if (!lowAhead && !highAhead) return HIDES_NOTHING;
  if (lowAhead) low = max(cross2(toLight, lowEnd) * inversesqrt(dot(lowEnd, lowEnd)), -1.0);
  if (highAhead) high = min(cross2(toLight, highEnd) * inversesqrt(dot(highEnd, highEnd)), 1.0);
  if (low >= high) return HIDES_NOTHING;
#ifdef DIRECTIONAL
  // The disk is at infinity: beyond every record.
  return IN_FRONT;
#endif
#ifdef LEAN_SHADOW
  if (diskBeyondAlongRay(lowEnd, highEnd, 0.5 * (low + high))) return IN_FRONT;
#else
  if (diskBeyond(lowEnd, highEnd)) return IN_FRONT;
#endif
  // Some of the disk lies in the wedge before the record. A record apart from the disk then hides
  // nothing: from a pixel it hides any of the disk from, the disk lies wholly beyond it in its wedge
  // (docs/shadows.md, "lean"). So only records that reach into the disk are seen past.
  return recordSeenPast(lowEnd, highEnd);
}

// The union of the front records' intervals: [-1, lowCover] ∪ [highCover, 1] ∪ middles.
float lowCover;
float highCover;
vec2 middles[MAX_MIDDLES];
int middleCount;
// Whether an interval was left out of the union, MAX_MIDDLES middles taken (see above).
bool unionOverflowed;

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
  else {
    // Left out: the quadrature, should it run, sweeps its directions (chord height t lies at
    // asin(t / distance) off the axis).
    unionOverflowed = true;
#ifndef LEAN_SHADOW
    pastFrom = min(pastFrom, asin(clamp(low / distanceInRadii, -1.0, 1.0)));
    pastTo = max(pastTo, asin(clamp(high / distanceInRadii, -1.0, 1.0)));
#endif
  }
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

// Pseudo-angle of a direction, in [0, 4), as src/shadow/shadowLayout.ts defines it for the bins (0 for
// the zero vector: a pixel at the bins' origin lies inside the filed disk, where every bin lists
// every hull that can shade it).
float pseudoAngle(vec2 d) {
  float p = d.y / max(abs(d.x) + abs(d.y), 1e-30);
  return d.x < 0.0 ? 2.0 - p : (d.y < 0.0 ? 4.0 + p : p);
}

#ifdef SHADOW_STATISTICS
// Records the main loop visited, and whether some were seen past, for the benchmark's statistics
// build (see light-common).
int visitedRecords = 0;
bool sweptPixel = false;
#endif

#include "shadow-behind"
#ifndef CLOSED_SHADOW
#include "shadow-quadrature"
#endif

// The number of records seen past, and when they are one record or one convex hull's fan (else
// pastFirst is -1), what hiddenBehind takes.
int pastCount;
int pastFirst;
int pastLast;
bool pastIsFan;

void addPastRecord(int record, ivec2 entryRecords) {
  if (pastCount == 0) {
    pastFirst = record;
    pastLast = record;
    pastIsFan = false;
  } else if (entryIsFan && pastFirst >= entryRecords.x && pastFirst <= entryRecords.y) {
    pastFirst = entryRecords.x;
    pastLast = entryRecords.y;
    pastIsFan = true;
  } else {
    pastFirst = -1;
  }
  pastCount++;
}

// Empties the union and the directions seen past.
void clearUnion() {
  lowCover = -1.0;
  highCover = 1.0;
  middleCount = 0;
  unionOverflowed = false;
  pastFrom = PI;
  pastTo = -PI;
  pastCount = 0;
}

// Sets the pixel and the light, and finds the pixel's bin.
void beginShadow() {
  pixel = v_world;
#ifdef DIRECTIONAL
  // A disk at infinity of angular radius α is, for chord heights, the disk of radius sin α at unit
  // distance towards the light: a direction θ off the light's has height sin θ / sin α either way.
  travel = u_shadow.xy;
  radius = max(u_shadow.z, MIN_SINE);
  centre = pixel - travel;
  distanceToLight = 1.0;
  toLight = -travel / radius;
  distanceInRadii = 1.0 / radius;
  insideDisk = false;
  float strip = floor((cross2(travel, pixel) - u_binning.x) / u_binning.y);
  int bin = int(clamp(strip, 0.0, float(BIN_COUNT - 1)));
#else
  centre = u_shadow.xy;
  radius = max(u_shadow.z, MIN_RADIUS);
  vec2 c = centre - pixel;
  distanceToLight = length(c);
  toLight = c / radius;
  distanceInRadii = distanceToLight / radius;
  insideDisk = distanceInRadii <= 1.0;
  vec2 fromBinOrigin = pixel - u_binning.xy;
  distanceToBinOrigin = length(fromBinOrigin);
  int bin = min(int(pseudoAngle(fromBinOrigin) * (float(BIN_COUNT) / 4.0)), BIN_COUNT - 1);
#endif
#ifdef LISTED_TILES
  // The walk's entries are the tile's listed records: as many as its mask has bits.
  ivec2 tile = clamp(ivec2(floor(v_tile)), ivec2(0), ivec2(TILE_COLUMNS - 1, TILE_ROWS - 1));
  int texel = int(u_shadow.w) * TILE_COUNT + tile.y * TILE_COLUMNS + tile.x;
  uvec2 halves = texelFetch(u_tileRecords, texelOf(texel), 0).rg;
  tileMask = halves.x | (halves.y << 16);
  binCount = 0;
  for (uint rest = tileMask; rest != 0u; rest &= rest - 1u) binCount++;
  stillCount = binCount;
#else
  vec4 binEntries = texelFetch(u_bins, ivec2(bin, int(u_shadow.w)), 0);
  binFirst = int(binEntries.x);
  stillCount = int(binEntries.y);
  movingFirst = int(binEntries.z) - stillCount;
  binCount = stillCount + int(binEntries.w);
#endif
}

// One step of a walk up the union's intervals from chord height x: the end of the interval that
// holds x (reach, x when none does) and the start of the next one above x (next, 1 when none is).
void unionStep(float x, inout float reach, inout float next) {
  if (x < lowCover) reach = lowCover;
  if (x >= highCover) reach = 1.0;
  else next = min(next, highCover);
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    if (middles[k].x <= x && x < middles[k].y) reach = middles[k].y;
    else if (middles[k].x > x) next = min(next, middles[k].x);
  }
}

// The fraction of the disk visible from the pixel, in one pass over the pixel's bin (see
// shadowVisibility); `holds` tells whether a hull was found holding the pixel (in the first pass).
//
// The first walk over the bin merges the records in front into the union and finds the records
// seen past. The hidden area is then the union's, plus, with one hull seen past, what it hides in
// the directions the union leaves open: in closed form, one window of chord heights at a time, as
// a walk up the union from −1 to 1 finds the gaps between its intervals. When the union
// overflowed, that walk is a sweep over the bin: each step walks the bin again, extending the
// covered run from x by the intervals that start at or before it, or else moving x to the start of
// the next one; x only grows, so it takes at most two steps an interval, and the area is exact
// however many disjoint intervals there are. The walks share one loop, so that the program holds
// one copy of the record code. With several hulls seen past, the quadrature takes the rest.
const int FIRST_WALK = 0;
const int UNION_STEPS = 1;
const int SWEEP_STEPS = 2;

float visibleFraction(int shadowType, out bool holds) {
  holds = false;
  clearUnion();
  seekingHolders = false;
  // Once the union is whole, a hull holding the pixel is left to find only in an Illuminated or
  // Occluded light's first pass.
  bool seeksHolder = shadowType != SHADOW_SOLID && !held;
  int walk = FIRST_WALK;
  float x = -1.0, hidden = 0.0;
  for (;;) {
    if (walk == SWEEP_STEPS) {
      // A sweep step keeps the run's reach and the next interval's start in the union's covers,
      // which the sweep no longer needs: no more values live through the walk.
      lowCover = x;
      highCover = 1.0;
    }
    for (int i = 0; i < (walk == UNION_STEPS ? 0 : binCount); i++) {
      ivec2 records = recordsOfEntry(i);
#ifdef LISTED_TILES
      // One record an entry: no loop over the entry's records.
      {
        int record = records.x;
#else
      for (int record = records.x; record <= records.y; record++) {
#endif
#ifdef SHADOW_STATISTICS
        if (walk == FIRST_WALK) visitedRecords++;
#endif
        if (!loadRecord(record)) continue;
        float low, high;
        int kind = classifyRecord(low, high);
        if (walk == SWEEP_STEPS) {
          if (kind != IN_FRONT) continue;
          if (low <= x) lowCover = max(lowCover, high);
          else highCover = min(highCover, low);
          continue;
        }
        if (kind == HOLDS_PIXEL) {
          // Lit as from inside its holders, the pixel passes through their records holding it.
          if (held) continue;
          holds = true;
          return shadowType == SHADOW_SOLID ? 0.0 : 1.0;
        }
        if (kind == IN_FRONT) insertInterval(low, high);
#ifndef LEAN_SHADOW
        if (kind == SEEN_PAST) addPastRecord(record, records);
#endif
      }
      if (walk == SWEEP_STEPS) continue;
      if (coverIsWhole() && !seeksHolder) return 0.0;
      seekingHolders = coverIsWhole();
    }
    if (walk == FIRST_WALK) {
      if (coverIsWhole()) return 0.0;
      seekingHolders = false;
      if ((pastCount > 0 && pastFirst < 0) || !(unionOverflowed || pastCount > 0)) break;
      walk = unionOverflowed ? SWEEP_STEPS : UNION_STEPS;
      continue;
    }
    // The lean program sees no record past: its only steps are the sweep's.
#ifdef LEAN_SHADOW
    float reach = lowCover, next = highCover;
#else
    float reach = x, next = 1.0;
    if (walk == UNION_STEPS) unionStep(x, reach, next);
    else {
      reach = lowCover;
      next = highCover;
    }
#endif
    if (reach > x) {
      hidden += diskAreaBelow(reach) - diskAreaBelow(x);
      x = reach;
    } else {
#ifndef LEAN_SHADOW
      entryIsFan = pastIsFan;
      if (pastCount > 0) hidden += hiddenBehind(pastFirst, pastLast, pastIsFan, !insideDisk, x, next);
      entryIsFan = false;
#endif
      x = next;
    }
    if (x >= 1.0) break;
  }
  if (walk == FIRST_WALK) {
    hidden = insideDisk ? 0.0 : coveredBetween(-1.0, 1.0);
#ifndef LEAN_SHADOW
#ifndef CLOSED_SHADOW
    for (int once = 0; once < (pastCount > 0 ? 1 : 0); once++) hidden += hiddenPast();
#endif
#ifdef SHADOW_STATISTICS
    sweptPixel = pastCount > 0;
#endif
#endif
  }
  return clamp(1.0 - hidden, 0.0, 1.0);
}

#ifdef HELD_SHADOW
// Whether a hull of the pixel's bin holds it: a walk that looks only into the hulls whose circle
// holds the pixel, and leaves each list where its hulls lie beyond the pixel.
float shadowVisibility() {
  beginShadow();
  for (int i = 0; i < binCount; i++) {
    vec4 entry = entryAt(i);
    if (beyondPixel(entry)) {
      leaveList(i);
      continue;
    }
    if (length(entry.yz - pixel) > entry.w) continue;
    ivec2 records = recordsOf(entry);
    for (int record = records.x; record <= records.y; record++) {
      loadRecordPoints(record);
      if (pixelInsideRecord()) return 1.0;
    }
  }
  return 0.0;
}
#else
// The fraction of the disk visible from the pixel. One pass over the pixel's bin merges the records
// in front into the union, leaving each list at its first hull farther from the light than the pixel; where
// records are seen past, the quadrature adds what they hide. An Occluded light's pixel found inside
// a hull takes a second pass as from inside it (one call site in a loop: the pass is inlined once).
float shadowVisibility() {
  beginShadow();
  int shadowType = int(u_shadowType + 0.5);
  held = false;
  bool holds;
#if defined(LEAN_SHADOW) || defined(CLOSED_SHADOW)
  return visibleFraction(shadowType, holds);
#else
  float visible = 1.0;
  for (int pass = 0; pass < 2; pass++) {
    visible = visibleFraction(shadowType, holds);
    if (!holds || shadowType != SHADOW_OCCLUDED) break;
    held = true;
  }
  return visible;
#endif
}
#endif
