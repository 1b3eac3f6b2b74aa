/** Smallest cell side, in world units: finer cells cost more cell visits than they save box tests. */
const MIN_CELL_SIZE = 64;
/** Most cells per hull: bounds the grid's memory when a few hulls lie far apart. */
const CELLS_PER_HULL = 4;

/**
 * A uniform grid over boxes (the hulls' coarse bounds, computed without transforming a hull's
 * points, so hulls no light reaches are never transformed; see `ShadowGeometry.coarseBounds`),
 * rebuilt each frame in O(hulls) with a counting sort into reused typed arrays, from flat arrays
 * only (not each hull's own objects, which would cost a pointer chase per hull), so finding the
 * hulls near a light visits only the cells its bounds overlap instead of every hull. Chosen over a
 * packed R-tree (flatbush), which answers as fast but allocates its arrays on every rebuild and its
 * results on every query.
 */
export class HullGrid {
  private cellSize = MIN_CELL_SIZE;
  /** `[minX, minY, maxX, maxY]` of the boxes the last `build` filed (infinite, inside out, when none was). */
  readonly extent = new Float64Array(4);
  private originX = 0;
  private originY = 0;
  private columns = 0;
  private rows = 0;
  /** Start of each cell's run in `items` (`cells + 1` entries, CSR layout). */
  private cellStart = new Int32Array(1);
  /** Hull indices (box numbers given to `build`), grouped by cell. */
  private items = new Int32Array(0);
  /** Per box: 1 when the last `build` filed it. */
  private inGrid = new Uint8Array(0);
  /** Per hull: the number of the last query that reported it, so a hull in many cells is reported once. */
  private stamps = new Uint32Array(0);
  private query = 0;
  private bounds: Float64Array = new Float64Array(0);
  /** Hull indices found by the last {@link HullGrid.search}. */
  found = new Int32Array(64);
  foundCount = 0;

  /**
   * Files box `i` (`bounds[4i .. 4i + 3]` = `[minX, minY, maxX, maxY]`) by the cells it overlaps,
   * for each `i < count` with `filed[i]` set that overlaps `clip` (the region queries will cover:
   * boxes outside it cost one test, not a place in the grid).
   */
  build(bounds: Float64Array, filed: Uint8Array, count: number, clip: ArrayLike<number>): void {
    this.bounds = bounds;
    if (this.inGrid.length < count) this.inGrid = new Uint8Array(Math.ceil(count * 1.5));
    const inGrid = this.inGrid;
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity, filedCount = 0;
    for (let i = 0; i < count; i++) {
      const k = 4 * i;
      inGrid[i] = filed[i] !== 0 && !(bounds[k] > clip[2] || bounds[k + 2] < clip[0] || bounds[k + 1] > clip[3] || bounds[k + 3] < clip[1]) ? 1 : 0;
      if (inGrid[i] === 0) continue;
      if (bounds[k] < minX) minX = bounds[k];
      if (bounds[k + 1] < minY) minY = bounds[k + 1];
      if (bounds[k + 2] > maxX) maxX = bounds[k + 2];
      if (bounds[k + 3] > maxY) maxY = bounds[k + 3];
      filedCount++;
    }
    const extent = this.extent;
    extent[0] = minX;
    extent[1] = minY;
    extent[2] = maxX;
    extent[3] = maxY;
    if (filedCount === 0) {
      this.columns = this.rows = 0;
      return;
    }
    const width = maxX - minX, height = maxY - minY;
    this.cellSize = Math.max(MIN_CELL_SIZE, Math.sqrt(width * height / (filedCount * CELLS_PER_HULL)));
    this.originX = minX;
    this.originY = minY;
    this.columns = Math.floor(width / this.cellSize) + 1;
    this.rows = Math.floor(height / this.cellSize) + 1;
    const cells = this.columns * this.rows;
    if (this.cellStart.length < cells + 1) this.cellStart = new Int32Array(Math.ceil((cells + 1) * 1.5));
    if (this.stamps.length < count) this.stamps = new Uint32Array(Math.ceil(count * 1.5));
    const start = this.cellStart;
    start.fill(0, 0, cells + 1);
    // Pass 1 counts each cell's boxes (shifted by one), pass 2 turns counts into starts, pass 3 fills.
    let total = 0;
    for (let i = 0; i < count; i++) if (inGrid[i] !== 0) total += this.forCells(i, start, false);
    for (let cell = 0; cell < cells; cell++) start[cell + 1] += start[cell];
    if (this.items.length < total) this.items = new Int32Array(Math.ceil(total * 1.5));
    for (let i = 0; i < count; i++) if (inGrid[i] !== 0) this.forCells(i, start, true);
    // Pass 3 advanced every start to the next cell's: shift back.
    for (let cell = cells; cell > 0; cell--) start[cell] = start[cell - 1];
    start[0] = 0;
  }

  /**
   * Puts into `found` the numbers of the filed boxes that overlap the box
   * `[minX, minY, maxX, maxY]`, each once; returns how many.
   */
  /** The least value of x·dx + y·dy over {@link HullGrid.extent}'s corners; +∞ when nothing was filed. */
  leastAlong(dx: number, dy: number): number {
    const e = this.extent;
    if (e[0] > e[2]) return Infinity;
    return (dx < 0 ? e[2] : e[0]) * dx + (dy < 0 ? e[3] : e[1]) * dy;
  }

  search(box: ArrayLike<number>): number {
    this.foundCount = 0;
    if (this.columns === 0) return 0;
    const size = this.cellSize;
    if (box[2] < this.originX || box[3] < this.originY
      || box[0] > this.originX + this.columns * size || box[1] > this.originY + this.rows * size) return 0;
    if (++this.query === 0xffffffff) {
      this.stamps.fill(0);
      this.query = 1;
    }
    const c0 = this.cell(box[0] - this.originX, this.columns), c1 = this.cell(box[2] - this.originX, this.columns);
    const r0 = this.cell(box[1] - this.originY, this.rows), r1 = this.cell(box[3] - this.originY, this.rows);
    const { cellStart, items, stamps, bounds, query } = this;
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        const cell = r * this.columns + c;
        for (let k = cellStart[cell], end = cellStart[cell + 1]; k < end; k++) {
          const index = items[k];
          if (stamps[index] === query) continue;
          stamps[index] = query;
          const b = 4 * index;
          if (bounds[b] > box[2] || bounds[b + 2] < box[0] || bounds[b + 1] > box[3] || bounds[b + 3] < box[1]) continue;
          this.push(index);
        }
      }
    }
    return this.foundCount;
  }

  /**
   * For each cell box `index` overlaps: without `fill` counts the box in the cell (one slot ahead);
   * with `fill` writes `index` at the cell's cursor and advances it. Returns the number of cells.
   */
  private forCells(index: number, start: Int32Array, fill: boolean): number {
    // Inlined cell numbers (see `cell`): this runs for every hull every frame.
    const size = this.cellSize, columns = this.columns, rows = this.rows, bounds = this.bounds, k = 4 * index;
    const c0 = Math.min(columns - 1, Math.max(0, Math.floor((bounds[k] - this.originX) / size)));
    const c1 = Math.min(columns - 1, Math.max(0, Math.floor((bounds[k + 2] - this.originX) / size)));
    const r0 = Math.min(rows - 1, Math.max(0, Math.floor((bounds[k + 1] - this.originY) / size)));
    const r1 = Math.min(rows - 1, Math.max(0, Math.floor((bounds[k + 3] - this.originY) / size)));
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        const cell = r * columns + c;
        if (fill) this.items[start[cell]++] = index;
        else start[cell + 1]++;
      }
    }
    return (c1 - c0 + 1) * (r1 - r0 + 1);
  }

  /** The cell number along one axis of an offset from the grid's origin, clamped to `[0, cells)`. */
  private cell(offset: number, cells: number): number {
    const cell = Math.floor(offset / this.cellSize);
    return cell < 0 ? 0 : cell >= cells ? cells - 1 : cell;
  }

  private push(index: number): void {
    if (this.foundCount === this.found.length) {
      const grown = new Int32Array(this.found.length * 2);
      grown.set(this.found);
      this.found = grown;
    }
    this.found[this.foundCount++] = index;
  }
}
