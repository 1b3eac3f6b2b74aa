/**
 * Outlines of the solid pixels of an image, as simple polygons: pure, no DOM, no GL.
 *
 * Pixel `(x, y)` covers `[x, x + 1] × [y, y + 1]`, y down. The solid pixels are split (by
 * {@link holeFreeRegions}) into 4-connected regions without holes; each region's outline is the
 * marching-squares contour of that region's own mask at level ½ (the polygon through the midpoints
 * of the pixel edges that separate it from the rest, diagonal saddles separated), then simplified
 * by Douglas–Peucker. Every returned polygon has positive {@link signedArea2} (the library's
 * counter-clockwise) and passes {@link isSimplePolygon}.
 *
 * Invariants the callers rely on:
 * - Unsimplified (tolerance 0), a region's outline holds exactly the centres of its pixels: the
 *   marching-squares contour passes midway between every inside and outside pixel centre.
 * - Two regions that the splitter cut apart share every midpoint of the pixel edges between them
 *   (both outlines run through them). Those points are pinned: the splitter cuts along rows, so
 *   each run of them is straight, and simplification keeps both ends of each run; the simplified
 *   outlines still meet exactly along the cut, with no gap for light to pass.
 */
import { holeFreeRegions, type CellGrid } from './gridRegions';
import { isSimplePolygon, signedArea2 } from './polygon';

/** How {@link alphaOutlines} and {@link regionOutlines} simplify and filter. */
export interface OutlineOptions {
  /** Largest distance, in pixels, of the simplified outline from the traced one. */
  readonly tolerance: number;
  /** Most points per outline (≥ 3; `Infinity` for no cap); the tolerance grows until it is met. */
  readonly maxPoints: number;
  /** Islands (4-connected solid pixels, all their regions together) with fewer pixels are dropped. */
  readonly minArea: number;
}

/**
 * The pixels of RGBA bytes `data` (4 per pixel, row after row) with `alpha ≥ threshold`, as the
 * cell grid that {@link holeFreeRegions} reads: straight from the bytes, no mask built first.
 */
export function alphaGrid(data: ArrayLike<number>, width: number, height: number, threshold: number): CellGrid {
  return { width, height, solid: (x, y) => data[4 * (y * width + x) + 3] >= threshold };
}

/**
 * Outlines of the pixels with `alpha ≥ threshold` in RGBA bytes `data` (4 per pixel, row after
 * row): one flat `[x0, y0, x1, y1, …]` polygon per hole-free region, in pixel units.
 */
export function alphaOutlines(data: ArrayLike<number>, width: number, height: number, threshold: number, options: OutlineOptions): Float64Array[] {
  if (width === 0 || height === 0) return [];
  const { labels, count } = holeFreeRegions(alphaGrid(data, width, height, threshold));
  return regionOutlines(labels, count, width, height, options);
}

/**
 * One simplified outline per labelled region (`labels[y * width + x]` = region index, or −1 for
 * empty), regions in index order, without those of islands smaller than `options.minArea`.
 * Each region must be 4-connected and without holes.
 */
export function regionOutlines(labels: Int32Array, count: number, width: number, height: number, options: OutlineOptions): Float64Array[] {
  const { starts, kept } = scanRegions(labels, count, width, height, options.minArea);
  const outlines: Float64Array[] = [];
  const tracer = new Tracer(labels, width, height);
  for (let region = 0; region < count; region++) {
    if (!kept[region] || starts[region] < 0) continue;
    const ring = tracer.trace(region, starts[region]);
    outlines.push(simplifyOutline(ring, options.tolerance, options.maxPoints));
  }
  return outlines;
}

/**
 * Each region's first pixel in row order (where its outline starts; −1 for a region without
 * pixels), and whether its island has at least `minArea` pixels.
 *
 * The first pixels come from `indexOf` (native, fast even before the JIT warms up, which is what
 * the first sprite a game loads meets): regions are numbered in row order of their first pixel,
 * so each search starts past the previous region's first pixel, and the searches cover the labels
 * once. With `minArea`, one pass over the labels sums each region's pixels and joins the regions
 * the splitter cut apart (solid neighbours with different labels) into islands, by union–find.
 */
function scanRegions(labels: Int32Array, count: number, width: number, height: number, minArea: number): { starts: Int32Array; kept: Uint8Array } {
  const starts = new Int32Array(count);
  for (let r = 0, from = 0; r < count; r++) {
    let start = labels.indexOf(r, from);
    // Only if the numbering were not in row order: search from the top.
    if (start < 0 && from > 0) start = labels.indexOf(r);
    starts[r] = start;
    if (start >= 0) from = start + 1;
  }
  const kept = new Uint8Array(count).fill(1);
  if (minArea <= 0) return { starts, kept };
  const areas = new Float64Array(count);
  const parent = Int32Array.from({ length: count }, (_, i) => i);
  const root = (r: number): number => {
    while (parent[r] !== r) r = parent[r] = parent[parent[r]];
    return r;
  };
  for (let y = 0, i = 0; y < height; y++) {
    for (let x = 0; x < width; x++, i++) {
      const label = labels[i];
      if (label < 0) continue;
      areas[label]++;
      const right = x + 1 < width ? labels[i + 1] : -1, below = y + 1 < height ? labels[i + width] : -1;
      if (right >= 0 && right !== label) parent[root(right)] = root(label);
      if (below >= 0 && below !== label) parent[root(below)] = root(label);
    }
  }
  const islandAreas = new Float64Array(count);
  for (let r = 0; r < count; r++) islandAreas[root(r)] += areas[r];
  for (let r = 0; r < count; r++) kept[r] = islandAreas[root(r)] >= minArea ? 1 : 0;
  return { starts, kept };
}

/** A traced outline: crack midpoints in order, and which of them lie on a cut (pinned). */
interface Ring {
  readonly xs: Float64Array;
  readonly ys: Float64Array;
  readonly pinned: Uint8Array;
  readonly n: number;
}

// Directions in pixel space (y down): 0 = +x, 1 = +y, 2 = −x, 3 = −y; turning right on screen is +1.
const DX = [1, 0, -1, 0], DY = [0, 1, 0, -1];
/** Offset from a lattice point to the pixel ahead and to the right (on screen) of direction d. */
const RIGHT_X = [0, -1, -1, 0], RIGHT_Y = [0, 0, -1, -1];
/** Offset from a lattice point to the pixel ahead and to the left of direction d. */
const LEFT_X = [0, 0, -1, -1], LEFT_Y = [-1, 0, 0, -1];

/**
 * Follows a region's boundary along pixel edges (cracks), the region on the right on screen, so
 * that the outline comes out with positive signed area. At a lattice point, with R and L the two
 * pixels ahead (right and left): R outside → turn right; R and L inside → turn left; else straight.
 * A diagonal pair (R outside, L inside) turns right, keeping to the pixel it follows: regions are
 * 4-connected, so diagonal saddles are separated and no point is visited twice.
 */
class Tracer {
  private xs = new Float64Array(64);
  private ys = new Float64Array(64);
  private pinned = new Uint8Array(64);

  constructor(private readonly labels: Int32Array, private readonly width: number, private readonly height: number) {}

  /** The label at pixel (x, y), −1 outside the image. */
  private label(x: number, y: number): number {
    return x >= 0 && y >= 0 && x < this.width && y < this.height ? this.labels[y * this.width + x] : -1;
  }

  /**
   * Traces `region` from its first pixel in row order, `start` (= y · width + x): nothing of the
   * region lies above or left of it, so its top edge, walked in +x, is on the outline, and its
   * top-left corner is on no other part of it (the walk ends on returning there in +x).
   */
  trace(region: number, start: number): Ring {
    const px = start % this.width, py = (start - px) / this.width;
    let x = px, y = py, d = 0, n = 0;
    do {
      // The crack from (x, y) in direction d: the region's pixel on its right, another pixel on its left.
      if (n === this.xs.length) this.grow();
      this.xs[n] = x + DX[d] / 2;
      this.ys[n] = y + DY[d] / 2;
      this.pinned[n] = this.label(x + LEFT_X[d], y + LEFT_Y[d]) >= 0 ? 1 : 0;
      n++;
      x += DX[d];
      y += DY[d];
      if (this.label(x + RIGHT_X[d], y + RIGHT_Y[d]) !== region) d = (d + 1) & 3;
      else if (this.label(x + LEFT_X[d], y + LEFT_Y[d]) === region) d = (d + 3) & 3;
    } while (x !== px || y !== py || d !== 0);
    return { xs: this.xs.slice(0, n), ys: this.ys.slice(0, n), pinned: this.pinned.slice(0, n), n };
  }

  private grow(): void {
    const size = this.xs.length * 2;
    const xs = new Float64Array(size), ys = new Float64Array(size), pinned = new Uint8Array(size);
    xs.set(this.xs);
    ys.set(this.ys);
    pinned.set(this.pinned);
    this.xs = xs;
    this.ys = ys;
    this.pinned = pinned;
  }
}

/** Tolerances below this are treated as 0 (only collinear points go) when backing off from a self-crossing. */
const SMALLEST_TOLERANCE = 1 / 32;
/** Factor by which the tolerance grows while an outline has more than `maxPoints` points. */
const TOLERANCE_GROWTH = 1.5;
/** Growth steps before giving up (1.5^80 ≈ 10^14 pixels: past any image, the chords leave only the anchors). */
const MAX_GROWTH_STEPS = 80;

/**
 * Simplifies a traced ring to within `tolerance` pixels, backing off (halving, down to 0) where
 * that makes it cross itself, then, while it has more than `maxPoints` points, growing the
 * tolerance until a simple outline fits. Tolerance 0 removes only collinear points, which always
 * leaves a simple polygon. If no tolerance yields a simple outline within the cap: with no pinned
 * point, the convex hull cut down to the cap (the cap wins over fidelity); with pinned points, the
 * simple outline with the fewest points found (the pins win over the cap: no gap along a cut).
 */
function simplifyOutline(ring: Ring, tolerance: number, maxPoints: number): Float64Array {
  const anchors = anchorPoints(ring);
  let best: Float64Array | null = null;
  for (let t = tolerance; ; t = t / 2 < SMALLEST_TOLERANCE ? 0 : t / 2) {
    const candidate = douglasPeucker(ring, anchors, t);
    if (isSimplePolygon(candidate)) {
      best = candidate;
      break;
    }
    if (t === 0) break;
  }
  // Unreachable for a valid region (see the function's comment); a safe answer all the same.
  if (best === null) best = collinearFree(ring);
  if (best.length >> 1 <= maxPoints) return best;

  let fewest = best;
  let t = Math.max(tolerance, SMALLEST_TOLERANCE);
  for (let step = 0; step < MAX_GROWTH_STEPS; step++) {
    t *= TOLERANCE_GROWTH;
    const candidate = douglasPeucker(ring, anchors, t);
    const simple = isSimplePolygon(candidate);
    if (simple && candidate.length >> 1 <= maxPoints) return candidate;
    if (simple && candidate.length < fewest.length) fewest = candidate;
    // Only the anchors left: a larger tolerance cannot remove more.
    if (candidate.length >> 1 <= Math.max(anchors.length, 2)) break;
  }
  return ring.pinned.includes(1) ? fewest : convexWithin(ring, maxPoints);
}

/**
 * The ring's points that simplification must keep: the ends of each run of pinned points (the
 * splitter cuts along rows, so a run is straight and its ends carry it). With none, point 0 (the
 * middle of the first pixel's top edge: no point lies above it) and the point farthest from it:
 * both are extreme points of the outline, so the split into two chains follows its shape.
 */
function anchorPoints(ring: Ring): number[] {
  const { xs, ys, pinned, n } = ring;
  const anchors: number[] = [];
  for (let i = 0; i < n; i++) {
    if (pinned[i] && (!pinned[i === 0 ? n - 1 : i - 1] || !pinned[i + 1 === n ? 0 : i + 1])) anchors.push(i);
  }
  if (anchors.length > 0) return anchors;
  let far = 0, farDistance = -1;
  for (let i = 1; i < n; i++) {
    const distance = (xs[i] - xs[0]) ** 2 + (ys[i] - ys[0]) ** 2;
    if (distance > farDistance) {
      far = i;
      farDistance = distance;
    }
  }
  return [0, far];
}

/**
 * Douglas–Peucker on a closed ring: each chain between consecutive anchors (the whole ring from a
 * single anchor back to itself) keeps its farthest point from the segment joining its ends while
 * that is farther than `tolerance`, and recurses on both halves. Distances are to the segment, so
 * a chain that doubles back past its ends keeps the point where it turns. Returns the kept points
 * in ring order, flat.
 */
function douglasPeucker(ring: Ring, anchors: readonly number[], tolerance: number): Float64Array {
  const { xs, ys, n } = ring;
  const keep = new Uint8Array(n);
  const limit = tolerance * tolerance;
  const stack: number[] = [];
  for (let k = 0; k < anchors.length; k++) {
    const a = anchors[k], b = anchors[(k + 1) % anchors.length];
    keep[a] = 1;
    // Offsets along the ring from a: the chain is a … a + span.
    stack.push(a, b > a ? b - a : b - a + n);
    while (stack.length > 0) {
      const span = stack.pop()!, from = stack.pop()!;
      if (span < 2) continue;
      const to = (from + span) % n;
      const ax = xs[from], ay = ys[from], bx = xs[to], by = ys[to];
      const ex = bx - ax, ey = by - ay, length2 = ex * ex + ey * ey;
      let worst = -1, worstDistance = -1;
      for (let s = 1; s < span; s++) {
        const i = (from + s) % n;
        let dx = xs[i] - ax, dy = ys[i] - ay;
        if (length2 > 0) {
          const along = Math.min(1, Math.max(0, (dx * ex + dy * ey) / length2));
          dx -= along * ex;
          dy -= along * ey;
        }
        const distance = dx * dx + dy * dy;
        if (distance > worstDistance) {
          worst = s;
          worstDistance = distance;
        }
      }
      if (worstDistance > limit) {
        keep[(from + worst) % n] = 1;
        stack.push(from, worst, (from + worst) % n, span - worst);
      }
    }
  }
  return keptPoints(ring, keep);
}

function keptPoints(ring: Ring, keep: Uint8Array): Float64Array {
  let count = 0;
  for (let i = 0; i < ring.n; i++) count += keep[i];
  const out = new Float64Array(2 * count);
  for (let i = 0, k = 0; i < ring.n; i++) {
    if (!keep[i]) continue;
    out[k++] = ring.xs[i];
    out[k++] = ring.ys[i];
  }
  return out;
}

/** The ring without the points collinear with their neighbours (what tolerance 0 gives). */
function collinearFree(ring: Ring): Float64Array {
  const { xs, ys, n } = ring;
  const keep = new Uint8Array(n);
  for (let i = 0; i < n; i++) {
    const p = i === 0 ? n - 1 : i - 1, q = i + 1 === n ? 0 : i + 1;
    keep[i] = (xs[i] - xs[p]) * (ys[q] - ys[i]) - (ys[i] - ys[p]) * (xs[q] - xs[i]) !== 0 ? 1 : 0;
  }
  return keptPoints(ring, keep);
}

/**
 * The last resort of {@link simplifyOutline}: the convex hull of the ring (Andrew's monotone
 * chain), then, while over `maxPoints`, without the point whose removal loses the least area
 * (Visvalingam). Removing a point of a convex polygon leaves it convex, so the result stays simple.
 */
function convexWithin(ring: Ring, maxPoints: number): Float64Array {
  const order = Array.from({ length: ring.n }, (_, i) => i).sort((a, b) => ring.xs[a] - ring.xs[b] || ring.ys[a] - ring.ys[b]);
  const hull: number[] = [];
  const cross = (o: number, a: number, b: number) =>
    (ring.xs[a] - ring.xs[o]) * (ring.ys[b] - ring.ys[o]) - (ring.ys[a] - ring.ys[o]) * (ring.xs[b] - ring.xs[o]);
  for (const pass of [order, order.slice().reverse()]) {
    const start = hull.length;
    for (const i of pass) {
      while (hull.length >= start + 2 && cross(hull[hull.length - 2], hull[hull.length - 1], i) <= 0) hull.pop();
      hull.push(i);
    }
    hull.pop();
  }
  while (hull.length > Math.max(3, maxPoints)) {
    let smallest = 0, smallestArea = Infinity;
    for (let k = 0; k < hull.length; k++) {
      const area = Math.abs(cross(hull[(k + hull.length - 1) % hull.length], hull[k], hull[(k + 1) % hull.length]));
      if (area < smallestArea) {
        smallest = k;
        smallestArea = area;
      }
    }
    hull.splice(smallest, 1);
  }
  const out = new Float64Array(2 * hull.length);
  hull.forEach((i, k) => {
    out[2 * k] = ring.xs[i];
    out[2 * k + 1] = ring.ys[i];
  });
  // Andrew's chain is counter-clockwise in a y-up frame: positive signed area, as the outlines.
  return signedArea2(out) < 0 ? reversed(out) : out;
}

function reversed(coords: Float64Array): Float64Array {
  const n = coords.length >> 1, out = new Float64Array(coords.length);
  for (let i = 0; i < n; i++) {
    out[2 * i] = coords[2 * (n - 1 - i)];
    out[2 * i + 1] = coords[2 * (n - 1 - i) + 1];
  }
  return out;
}
