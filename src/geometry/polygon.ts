/**
 * Pure polygon helpers on flat coordinate arrays `[x0, y0, x1, y1, …]`.
 * Positive signed area means counter-clockwise in a y-up frame; the library stores every
 * hull with positive area so that each edge's outward normal is `(dy, -dx)`.
 */

/** Twice the signed area (shoelace formula). */
export function signedArea2(coords: ArrayLike<number>, count = coords.length >> 1): number {
  let sum = 0;
  for (let i = 0, j = count - 1; i < count; j = i++) {
    sum += coords[2 * j] * coords[2 * i + 1] - coords[2 * i] * coords[2 * j + 1];
  }
  return sum;
}

/**
 * Removes consecutive duplicate points and points collinear with their neighbours (neither
 * changes the shape), returning a new flat array.
 */
export function simplifyPolygon(coords: ArrayLike<number>): number[] {
  const out: number[] = [];
  for (let i = 0; i < coords.length; i += 2) out.push(coords[i], coords[i + 1]);
  let changed = true;
  while (changed && out.length >= 6) {
    changed = false;
    const n = out.length >> 1;
    for (let i = 0; i < n; i++) {
      const p = (i + n - 1) % n;
      const q = (i + 1) % n;
      const cross = (out[2 * i] - out[2 * p]) * (out[2 * q + 1] - out[2 * p + 1])
        - (out[2 * i + 1] - out[2 * p + 1]) * (out[2 * q] - out[2 * p]);
      const duplicate = out[2 * i] === out[2 * p] && out[2 * i + 1] === out[2 * p + 1];
      if (duplicate || (cross === 0 && isBetween(out, p, i, q))) {
        out.splice(2 * i, 2);
        changed = true;
        break;
      }
    }
  }
  return out;
}

/** True when point `i` lies on the segment p–q (so removing it keeps the outline). */
function isBetween(c: number[], p: number, i: number, q: number): boolean {
  const dot = (c[2 * i] - c[2 * p]) * (c[2 * q] - c[2 * p]) + (c[2 * i + 1] - c[2 * p + 1]) * (c[2 * q + 1] - c[2 * p + 1]);
  const len2 = (c[2 * q] - c[2 * p]) ** 2 + (c[2 * q + 1] - c[2 * p + 1]) ** 2;
  return dot >= 0 && dot <= len2;
}

function orientation(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  const v = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  return v > 0 ? 1 : v < 0 ? -1 : 0;
}

function onSegment(ax: number, ay: number, bx: number, by: number, px: number, py: number): boolean {
  return Math.min(ax, bx) <= px && px <= Math.max(ax, bx) && Math.min(ay, by) <= py && py <= Math.max(ay, by);
}

/** True when the closed segments a–b and c–d share at least one point. */
export function segmentsIntersect(
  ax: number, ay: number, bx: number, by: number,
  cx: number, cy: number, dx: number, dy: number,
): boolean {
  const o1 = orientation(ax, ay, bx, by, cx, cy);
  const o2 = orientation(ax, ay, bx, by, dx, dy);
  const o3 = orientation(cx, cy, dx, dy, ax, ay);
  const o4 = orientation(cx, cy, dx, dy, bx, by);
  if (o1 !== o2 && o3 !== o4) return true;
  return (o1 === 0 && onSegment(ax, ay, bx, by, cx, cy))
    || (o2 === 0 && onSegment(ax, ay, bx, by, dx, dy))
    || (o3 === 0 && onSegment(cx, cy, dx, dy, ax, ay))
    || (o4 === 0 && onSegment(cx, cy, dx, dy, bx, by));
}

/**
 * True for a simple polygon: at least 3 points, non-zero area, and no two edges meeting
 * anywhere but at their shared end point.
 */
export function isSimplePolygon(coords: ArrayLike<number>): boolean {
  const n = coords.length >> 1;
  if (n < 3 || signedArea2(coords, n) === 0) return false;
  for (let i = 0; i < n; i++) {
    const i2 = (i + 1) % n;
    for (let j = i + 1; j < n; j++) {
      const j2 = (j + 1) % n;
      if (j === i2 || j2 === i) continue;
      if (segmentsIntersect(
        coords[2 * i], coords[2 * i + 1], coords[2 * i2], coords[2 * i2 + 1],
        coords[2 * j], coords[2 * j + 1], coords[2 * j2], coords[2 * j2 + 1],
      )) return false;
    }
  }
  return true;
}

/** Whether a simple counter-clockwise polygon is convex: it never turns clockwise. */
export function isConvexPolygon(coords: ArrayLike<number>): boolean {
  const count = coords.length >> 1;
  for (let i = 0; i < count; i++) {
    const a = (i + count - 1) % count, b = (i + 1) % count;
    const ax = coords[2 * i] - coords[2 * a], ay = coords[2 * i + 1] - coords[2 * a + 1];
    const bx = coords[2 * b] - coords[2 * i], by = coords[2 * b + 1] - coords[2 * i + 1];
    if (ax * by - ay * bx < 0) return false;
  }
  return true;
}

/**
 * Even-odd test of `point` (`[x, y]`) against the polygon of `count` points starting at point
 * `first`. The point comes as an array: two doubles passed to a call that is not inlined are boxed.
 */
export function isInsidePolygon(coords: ArrayLike<number>, point: ArrayLike<number>, first = 0, count = (coords.length >> 1) - first): boolean {
  const x = point[0], y = point[1];
  let inside = false;
  for (let i = 0, j = count - 1; i < count; j = i++) {
    const xi = coords[2 * (first + i)], yi = coords[2 * (first + i) + 1];
    const xj = coords[2 * (first + j)], yj = coords[2 * (first + j) + 1];
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/**
 * Ear-clipping triangulation of a simple counter-clockwise polygon. Returns point indices,
 * three per triangle; the triangulation survives any affine transform of the points.
 */
export function triangulate(coords: ArrayLike<number>): number[] {
  const remaining: number[] = [];
  for (let i = 0; i < coords.length >> 1; i++) remaining.push(i);
  const triangles: number[] = [];
  let guard = remaining.length * remaining.length;
  while (remaining.length > 3 && guard-- > 0) {
    for (let k = 0; k < remaining.length; k++) {
      const a = remaining[(k + remaining.length - 1) % remaining.length];
      const b = remaining[k];
      const c = remaining[(k + 1) % remaining.length];
      if (isEar(coords, remaining, a, b, c)) {
        triangles.push(a, b, c);
        remaining.splice(k, 1);
        break;
      }
    }
  }
  if (remaining.length === 3) triangles.push(remaining[0], remaining[1], remaining[2]);
  return triangles;
}

function isEar(c: ArrayLike<number>, remaining: number[], a: number, b: number, d: number): boolean {
  const ax = c[2 * a], ay = c[2 * a + 1], bx = c[2 * b], by = c[2 * b + 1], dx = c[2 * d], dy = c[2 * d + 1];
  if ((bx - ax) * (dy - ay) - (by - ay) * (dx - ax) <= 0) return false;
  for (const p of remaining) {
    if (p === a || p === b || p === d) continue;
    const px = c[2 * p], py = c[2 * p + 1];
    if (orientation(ax, ay, bx, by, px, py) >= 0 && orientation(bx, by, dx, dy, px, py) >= 0
      && orientation(dx, dy, ax, ay, px, py) >= 0) return false;
  }
  return true;
}
