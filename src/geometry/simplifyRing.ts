/**
 * Simplification of a traced outline (a ring of points, some pinned) to a simple polygon within a
 * tolerance and a point cap: Douglas–Peucker, in O(n log n) on any outline ({@link RingSimplifier}).
 * Pure.
 *
 * Douglas–Peucker splits a chain at the point that strays farthest from the chord joining its
 * ends; which point that is does not depend on the tolerance, only where the recursion stops
 * does. So the splits form one tree per ring, shared by every tolerance tried (backing off from a
 * self-crossing, growing to meet the cap): a chain's split point and error are found once, when a
 * tolerance first needs them, by O(log² n) queries on the convex hulls of the ring's index ranges
 * ({@link RangeHulls}) rather than by a scan of the chain (a scan makes comb-like outlines
 * quadratic: each split peels off one tooth). A tolerance then costs a walk over the part of the
 * tree it keeps, and at most one simplicity test.
 */
import { isSimplePolygon, signedArea2 } from './polygon';
import { RangeHulls } from './rangeHulls';

/** A traced outline: its points in order, and those that every simplification keeps. */
export interface Ring {
  /** Point i is `(xs[i], ys[i])` for i < n; the arrays may be longer. */
  readonly xs: Float64Array;
  readonly ys: Float64Array;
  readonly n: number;
  /**
   * Indices of the points kept at any tolerance, ascending: the ends of the straight runs along
   * which the outline meets another (pinned), so that the two still meet along the whole run.
   */
  readonly pinnedEnds: readonly number[];
}

/** Tolerances below this are treated as 0 (only collinear points go) when backing off from a self-crossing. */
const SMALLEST_TOLERANCE = 1 / 32;
/** Factor by which the tolerance grows while an outline has more than `maxPoints` points. */
const TOLERANCE_GROWTH = 1.5;
/** Growth steps before giving up (1.5^80 ≈ 10^14 pixels: past any image, the chords leave only the anchors). */
const MAX_GROWTH_STEPS = 80;

/**
 * Simplifies rings; one instance serves any number of rings in turn, reusing its buffers (an
 * image's outlines can be thousands of specks).
 */
export class RingSimplifier {
  private readonly splits = new SplitTree();

  /**
   * Simplifies `ring` to within `tolerance` of it, backing off (halving, down to 0) where that
   * makes it cross itself, then, while it has more than `maxPoints` points, growing the tolerance
   * until a simple outline fits. Tolerance 0 removes only points on the segment between their
   * kept neighbours, which leaves a simple ring simple. If no tolerance yields a simple outline
   * within the cap: with no pinned point, the convex hull cut down to the cap (the cap wins over
   * fidelity); with pinned points, the simple outline with the fewest points found (the pins win
   * over the cap: no gap along a cut). Returns flat `[x0, y0, …]` in ring order.
   */
  simplify(ring: Ring, tolerance: number, maxPoints: number): Float64Array {
    const splits = this.splits;
    splits.reset(ring, anchorPoints(ring));
    let best: Float64Array | null = null;
    for (let t = tolerance; ; t = t / 2 < SMALLEST_TOLERANCE ? 0 : t / 2) {
      const candidate = splits.pointsWithin(t);
      if (isSimplePolygon(candidate)) {
        best = candidate;
        break;
      }
      if (t === 0) break;
    }
    // Unreachable for a simple ring (see above); a safe answer all the same.
    if (best === null) best = splits.pointsWithin(0);
    if (best.length >> 1 <= maxPoints) return best;

    const pinned = ring.pinnedEnds.length > 0;
    let fewest = best;
    let t = Math.max(tolerance, SMALLEST_TOLERANCE);
    for (let step = 0; step < MAX_GROWTH_STEPS; step++) {
      t *= TOLERANCE_GROWTH;
      const candidate = splits.pointsWithin(t), count = candidate.length >> 1;
      // One simplicity test a step, and only for an outline that could be the answer.
      if ((count <= maxPoints || (pinned && candidate.length < fewest.length)) && isSimplePolygon(candidate)) {
        if (count <= maxPoints) return candidate;
        fewest = candidate;
      }
      // Only the anchors left: a larger tolerance cannot remove more.
      if (count <= splits.anchorCount) break;
    }
    return pinned ? fewest : convexWithin(ring, splits.hulls.hull(), maxPoints);
  }
}

/**
 * The ring's points that simplification must keep, in ring order: the ends of its pinned runs.
 * With none, point 0 and the point farthest from it; with a single one, it and the point farthest
 * from it: both are extreme points of the outline, so the split into two chains follows its
 * shape, and no chord has zero length.
 */
function anchorPoints(ring: Ring): readonly number[] {
  const { xs, ys, n, pinnedEnds } = ring;
  if (pinnedEnds.length > 1) return pinnedEnds;
  const from = pinnedEnds.length === 1 ? pinnedEnds[0] : 0;
  let far = from, farDistance = -1;
  for (let i = 0; i < n; i++) {
    const distance = (xs[i] - xs[from]) ** 2 + (ys[i] - ys[from]) ** 2;
    if (distance > farDistance) {
      far = i;
      farDistance = distance;
    }
  }
  return far < from ? [far, from] : [from, far];
}

/**
 * Douglas–Peucker's splits of a ring: a binary tree per chain between consecutive anchors (the
 * last one wraps round to the first), grown on demand. Node k is the chain from point `start[k]`
 * over `span[k]` steps along the ring; its error is how far its inner points may stray from its
 * chord, and where it splits, the point that strays farthest.
 *
 * The error is an upper bound on the distance of the inner points from the chord as a segment:
 * with the chord a→b of length L, a point off its line by at most `side` and past its ends
 * (behind a or beyond b) by at most `past`, is within √(side² + past²) of the segment. Points
 * past the ends matter: a chain that doubles back beyond its chord keeps the point where it turns.
 * The node splits at the point farthest from the line when `side ≥ past`, else at the point
 * farthest past an end. With half-integer coordinates every term is exact, so an error is 0
 * exactly when the inner points lie on the segment.
 */
class SplitTree {
  hulls = new RangeHulls(new Float64Array(0), new Float64Array(0), 0);
  anchorCount = 0;
  private ring: Ring = { xs: new Float64Array(0), ys: new Float64Array(0), n: 0, pinnedEnds: [] };
  private start: Int32Array = new Int32Array(64);
  private span: Int32Array = new Int32Array(64);
  private split: Int32Array = new Int32Array(64);
  private error2 = new Float64Array(64);
  /** Children, −1 until first needed. */
  private below: Int32Array = new Int32Array(128);
  private nodes = 0;
  /** Scratch: indices kept by {@link pointsWithin}, and the walk's stack of nodes. */
  private kept: Int32Array = new Int32Array(64);
  private stack: Int32Array = new Int32Array(64);

  /** Starts over on `ring`, with a root for each chain between consecutive `anchors` (ascending). */
  reset(ring: Ring, anchors: readonly number[]): void {
    this.ring = ring;
    this.hulls = new RangeHulls(ring.xs, ring.ys, ring.n);
    this.nodes = 0;
    this.anchorCount = anchors.length;
    for (let k = 0; k < anchors.length; k++) {
      const a = anchors[k], b = anchors[(k + 1) % anchors.length];
      this.addNode(a, b > a ? b - a : b - a + ring.n);
    }
  }

  /** The points Douglas–Peucker keeps at `tolerance`, in ring order (from the lowest index), flat. */
  pointsWithin(tolerance: number): Float64Array {
    const limit = tolerance * tolerance;
    let count = 0, top = 0;
    for (let root = 0; root < this.anchorCount; root++) {
      this.keep(count++, this.start[root]);
      this.push(top++, root);
      while (top > 0) {
        const node = this.stack[--top];
        if (this.error2[node] <= limit) continue;
        this.keep(count++, this.split[node]);
        this.push(top++, this.child(node, 0));
        this.push(top++, this.child(node, 1));
      }
    }
    const kept = this.kept.subarray(0, count).sort(), { xs, ys } = this.ring;
    const out = new Float64Array(2 * count);
    for (let k = 0; k < count; k++) {
      out[2 * k] = xs[kept[k]];
      out[2 * k + 1] = ys[kept[k]];
    }
    return out;
  }

  /** Child `side` (0: from the start to the split, 1: from the split on) of a node that splits, made on first use. */
  private child(node: number, side: number): number {
    let child = this.below[2 * node + side];
    if (child < 0) {
      const n = this.ring.n, offset = (this.split[node] - this.start[node] + n) % n;
      child = side === 0 ? this.addNode(this.start[node], offset) : this.addNode(this.split[node], this.span[node] - offset);
      this.below[2 * node + side] = child;
    }
    return child;
  }

  /** Adds the chain from point `from` over `span` steps, with its error and split point. */
  private addNode(from: number, span: number): number {
    const node = this.nodes++;
    if (node === this.start.length) this.grow();
    this.start[node] = from;
    this.span[node] = span;
    this.below[2 * node] = this.below[2 * node + 1] = -1;
    this.error2[node] = 0;
    this.split[node] = -1;
    if (span < 2) return node;
    const { xs, ys, n } = this.ring, hulls = this.hulls, to = (from + span) % n;
    const ax = xs[from], ay = ys[from], ex = xs[to] - ax, ey = ys[to] - ay, first = from + 1 === n ? 0 : from + 1;
    // The inner points farthest off the line on either side ((p − a) × e) and along it ((p − a) · e), each scaled by L.
    const left = hulls.farthest(first, span - 1, ey, -ex), right = hulls.farthest(first, span - 1, -ey, ex);
    const ahead = hulls.farthest(first, span - 1, ex, ey), behind = hulls.farthest(first, span - 1, -ex, -ey);
    const leftSide = (xs[left] - ax) * ey - (ys[left] - ay) * ex, rightSide = (ys[right] - ay) * ex - (xs[right] - ax) * ey;
    const length2 = ex * ex + ey * ey;
    const beyond = (xs[ahead] - ax) * ex + (ys[ahead] - ay) * ey - length2, before = -((xs[behind] - ax) * ex + (ys[behind] - ay) * ey);
    const side = Math.max(leftSide, rightSide), past = Math.max(beyond, before, 0);
    this.error2[node] = (side * side + past * past) / length2;
    this.split[node] = side >= past ? (leftSide >= rightSide ? left : right) : beyond >= before ? ahead : behind;
    return node;
  }

  private keep(at: number, index: number): void {
    if (at === this.kept.length) this.kept = grown(this.kept);
    this.kept[at] = index;
  }

  private push(at: number, node: number): void {
    if (at === this.stack.length) this.stack = grown(this.stack);
    this.stack[at] = node;
  }

  private grow(): void {
    this.start = grown(this.start);
    this.span = grown(this.span);
    this.split = grown(this.split);
    this.below = grown(this.below);
    const error2 = new Float64Array(2 * this.error2.length);
    error2.set(this.error2);
    this.error2 = error2;
  }
}

function grown(array: Int32Array): Int32Array {
  const out = new Int32Array(2 * array.length);
  out.set(array);
  return out;
}

/**
 * The last resort of {@link RingSimplifier.simplify}: the ring's convex hull (point indices,
 * counter-clockwise in a y-up frame), then, while over `maxPoints`, without the point whose
 * removal loses the least area (Visvalingam). Removing a point of a convex polygon leaves it
 * convex, so the result stays simple. Quadratic in the hull's size, which for an outline of
 * pixels in a W × H image is O((W·H)^⅓).
 */
function convexWithin(ring: Ring, hull: number[], maxPoints: number): Float64Array {
  const { xs, ys } = ring;
  const cross = (o: number, a: number, b: number) => (xs[a] - xs[o]) * (ys[b] - ys[o]) - (ys[a] - ys[o]) * (xs[b] - xs[o]);
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
    out[2 * k] = xs[i];
    out[2 * k + 1] = ys[i];
  });
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
