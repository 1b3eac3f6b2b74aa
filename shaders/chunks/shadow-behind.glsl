// Included by shadow-visibility: the disk area hidden by one convex polygon the pixel sees past, in
// closed form, within the directions the records in front leave open (one window of chord heights).
//
// The points q whose segment to the pixel p meets a convex polygon P (p outside it) form a convex
// region S: P's edges facing p (its near chain, from the counter-clockwise-most silhouette point
// to the clockwise-most), the rays from p through those two points beyond them, closed far
// beyond the disk. Within a window of directions from p, S is cut by the window's two rays: the
// chain cut to the window, rays out from its two ends, the same closure. The part of the disk in S
// is what P hides, the disk's own points inside P included (their segments to p meet P). Its area
// is the sum, over S's edges a → b, of the signed area of the disk within the triangle (centre, a,
// b) — a triangle where the edge is inside the disk, a sector where it is outside — with no
// quadrature and no arrays.
//
// P is one record, or every record of a convex hull's fan (their shared diagonals lie inside the
// hull and are left out of the outline: S of the hull is the union of S of its records).
//
// Accuracy: exact to float rounding. Coordinates are relative to the disk's centre, so rounding is
// about 1e-7 of the pixel's distance: it only shows in the area for a pixel far from a disk of a
// thousandth of a unit (radius 0), and there only within that distance of a shadow's edge.

// The far closure lies this many times the farthest disk point from the pixel away: each of its two
// edges spans at most 90° from the pixel, so it stays beyond cos 45° of that, beyond the disk.
const float CLOSURE_REACH = 1.5;

// Signed area of the disk within the triangle (centre, a, b), per lane; a and b relative to the centre.
vec4 diskTriangleAreas(vec4 ax, vec4 ay, vec4 bx, vec4 by) {
  vec4 dx = bx - ax, dy = by - ay;
  vec4 length2 = max(dx * dx + dy * dy, vec4(1e-30));
  // Where the edge's line crosses the rim, as fractions along the edge: the nearest point to the
  // centre ± the half chord. The discriminant as r²|d|² − (a × d)²: no cancellation far away.
  vec4 offset = ax * dy - ay * dx;
  vec4 halfChord = sqrt(max(radius * radius * length2 - offset * offset, vec4(0.0))) / length2;
  vec4 nearest = -(ax * dx + ay * dy) / length2;
  vec4 enter = clamp(nearest - halfChord, 0.0, 1.0), leave = clamp(nearest + halfChord, 0.0, 1.0);
  vec4 px = ax + enter * dx, py = ay + enter * dy, qx = ax + leave * dx, qy = ay + leave * dy;
  // Outside the rim: sectors from a to where the edge enters and from where it leaves to b (zero
  // where those coincide; the tiny term keeps atan(0, 0) away from a point at the centre).
  vec4 sectors = atan(ax * py - ay * px, ax * px + ay * py + 1e-30) + atan(qx * by - qy * bx, qx * bx + qy * by + 1e-30);
  return 0.5 * (radius * radius * sectors + (px * qy - py * qx));
}

// A number that grows with the angle of `v` (not zero) off the unit `axis`, over (−2, 2] for
// (−π, π]: the pseudo-angle of `v` in the axis' frame, turned to start behind.
float angleOff(vec2 axis, vec2 v) {
  float turn = pseudoAngle(vec2(dot(axis, v), cross2(axis, v)));
  return turn > 2.0 ? turn - 4.0 : turn;
}

// The direction off the unit `axis` (towards the disk's centre) whose line has chord height t.
vec2 directionAtHeight(vec2 axis, float t) {
  float sine = clamp(t / distanceInRadii, -1.0, 1.0);
  return axis * sqrt(1.0 - sine * sine) + vec2(-axis.y, axis.x) * sine;
}

// For each lane's edge a + u (b − a), u in [0, 1], the part whose direction from the pixel lies
// counter-clockwise of `low` and clockwise of `high` (less than π apart): (from, to) per lane, as
// two vectors; empty where from ≥ to.
void clipToWindow(vec4 ax, vec4 ay, vec4 ex, vec4 ey, vec2 low, vec2 high, out vec4 from, out vec4 to) {
  from = vec4(0.0);
  to = vec4(1.0);
  // cross(low, a + u e) ≥ 0 and cross(a + u e, high) ≥ 0, each linear in u.
  vec4 lowAt0 = low.x * ay - low.y * ax, lowSlope = low.x * ey - low.y * ex;
  vec4 highAt0 = ax * high.y - ay * high.x, highSlope = ex * high.y - ey * high.x;
  vec4 lowRoot = -lowAt0 / mix(lowSlope, vec4(1.0), equal(lowSlope, vec4(0.0)));
  vec4 highRoot = -highAt0 / mix(highSlope, vec4(1.0), equal(highSlope, vec4(0.0)));
  // A side the edge approaches bounds it from below, one it leaves from above.
  from = max(from, mix(vec4(0.0), lowRoot, greaterThan(lowSlope, vec4(0.0))));
  to = min(to, mix(vec4(1.0), lowRoot, lessThan(lowSlope, vec4(0.0))));
  from = max(from, mix(vec4(0.0), highRoot, greaterThan(highSlope, vec4(0.0))));
  to = min(to, mix(vec4(1.0), highRoot, lessThan(highSlope, vec4(0.0))));
  // Parallel to a side and outside it: nothing.
  bvec4 outside = bvec4(vec4(equal(lowSlope, vec4(0.0))) * vec4(lessThan(lowAt0, vec4(0.0)))
                      + vec4(equal(highSlope, vec4(0.0))) * vec4(lessThan(highAt0, vec4(0.0))));
  to = mix(to, vec4(-1.0), outside);
}

// The disk area (fraction) hidden behind the records first..last — one record, or (fan) all the
// records of one convex hull's fan, whose first and last edges (to the fan's apex) are diagonals
// except at the fan's ends — within the directions of chord heights [low, high] (`windowed`; the
// pixel outside the disk) or in all directions.
float hiddenBehind(int first, int last, bool fan, bool windowed, float low, float high) {
  vec2 c = centre - pixel;
  // The silhouette: the clockwise-most and counter-clockwise-most points, and the farthest.
  vec2 lowEnd = vec2(0.0), highEnd = vec2(0.0);
  float farthest2 = 0.0;
  for (int record = first; record <= last; record++) {
    loadRecord(record);
    if (record == first) {
      lowEnd = vec2(xs.x, ys.x);
      highEnd = lowEnd;
    }
    widenSilhouette(lowEnd, highEnd);
    vec4 distances2 = xs * xs + ys * ys;
    farthest2 = max(farthest2, max(max(distances2.x, distances2.y), max(distances2.z, distances2.w)));
  }
  // The directions taken: the silhouette's, narrowed to the window's. Both window sides lie within
  // 90° of the axis; a silhouette turning through the back direction wraps, and then only one of
  // its ends can meet the window.
  vec2 lowDirection = normalize(lowEnd), highDirection = normalize(highEnd);
  if (windowed) {
    vec2 axis = toLight / distanceInRadii;
    vec2 windowLow = directionAtHeight(axis, low), windowHigh = directionAtHeight(axis, high);
    float lowAngle = angleOff(axis, lowEnd), highAngle = angleOff(axis, highEnd);
    float windowLowAngle = angleOff(axis, windowLow), windowHighAngle = angleOff(axis, windowHigh);
    if (highAngle < lowAngle) {
      if (lowAngle < windowHighAngle) highAngle = 3.0;
      else lowAngle = -3.0;
    }
    if (max(lowAngle, windowLowAngle) >= min(highAngle, windowHighAngle)) return 0.0;
    if (windowLowAngle > lowAngle) lowDirection = windowLow;
    if (windowHighAngle < highAngle) highDirection = windowHigh;
  }
  // The near chain within those directions: outline edges with the pixel on their outer side (the
  // records are counter-clockwise with the pixel at the origin), each cut to the window. Its ends
  // are the counter-clockwise-most start and the clockwise-most end of the pieces taken.
  float area = 0.0;
  bool anyTaken = false;
  vec2 lowPoint = vec2(0.0), highPoint = vec2(0.0);
  for (int record = first; record <= last; record++) {
    loadRecord(record);
    vec4 ex = nextXs - xs, ey = nextYs - ys, from, to;
    clipToWindow(xs, ys, ex, ey, lowDirection, highDirection, from, to);
    bvec4 facing = lessThan(xs * nextYs - ys * nextXs, vec4(0.0));
    bvec4 outline = bvec4(!fan || record == first, true, true, !fan || record == last);
    bvec4 taken = bvec4(vec4(facing) * vec4(outline) * vec4(lessThan(from, to)));
    vec4 startX = xs + from * ex, startY = ys + from * ey, endX = xs + to * ex, endY = ys + to * ey;
    vec4 areas = diskTriangleAreas(startX - c.x, startY - c.y, endX - c.x, endY - c.y);
    // Selects, not products: an area may be huge where an edge is not taken.
    vec4 chain = mix(vec4(0.0), areas, taken);
    area += chain.x + chain.y + chain.z + chain.w;
    for (int k = 0; k < 4; k++) {
      if (!taken[k]) continue;
      vec2 start = vec2(startX[k], startY[k]), end = vec2(endX[k], endY[k]);
      if (!anyTaken || cross2(highPoint, start) > 0.0) highPoint = start;
      if (!anyTaken || cross2(lowPoint, end) < 0.0) lowPoint = end;
      anyTaken = true;
    }
  }
  if (!anyTaken) return 0.0;
  // The ray out from the chain's clockwise end, the far closure, and back in to its other end.
  lowDirection = normalize(lowPoint);
  highDirection = normalize(highPoint);
  float reach = max(CLOSURE_REACH * (distanceToLight + radius), sqrt(farthest2));
  vec2 bisector = lowDirection + highDirection;
  // Nearly opposite sides (the pixel on the polygon's outline): a quarter turn from the low side.
  vec2 middleDirection = dot(bisector, bisector) > 0.01 ? normalize(bisector) : vec2(-lowDirection.y, lowDirection.x);
  vec2 lowFar = reach * lowDirection, middleFar = reach * middleDirection, highFar = reach * highDirection;
  vec4 closure = diskTriangleAreas(vec4(lowPoint.x, lowFar.x, middleFar.x, highFar.x) - c.x, vec4(lowPoint.y, lowFar.y, middleFar.y, highFar.y) - c.y,
                                   vec4(lowFar.x, middleFar.x, highFar.x, highPoint.x) - c.x, vec4(lowFar.y, middleFar.y, highFar.y, highPoint.y) - c.y);
  area += closure.x + closure.y + closure.z + closure.w;
  return area / (PI * radius * radius);
}
