/**
 * The exact fraction of a light's disk visible from a point past a set of edges (the share of its
 * area whose segments to the point meet no edge; docs/shadows.md), on the CPU in double precision: what `PenumbraRenderer.illuminationAt` reports per light.
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
 * A shortcut for convex pieces (a convex polygon, an open polyline's segment) from outside the
 * disk, as the renderer's union of the records in front: such a piece spans less than 180° from p,
 * between its clockwise-most point a and counter-clockwise-most b, and every ray between them
 * crosses the chord a–b, which lies in the piece. When the disk misses the triangle (p, a, b), every
 * disk point in that wedge lies beyond the chord: the piece hides exactly the wedge's directions,
 * and no others. Its edges are then left out and the wedge is kept as a covered interval of
 * directions, which the sweep skips; once the intervals cover the whole disk the fraction is 0 with
 * no sweep at all (the common case of a light far behind walls). A piece whose wedge misses the
 * disk's directions is left out too.
 *
 * Cost: O(B · E) per point for E edges kept and B cuts (2E plus the edge crossings and rim
 * crossings), with the pairs of edges tested for crossings in O(E²); O(points) per convex piece.
 * Nothing is allocated once the buffers have grown to the largest counts seen.
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
  /** Directions (δ) hidden whole by convex pieces in front: sorted, disjoint `[low, high]` pairs, the first `coverCount`. */
  private covers = new Float64Array(16);
  private coverCount = 0;
  /** Set when the whole disk is known to be hidden. */
  private hidden = false;
  /**
   * What {@link DiskVisibility.start} reads: `[px, py, cx, cy, r]`. Hot callers write it and call
   * `start()` instead of `begin(…)` (see Hot-path rules in docs/architecture.md).
   */
  readonly input = new Float64Array(5);
  /** What {@link DiskVisibility.computeFraction} found: `[fraction]`. */
  readonly output = new Float64Array(1);
  /** An edge given to {@link DiskVisibility.addEdge}, in the layout `keepEdge` reads. */
  private readonly edgeInput = new Float64Array(4);

  /** Starts a point p = (px, py) and a disk of centre (cx, cy) and radius r ≥ 0; forgets the edges. */
  begin(px: number, py: number, cx: number, cy: number, r: number): void {
    const input = this.input;
    input[0] = px;
    input[1] = py;
    input[2] = cx;
    input[3] = cy;
    input[4] = r;
    this.start();
  }

  /** {@link DiskVisibility.begin} with the point and disk from {@link DiskVisibility.input}. */
  start(): void {
    const input = this.input;
    const px = this.px = input[0], py = this.py = input[1], cx = this.cx = input[2], cy = this.cy = input[3], r = this.r = input[4];
    this.edgeCount = 0;
    this.coverCount = 0;
    this.hidden = false;
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

  /** Whether the edges and pieces added so far hide the whole disk (then {@link DiskVisibility.fraction} is 0 whatever else is added). */
  get covered(): boolean {
    return this.hidden;
  }

  /** Adds the edge a → b, kept only when it comes within r of the segment from the point to the centre. */
  addEdge(ax: number, ay: number, bx: number, by: number): void {
    const edge = this.edgeInput;
    edge[0] = ax;
    edge[1] = ay;
    edge[2] = bx;
    edge[3] = by;
    this.keepEdge(edge, 0, 1);
  }

  /**
   * Keeps the edge from point `i` to point `j` of `coords` when it crosses the segment p → c or
   * comes within r of it. One body, no helper returning a number: this runs for every edge near
   * every light of every query.
   */
  private keepEdge(coords: ArrayLike<number>, i: number, j: number): void {
    const ax = coords[2 * i], ay = coords[2 * i + 1], bx = coords[2 * j], by = coords[2 * j + 1];
    const box = this.box;
    if ((ax < bx ? bx : ax) < box[0] || (ax < bx ? ax : bx) > box[2] || (ay < by ? by : ay) < box[1] || (ay < by ? ay : by) > box[3]) return;
    const px = this.px, py = this.py, r = this.r;
    const dx = this.cx - px, dy = this.cy - py, ex = bx - ax, ey = by - ay;
    // Crossing (ends included; parallel segments count as not crossing).
    const denominator = dx * ey - dy * ex;
    let near = false;
    if (denominator !== 0) {
      const wx = ax - px, wy = ay - py;
      const t = (wx * ey - wy * ex) / denominator, u = (wx * dy - wy * dx) / denominator;
      near = t >= 0 && t <= 1 && u >= 0 && u <= 1;
    }
    if (!near && r > 0) {
      // Within r: an end of either segment within r of the other segment.
      const r2 = r * r, e2 = ex * ex + ey * ey, d2 = dx * dx + dy * dy;
      for (let k = 0; k < 4 && !near; k++) {
        // Point (qx, qy) against segment (sx, sy) + t (vx, vy).
        const onEdge = k < 2;
        const qx = k === 0 ? px : k === 1 ? this.cx : k === 2 ? ax : bx;
        const qy = k === 0 ? py : k === 1 ? this.cy : k === 2 ? ay : by;
        const sx = onEdge ? ax : px, sy = onEdge ? ay : py, vx = onEdge ? ex : dx, vy = onEdge ? ey : dy, v2 = onEdge ? e2 : d2;
        let t = v2 > 0 ? ((qx - sx) * vx + (qy - sy) * vy) / v2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        const ox = qx - sx - t * vx, oy = qy - sy - t * vy;
        near = ox * ox + oy * oy < r2;
      }
    }
    if (!near) return;
    // With radius 0 the capsule is the segment p → c: an edge in it hides the whole (point) light.
    if (r === 0) this.hidden = true;
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
   * `coords` = `[x0, y0, x1, y1, …]`: the first `count` points. `convex` says a closed polygon is
   * convex (and the point outside it), so that it may be taken whole when it lies in front of the
   * disk; a polyline's segments always may.
   */
  addOutline(coords: ArrayLike<number>, count: number, closed: boolean, convex = false): void {
    if (this.hidden) return;
    const shortcut = this.r > 0 && !this.inside;
    if (closed && convex && shortcut && this.coverConvex(coords, 0, count)) return;
    for (let i = 0; i + 1 < count; i++) {
      if (!closed && shortcut && this.coverConvex(coords, i, 2)) continue;
      this.keepEdge(coords, i, i + 1);
    }
    if (closed && count > 2) this.keepEdge(coords, count - 1, 0);
  }

  /**
   * Adds the edges of the closed polygon `coords` (the first `count` points, either winding) that
   * face the point — those with the point strictly on their outer side — for a point inside the
   * polygon that is lit as from inside it (`ShadowType.Occluded`): a segment from the point leaves
   * the polygon once, and only crossing a facing edge does it enter again.
   */
  addFacingEdges(coords: ArrayLike<number>, count: number): void {
    if (this.hidden) return;
    let twiceArea = 0;
    for (let i = 0, j = count - 1; i < count; j = i++) twiceArea += coords[2 * j] * coords[2 * i + 1] - coords[2 * i] * coords[2 * j + 1];
    const px = this.px, py = this.py;
    for (let i = 0; i < count; i++) {
      const j = i + 1 === count ? 0 : i + 1;
      const ax = coords[2 * i], ay = coords[2 * i + 1];
      // Positive: the point left of a → b, inside for a counter-clockwise outline.
      const side = (coords[2 * j] - ax) * (py - ay) - (coords[2 * j + 1] - ay) * (px - ax);
      if (side * twiceArea < 0) this.keepEdge(coords, i, j);
    }
  }

  /**
   * The shortcut for the convex piece of points `first .. first + count − 1` of `coords` (see the
   * class comment), from outside the disk: true when it is settled (its wedge misses the disk's
   * directions, or it lies in front of the disk and its wedge is now covered), false when its edges
   * must be added.
   */
  private coverConvex(coords: ArrayLike<number>, first: number, count: number): boolean {
    const px = this.px, py = this.py;
    // The silhouette: the clockwise-most and counter-clockwise-most points, relative to p.
    let lowX = coords[2 * first] - px, lowY = coords[2 * first + 1] - py, highX = lowX, highY = lowY;
    for (let i = first + 1; i < first + count; i++) {
      const x = coords[2 * i] - px, y = coords[2 * i + 1] - py;
      if (highX * y - highY * x > 0) {
        highX = x;
        highY = y;
      }
      if (lowX * y - lowY * x < 0) {
        lowX = x;
        lowY = y;
      }
    }
    // p on the piece's outline (or the line of a segment): no wedge to speak of.
    if (!(lowX * highY - lowY * highX > 0)) return false;
    // The wedge's directions within the span; an end 90° or more off the centre's direction was
    // reached by turning past ±90°, and with both ends there the piece is behind p.
    const ux = (this.cx - px) / this.d, uy = (this.cy - py) / this.d, span = this.span;
    const lowAhead = ux * lowX + uy * lowY > 0, highAhead = ux * highX + uy * highY > 0;
    if (!lowAhead && !highAhead) return true;
    const low = lowAhead ? Math.max(-span, Math.atan2(ux * lowY - uy * lowX, ux * lowX + uy * lowY)) : -span;
    const high = highAhead ? Math.min(span, Math.atan2(ux * highY - uy * highX, ux * highX + uy * highY)) : span;
    if (low >= high) return true;
    if (!this.diskBeyond(lowX, lowY, highX, highY)) return false;
    this.cover(low, high);
    return true;
  }

  /** Whether the disk misses the triangle (p, p + a, p + b): then every disk point in that wedge lies beyond the chord a–b. */
  private diskBeyond(ax: number, ay: number, bx: number, by: number): boolean {
    const cx = this.cx - this.px, cy = this.cy - this.py, r2 = this.r * this.r;
    const ex = bx - ax, ey = by - ay;
    // The common case first: the centre at least r beyond the chord's line, on the side away from p.
    const beyond = ex * (cy - ay) - ey * (cx - ax), pSide = ex * -ay - ey * -ax;
    if (beyond * pSide < 0 && beyond * beyond >= r2 * (ex * ex + ey * ey)) return true;
    const centreInside = (ax * cy - ay * cx) * (ax * by - ay * bx) > 0 && (bx * cy - by * cx) * (bx * ay - by * ax) > 0 && beyond * pSide > 0;
    return !centreInside && pointSegmentDistance2(cx, cy, 0, 0, ax, ay) >= r2 && pointSegmentDistance2(cx, cy, 0, 0, bx, by) >= r2
      && pointSegmentDistance2(cx, cy, ax, ay, bx, by) >= r2;
  }

  /** Adds [low, high] (within the span) to the covered directions, merging; notes when they cover the span. */
  private cover(low: number, high: number): void {
    const covers = this.covers;
    let count = this.coverCount;
    // Merge every interval that overlaps or touches [low, high] into it, and keep the rest in order.
    let write = 0;
    for (let k = 0; k < count; k++) {
      const from = covers[2 * k], to = covers[2 * k + 1];
      if (to >= low && from <= high) {
        if (from < low) low = from;
        if (to > high) high = to;
      } else {
        covers[2 * write] = from;
        covers[2 * write + 1] = to;
        write++;
      }
    }
    count = write;
    if (2 * count + 2 > covers.length) this.covers = grown(covers, 2 * count + 2);
    const list = this.covers;
    let at = count;
    while (at > 0 && list[2 * at - 2] > low) {
      list[2 * at] = list[2 * at - 2];
      list[2 * at + 1] = list[2 * at - 1];
      at--;
    }
    list[2 * at] = low;
    list[2 * at + 1] = high;
    this.coverCount = count + 1;
    if (low <= -this.span && high >= this.span) this.hidden = true;
  }

  /** The fraction of the disk, 0..1, whose segment to the point crosses none of the edges added. */
  fraction(): number {
    this.computeFraction();
    return this.output[0];
  }

  /**
   * {@link DiskVisibility.fraction} into `output[0]`, where hot callers read it (see Hot-path rules
   * in docs/architecture.md).
   */
  computeFraction(): void {
    const output = this.output;
    output[0] = 0;
    if (this.hidden) return;
    output[0] = 1;
    const count = this.edgeCount, covers = this.covers, coverCount = this.coverCount;
    if (count === 0 && coverCount === 0) return;
    const edges = this.edges, r = this.r;
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
    // The ends of the covered intervals.
    for (let k = 0; k < 2 * coverCount; k++) {
      const end = covers[k];
      if (!(end > -span && end < span)) continue;
      if (this.breakCount === this.breaks.length) this.breaks = grown(this.breaks, this.breakCount + 1);
      this.breaks[this.breakCount++] = end;
    }
    const breaks = this.breaks, breakCount = this.breakCount;
    sortAscending(breaks, breakCount);

    let visible = 0, cover = 0;
    for (let k = 0; k + 1 < breakCount; k++) {
      const a = breaks[k], b = breaks[k + 1];
      if (!(b - a > 1e-12)) continue;
      const middle = 0.5 * (a + b);
      // Covered: hidden whole. The pieces and the intervals are both in order.
      while (cover < coverCount && covers[2 * cover + 1] < middle) cover++;
      if (cover < coverCount && covers[2 * cover] < middle) continue;
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
    output[0] = fraction < 0 ? 0 : fraction > 1 ? 1 : fraction;
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
