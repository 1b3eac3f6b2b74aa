// Included by shadow-visibility: what the records seen past hide where the closed form (the chunk
// shadow-behind) does not apply — several hulls seen past, or a union with middles.
//
// In the angle φ of directions from the pixel, the area hidden along the thin wedge at φ is
// ½ (far² − max(near, nearest)²) dφ, with near and far where the direction enters and leaves the
// disk and nearest where it first meets a record seen past. The sweep takes DIRECTIONS evenly
// spaced directions (midpoints) over the span of the records seen past, leaves out those in the
// union of the records in front, and rescans the pixel's bin for each (directions outside the union
// miss every record in front, so the scan need not tell records apart). It is short on purpose: on
// SwiftShader a shader's code costs every fragment whether it runs or not (docs/performance.md).
//
// Accuracy: the midpoint rule over a kinked integrand with jumps at the union's ends: within about
// a DIRECTIONS-th of the disk per jump (the random-scene test bounds what this costs).
const int DIRECTIONS = 96;

// Whether the unit `direction` (the pixel outside the disk) lies in the union of the records in front.
bool inUnion(vec2 direction) {
  float t = cross2(toLight, direction);
  if (t <= lowCover || t >= highCover) return true;
  for (int k = 0; k < MAX_MIDDLES; k++) {
    if (k >= middleCount) break;
    if (t >= middles[k].x && t <= middles[k].y) return true;
  }
  return false;
}

// The number of records seen past.
int pastCount;

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

// ½ (far² − max(near, nearest)²) along the unit `direction`.
float hiddenAlong(vec2 direction) {
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

// The angle off the direction to the centre of a turnOf value.
float angleOfTurn(float turn) {
  float p = turn > 1.0 ? 2.0 - turn : (turn < -1.0 ? -2.0 - turn : turn);
  float angle = atan(p, abs(turn) > 1.0 ? abs(p) - 1.0 : 1.0 - abs(p));
  // atan gives π, not −π, for the turn of −2 (straight back, reached clockwise).
  return turn < 0.0 && angle > 0.0 ? angle - 2.0 * PI : angle;
}

// The disk area (fraction) the records seen past hide outside the union.
float hiddenPast() {
  float halfSpan = insideDisk ? PI : asin(1.0 / distanceInRadii);
  // Only the directions the records seen past cover can hide anything more.
  float from = max(-halfSpan, angleOfTurn(pastFrom)), to = min(halfSpan, angleOfTurn(pastTo));
  float step = max(to - from, 0.0) / float(DIRECTIONS);
  // Directions by turning the first by one step at a time: no trigonometry in the loop.
  vec2 axis = toLight / distanceInRadii;
  float first = from + 0.5 * step;
  vec2 direction = axis * cos(first) + vec2(-axis.y, axis.x) * sin(first);
  vec2 turn = vec2(cos(step), sin(step));
  float hidden = 0.0;
  for (int k = 0; k < DIRECTIONS; k++) {
    if (insideDisk || !inUnion(direction)) hidden += step * hiddenAlong(direction);
    direction = vec2(direction.x * turn.x - direction.y * turn.y, direction.x * turn.y + direction.y * turn.x);
  }
  return hidden / (PI * radius * radius);
}
