// Included by shadow-visibility: what the records seen past hide.
//
// In the angle φ of directions from the pixel, the area hidden along the thin wedge at φ is
// ½ (far² − max(near, nearest)²) dφ, with near and far where the direction enters and leaves the
// disk and nearest where it first meets a record. The integrand is smooth between "breaks": the
// directions of the records' points (where the nearest edge changes), of their edges' crossings
// with the disk's rim, and of the union's ends (where the records in front take over). The sweep
// goes from break to break (pieces wider than MAX_STEP are cut, and breaks less than MIN_STEP after
// the last one are passed over), skips the pieces the union covers, and gives each piece two
// Gauss–Legendre nodes. It keeps no arrays (ANGLE zeroes them in every
// fragment, used or not; see docs/performance.md): it scans the pixel's bin again for each next break and each node.
// Directions in a piece outside the union miss every record in front, so the scans need not tell
// records apart.
const int MAX_PIECES = 64;
const float MAX_STEP = PI / 16.0;
// Breaks this close share a piece: the corners at each end of an open hull's thin segment box
// (see ShadowGeometry) would otherwise take pieces of their own and use up MAX_PIECES. A break
// passed over spoils the integrand over at most MIN_STEP of angle, which holds less than
// ½ (2r)² MIN_STEP of the disk's area: under 2e-4 of it.
const float MIN_STEP = 3e-4;

// The angle of the direction to the disk's centre, and half the disk's angular width (π inside it).
float axisAngle;
float halfSpan;

// Angles from the axis of the directions (xs, ys), in (−π, π].
vec4 anglesOf(vec4 x, vec4 y) {
  vec4 angle = atan(y, x) - axisAngle;
  return angle + 2.0 * PI * (vec4(lessThanEqual(angle, vec4(-PI))) - vec4(greaterThan(angle, vec4(PI))));
}

// The smallest of `next` and the angles in `candidates` (where `valid`) after `after`.
float nextAfter(float after, float next, vec4 candidates, bvec4 valid) {
  // Selects, not products: a candidate may be infinite or NaN where it is not valid.
  bvec4 take = bvec4(vec4(valid) * vec4(greaterThan(candidates, vec4(after))));
  vec4 later = mix(vec4(next), candidates, take);
  return min(next, min(min(later.x, later.y), min(later.z, later.w)));
}

// The smallest of `next` and the loaded record's breaks after `after`.
float nextRecordBreak(float after, float next) {
  next = nextAfter(after, next, anglesOf(xs, ys), bvec4(true));
  // Where edge a + u·(b − a) crosses the rim: u² |e|² + 2u e·(a − c) + |a − c|² − r² = 0.
  vec2 c = centre - pixel;
  vec4 ex = nextXs - xs, ey = nextYs - ys, ax = xs - c.x, ay = ys - c.y;
  vec4 length2 = ex * ex + ey * ey, halfB = ex * ax + ey * ay;
  vec4 discriminant = halfB * halfB - length2 * (ax * ax + ay * ay - radius * radius);
  vec4 root = sqrt(max(discriminant, 0.0)), divisor = max(length2, 1e-20);
  bvec4 crosses = greaterThan(discriminant, vec4(0.0));
  for (int end = 0; end < 2; end++) {
    vec4 u = (-halfB + (end == 0 ? -root : root)) / divisor;
    bvec4 onEdge = bvec4(vec4(crosses) * vec4(greaterThan(u, vec4(0.0))) * vec4(lessThan(u, vec4(1.0))));
    next = nextAfter(after, next, anglesOf(xs + u * ex, ys + u * ey), onEdge);
  }
  return next;
}

// The smallest of `next` and the union's ends after `after` (chord height t is at asin(t / distance)).
float nextUnionBreak(float after, float next) {
  float scale = 1.0 / distanceInRadii;
  vec4 ends = asin(clamp(vec4(lowCover, highCover, lowCover, highCover) * scale, -1.0, 1.0));
  next = nextAfter(after, next, ends, bvec4(true));
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    next = nextAfter(after, next, asin(vec4(middles[k], middles[k]) * scale), bvec4(true));
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

// The next break after `after`, at most `limit`.
float nextBreak(float after, float limit) {
  float next = insideDisk ? limit : nextUnionBreak(after, limit);
  for (int i = 0; i < binCount; i++) {
    ivec2 records = recordsOfEntry(i);
    for (int record = records.x; record <= records.y; record++) {
      if (!loadRecord(record)) continue;
      next = nextRecordBreak(after, next);
    }
  }
  return min(next, limit);
}

// Distance along the unit `direction` from the pixel to where it enters the loaded record (positive
// area, not holding the pixel), or a huge value when it misses.
float entryDistance(vec2 direction) {
  vec4 normalX = nextYs - ys, normalY = xs - nextXs; // outward; zero for a repeated point
  vec4 toward = normalX * direction.x + normalY * direction.y, room = normalX * xs + normalY * ys;
  // Selects, not products: a ratio may be infinite.
  vec4 ratio = room / mix(toward, vec4(1.0), equal(toward, vec4(0.0)));
  vec4 enters = mix(vec4(0.0), ratio, lessThan(toward, vec4(0.0)));
  vec4 leaves = mix(vec4(1e30), ratio, greaterThan(toward, vec4(0.0)));
  float enter = max(max(enters.x, enters.y), max(enters.z, enters.w));
  float leave = min(min(leaves.x, leaves.y), min(leaves.z, leaves.w));
  bool parallelOutside = any(lessThan(room * vec4(equal(toward, vec4(0.0))), vec4(0.0)));
  return enter <= leave && !parallelOutside ? enter : 1e30;
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
    for (int record = records.x; record <= records.y; record++) {
      if (!loadRecord(record)) continue;
      nearest = min(nearest, entryDistance(direction));
    }
  }
  nearest = max(nearest, max(0.0, along - halfChord));
  return 0.5 * max(0.0, far * far - nearest * nearest);
}

// The disk area (fraction) the records seen past hide outside the union.
float hiddenPast() {
  vec2 c = centre - pixel;
  axisAngle = atan(c.y, c.x);
  halfSpan = insideDisk ? PI : asin(1.0 / distanceInRadii);
  const float offset = 0.28867513; // 1 / (2√3): Gauss–Legendre's two nodes on a unit piece
  // Only the directions the records seen past cover can hide anything more.
  float end = min(halfSpan, pastTo);
  float hidden = 0.0, from = max(-halfSpan, pastFrom);
  for (int piece = 0; piece < MAX_PIECES; piece++) {
    if (from >= end) break;
    // The last piece allowed takes the rest of the domain.
    float to = piece == MAX_PIECES - 1 ? end : nextBreak(from + MIN_STEP, min(end, from + MAX_STEP));
    float middle = 0.5 * (from + to), step = to - from;
    if (insideDisk || !inUnion(middle)) {
      hidden += 0.5 * step * (hiddenAlong(middle - offset * step) + hiddenAlong(middle + offset * step));
    }
    from = to;
  }
  return hidden / (PI * radius * radius);
}
