/**
 * Pure polygon helpers on flat coordinate arrays `[x0, y0, x1, y1, …]`.
 * Positive signed area means counter-clockwise in a y-up frame; the library stores every
 * hull with positive area so that each edge's outward normal is `(dy, -dx)`.
 *
 * Every decision on which side of a line a point lies (crossings, folds, collinear points,
 * convexity, ears, inside tests) goes through the exact {@link orient2d}: rounding cannot make
 * nearly collinear edges cross, nor a simple polygon look self-intersecting, at any placement.
 */
import { orient2d, orientationSign } from './orient2d';

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
 * changes the shape), returning a new flat array. Linear time: a point is dropped as soon as the
 * next one shows it removable, and whatever that exposes is checked at once, so every point is
 * pushed and popped at most once.
 */
export function simplifyPolygon(coords: ArrayLike<number>): number[] {
  return closeSeam(simplifyPolyline(coords));
}

/**
 * The points of an open polyline `[x0, y0, …]` without repeated points and without points that
 * lie on the segment between their neighbours (where the line goes on in the same direction; a
 * point where it turns back is kept). The ends are always kept.
 */
export function simplifyPolyline(coords: ArrayLike<number>): number[] {
  const out: number[] = [];
  for (let i = 0; i + 1 < coords.length; i += 2) {
    const x = coords[i], y = coords[i + 1];
    while (out.length >= 4 && isRemovable(out, out.length - 4, out.length - 2, x, y)) out.length -= 2;
    if (out.length < 2 || out[out.length - 2] !== x || out[out.length - 1] !== y) out.push(x, y);
  }
  return out;
}

/**
 * Finishes {@link simplifyPolygon} where the outline wraps around: only the points next to the
 * seam can have become removable, so it drops the last or the first point until neither is.
 */
function closeSeam(out: number[]): number[] {
  let first = 0;
  while (out.length - first >= 6) {
    const last = out.length - 2;
    if (isRemovable(out, last - 2, last, out[first], out[first + 1])) out.length -= 2;
    else if (isRemovable(out, last, first, out[first + 2], out[first + 3])) first += 2;
    else break;
  }
  return first === 0 ? out : out.slice(first);
}

/**
 * Whether the point at offset `i` of `c` can go between the point at offset `p` and `(qx, qy)`:
 * it repeats `p`, or lies on the segment between them.
 */
function isRemovable(c: number[], p: number, i: number, qx: number, qy: number): boolean {
  const px = c[p], py = c[p + 1], ix = c[i], iy = c[i + 1];
  if (ix === px && iy === py) return true;
  return orient2d(px, py, ix, iy, qx, qy) === 0 && onSegment(px, py, qx, qy, ix, iy);
}

/** Whether (px, py), on the line through a and b, lies between them (a box test: exact). */
function onSegment(ax: number, ay: number, bx: number, by: number, px: number, py: number): boolean {
  return Math.min(ax, bx) <= px && px <= Math.max(ax, bx) && Math.min(ay, by) <= py && py <= Math.max(ay, by);
}

/** True when the closed segments a–b and c–d share at least one point. */
export function segmentsIntersect(
  ax: number, ay: number, bx: number, by: number,
  cx: number, cy: number, dx: number, dy: number,
): boolean {
  const o1 = orientationSign(ax, ay, bx, by, cx, cy);
  const o2 = orientationSign(ax, ay, bx, by, dx, dy);
  const o3 = orientationSign(cx, cy, dx, dy, ax, ay);
  const o4 = orientationSign(cx, cy, dx, dy, bx, by);
  if (o1 !== o2 && o3 !== o4) return true;
  return (o1 === 0 && onSegment(ax, ay, bx, by, cx, cy))
    || (o2 === 0 && onSegment(ax, ay, bx, by, dx, dy))
    || (o3 === 0 && onSegment(cx, cy, dx, dy, ax, ay))
    || (o4 === 0 && onSegment(cx, cy, dx, dy, bx, by));
}

/**
 * True for a simple polygon: at least 3 points, non-zero area, and no two edges meeting
 * anywhere but at their shared end point (so also no outline folding back along itself).
 * Exact for any doubles (see `orient2d`). Zero area needs no test of its own (a rounded
 * area could call a thin polygon far from the origin degenerate): points all on one line always
 * fold back at the outermost one.
 * O(n log n): after linear checks of the points, a sweep line (Shamos–Hoey) tests only edges
 * that become neighbours in the order the sweep meets them. Outlines of up to 8 points
 * (`PAIRWISE_MAX_POINTS`) test every pair instead, without sorting or allocating.
 */
export function isSimplePolygon(coords: ArrayLike<number>): boolean {
  const n = coords.length >> 1;
  if (n < 3 || foldsBack(coords, n)) return false;
  if (n <= PAIRWISE_MAX_POINTS) return !pairMeets(coords, n);
  const order = sortedPoints(coords, n);
  return !hasRepeatedPoint(coords, order) && !sweepFindsCrossing(coords, n, order);
}

/**
 * Up to this many points (a tile, a box, most sprite and level hulls), testing all n(n − 3)/2
 * pairs of edges that are not neighbours is cheaper than sorting for the sweep: a tile map's
 * thousands of small hulls are checked in a third of the time.
 */
const PAIRWISE_MAX_POINTS = 8;

/** Whether two points coincide or two edges that are not neighbours share a point. */
function pairMeets(coords: ArrayLike<number>, n: number): boolean {
  for (let i = 0; i < n; i++) {
    for (let j = i + 1; j < n; j++) {
      if (coords[2 * i] === coords[2 * j] && coords[2 * i + 1] === coords[2 * j + 1]) return true;
      if (j === i + 1 || (i === 0 && j === n - 1)) continue;
      const a = 2 * i, b = 2 * ((i + 1) % n), c = 2 * j, d = 2 * ((j + 1) % n);
      if (segmentsIntersect(coords[a], coords[a + 1], coords[b], coords[b + 1], coords[c], coords[c + 1], coords[d], coords[d + 1])) return true;
    }
  }
  return false;
}

/** Point indices in sweep order: by x, then y. */
function sortedPoints(coords: ArrayLike<number>, n: number): Int32Array {
  const order = new Int32Array(n);
  for (let i = 0; i < n; i++) order[i] = i;
  return order.sort((a, b) => comparePoints(coords, a, b));
}

function comparePoints(coords: ArrayLike<number>, a: number, b: number): number {
  return coords[2 * a] - coords[2 * b] || coords[2 * a + 1] - coords[2 * b + 1];
}

/** Whether two points coincide (the outline touches itself there); `order` puts equal points side by side. */
function hasRepeatedPoint(coords: ArrayLike<number>, order: Int32Array): boolean {
  for (let k = 1; k < order.length; k++) if (comparePoints(coords, order[k - 1], order[k]) === 0) return true;
  return false;
}

/**
 * Whether the outline turns back along itself at a point: neighbouring edges can meet anywhere
 * but at their shared point only by overlapping that way, so the sweep need not test them.
 */
function foldsBack(coords: ArrayLike<number>, n: number): boolean {
  for (let i = 0; i < n; i++) {
    const p = (i + n - 1) % n, q = (i + 1) % n;
    if (orientationOf(coords, p, i, q) !== 0) continue;
    // Collinear: the neighbours lie on one side of point i when each coordinate's difference has
    // one sign (a difference of doubles has the sign of the exact one).
    const ux = coords[2 * p] - coords[2 * i], uy = coords[2 * p + 1] - coords[2 * i + 1];
    const vx = coords[2 * q] - coords[2 * i], vy = coords[2 * q + 1] - coords[2 * i + 1];
    if (ux * vx + uy * vy > 0) return true;
  }
  return false;
}

/**
 * The sweep: visits the points in `order`; at each it removes the edges that end there and
 * inserts the edges that start there into the edges the sweep line crosses, ordered from below
 * to above. Points are distinct (checked before), so the edges meeting at a point are exactly
 * its two edges. Returns at the first crossing found: until then the order is well defined.
 *
 * Where one edge ends and the other starts (most points of most outlines), the new edge takes the
 * old one's place without a search: no edge lies between them at the point unless it passes
 * through the point, and then it is their neighbour and the crossing test finds it.
 */
function sweepFindsCrossing(coords: ArrayLike<number>, n: number, order: Int32Array): boolean {
  const sweep = new SweepLine(coords, n);
  for (let k = 0; k < n; k++) {
    const point = order[k], before = (point + n - 1) % n;
    const beforeEnds = sweep.endsAt(before, point), afterEnds = sweep.endsAt(point, point);
    if (beforeEnds !== afterEnds) {
      if (beforeEnds ? sweep.replace(before, point) : sweep.replace(point, before)) return true;
    } else if (beforeEnds) {
      if (sweep.remove(before) || sweep.remove(point)) return true;
    } else if (sweep.insert(before) || sweep.insert(point)) return true;
  }
  return false;
}

function orientationOf(coords: ArrayLike<number>, a: number, b: number, c: number): number {
  return orientationSign(coords[2 * a], coords[2 * a + 1], coords[2 * b], coords[2 * b + 1], coords[2 * c], coords[2 * c + 1]);
}

/**
 * The edges (edge i runs from point i to the next) that the sweep line crosses, from below to
 * above, as a skip list over edge indices: O(log n) expected insertion by comparison, O(1) removal
 * and neighbours. Node levels come from a fixed-seed generator, so a polygon always takes the
 * same steps. Each insertion and removal tests the edges it makes neighbours.
 */
class SweepLine {
  /** The end of each edge that the sweep meets first, and the other. */
  private readonly start: Int32Array;
  private readonly end: Int32Array;
  private readonly levels: number;
  /** Links: `next[level * (n + 1) + node]`; node n is the head, before every edge; −1 past the last. */
  private readonly next: Int32Array;
  private readonly previous: Int32Array;
  private readonly nodeLevels: Uint8Array;
  private seed = 0x9e3779b9;

  constructor(private readonly coords: ArrayLike<number>, private readonly n: number) {
    this.start = new Int32Array(n);
    this.end = new Int32Array(n);
    for (let edge = 0; edge < n; edge++) {
      const next = (edge + 1) % n, forward = comparePoints(coords, edge, next) < 0;
      this.start[edge] = forward ? edge : next;
      this.end[edge] = forward ? next : edge;
    }
    // Enough levels for the expected O(log n) a search.
    this.levels = 32 - Math.clz32(n);
    this.next = new Int32Array(this.levels * (n + 1)).fill(-1);
    this.previous = new Int32Array(this.levels * (n + 1)).fill(-1);
    this.nodeLevels = new Uint8Array(n);
  }

  /** Whether edge `edge` ends (rather than starts) at point `point`. */
  endsAt(edge: number, point: number): boolean {
    return this.end[edge] === point;
  }

  /** Inserts `edge` in its place; true when it touches an edge it passes or becomes neighbour of. */
  insert(edge: number): boolean {
    const n = this.n, level = this.randomLevel();
    this.nodeLevels[edge] = level;
    let at = n;
    for (let l = this.levels - 1; l >= 0; l--) {
      for (let next = this.next[l * (n + 1) + at]; next >= 0; next = this.next[l * (n + 1) + at]) {
        const side = this.compareAtStart(edge, next);
        if (side === 0) return true;
        if (side < 0) break;
        at = next;
      }
      if (l < level) this.link(at, edge, l);
    }
    return this.cross(this.previous[edge], edge) || this.cross(edge, this.next[edge]);
  }

  /** Removes `edge`; true when the edges that become neighbours cross. */
  remove(edge: number): boolean {
    const n = this.n;
    for (let l = 0; l < this.nodeLevels[edge]; l++) {
      const previous = this.previous[l * (n + 1) + edge], next = this.next[l * (n + 1) + edge];
      this.next[l * (n + 1) + previous] = next;
      if (next >= 0) this.previous[l * (n + 1) + next] = previous;
    }
    return this.cross(this.previous[edge], this.next[edge]);
  }

  /** Puts `edge` in the place of `old`, which ends where `edge` starts; true when it touches a new neighbour. */
  replace(old: number, edge: number): boolean {
    const n = this.n;
    this.nodeLevels[edge] = this.nodeLevels[old];
    for (let l = 0; l < this.nodeLevels[old]; l++) {
      const row = l * (n + 1), previous = this.previous[row + old], next = this.next[row + old];
      this.previous[row + edge] = previous;
      this.next[row + edge] = next;
      this.next[row + previous] = edge;
      if (next >= 0) this.previous[row + next] = edge;
    }
    return this.cross(this.previous[edge], edge) || this.cross(edge, this.next[edge]);
  }

  /**
   * Where `edge` goes, at its start, relative to `other` already crossed by the sweep line: 1
   * above, −1 below, 0 when its start lies on `other`. Two edges leaving the same point are
   * ordered by where they go.
   */
  private compareAtStart(edge: number, other: number): number {
    const start = this.start[edge], otherStart = this.start[other], otherEnd = this.end[other];
    const side = orientationOf(this.coords, otherStart, otherEnd, start);
    if (side !== 0 || otherStart !== start) return side;
    return orientationOf(this.coords, start, otherEnd, this.end[edge]);
  }

  /** Whether two edges that the sweep made neighbours (the head or −1: none) cross; edges sharing a point cannot (see `foldsBack`). */
  private cross(a: number, b: number): boolean {
    const n = this.n, co = this.coords;
    if (a < 0 || b < 0 || a === n || b === n || (a + 1) % n === b || (b + 1) % n === a) return false;
    const a2 = (a + 1) % n, b2 = (b + 1) % n;
    return segmentsIntersect(
      co[2 * a], co[2 * a + 1], co[2 * a2], co[2 * a2 + 1],
      co[2 * b], co[2 * b + 1], co[2 * b2], co[2 * b2 + 1],
    );
  }

  private link(after: number, node: number, level: number): void {
    const row = level * (this.n + 1), next = this.next[row + after];
    this.next[row + node] = next;
    this.previous[row + node] = after;
    this.next[row + after] = node;
    if (next >= 0) this.previous[row + next] = node;
  }

  /** 1 + the trailing zero bits of a xorshift32 draw (level k with probability 2^−k), at most `levels`. */
  private randomLevel(): number {
    let x = this.seed;
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    this.seed = x >>> 0;
    return Math.min(this.levels, 32 - Math.clz32(this.seed & -this.seed));
  }
}

/** Whether a simple counter-clockwise polygon is convex: it never turns clockwise. */
export function isConvexPolygon(coords: ArrayLike<number>): boolean {
  return sharpestRightTurn(coords) >= 0;
}

/** The least turn of the outline at a point, as a sign: −1 where it turns clockwise somewhere, 0 where it runs straight on, else 1. */
function sharpestRightTurn(coords: ArrayLike<number>): number {
  const count = coords.length >> 1;
  let least = 1;
  for (let i = 0; i < count && least >= 0; i++) least = Math.min(least, orientationOf(coords, (i + count - 1) % count, i, (i + 1) % count));
  return least;
}

/** The fan of triangles from point 0: a triangulation of an outline that turns strictly left everywhere. */
function fan(n: number): number[] {
  const triangles: number[] = [];
  for (let i = 1; i + 1 < n; i++) triangles.push(0, i, i + 1);
  return triangles;
}

/**
 * Even-odd test of `point` (`[x, y]`) against the polygon of `count` points starting at point
 * `first`. The point comes as an array (see Hot-path rules in docs/architecture.md).
 */
export function isInsidePolygon(coords: ArrayLike<number>, point: ArrayLike<number>, first = 0, count = (coords.length >> 1) - first): boolean {
  const x = point[0], y = point[1];
  let inside = false;
  for (let i = 0, j = count - 1; i < count; j = i++) {
    const xi = coords[2 * (first + i)], yi = coords[2 * (first + i) + 1];
    const xj = coords[2 * (first + j)], yj = coords[2 * (first + j) + 1];
    if ((yi > y) === (yj > y)) continue;
    // The point is left of where the edge crosses its row: on the edge's left going up, on its right going down.
    const side = orient2d(xj, yj, xi, yi, x, y);
    if (yi > yj ? side > 0 : side < 0) inside = !inside;
  }
  return inside;
}

/**
 * Ear-clipping triangulation of a simple counter-clockwise polygon. Returns point indices,
 * three per triangle; the triangulation survives any affine transform of the points.
 *
 * Candidates for an ear are taken from a queue: first every point in outline order; after each
 * clip, the two neighbours whose ears it changed move to the back. So each clip costs O(1) ear
 * tests, and rounds around the outline clip every other point rather than fanning out from one
 * (a fan's ever larger triangles would each overlap most of the grid). A clip can also free an
 * ear elsewhere, by making a point inside it turn left: when the queue runs dry, every point is
 * queued again; a round without a clip means the outline is not simple (or rounding hides ears).
 *
 * When any point of the outline lies in a candidate ear, one that does not turn left does (the
 * classic lemma of ear clipping), and clipping only ever makes points turn left, never the other
 * way: so only the points that do not turn left at the start are bucketed, once, in a grid; an
 * ear is tested against the cells it overlaps, and a point found turning left leaves its cell.
 */
export function triangulate(coords: ArrayLike<number>): number[] {
  const n = coords.length >> 1;
  // Every point of a strictly convex outline is an ear: its fan needs no test (a tile's box, most small hulls).
  if (sharpestRightTurn(coords) > 0) return fan(n);
  const outline = new Outline(coords, n);
  const blockers = new ReflexPoints(coords, outline);
  const candidates = new PointQueue(n);
  const triangles: number[] = [];
  let remaining = n, onOutline = 0, clippedThisRound = true;
  while (remaining > 3) {
    let ear = candidates.shift();
    if (ear < 0) {
      if (!clippedThisRound) return triangles;
      clippedThisRound = false;
      candidates.pushRing(outline.next, onOutline);
      ear = candidates.shift();
    }
    const a = outline.previous[ear], c = outline.next[ear];
    if (outline.turnsLeft(ear) && !blockers.anyInTriangle(a, ear, c)) {
      triangles.push(a, ear, c);
      outline.remove(ear);
      remaining--;
      onOutline = c;
      candidates.push(a);
      candidates.push(c);
      clippedThisRound = true;
    }
  }
  if (remaining === 3) triangles.push(outline.previous[onOutline], onOutline, outline.next[onOutline]);
  return triangles;
}

/**
 * A first-in first-out queue of point indices where pushing a queued point moves it to the back.
 * A round holds at most n points pushed by {@link PointQueue.pushRing} and two per clip after
 * them, fewer than 3n; each round starts the buffer over.
 */
class PointQueue {
  private readonly items: Int32Array;
  /** Where each point was last pushed: an item elsewhere is a moved point's old place. */
  private readonly slot: Int32Array;
  private head = 0;
  private tail = 0;

  constructor(n: number) {
    this.items = new Int32Array(3 * n);
    this.slot = new Int32Array(n).fill(-1);
  }

  /** Starts a round with every point of the ring `next` from `first` on. */
  pushRing(next: Int32Array, first: number): void {
    this.head = this.tail = 0;
    let point = first;
    do this.push(point); while ((point = next[point]) !== first);
  }

  push(point: number): void {
    this.slot[point] = this.tail;
    this.items[this.tail++] = point;
  }

  /** The front point, removed; −1 when the queue is empty. */
  shift(): number {
    while (this.head < this.tail) {
      const at = this.head++, point = this.items[at];
      if (this.slot[point] === at) return point;
    }
    return -1;
  }
}

/** The points of a polygon still to triangulate, as a doubly linked ring. */
class Outline {
  readonly next: Int32Array;
  readonly previous: Int32Array;
  private readonly removed: Uint8Array;

  constructor(private readonly coords: ArrayLike<number>, n: number) {
    this.next = new Int32Array(n);
    this.previous = new Int32Array(n);
    this.removed = new Uint8Array(n);
    for (let i = 0; i < n; i++) {
      this.next[i] = (i + 1) % n;
      this.previous[i] = (i + n - 1) % n;
    }
  }

  /** Whether point `i`, still on the outline, turns strictly left (is convex) between its neighbours. */
  turnsLeft(i: number): boolean {
    return !this.removed[i] && orientationOf(this.coords, this.previous[i], i, this.next[i]) > 0;
  }

  /** Whether point `i` is still on the outline and does not turn left: only such points can lie in an ear. */
  isReflex(i: number): boolean {
    return !this.removed[i] && !this.turnsLeft(i);
  }

  pointsNotTurningLeft(): number[] {
    const points: number[] = [];
    for (let i = 0; i < this.next.length; i++) if (!this.turnsLeft(i)) points.push(i);
    return points;
  }

  remove(i: number): void {
    this.removed[i] = 1;
    this.next[this.previous[i]] = this.next[i];
    this.previous[this.next[i]] = this.previous[i];
  }
}

/**
 * The outline's points that do not turn left at the start, bucketed in a uniform grid over their
 * bounds, about one a cell; the grid's cells keep the aspect of the bounds so that thin polygons
 * get thin cells. A cell holds its live points first: a point met turning left (or clipped) is
 * swapped past its cell's end, for good, since it never turns back.
 */
class ReflexPoints {
  private readonly minX: number;
  private readonly minY: number;
  private readonly columns: number;
  private readonly rows: number;
  private readonly cellWidth: number;
  private readonly cellHeight: number;
  /** Live points of cell k: `points[start[k]]` to `points[end[k] - 1]`. */
  private readonly start: Int32Array;
  private readonly end: Int32Array;
  private readonly points: Int32Array;
  /** Scratch `[min x, max x]` of {@link PointGrid.triangleSpanInRow}. */
  private readonly span = new Float64Array(2);

  constructor(private readonly coords: ArrayLike<number>, private readonly outline: Outline) {
    const indices = outline.pointsNotTurningLeft();
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (const i of indices) {
      minX = Math.min(minX, coords[2 * i]);
      maxX = Math.max(maxX, coords[2 * i]);
      minY = Math.min(minY, coords[2 * i + 1]);
      maxY = Math.max(maxY, coords[2 * i + 1]);
    }
    const width = maxX - minX, height = maxY - minY;
    const cells = Math.max(1, indices.length);
    this.columns = width > 0 && height > 0 ? Math.min(cells, Math.max(1, Math.round(Math.sqrt((cells * width) / height)))) : width > 0 ? cells : 1;
    this.rows = Math.max(1, Math.ceil(cells / this.columns));
    this.minX = minX;
    this.minY = minY;
    this.cellWidth = width / this.columns || 1;
    this.cellHeight = height / this.rows || 1;
    [this.start, this.points] = this.bucket(indices);
    this.end = this.start.slice(1);
  }

  /**
   * Whether any point of the outline but a and c that does not turn left lies inside or on the
   * triangle of points a, b, c (counter-clockwise).
   */
  anyInTriangle(a: number, b: number, c: number): boolean {
    const co = this.coords, points = this.points, end = this.end;
    const ax = co[2 * a], ay = co[2 * a + 1], bx = co[2 * b], by = co[2 * b + 1], cx = co[2 * c], cy = co[2 * c + 1];
    const row0 = this.row(Math.min(ay, by, cy)), row1 = this.row(Math.max(ay, by, cy));
    for (let row = row0; row <= row1; row++) {
      // Only the cells the triangle overlaps in this row: a long thin triangle covers few of its bounds' cells.
      const span = this.triangleSpanInRow(ax, ay, bx, by, cx, cy, row);
      for (let column = this.column(span[0]), last = this.column(span[1]); column <= last; column++) {
        const cell = row * this.columns + column;
        for (let k = this.start[cell]; k < end[cell]; k++) {
          const p = points[k];
          if (!this.outline.isReflex(p)) {
            points[k--] = points[--end[cell]];
            continue;
          }
          const px = co[2 * p], py = co[2 * p + 1];
          if (p !== a && p !== c && orient2d(ax, ay, bx, by, px, py) >= 0 && orient2d(bx, by, cx, cy, px, py) >= 0
            && orient2d(cx, cy, ax, ay, px, py) >= 0) return true;
        }
      }
    }
    return false;
  }

  /**
   * The x extent of the triangle within `row`'s band of y. Band and extent are widened by a
   * millionth of a cell, so that rounding (in the band's bounds, in a point's cell, in where an
   * edge crosses the band) loses no point that lies on the triangle.
   */
  private triangleSpanInRow(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, row: number): Float64Array {
    const slackY = this.cellHeight * 1e-6, slackX = this.cellWidth * 1e-6;
    const low = this.minY + row * this.cellHeight - slackY, high = low + this.cellHeight + 2 * slackY;
    const span = this.span;
    span[0] = Infinity;
    span[1] = -Infinity;
    extendBySegmentInBand(span, ax, ay, bx, by, low, high);
    extendBySegmentInBand(span, bx, by, cx, cy, low, high);
    extendBySegmentInBand(span, cx, cy, ax, ay, low, high);
    span[0] -= slackX;
    span[1] += slackX;
    return span;
  }

  /** Counting sort of `indices` by cell. */
  private bucket(indices: readonly number[]): [Int32Array, Int32Array] {
    const start = new Int32Array(this.columns * this.rows + 1);
    const cellOf = indices.map((i) => this.row(this.coords[2 * i + 1]) * this.columns + this.column(this.coords[2 * i]));
    for (const cell of cellOf) start[cell + 1]++;
    for (let k = 1; k < start.length; k++) start[k] += start[k - 1];
    const points = new Int32Array(indices.length);
    const filled = start.slice(0, -1);
    indices.forEach((i, k) => { points[filled[cellOf[k]]++] = i; });
    return [start, points];
  }

  private column(x: number): number {
    return Math.min(this.columns - 1, Math.max(0, Math.floor((x - this.minX) / this.cellWidth)));
  }

  private row(y: number): number {
    return Math.min(this.rows - 1, Math.max(0, Math.floor((y - this.minY) / this.cellHeight)));
  }
}

/** Widens `span` ([min x, max x]) to the part of segment (x0, y0)–(x1, y1) with y in [low, high]. */
function extendBySegmentInBand(span: Float64Array, x0: number, y0: number, x1: number, y1: number, low: number, high: number): void {
  if (y0 > y1) {
    extendBySegmentInBand(span, x1, y1, x0, y0, low, high);
    return;
  }
  if (y1 < low || y0 > high) return;
  const from = y0 >= low ? x0 : x0 + ((x1 - x0) * (low - y0)) / (y1 - y0);
  const to = y1 <= high ? x1 : x0 + ((x1 - x0) * (high - y0)) / (y1 - y0);
  span[0] = Math.min(span[0], from, to);
  span[1] = Math.max(span[1], from, to);
}
