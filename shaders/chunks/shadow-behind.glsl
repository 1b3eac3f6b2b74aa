// Included by shadow-visibility: the disk area hidden by one convex polygon the pixel sees past, in
// closed form, for pixels where nothing else hides any of the disk (no record in front).
//
// The points q whose segment to the pixel p meets a convex polygon P (p outside it) form a convex
// region S: P's edges facing p (its near chain, from the counter-clockwise-most silhouette point
// to the clockwise-most), the rays from p through those two points beyond them, closed far
// beyond the disk. The part of the disk in S is what P hides: the disk's own points inside P
// included (SPEC §6). Its area is the sum, over S's edges a → b, of the signed area of the disk
// within the triangle (centre, a, b) — a triangle where the edge is inside the disk, a sector
// where it is outside — with no quadrature and no arrays.
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

// The disk area (fraction) hidden behind the records first..last: one record, or (fan) all the
// records of one convex hull's fan, whose first and last edges (to the fan's apex) are diagonals
// except at the fan's ends.
float hiddenBehind(int first, int last, bool fan) {
  vec2 c = centre - pixel;
  float area = 0.0;
  vec2 lowEnd = vec2(0.0), highEnd = vec2(0.0);
  float farthest2 = 0.0;
  for (int record = first; record <= last; record++) {
    loadRecord(record);
    if (record == first) {
      lowEnd = vec2(xs.x, ys.x);
      highEnd = lowEnd;
    }
    // The near chain: outline edges with the pixel on their outer side (the records are
    // counter-clockwise with the pixel at the origin). Selects, not products: an area may be huge.
    bvec4 facing = lessThan(xs * nextYs - ys * nextXs, vec4(0.0));
    bvec4 outline = bvec4(!fan || record == first, true, true, !fan || record == last);
    vec4 areas = diskTriangleAreas(xs - c.x, ys - c.y, nextXs - c.x, nextYs - c.y);
    vec4 chain = mix(vec4(0.0), areas, bvec4(vec4(facing) * vec4(outline)));
    area += chain.x + chain.y + chain.z + chain.w;
    for (int k = 0; k < 4; k++) {
      vec2 point = vec2(xs[k], ys[k]);
      if (cross2(highEnd, point) > 0.0) highEnd = point;
      if (cross2(lowEnd, point) < 0.0) lowEnd = point;
    }
    farthest2 = max(farthest2, max(max(dot(vec2(xs.x, ys.x), vec2(xs.x, ys.x)), dot(vec2(xs.y, ys.y), vec2(xs.y, ys.y))),
                                   max(dot(vec2(xs.z, ys.z), vec2(xs.z, ys.z)), dot(vec2(xs.w, ys.w), vec2(xs.w, ys.w)))));
  }
  // The rays out from the clockwise-most point, the far closure, and back in to the other.
  float reach = max(CLOSURE_REACH * (distanceToLight + radius), sqrt(farthest2));
  vec2 lowDirection = normalize(lowEnd), highDirection = normalize(highEnd);
  vec2 bisector = lowDirection + highDirection;
  // Nearly opposite ends (the pixel on the polygon's outline): a quarter turn from the low end.
  vec2 middleDirection = dot(bisector, bisector) > 0.01 ? normalize(bisector) : vec2(-lowDirection.y, lowDirection.x);
  vec2 lowFar = reach * lowDirection, middleFar = reach * middleDirection, highFar = reach * highDirection;
  vec4 closure = diskTriangleAreas(vec4(lowEnd.x, lowFar.x, middleFar.x, highFar.x) - c.x, vec4(lowEnd.y, lowFar.y, middleFar.y, highFar.y) - c.y,
                                   vec4(lowFar.x, middleFar.x, highFar.x, highEnd.x) - c.x, vec4(lowFar.y, middleFar.y, highFar.y, highEnd.y) - c.y);
  area += closure.x + closure.y + closure.z + closure.w;
  return area / (PI * radius * radius);
}
