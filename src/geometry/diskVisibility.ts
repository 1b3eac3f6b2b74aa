/**
 * The exact fraction of a light's disk visible from a point past a set of edges (SPEC §6), on the
 * CPU in double precision: what `PenumbraRenderer.illuminationAt` reports per light.
 *
 * From the point p, every point of the disk lies on one ray from p. In polar coordinates around p
 * (direction δ measured from the direction of the centre c, distance s along the ray) the disk's
 * area is ∫∫ s ds dδ, and a disk point at distance s is visible when the first edge the ray meets
 * lies farther than s. So
 *
 *   visible area = ∫ ½ (clamp(s_hit(δ), s_near(δ), s_far(δ))² − s_near(δ)²) dδ
 *
 * over the directions that meet the disk (|δ| ≤ asin(r / d), d = |c − p|), where the ray enters
 * the disk at s_near and leaves it at s_far; from inside the disk s_near = 0 and δ goes all the way
 * round. The fraction is that area over πr².
 *
 * The directions are cut at every edge end, every crossing of two edges and every crossing of an
 * edge with the disk's rim. Between two cuts the same edge (or none) is met first and it stays in
 * front of the disk, inside it or beyond it, so each piece is one closed form, chosen at its middle
 * direction. With w = d sin δ:
 *   - nothing met before the disk's far side: ½ (s_far² − s_near²) = 2 d cos δ √(r² − w²), whose
 *     antiderivative is F(δ) = w √(r² − w²) + r² asin(w / r) (from inside the disk, ½ s_far² has
 *     ½ r² δ + ¼ d² sin 2δ + ½ F(δ));
 *   - an edge met inside the disk: ½ (s_line² − s_near²), where s_line = h / cos(δ + θ − ψ) is the
 *     distance to the edge's line (h its distance from p, ψ its normal's direction, θ the centre's):
 *     ½ s_line² has ½ h² tan(δ + θ − ψ), and ½ s_near² has ½ r² δ + ¼ d² sin 2δ − ½ F(δ);
 *   - an edge met before the disk: nothing.
 * So each piece is exact to rounding, with no quadrature. Only edges that come within r of the
 * segment p → c can hide any of the disk (the disk and p lie in that capsule): the others are left
 * out as they are added. Radius 0 is a single segment test p → c (hard shadows).
 *
 * Cost: O(B · E) per point for E edges kept and B cuts (2E plus the edge crossings and rim
 * crossings), with the pairs of edges tested for crossings in O(E²). Nothing is allocated once the
 * buffers have grown to the largest edge count seen.
 */
export class DiskVisibility {
  /** The kept edges, `[ax, ay, bx, by, …]` (the first `4 × edgeCount`). */
  private edges = new Float64Array(64);
  private edgeCount = 0;
  /** The cut directions of the current point, as δ; the first `breakCount`. */
  private breaks = new Float64Array(64);
  private breakCount = 0;
  // The current point, disk and derived values (see begin).
  private px = 0;
  private py = 0;
  private cx = 0;
  private cy = 0;
  private r = 0;
  private d = 0;
  private theta = 0;
  private span = 0;
  private inside = false;
  /** Bounds of the capsule within r of p → c: `[minX, minY, maxX, maxY]`. */
  private readonly box = new Float64Array(4);
  /** Offset in `edges` of the edge the last {@link DiskVisibility.firstHit} met. */
  private hitEdge = -1;

  /** Starts a point p = (px, py) and a disk of centre (cx, cy) and radius r ≥ 0; forgets the edges. */
  begin(px: number, py: number, cx: number, cy: number, r: number): void {
    this.px = px;
    this.py = py;
    this.cx = cx;
    this.cy = cy;
    this.r = r;
    this.edgeCount = 0;
    const dx = cx - px, dy = cy - py;
    this.d = Math.sqrt(dx * dx + dy * dy);
    this.inside = this.d < r;
    this.theta = this.d > 0 ? Math.atan2(dy, dx) : 0;
    this.span = this.inside ? Math.PI : Math.asin(Math.min(1, r / this.d));
    const box = this.box;
    box[0] = Math.min(px, cx - r);
    box[1] = Math.min(py, cy - r);
    box[2] = Math.max(px, cx + r);
    box[3] = Math.max(py, cy + r);
  }

  /** Bounds `[minX, minY, maxX, maxY]` of the region an edge must reach to hide any of the disk from the point. */
  get bounds(): Readonly<Float64Array> {
    return this.box;
  }

  /** Number of edges kept since {@link DiskVisibility.begin}. */
  get keptEdges(): number {
    return this.edgeCount;
  }

  /** Adds the edge a → b, kept only when it comes within r of the segment from the point to the centre. */
  addEdge(ax: number, ay: number, bx: number, by: number): void {
    const box = this.box;
    if (Math.max(ax, bx) < box[0] || Math.min(ax, bx) > box[2] || Math.max(ay, by) < box[1] || Math.min(ay, by) > box[3]) return;
    if (!segmentsWithin(this.r, this.px, this.py, this.cx, this.cy, ax, ay, bx, by)) return;
    const k = 4 * this.edgeCount++;
    if (k + 4 > this.edges.length) this.edges = grown(this.edges, k + 4);
    const edges = this.edges;
    edges[k] = ax;
    edges[k + 1] = ay;
    edges[k + 2] = bx;
    edges[k + 3] = by;
  }

  /**
   * Adds the edges of a polygon (`closed`, last point back to the first) or a polyline, from
   * `coords` = `[x0, y0, x1, y1, …]`: the first `count` points.
   */
  addOutline(coords: ArrayLike<number>, count: number, closed: boolean): void {
    for (let i = 0; i + 1 < count; i++) this.addEdge(coords[2 * i], coords[2 * i + 1], coords[2 * i + 2], coords[2 * i + 3]);
    if (closed && count > 2) this.addEdge(coords[2 * count - 2], coords[2 * count - 1], coords[0], coords[1]);
  }

  /** The fraction of the disk, 0..1, whose segment to the point crosses none of the edges added. */
  fraction(): number {
    const count = this.edgeCount;
    if (count === 0) return 1;
    const edges = this.edges, r = this.r;
    // Every kept edge crosses the segment p → c when r is 0: the capsule is that segment.
    if (r === 0) return 0;
    const cx = this.cx, cy = this.cy, d = this.d, inside = this.inside;
    const span = this.span;
    this.breakCount = 0;
    this.breaks[this.breakCount++] = -span;
    this.breaks[this.breakCount++] = span;
    const r2 = r * r;
    for (let e = 0; e < 4 * count; e += 4) {
      const ax = edges[e], ay = edges[e + 1], bx = edges[e + 2], by = edges[e + 3];
      this.addDirection(ax, ay);
      this.addDirection(bx, by);
      // Where the edge crosses the rim: |a − c + t (b − a)|² = r², 0 ≤ t ≤ 1.
      const ex = bx - ax, ey = by - ay, fx = ax - cx, fy = ay - cy;
      const qa = ex * ex + ey * ey, qb = fx * ex + fy * ey, qc = fx * fx + fy * fy - r2;
      const discriminant = qb * qb - qa * qc;
      if (qa > 0 && discriminant > 0) {
        const root = Math.sqrt(discriminant);
        const t0 = (-qb - root) / qa, t1 = (-qb + root) / qa;
        if (t0 >= 0 && t0 <= 1) this.addDirection(ax + t0 * ex, ay + t0 * ey);
        if (t1 >= 0 && t1 <= 1) this.addDirection(ax + t1 * ex, ay + t1 * ey);
      }
    }
    // Where two edges cross inside both (overlapping hulls, a polyline crossing itself).
    for (let i = 0; i < 4 * count; i += 4) {
      const ax = edges[i], ay = edges[i + 1], dx = edges[i + 2] - ax, dy = edges[i + 3] - ay;
      for (let j = i + 4; j < 4 * count; j += 4) {
        const bx = edges[j], by = edges[j + 1], ex = edges[j + 2] - bx, ey = edges[j + 3] - by;
        const denominator = dx * ey - dy * ex;
        if (denominator === 0) continue;
        const qx = bx - ax, qy = by - ay;
        const t = (qx * ey - qy * ex) / denominator;
        if (!(t > 0 && t < 1)) continue;
        const u = (qx * dy - qy * dx) / denominator;
        if (u > 0 && u < 1) this.addDirection(ax + t * dx, ay + t * dy);
      }
    }
    const breaks = this.breaks, breakCount = this.breakCount;
    sortAscending(breaks, breakCount);

    let visible = 0;
    for (let k = 0; k + 1 < breakCount; k++) {
      const a = breaks[k], b = breaks[k + 1];
      if (!(b - a > 1e-12)) continue;
      const middle = 0.5 * (a + b);
      const w = d * Math.sin(middle), projection = d * Math.cos(middle);
      const root = Math.sqrt(Math.max(0, r2 - w * w));
      const far = projection + root;
      const near = inside ? 0 : projection - root;
      const hit = this.firstHit(Math.cos(this.theta + middle), Math.sin(this.theta + middle));
      if (hit >= far) {
        visible += inside ? farFromInside(b, d, r) - farFromInside(a, d, r) : circleTerm(b, d, r) - circleTerm(a, d, r);
      } else if (hit > near) {
        visible += this.lineArea(this.hitEdge, a, b);
        if (!inside) visible -= nearTerm(b, d, r) - nearTerm(a, d, r);
      }
    }
    const fraction = visible / (Math.PI * r2);
    return fraction < 0 ? 0 : fraction > 1 ? 1 : fraction;
  }

  /** Adds the direction of (x, y) from the point, as δ in (−π, π], when it lies strictly inside the span. */
  private addDirection(x: number, y: number): void {
    let delta = Math.atan2(y - this.py, x - this.px) - this.theta;
    if (delta > Math.PI) delta -= 2 * Math.PI;
    else if (delta <= -Math.PI) delta += 2 * Math.PI;
    if (!(delta > -this.span && delta < this.span)) return;
    if (this.breakCount === this.breaks.length) this.breaks = grown(this.breaks, this.breakCount + 1);
    this.breaks[this.breakCount++] = delta;
  }

  /** Distance along the ray from the point in direction (ux, uy) to the first kept edge (Infinity if none); sets `hitEdge`. */
  private firstHit(ux: number, uy: number): number {
    const edges = this.edges, px = this.px, py = this.py;
    let nearest = Infinity;
    this.hitEdge = -1;
    for (let e = 0, end = 4 * this.edgeCount; e < end; e += 4) {
      const ax = edges[e], ay = edges[e + 1], ex = edges[e + 2] - ax, ey = edges[e + 3] - ay;
      const denominator = ux * ey - uy * ex;
      if (denominator === 0) continue;
      const wx = ax - px, wy = ay - py;
      const s = (wx * ey - wy * ex) / denominator;
      if (!(s > 0 && s < nearest)) continue;
      const t = (wx * uy - wy * ux) / denominator;
      if (t >= 0 && t <= 1) {
        nearest = s;
        this.hitEdge = e;
      }
    }
    return nearest;
  }

  /** ∫ ½ s_line² dδ over [a, b] for the line of the edge at offset `e`: ½ h² (tan(θ + b − ψ) − tan(θ + a − ψ)). */
  private lineArea(e: number, a: number, b: number): number {
    const edges = this.edges;
    const ax = edges[e], ay = edges[e + 1], ex = edges[e + 2] - ax, ey = edges[e + 3] - ay;
    const length = Math.sqrt(ex * ex + ey * ey);
    let nx = ey / length, ny = -ex / length;
    let h = nx * (ax - this.px) + ny * (ay - this.py);
    if (h < 0) {
      h = -h;
      nx = -nx;
      ny = -ny;
    }
    const psi = Math.atan2(ny, nx);
    return 0.5 * h * h * (Math.tan(this.theta + b - psi) - Math.tan(this.theta + a - psi));
  }
}

/**
 * The visible fraction of the disk of centre (cx, cy) and radius r ≥ 0 from (px, py), past the
 * polygons and polylines in `outlines` (each `[x0, y0, x1, y1, …]`; see {@link DiskVisibility}).
 * Allocates a {@link DiskVisibility}: for one-off use; keep one and call it directly in a loop.
 */
export function diskVisibleFraction(
  px: number, py: number, cx: number, cy: number, r: number,
  outlines: ReadonlyArray<{ points: ArrayLike<number>; closed: boolean }>,
): number {
  const visibility = new DiskVisibility();
  visibility.begin(px, py, cx, cy, r);
  for (const { points, closed } of outlines) visibility.addOutline(points, points.length >> 1, closed);
  return visibility.fraction();
}

/** F(δ) = w √(r² − w²) + r² asin(w / r), w = d sin δ: an antiderivative of ½ (s_far² − s_near²) from outside the disk. */
function circleTerm(delta: number, d: number, r: number): number {
  let w = d * Math.sin(delta);
  w = w < -r ? -r : w > r ? r : w;
  return w * Math.sqrt(Math.max(0, r * r - w * w)) + r * r * Math.asin(w / r);
}

/** Q(δ) = ½ r² δ + ¼ d² sin 2δ: an antiderivative of ½ (r² + d² cos 2δ), the part ½ s_near² and ½ s_far² share. */
function squareTerm(delta: number, d: number, r: number): number {
  return 0.5 * r * r * delta + 0.25 * d * d * Math.sin(2 * delta);
}

/** An antiderivative of ½ s_near² = ½ (d cos δ − √(r² − w²))², from outside the disk. */
function nearTerm(delta: number, d: number, r: number): number {
  return squareTerm(delta, d, r) - 0.5 * circleTerm(delta, d, r);
}

/** An antiderivative of ½ s_far² = ½ (d cos δ + √(r² − w²))², from inside the disk (s_near = 0). */
function farFromInside(delta: number, d: number, r: number): number {
  return squareTerm(delta, d, r) + 0.5 * circleTerm(delta, d, r);
}

/** Whether the segments p → q and a → b cross or come closer than `distance` (`distance` 0: cross, ends included). */
function segmentsWithin(distance: number, px: number, py: number, qx: number, qy: number, ax: number, ay: number, bx: number, by: number): boolean {
  if (segmentsCross(px, py, qx, qy, ax, ay, bx, by)) return true;
  if (distance === 0) return false;
  const limit = distance * distance;
  return pointSegmentDistance2(px, py, ax, ay, bx, by) < limit || pointSegmentDistance2(qx, qy, ax, ay, bx, by) < limit
    || pointSegmentDistance2(ax, ay, px, py, qx, qy) < limit || pointSegmentDistance2(bx, by, px, py, qx, qy) < limit;
}

/** Whether the segments p → q and a → b share a point, ends included (parallel ones count as not: zero measure). */
function segmentsCross(px: number, py: number, qx: number, qy: number, ax: number, ay: number, bx: number, by: number): boolean {
  const dx = qx - px, dy = qy - py, ex = bx - ax, ey = by - ay;
  const denominator = dx * ey - dy * ex;
  if (denominator === 0) return false;
  const wx = ax - px, wy = ay - py;
  const t = (wx * ey - wy * ex) / denominator;
  const u = (wx * dy - wy * dx) / denominator;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

/** Squared distance from (x, y) to the segment a → b. */
function pointSegmentDistance2(x: number, y: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax, ey = by - ay;
  const length2 = ex * ex + ey * ey;
  const t = length2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * ex + (y - ay) * ey) / length2)) : 0;
  const dx = x - ax - t * ex, dy = y - ay - t * ey;
  return dx * dx + dy * dy;
}

/** Sorts the first `count` values of `values` in place (insertion sort: the lists are short, and a subarray would allocate). */
function sortAscending(values: Float64Array, count: number): void {
  for (let i = 1; i < count; i++) {
    const value = values[i];
    let j = i - 1;
    while (j >= 0 && values[j] > value) {
      values[j + 1] = values[j];
      j--;
    }
    values[j + 1] = value;
  }
}

/** A copy of `array` with room for at least `length` values. */
function grown(array: Float64Array, length: number): Float64Array<ArrayBuffer> {
  const copy = new Float64Array(Math.max(length, 2 * array.length));
  copy.set(array);
  return copy;
}
