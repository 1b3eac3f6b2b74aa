/**
 * Outlines of the solid pixels of an image, as simple polygons: pure, no DOM, no GL.
 *
 * Pixel `(x, y)` covers `[x, x + 1] × [y, y + 1]`, y down. The solid pixels are split (by
 * {@link holeFreeRegions}) into 4-connected regions without holes; each region's outline is the
 * marching-squares contour of that region's own mask at level ½ (the polygon through the midpoints
 * of the pixel edges that separate it from the rest, diagonal saddles separated), then simplified
 * by Douglas–Peucker ({@link RingSimplifier}, O(n log n) in the outline's length). Every returned
 * polygon has positive signed area (the library's counter-clockwise) and is simple.
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
import { RingSimplifier, type Ring } from './simplifyRing';

/** How {@link alphaOutlines} and {@link regionOutlines} simplify and filter. */
interface OutlineOptions {
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
function alphaGrid(data: ArrayLike<number>, width: number, height: number, threshold: number): CellGrid {
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
function regionOutlines(labels: Int32Array, count: number, width: number, height: number, options: OutlineOptions): Float64Array[] {
  const { starts, kept } = scanRegions(labels, count, width, height, options.minArea);
  const outlines: Float64Array[] = [];
  const tracer = new Tracer(labels, width, height), simplifier = new RingSimplifier();
  for (let region = 0; region < count; region++) {
    if (!kept[region] || starts[region] < 0) continue;
    const ring = tracer.trace(region, starts[region]);
    outlines.push(simplifier.simplify(ring, options.tolerance, options.maxPoints));
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

  constructor(private readonly labels: Int32Array, private readonly width: number, private readonly height: number) {}

  /**
   * The outline of `region` through the midpoints of its cracks, in order, less the midpoints that
   * lie on the segment between their neighbours' (a crack's does when the cracks before and after
   * it run the same way: along straight edges and even staircases), which no tolerance keeps. A
   * crack is pinned when the pixel across it is solid (another region's, across a cut); the ends
   * of each run of pinned cracks are always kept, and listed.
   *
   * The ring's coordinates are the tracer's buffers, valid until the next trace.
   *
   * Traces `region` from its first pixel in row order, `start` (= y · width + x): nothing of the
   * region lies above or left of it, so its top edge, walked in +x, is on the outline (its
   * midpoint, point 0, is always kept), and its top-left corner is on no other part of it (the
   * walk ends on returning there in +x). The pixel across the next crack is one the walk has just
   * looked at: R after a right turn, L going straight, the pixel across the last crack after a
   * left turn; so two lookups a step at most.
   */
  trace(region: number, start: number): Ring {
    const labels = this.labels, width = this.width, height = this.height;
    const label = (x: number, y: number) => (x >= 0 && y >= 0 && x < width && y < height ? labels[y * width + x] : -1);
    const px = start % width, py = (start - px) / width, pinnedEnds: number[] = [];
    let x = px, y = py, d = 0, n = 0, k = 0;
    let pinned = label(px + LEFT_X[0], py + LEFT_Y[0]) >= 0;
    // Cracks k − 1 and k − 2 (the last two seen), and whether cracks 0 and 1 are pinned.
    let lastD = 0, lastPinned = false, beforeD = 0, beforePinned = false, pinned0 = false, pinned1 = false;
    do {
      // Crack k, from (x, y) in direction d: the region's pixel on its right, another pixel on its left.
      // Crack k − 1 is settled once crack k is known; crack 0 is always kept.
      if (k >= 2) n = settle(n, beforeD, beforePinned, lastPinned, d, pinned, pinnedEnds);
      else if (k === 1) pinned1 = pinned;
      else pinned0 = pinned;
      if (n === this.xs.length) this.grow();
      this.xs[n] = x + DX[d] / 2;
      this.ys[n] = y + DY[d] / 2;
      n++;
      k++;
      beforeD = lastD;
      beforePinned = lastPinned;
      lastD = d;
      lastPinned = pinned;
      x += DX[d];
      y += DY[d];
      const right = label(x + RIGHT_X[d], y + RIGHT_Y[d]);
      if (right !== region) {
        d = (d + 1) & 3;
        pinned = right >= 0;
      } else {
        const left = label(x + LEFT_X[d], y + LEFT_Y[d]);
        if (left === region) d = (d + 3) & 3;
        else pinned = left >= 0;
      }
    } while (x !== px || y !== py || d !== 0);
    // The last crack lies between the one before it and crack 0 (direction 0); crack 0 between the last and crack 1.
    n = settle(n, beforeD, beforePinned, lastPinned, 0, pinned0, pinnedEnds);
    if (pinned0 && (!lastPinned || !pinned1)) pinnedEnds.unshift(0);
    return { xs: this.xs, ys: this.ys, n, pinnedEnds };
  }

  private grow(): void {
    const xs = new Float64Array(this.xs.length * 2), ys = new Float64Array(this.xs.length * 2);
    xs.set(this.xs);
    ys.set(this.ys);
    this.xs = xs;
    this.ys = ys;
  }
}

/**
 * Settles the crack in slot `n − 1`, between cracks running `beforeD` and `nextD`: kept and listed
 * in `pinnedEnds` where it ends a run of pinned cracks, dropped where its midpoint lies on the
 * segment between its neighbours' (they run the same way). Returns the new count.
 */
function settle(n: number, beforeD: number, beforePinned: boolean, pinned: boolean, nextD: number, nextPinned: boolean, pinnedEnds: number[]): number {
  if (pinned && (!beforePinned || !nextPinned)) {
    pinnedEnds.push(n - 1);
    return n;
  }
  return beforeD === nextD ? n - 1 : n;
}
