/**
 * Solid cells of a grid grouped into regions that are each a topological disk: 4-connected, no
 * holes, and not touching themselves at a corner. The outline of such a region, traced along cell
 * edges, is a simple polygon (see `tileOutlines.ts`).
 */

/** A grid of width × height cells; cell (x, y), row-major, y down. */
export interface CellGrid {
  readonly width: number;
  readonly height: number;
  solid(x: number, y: number): boolean;
}

/**
 * Solid cells split into 4-connected regions, each without holes (a region whose outline would
 * enclose empty cells is cut along row boundaries through the hole until none is left), and
 * without two of its cells meeting only at a corner where the region's outline would pass twice.
 * `labels[y * width + x]` = region index or −1; regions are numbered in row-major order of their
 * first cell. A 4-connected group of cells that already has neither holes nor such corners is
 * always one region; a ring becomes 2.
 *
 * Two sweeps, O(cells + runs · log runs). Each row is cut into runs (maximal horizontal stretches
 * of solid cells); a run touches the runs of the row above that overlap it (sharing an edge) or
 * meet it at a corner. The first sweep finds the 4-connected groups of runs (corners between
 * groups never matter). In the second, a union–find over the runs builds the *pieces* (the
 * regions), and each piece keeps the pieces of its group it touches without being joined to them.
 * A run joins a piece above when it overlaps exactly one run of that piece and touches no other,
 * and that piece is not kept apart from the pieces the run has already joined (joining would close
 * a loop or make a corner). Every piece thus stays a tree of runs glued edge to edge, which is a
 * disk; a run that joins no piece starts one (that is the cut, along the row boundary above it).
 * A group that is already a disk has no loop, so nothing in it is ever cut.
 */
export function holeFreeRegions(grid: CellGrid): { labels: Int32Array; count: number } {
  const width = grid.width, height = grid.height;
  const labels = new Int32Array(width * height).fill(-1);
  if (width <= 0 || height <= 0) return { labels, count: 0 };

  // Runs, row by row: runStart/runEnd inclusive cell columns; rowFirst[y] = index of row y's first run.
  const maxRuns = ((width + 1) >> 1) * height;
  const runStart = new Int32Array(maxRuns), runEnd = new Int32Array(maxRuns);
  const rowFirst = new Int32Array(height + 1);
  let runs = 0;
  for (let y = 0; y < height; y++) {
    rowFirst[y] = runs;
    let x = 0;
    while (x < width) {
      if (!grid.solid(x, y)) {
        x++;
        continue;
      }
      const start = x;
      while (x + 1 < width && grid.solid(x + 1, y)) x++;
      runStart[runs] = start;
      runEnd[runs] = x;
      runs++;
      x += 2; // the cell after a run is empty
    }
  }
  rowFirst[height] = runs;

  // Runs of the row above touching each run s (sharing an edge or a corner): above[s] .. aboveLast[s] - 1.
  // The groups: 4-connected sets of runs (joined by shared edges only).
  const above = new Int32Array(runs), aboveLast = new Int32Array(runs);
  const group = new Int32Array(runs), piece = new Int32Array(runs);
  for (let r = 0; r < runs; r++) group[r] = piece[r] = r;
  for (let y = 1; y < height; y++) {
    const aboveEnd = rowFirst[y];
    let first = rowFirst[y - 1]; // first run above that can still touch the current run or a later one
    for (let s = rowFirst[y]; s < rowFirst[y + 1]; s++) {
      const a = runStart[s], b = runEnd[s];
      while (first < aboveEnd && runEnd[first] < a - 1) first++;
      let last = first;
      while (last < aboveEnd && runStart[last] <= b + 1) {
        if (runEnd[last] >= a && runStart[last] <= b) {
          const g = find(group, last), own = find(group, s);
          if (g !== own) group[g] = own;
        }
        last++;
      }
      above[s] = first;
      aboveLast[s] = last;
    }
  }

  // Per piece root: how many runs touching the current run it holds (a corner counts 2: disqualifying).
  const touchCount = new Int32Array(runs), touchStamp = new Int32Array(runs).fill(-1);
  const apart = new ApartPieces(piece);
  for (let y = 1; y < height; y++) {
    for (let s = rowFirst[y]; s < rowFirst[y + 1]; s++) {
      const a = runStart[s], b = runEnd[s], first = above[s], last = aboveLast[s];
      if (first === last) continue;
      const g = find(group, s);
      // Pass 1: count the touching runs per piece; a corner with another group does not matter.
      let touching = 0;
      for (let u = first; u < last; u++) {
        const corner = runEnd[u] < a || runStart[u] > b;
        if (corner && find(group, u) !== g) continue;
        const p = find(piece, u);
        if (touchStamp[p] !== s) {
          touchStamp[p] = s;
          touchCount[p] = 0;
        }
        touchCount[p] += corner ? 2 : 1;
        touching++;
      }
      if (touching === 0) continue;
      // Pass 2: join each piece touched by one overlapping run only, unless apart from s's piece.
      for (let u = first; u < last; u++) {
        const p = find(piece, u), own = find(piece, s);
        if (p !== own && touchStamp[p] === s && touchCount[p] === 1 && !apart.has(p, own)) apart.merge(p, own);
      }
      // Pass 3: every other piece touching s's piece (in its group) stays apart from it.
      for (let u = first; u < last; u++) {
        const p = find(piece, u);
        if (touchStamp[p] !== s) continue;
        const own = find(piece, s);
        if (p !== own) apart.add(p, own);
      }
    }
  }

  // Number the pieces in row-major order of their first run and paint the labels.
  const index = new Int32Array(runs).fill(-1);
  let count = 0;
  for (let y = 0; y < height; y++) {
    for (let r = rowFirst[y]; r < rowFirst[y + 1]; r++) {
      const root = find(piece, r);
      if (index[root] < 0) index[root] = count++;
      labels.fill(index[root], y * width + runStart[r], y * width + runEnd[r] + 1);
    }
  }
  return { labels, count };
}

/**
 * Union–find over pieces with, per root, the pieces it touches without being joined to them (a cut
 * edge or a corner): joining two such pieces would close a loop. Sets are merged small into
 * large, so each entry moves O(log n) times.
 */
class ApartPieces {
  private readonly sets: Array<Set<number> | undefined> = [];
  constructor(private readonly parent: Int32Array) {}

  has(p: number, q: number): boolean {
    return this.sets[p]?.has(q) ?? false;
  }

  add(p: number, q: number): void {
    (this.sets[p] ??= new Set()).add(q);
    (this.sets[q] ??= new Set()).add(p);
  }

  /** Joins the pieces of roots `p` and `q` (not apart); the root with more entries survives. */
  merge(p: number, q: number): void {
    let keep = q, gone = p;
    if ((this.sets[p]?.size ?? 0) > (this.sets[q]?.size ?? 0)) {
      keep = p;
      gone = q;
    }
    this.parent[gone] = keep;
    const moved = this.sets[gone];
    if (moved === undefined) return;
    const kept = (this.sets[keep] ??= new Set());
    for (const x of moved) {
      const other = this.sets[x]!;
      other.delete(gone);
      other.add(keep);
      kept.add(x);
    }
    this.sets[gone] = undefined;
  }
}

/** Union–find root of `i`, halving the path on the way. */
function find(parent: Int32Array, i: number): number {
  while (parent[i] !== i) {
    const up = parent[parent[i]];
    parent[i] = up;
    i = up;
  }
  return i;
}
