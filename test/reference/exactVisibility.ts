import { SceneGeometry, segmentsCross, segmentsWithin } from './sceneGeometry';

// Locals: vitest's module transform turns every call of an imported function into a property read.
const crosses = segmentsCross;
const within = segmentsWithin;

/**
 * The exact visible fraction of a light's disk (SPEC §6), computed without the renderer's math and
 * without sampling the disk.
 *
 * From a pixel centre p, every point of the disk lies on one ray from p. In polar coordinates
 * around p the disk's area is ∫ ∫ s ds dφ, and a point at distance s along direction φ is visible
 * when the first hull edge the ray meets is farther than s (s_hit ≥ s). So
 *
 *   visible area = ∫ ½ (min(s_hit(φ), s_far(φ))² − s_near(φ)²)₊ dφ
 *
 * over the directions that meet the disk, where the ray enters the disk at s_near and leaves it at
 * s_far (s_near = 0 and φ all the way round when p is inside the disk); the fraction is that area
 * over πr².
 *
 * The φ range is split at the directions of every edge end, every crossing of two edges and every
 * point where an edge crosses the light's circle. Between two such directions the same edge (or
 * none) is hit first, and it stays in front of the disk, inside it or behind it, so the integrand
 * is one closed-form expression on the whole piece, found at its middle direction:
 *   - nothing in front of the disk's far side: ½ (s_far² − s_near²), the disk's own area term;
 *   - an edge inside the disk: ½ (s_line² − s_near²), where s_line is the distance to the edge's line;
 *   - an edge in front of the disk: 0.
 * With δ = φ − (direction of the centre), d = |c − p| and w = d sin δ:
 *   s_far, s_near = d cos δ ± √(r² − w²), so ½ s_far,near² has the antiderivative Q ± G with
 *   Q(δ) = ½ r² δ + ¼ d² sin 2δ and G(δ) = ½ (w √(r² − w²) + r² asin(w / r));
 *   s_line = h / cos(φ − ψ) (h the line's distance from p, ψ its normal's direction), so
 *   ½ s_line² has the antiderivative ½ h² tan(φ − ψ).
 * Each piece is thus integrated exactly (to rounding). `method: 'quadrature'` integrates the same
 * pieces with Gauss–Legendre instead (after δ = span · sin τ, which removes the square-root ends
 * of the span): a cross-check of the closed forms, used by the unit tests.
 *
 * Radius 0 is a single segment test p → centre (hard shadows).
 */
export interface ExactVisibilityOptions {
  method?: 'closed-form' | 'quadrature';
  /** Gauss–Legendre nodes per piece for `method: 'quadrature'`. Default 8. */
  nodes?: number;
}

/** Pieces graded towards the grazing directions on each side of them, for `'quadrature'` from inside the disk. */
const GRADED_BREAKS = 6;

export class ExactVisibility {
  private readonly relevant: Float64Array;
  private readonly breaks: Float64Array;
  private readonly quadrature: { nodes: Float64Array; weights: Float64Array } | null;
  // Per call: the pixel, the direction of the light's centre and the half-width of the span.
  private px = 0;
  private py = 0;
  private theta = 0;
  private span = 0;
  private breakCount = 0;
  private relevantCount = 0;
  /** Offset in `relevant` of the edge the last `firstHit` met. */
  private hitEdge = -1;

  constructor(private readonly geometry: SceneGeometry, options: ExactVisibilityOptions = {}) {
    this.relevant = new Float64Array(geometry.edges.length);
    this.breaks = new Float64Array(4 + 4 * GRADED_BREAKS + geometry.edges.length + geometry.crossings.length / 2);
    this.quadrature = options.method === 'quadrature' ? gaussLegendre(options.nodes ?? 8) : null;
  }

  /** Fraction of the disk (centre (cx, cy), radius r) whose segment to (px, py) crosses no hull edge. */
  fraction(px: number, py: number, cx: number, cy: number, r: number): number {
    const edges = this.geometry.edges;
    if (r === 0) {
      for (let e = 0; e < edges.length; e += 4) {
        if (crosses(px, py, cx, cy, edges[e], edges[e + 1], edges[e + 2], edges[e + 3])) return 0;
      }
      return 1;
    }
    const dx = cx - px, dy = cy - py;
    const d = Math.sqrt(dx * dx + dy * dy);
    const inside = d < r;
    this.px = px;
    this.py = py;
    this.theta = d > 0 ? Math.atan2(dy, dx) : 0;
    this.span = inside ? Math.PI : Math.asin(r / d);

    // Only edges that meet the hull of p and the disk (within r of the segment p → c) can hide any of it.
    let count = 0;
    for (let e = 0; e < edges.length; e += 4) {
      if (within(r, px, py, cx, cy, edges[e], edges[e + 1], edges[e + 2], edges[e + 3])) {
        this.relevant.set(edges.subarray(e, e + 4), count);
        count += 4;
      }
    }
    if (count === 0) return 1;
    this.relevantCount = count;

    // Directions where the integrand changes form.
    const span = this.span;
    const breaks = this.breaks;
    this.breakCount = 0;
    breaks[this.breakCount++] = -span;
    breaks[this.breakCount++] = span;
    if (inside && this.quadrature) {
      // From just inside the rim, √(r² − w²) = √(r² − d² + d² cos² δ) turns sharply within about
      // √(r² − d²) / d of |δ| = π/2: pieces graded towards those directions keep the nodes dense there.
      const width = Math.sqrt(r * r - d * d) / Math.max(d, 1e-9);
      for (const side of [-1, 1]) {
        breaks[this.breakCount++] = side * Math.PI / 2;
        for (let j = 0, offset = width; j < GRADED_BREAKS && offset < Math.PI / 2; j++, offset *= 4) {
          breaks[this.breakCount++] = side * Math.PI / 2 - offset;
          breaks[this.breakCount++] = side * Math.PI / 2 + offset;
        }
      }
    }
    const rel = this.relevant;
    for (let e = 0; e < count; e += 4) {
      const ax = rel[e], ay = rel[e + 1], bx = rel[e + 2], by = rel[e + 3];
      this.addDirection(ax, ay);
      this.addDirection(bx, by);
      // Where the edge crosses the light's circle: |a − c + t (b − a)|² = r².
      const ex = bx - ax, ey = by - ay, fx = ax - cx, fy = ay - cy;
      const qa = ex * ex + ey * ey, qb = fx * ex + fy * ey, qc = fx * fx + fy * fy - r * r;
      const discriminant = qb * qb - qa * qc;
      if (qa > 0 && discriminant > 0) {
        const root = Math.sqrt(discriminant);
        const t0 = (-qb - root) / qa, t1 = (-qb + root) / qa;
        if (t0 >= 0 && t0 <= 1) this.addDirection(ax + t0 * ex, ay + t0 * ey);
        if (t1 >= 0 && t1 <= 1) this.addDirection(ax + t1 * ex, ay + t1 * ey);
      }
    }
    const crossings = this.geometry.crossings;
    for (let i = 0; i < crossings.length; i += 2) {
      if (within(r, px, py, cx, cy, crossings[i], crossings[i + 1], crossings[i], crossings[i + 1])) {
        this.addDirection(crossings[i], crossings[i + 1]);
      }
    }
    const sorted = breaks.subarray(0, this.breakCount).sort();

    const r2 = r * r;
    let visible = 0;
    let hidden = false;
    let seen = false;
    for (let k = 0; k + 1 < sorted.length; k++) {
      const a = sorted[k], b = sorted[k + 1];
      if (!(b - a > 1e-12)) continue;
      if (this.quadrature) {
        const piece = this.integrate(a, b, d, r2, inside);
        visible += piece.area;
        hidden ||= piece.hidden;
        seen ||= piece.seen;
        continue;
      }
      const mid = 0.5 * (a + b);
      const w = d * Math.sin(mid);
      const projection = d * Math.cos(mid);
      const root = Math.sqrt(Math.max(0, r2 - w * w));
      const far = projection + root;
      const near = inside ? 0 : projection - root;
      const hit = this.firstHit(Math.cos(this.theta + mid), Math.sin(this.theta + mid));
      if (hit >= far) {
        seen = true;
        visible += inside ? farArea(b, d, r) - farArea(a, d, r) : 2 * (circleTerm(b, d, r) - circleTerm(a, d, r));
      } else {
        hidden = true;
        if (hit > near) {
          seen = true;
          visible += this.lineArea(this.hitEdge, a, b) - (inside ? 0 : nearArea(b, d, r) - nearArea(a, d, r));
        }
      }
    }
    if (!hidden) return 1;
    if (!seen) return 0;
    return Math.min(1, Math.max(0, visible / (Math.PI * r2)));
  }

  /** Adds the direction of (x, y) from the pixel, relative to the centre's, when it is inside the span. */
  private addDirection(x: number, y: number): void {
    let delta = Math.atan2(y - this.py, x - this.px) - this.theta;
    if (delta > Math.PI) delta -= 2 * Math.PI;
    else if (delta <= -Math.PI) delta += 2 * Math.PI;
    if (delta > -this.span && delta < this.span) this.breaks[this.breakCount++] = delta;
  }

  /** Distance along the ray from the pixel in direction (ux, uy) to the first relevant edge (Infinity if none). */
  private firstHit(ux: number, uy: number): number {
    const rel = this.relevant;
    let nearest = Infinity;
    this.hitEdge = -1;
    for (let e = 0; e < this.relevantCount; e += 4) {
      const ax = rel[e], ay = rel[e + 1], ex = rel[e + 2] - ax, ey = rel[e + 3] - ay;
      const denominator = ux * ey - uy * ex;
      if (denominator === 0) continue;
      const wx = ax - this.px, wy = ay - this.py;
      const s = (wx * ey - wy * ex) / denominator;
      const t = (wx * uy - wy * ux) / denominator;
      if (s > 0 && t >= 0 && t <= 1 && s < nearest) {
        nearest = s;
        this.hitEdge = e;
      }
    }
    return nearest;
  }

  /** ∫ ½ s_line² dφ over [θ + a, θ + b] for the line of relevant edge `e`: ½ h² (tan(φb − ψ) − tan(φa − ψ)). */
  private lineArea(e: number, a: number, b: number): number {
    const rel = this.relevant;
    const ax = rel[e], ay = rel[e + 1], ex = rel[e + 2] - ax, ey = rel[e + 3] - ay;
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

  /** Gauss–Legendre over [a, b] of ½ (min(s_hit, s_far)² − s_near²)₊, in τ with δ = span · sin τ when p is outside the disk. */
  private integrate(a: number, b: number, d: number, r2: number, inside: boolean): { area: number; hidden: boolean; seen: boolean } {
    const { nodes, weights } = this.quadrature!;
    const span = this.span;
    const clampUnit = (x: number) => Math.min(1, Math.max(-1, x));
    const lower = inside ? a : Math.asin(clampUnit(a / span));
    const upper = inside ? b : Math.asin(clampUnit(b / span));
    const middle = 0.5 * (lower + upper), half = 0.5 * (upper - lower);
    let area = 0, hidden = false, seen = false;
    for (let i = 0; i < nodes.length; i++) {
      const x = middle + half * nodes[i];
      const delta = inside ? x : span * Math.sin(x);
      const jacobian = inside ? 1 : span * Math.cos(x);
      const w = d * Math.sin(delta);
      const projection = d * Math.cos(delta);
      const root = Math.sqrt(Math.max(0, r2 - w * w));
      const far = projection + root;
      const near = inside ? 0 : projection - root;
      const hit = this.firstHit(Math.cos(this.theta + delta), Math.sin(this.theta + delta));
      const reach = Math.min(hit, far);
      if (hit < far) hidden = true;
      if (reach > near) {
        seen = true;
        area += weights[i] * half * jacobian * 0.5 * (reach * reach - near * near);
      }
    }
    return { area, hidden, seen };
  }
}

/** G(δ) = ½ (w √(r² − w²) + r² asin(w / r)), w = d sin δ: an antiderivative of d cos δ √(r² − w²). */
function circleTerm(delta: number, d: number, r: number): number {
  const w = Math.min(r, Math.max(-r, d * Math.sin(delta)));
  return 0.5 * (w * Math.sqrt(Math.max(0, r * r - w * w)) + r * r * Math.asin(w / r));
}

/** Q(δ) = ½ r² δ + ¼ d² sin 2δ: an antiderivative of ½ (r² + d² cos 2δ). */
function squareTerm(delta: number, d: number, r: number): number {
  return 0.5 * r * r * delta + 0.25 * d * d * Math.sin(2 * delta);
}

/** Q + G: an antiderivative of ½ s_far² (s_far = d cos δ + √(r² − w²)). */
function farArea(delta: number, d: number, r: number): number {
  return squareTerm(delta, d, r) + circleTerm(delta, d, r);
}

/** Q − G: an antiderivative of ½ s_near² (s_near = d cos δ − √(r² − w²)). */
function nearArea(delta: number, d: number, r: number): number {
  return squareTerm(delta, d, r) - circleTerm(delta, d, r);
}

/** Nodes and weights of n-point Gauss–Legendre quadrature on [−1, 1] (Newton on the Legendre polynomial). */
export function gaussLegendre(n: number): { nodes: Float64Array; weights: Float64Array } {
  const nodes = new Float64Array(n), weights = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    let x = Math.cos((Math.PI * (i + 0.75)) / (n + 0.5));
    let derivative = 0;
    for (let iteration = 0; iteration < 100; iteration++) {
      let p0 = 1, p1 = x;
      for (let k = 2; k <= n; k++) [p0, p1] = [p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k];
      derivative = (n * (x * p1 - p0)) / (x * x - 1);
      const step = p1 / derivative;
      x -= step;
      if (Math.abs(step) < 1e-16) break;
    }
    nodes[i] = x;
    weights[i] = 2 / ((1 - x * x) * derivative * derivative);
  }
  return { nodes, weights };
}
