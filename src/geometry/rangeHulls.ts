/**
 * Convex hulls of the index ranges of a closed sequence of points, for the question a
 * simplification asks of a stretch of an outline: which of its points lies farthest along a
 * direction. Pure.
 *
 * The points are grouped in blocks of {@link LEAF_SIZE} consecutive indices, and the blocks in a
 * binary hierarchy (block b of level l + 1 holds blocks 2b and 2b + 1 of level l); each block keeps
 * its convex hull as two chains sorted by x, merged from its halves' in time linear in their
 * size. A range is covered by O(log n) blocks plus at most 2 · LEAF_SIZE loose points, and a
 * block answers by binary search on one chain: O(log² n) a query. Building is O(n log n) (in
 * practice O(n): a block's hull is small beside its points).
 *
 * Hull decisions use plain floating-point cross products: exact for the coordinates it serves
 * (multiples of ½ below 2^20, pixel outlines); a rounded decision elsewhere could only make a
 * query return a point slightly short of the farthest.
 */

/** Points per block at the lowest level; ranges this short or shorter are scanned point by point. */
const LEAF_SIZE = 8;

/** A level of the hierarchy: each block's upper and lower chains, point indices sorted by (x, y). */
interface Level {
  readonly upper: Int32Array;
  /** Block b's upper chain is `upper[upperStart[b]]` to `upper[upperStart[b + 1] − 1]`. */
  readonly upperStart: Int32Array;
  readonly lower: Int32Array;
  readonly lowerStart: Int32Array;
}

export class RangeHulls {
  /** Built on the first query that needs a block (never for a sequence of a few points). */
  private levels: Level[] | null = null;

  /** Points `(xs[i], ys[i])` for i in 0 … n − 1, read (not copied) on every query. */
  constructor(private readonly xs: ArrayLike<number>, private readonly ys: ArrayLike<number>, private readonly n: number) {}

  private built(): Level[] {
    if (this.levels !== null) return this.levels;
    let level = this.leafLevel();
    const levels = [level];
    while (level.upperStart.length > 2) {
      level = this.mergedLevel(level);
      levels.push(level);
    }
    return (this.levels = levels);
  }

  /**
   * The index, among the `count` indices from `from` on (wrapping past n − 1 to 0), of a point
   * with the largest x · dx + y · dy.
   */
  farthest(from: number, count: number, dx: number, dy: number): number {
    const n = this.n;
    if (from + count <= n) return this.farthestIn(from, from + count, dx, dy, -1);
    const best = this.farthestIn(from, n, dx, dy, -1);
    return this.farthestIn(0, from + count - n, dx, dy, best);
  }

  /**
   * The whole sequence's convex hull as point indices, counter-clockwise in a y-up frame (the
   * lower chain left to right, then the upper chain back), without collinear points.
   */
  hull(): number[] {
    const levels = this.built(), top = levels[levels.length - 1];
    const lower = Array.from(top.lower.subarray(top.lowerStart[0], top.lowerStart[1]));
    const upper = Array.from(top.upper.subarray(top.upperStart[0], top.upperStart[1]));
    return [...lower.slice(0, -1), ...upper.reverse().slice(0, -1)];
  }

  /** `best`, or the index in [lo, hi) that beats it along (dx, dy). */
  private farthestIn(lo: number, hi: number, dx: number, dy: number, best: number): number {
    if (hi - lo <= 2 * LEAF_SIZE) {
      for (let i = lo; i < hi; i++) best = this.better(best, i, dx, dy);
      return best;
    }
    while (lo % LEAF_SIZE !== 0) best = this.better(best, lo++, dx, dy);
    while (hi % LEAF_SIZE !== 0) best = this.better(best, --hi, dx, dy);
    // The whole blocks, bottom up: at each level, an odd block at either end is taken whole.
    let first = lo / LEAF_SIZE, end = hi / LEAF_SIZE;
    for (let l = 0; first < end; l++) {
      if (first & 1) best = this.better(best, this.farthestInBlock(l, first++, dx, dy), dx, dy);
      if (end & 1) best = this.better(best, this.farthestInBlock(l, --end, dx, dy), dx, dy);
      first >>= 1;
      end >>= 1;
    }
    return best;
  }

  private better(best: number, i: number, dx: number, dy: number): number {
    return best < 0 || this.xs[i] * dx + this.ys[i] * dy > this.xs[best] * dx + this.ys[best] * dy ? i : best;
  }

  /**
   * Binary search along the chain facing (dx, dy) (the upper one when dy ≥ 0): a convex chain's
   * edges turn one way, so their projections on the direction change sign once, from positive to
   * not; the farthest point is where the first edge that does not advance starts.
   */
  private farthestInBlock(l: number, block: number, dx: number, dy: number): number {
    const level = this.built()[l];
    const chain = dy >= 0 ? level.upper : level.lower, starts = dy >= 0 ? level.upperStart : level.lowerStart;
    let a = starts[block], b = starts[block + 1] - 1;
    while (a < b) {
      const m = (a + b) >> 1, p = chain[m], q = chain[m + 1];
      if ((this.xs[q] - this.xs[p]) * dx + (this.ys[q] - this.ys[p]) * dy <= 0) b = m;
      else a = m + 1;
    }
    return chain[a];
  }

  /** Each block of LEAF_SIZE points: sorted by (x, y), then its two chains by Andrew's monotone chain. */
  private leafLevel(): Level {
    const n = this.n, blocks = Math.ceil(n / LEAF_SIZE);
    const upper = new Int32Array(n), lower = new Int32Array(n);
    const upperStart = new Int32Array(blocks + 1), lowerStart = new Int32Array(blocks + 1);
    const sorted = new Int32Array(LEAF_SIZE);
    let upperEnd = 0, lowerEnd = 0;
    for (let block = 0; block < blocks; block++) {
      const from = block * LEAF_SIZE, count = Math.min(LEAF_SIZE, n - from);
      for (let k = 0; k < count; k++) {
        // Insertion sort: a block is short.
        let at = k;
        while (at > 0 && this.before(from + k, sorted[at - 1])) sorted[at] = sorted[--at];
        sorted[at] = from + k;
      }
      upperEnd = this.chain(sorted, 0, count, upper, upperEnd, -1);
      lowerEnd = this.chain(sorted, 0, count, lower, lowerEnd, 1);
      upperStart[block + 1] = upperEnd;
      lowerStart[block + 1] = lowerEnd;
    }
    return { upper: upper.slice(0, upperEnd), upperStart, lower: lower.slice(0, lowerEnd), lowerStart };
  }

  /** The next level: each block's chains from its halves' chains, merged by (x, y) and chained again. */
  private mergedLevel(below: Level): Level {
    const blocks = Math.ceil((below.upperStart.length - 1) / 2);
    const upperStart = new Int32Array(blocks + 1), lowerStart = new Int32Array(blocks + 1);
    const upper = new Int32Array(below.upper.length), lower = new Int32Array(below.lower.length);
    const merged = new Int32Array(Math.max(below.upper.length, below.lower.length));
    let upperEnd = 0, lowerEnd = 0;
    for (let block = 0; block < blocks; block++) {
      const count = this.mergeChains(below.upper, below.upperStart, block, merged);
      upperEnd = this.chain(merged, 0, count, upper, upperEnd, -1);
      upperStart[block + 1] = upperEnd;
      const lowerCount = this.mergeChains(below.lower, below.lowerStart, block, merged);
      lowerEnd = this.chain(merged, 0, lowerCount, lower, lowerEnd, 1);
      lowerStart[block + 1] = lowerEnd;
    }
    return { upper: upper.slice(0, upperEnd), upperStart, lower: lower.slice(0, lowerEnd), lowerStart };
  }

  /** Merges the chains of blocks 2·block and 2·block + 1 (if any) of `chains` into `out` by (x, y); returns the count. */
  private mergeChains(chains: Int32Array, starts: Int32Array, block: number, out: Int32Array): number {
    const halves = starts.length - 1;
    const paired = 2 * block + 1 < halves, iEnd = starts[2 * block + 1], jEnd = paired ? starts[2 * block + 2] : 0;
    let i = starts[2 * block], j = paired ? starts[2 * block + 1] : 0;
    let count = 0;
    while (i < iEnd && j < jEnd) out[count++] = this.before(chains[j], chains[i]) ? chains[j++] : chains[i++];
    while (i < iEnd) out[count++] = chains[i++];
    while (j < jEnd) out[count++] = chains[j++];
    return count;
  }

  /**
   * Andrew's monotone chain over `sorted[from … to − 1]` (sorted by (x, y)), appended to `out` at
   * `end`; `turn` −1 keeps the upper chain (turning clockwise in a y-up frame), 1 the lower.
   * Collinear points are dropped. Returns the new end.
   */
  private chain(sorted: Int32Array, from: number, to: number, out: Int32Array, end: number, turn: number): number {
    const start = end, xs = this.xs, ys = this.ys;
    for (let k = from; k < to; k++) {
      const p = sorted[k];
      while (end - start >= 2) {
        const o = out[end - 2], a = out[end - 1];
        const cross = (xs[a] - xs[o]) * (ys[p] - ys[o]) - (ys[a] - ys[o]) * (xs[p] - xs[o]);
        if (cross * turn > 0) break;
        end--;
      }
      out[end++] = p;
    }
    return end;
  }

  /** Whether point i comes before point j by x, then y. */
  private before(i: number, j: number): boolean {
    return this.xs[i] < this.xs[j] || (this.xs[i] === this.xs[j] && this.ys[i] < this.ys[j]);
  }
}
