import { RECORD_FLOATS, RECORD_POINTS, TILE_CLASSES, TILE_GRID, TILE_IN_RUN, tileCode } from './shadowLayout';
import type { ShadowGeometry } from './ShadowGeometry';

/** Tiles per light. */
const TILE_COUNT = TILE_GRID * TILE_GRID;
/** The classes of TILE_CLASSES, 0 to 3. */
const CLASS_COUNT = 4;
/**
 * Slack of the geometric tests, relative to the scale of the light's box: float32 rounding in the
 * shader is about 1e-7 of the coordinates, so a pixel this far inside a region is classified as
 * the shader would shade it.
 */
const RELATIVE_SLACK = 1e-5;
/** The shader's radius for a hard light (shadow-visibility's MIN_RADIUS). */
const MIN_RADIUS = 1e-3;
/** Room for a convex polygon clipped by the half-planes of one record: the box's 4 corners, one more per half-plane. */
const POLYGON_CAPACITY = 4 + 2 * RECORD_POINTS + RECORD_POINTS + 2;

/**
 * The per-light tile classes (see shadowLayout, TILE_CLASSES): every shadowed point light's box
 * (its filed bounds) cut into TILE_GRID² tiles, each found **lit** (no hull can hide any part of the
 * disk from any of its pixels), **dark** (one record hides the whole disk from all of them, and no
 * record lies in it where the light lights the inside of hulls), **outside** the light's reach, or
 * **exact** (anything else: the shader computes it). Lit and dark are proven, never guessed, by two
 * convex regions per record P of disk D (centre o, radius R, with D and P apart):
 *
 * - **The shadow region** S(P), the points from which some segment to D meets P, lies on P's side
 *   of every line that separates P from D: the tangents from P's corners to D that have P and D on
 *   opposite sides, P's edges that face the whole disk, and the line through P's point nearest o.
 *   (For x beyond such a line, a segment from x to a point of D stays off P's side.) A tile that
 *   this clipped region misses is lit by P; a disk that meets P may shadow any point.
 * - **The umbra** with P, U(P) ∪ P, the points whose every segment to D meets P, is convex (the
 *   intersection over d ∈ D of the point shadows, each convex) and is exactly the intersection of
 *   the tangents from P's corners to D that have P and D on the same side, and the inner sides of
 *   P's edges that some point of D lies outside of: for each d its point shadow is bounded by the
 *   two lines from d through P's silhouette corners and by P's edges facing d, whose extremes over
 *   D are those tangents and edges. A tile wholly inside is dark (inside P too, for a Solid light).
 *
 * Computed when a light is filed, from the still hulls (kept with the filing, so static lights and
 * walls cost nothing per frame), and per frame a lit tile that a moving hull's shadow region
 * touches becomes exact (and, but for a Solid light, a dark tile it lies in). Classified for the
 * filed disk and reach, which hold the light's own while the filing does, so the classes hold too.
 */
export class LightTiles {
  /** Rows of TILE_COUNT classes, one per filing row. */
  classes = new Uint8Array(TILE_COUNT);
  /** `classes` as the light pass reads them, runs merged (see shadowLayout, `tileCode`). */
  codes = new Uint8Array(TILE_COUNT);
  /** Per row: 1 when written since {@link LightTiles.beginFrame}. */
  dirtyRows = new Uint8Array(1);
  /** Rows of TILE_COUNT classes from the still hulls alone, one per filing row. */
  private kept = new Uint8Array(TILE_COUNT);
  /** Per row, its tiles of each class. */
  private counts = new Int32Array(CLASS_COUNT);
  /** Per tile of the light being classified: it may be shadowed, it is dark, a record lies in it. */
  private readonly shadowed = new Uint8Array(TILE_COUNT);
  private readonly dark = new Uint8Array(TILE_COUNT);
  private readonly occupied = new Uint8Array(TILE_COUNT);
  /** Polygon scratch (x, y pairs), ping-ponged by the clipping. */
  private polygon = new Float64Array(2 * POLYGON_CAPACITY);
  private clipped = new Float64Array(2 * POLYGON_CAPACITY);
  private polygonCount = 0;
  /** What `spanWithin` found. */
  private spanLeft = 0;
  private spanRight = 0;
  /** The loaded record's corners without repeats, `pointCount` of them, counter-clockwise. */
  private readonly xs = new Float64Array(RECORD_POINTS);
  private readonly ys = new Float64Array(RECORD_POINTS);
  private pointCount = 0;
  /** Half-planes `a·x + b·y ≤ c`: the shadow region's and the umbra's, for the loaded record. */
  private readonly shadowPlanes = new Float64Array(3 * (3 * RECORD_POINTS + 1));
  private shadowPlaneCount = 0;
  private readonly umbraPlanes = new Float64Array(3 * (3 * RECORD_POINTS));
  private umbraPlaneCount = 0;
  /** The light being classified: box, tile size, disk, reach, whether it is confined to its range disk and lights the inside of hulls. */
  private minX = 0;
  private minY = 0;
  private tileWidth = 1;
  private tileHeight = 1;
  private centreX = 0;
  private centreY = 0;
  private radius = 0;
  private reach = 0;
  private slack = 0;
  private confined = true;
  private solid = true;

  /** Starts a frame: no row is dirty. */
  beginFrame(): void {
    this.dirtyRows.fill(0);
  }

  /** Writes the tiles of each class in `row` (the light pass skips a class it has none of) into `out`, indexed by class. */
  writeCounts(row: number, out: Int32Array): void {
    for (let c = 0; c < CLASS_COUNT; c++) out[c] = this.counts[row * CLASS_COUNT + c];
  }

  /**
   * Starts classifying a light: its box `[minX, minY, maxX, maxY]` (the grid), its filed disk and
   * reach around `(x, y)`; `confined`: it adds nothing beyond its reach; `solid`: the inside of hulls is dark.
   */
  beginLight(bounds: Float64Array, x: number, y: number, radius: number, reach: number, confined: boolean, solid: boolean): void {
    this.minX = bounds[0];
    this.minY = bounds[1];
    this.tileWidth = Math.max(bounds[2] - bounds[0], 1e-9) / TILE_GRID;
    this.tileHeight = Math.max(bounds[3] - bounds[1], 1e-9) / TILE_GRID;
    this.centreX = x;
    this.centreY = y;
    this.slack = RELATIVE_SLACK * Math.max(Math.abs(bounds[0]), Math.abs(bounds[1]), Math.abs(bounds[2]), Math.abs(bounds[3]), bounds[2] - bounds[0], bounds[3] - bounds[1]);
    this.radius = Math.max(radius, MIN_RADIUS) + this.slack;
    this.reach = reach;
    this.confined = confined;
    this.solid = solid;
    this.shadowed.fill(0);
    this.dark.fill(0);
    this.occupied.fill(0);
  }

  /** Adds the records of the `count` hulls at `indices` (prepared) to the light being classified. */
  addStillHulls(geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    for (let i = 0; i < count; i++) {
      const hull = indices[i];
      for (let record = geometry.firstRecords[hull], end = record + geometry.recordCounts[hull]; record < end; record++) {
        if (!this.loadRecord(geometry.records, record)) continue;
        this.markShadowRegion(this.shadowed);
        this.markUmbra();
        if (!this.solid) this.markRecordBox(this.occupied);
      }
    }
  }

  /** Ends the still hulls' classification of `row`: its kept classes, copied to its classes. */
  endLight(row: number): void {
    this.ensureRow(row);
    const kept = this.kept, at = row * TILE_COUNT;
    for (let j = 0; j < TILE_GRID; j++) {
      for (let i = 0; i < TILE_GRID; i++) {
        const tile = j * TILE_GRID + i;
        let value: number = TILE_CLASSES.lit;
        if (this.confined && this.tileBeyondReach(i, j)) value = TILE_CLASSES.outside;
        else if (this.dark[tile] !== 0 && (this.solid || this.occupied[tile] === 0)) value = TILE_CLASSES.dark;
        else if (this.shadowed[tile] !== 0) value = TILE_CLASSES.exact;
        kept[at + tile] = value;
      }
    }
    this.restoreKept(row);
  }

  /** Sets `row`'s classes to its kept ones (a light whose moving hulls left it), marking it dirty. */
  restoreKept(row: number): void {
    this.ensureRow(row);
    // A loop, not set(subarray()): a view per call would be an allocation per light and frame.
    const classes = this.classes, kept = this.kept;
    for (let i = row * TILE_COUNT, end = i + TILE_COUNT; i < end; i++) classes[i] = kept[i];
    this.dirtyRows[row] = 1;
    this.count(row);
  }

  /** Counts the tiles of each class in `row`, and writes its codes: each run of one class along a row of tiles drawn as one rectangle. */
  private count(row: number): void {
    const classes = this.classes, codes = this.codes, counts = this.counts, at = row * CLASS_COUNT;
    for (let c = 0; c < CLASS_COUNT; c++) counts[at + c] = 0;
    for (let i = row * TILE_COUNT, end = i + TILE_COUNT; i < end; i++) counts[at + classes[i]]++;
    for (let j = 0; j < TILE_GRID; j++) {
      const first = row * TILE_COUNT + j * TILE_GRID;
      for (let i = 0; i < TILE_GRID;) {
        const value = classes[first + i];
        let run = 1;
        while (i + run < TILE_GRID && classes[first + i + run] === value) run++;
        codes[first + i] = tileCode(value, run);
        for (let k = 1; k < run; k++) codes[first + i + k] = TILE_IN_RUN;
        i += run;
      }
    }
  }

  /**
   * Sets `row`'s classes to its kept ones less what the `count` moving hulls at `indices` (prepared)
   * may change: the lit tiles their shadow regions touch, and, unless `solid` (set by the last
   * {@link LightTiles.beginLight} for this light's filing, with `bounds`, disk and reach as there),
   * the dark tiles they lie in, become exact.
   */
  addMovingHulls(row: number, geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    this.restoreKept(row);
    this.shadowed.fill(0);
    this.occupied.fill(0);
    for (let i = 0; i < count; i++) {
      const hull = indices[i];
      for (let record = geometry.firstRecords[hull], end = record + geometry.recordCounts[hull]; record < end; record++) {
        if (!this.loadRecord(geometry.records, record)) continue;
        this.markShadowRegion(this.shadowed);
        if (!this.solid) this.markRecordBox(this.occupied);
      }
    }
    const classes = this.classes, at = row * TILE_COUNT;
    for (let tile = 0; tile < TILE_COUNT; tile++) {
      const value = classes[at + tile];
      if ((value === TILE_CLASSES.lit && this.shadowed[tile] !== 0) || (value === TILE_CLASSES.dark && this.occupied[tile] !== 0)) classes[at + tile] = TILE_CLASSES.exact;
    }
    this.count(row);
  }

  private ensureRow(row: number): void {
    const needed = (row + 1) * TILE_COUNT;
    if (this.kept.length >= needed) return;
    const size = Math.max(needed, 2 * this.kept.length);
    const kept = new Uint8Array(size), classes = new Uint8Array(size), codes = new Uint8Array(size);
    kept.set(this.kept);
    classes.set(this.classes);
    codes.set(this.codes);
    this.kept = kept;
    this.classes = classes;
    this.codes = codes;
    const dirty = new Uint8Array(size / TILE_COUNT), counts = new Int32Array((size / TILE_COUNT) * CLASS_COUNT);
    dirty.set(this.dirtyRows);
    counts.set(this.counts);
    this.dirtyRows = dirty;
    this.counts = counts;
  }

  /** Whether tile (i, j) lies wholly beyond the reach of the filing's centre. */
  private tileBeyondReach(i: number, j: number): boolean {
    const x0 = this.minX + i * this.tileWidth, y0 = this.minY + j * this.tileHeight;
    const dx = Math.max(x0 - this.centreX, 0, this.centreX - x0 - this.tileWidth);
    const dy = Math.max(y0 - this.centreY, 0, this.centreY - y0 - this.tileHeight);
    return Math.sqrt(dx * dx + dy * dy) > this.reach + this.slack;
  }

  /**
   * Loads the record's distinct corners and the half-planes of its shadow region and umbra; false
   * when the disk meets the record (its shadow region is then every tile, which it marks, and it
   * has no umbra taken).
   */
  private loadRecord(records: Float32Array, record: number): boolean {
    const xs = this.xs, ys = this.ys;
    let n = 0;
    for (let k = 0; k < RECORD_POINTS; k++) {
      const x = records[record * RECORD_FLOATS + 2 * k], y = records[record * RECORD_FLOATS + 2 * k + 1];
      if (n > 0 && x === xs[n - 1] && y === ys[n - 1]) continue;
      if (k === RECORD_POINTS - 1 && n > 0 && x === xs[0] && y === ys[0]) continue;
      xs[n] = x;
      ys[n] = y;
      n++;
    }
    this.pointCount = n;
    this.shadowPlaneCount = 0;
    this.umbraPlaneCount = 0;
    if (this.diskMeetsRecord()) {
      this.shadowed.fill(1);
      return false;
    }
    this.findPlanes();
    return true;
  }

  /** Whether the disk, widened by the slack, meets the loaded record: its centre inside, or within a radius of an edge. */
  private diskMeetsRecord(): boolean {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, r = this.radius;
    let inside = n >= 3;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], bx = xs[(k + 1) % n], by = ys[(k + 1) % n];
      const ex = bx - ax, ey = by - ay, length2 = ex * ex + ey * ey;
      const along = length2 > 0 ? Math.min(Math.max(((cx - ax) * ex + (cy - ay) * ey) / length2, 0), 1) : 0;
      const ox = cx - ax - along * ex, oy = cy - ay - along * ey;
      if (ox * ox + oy * oy <= r * r) return true;
      if (ex * (cy - ay) - ey * (cx - ax) < 0) inside = false;
    }
    return inside;
  }

  /**
   * The half-planes of the loaded record (the disk apart from it): per corner, its two tangents to
   * the disk that have the whole record on one side; per edge, its line when it faces the whole disk
   * (shadow region) or some of it (umbra); and the line through the point nearest the centre.
   */
  private findPlanes(): void {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, r = this.radius;
    for (let k = 0; k < n; k++) {
      const vx = xs[k], vy = ys[k];
      const dx = cx - vx, dy = cy - vy, distance = Math.sqrt(dx * dx + dy * dy);
      const sine = r / distance, cosine = Math.sqrt(Math.max(0, 1 - sine * sine));
      for (let side = -1; side <= 1; side += 2) {
        // The tangent's direction: towards the centre turned by ±asin(r / distance); its normal.
        const ux = (dx * cosine - side * dy * sine) / distance, uy = (dy * cosine + side * dx * sine) / distance;
        const nx = -uy, ny = ux;
        let least = Infinity, most = -Infinity;
        for (let m = 0; m < n; m++) {
          const s = nx * (xs[m] - vx) + ny * (ys[m] - vy);
          if (s < least) least = s;
          if (s > most) most = s;
        }
        const diskSide = nx * dx + ny * dy;
        const eps = this.slack;
        if (least >= -eps) {
          // The record on the + side: the disk too (same side) or opposite.
          if (diskSide > 0) this.addUmbraPlane(-nx, -ny, -(nx * vx + ny * vy) - eps);
          else this.addShadowPlane(-nx, -ny, -(nx * vx + ny * vy) + eps);
        } else if (most <= eps) {
          if (diskSide < 0) this.addUmbraPlane(nx, ny, nx * vx + ny * vy - eps);
          else this.addShadowPlane(nx, ny, nx * vx + ny * vy + eps);
        }
      }
    }
    let nearest2 = Infinity, nearestX = 0, nearestY = 0;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], bx = xs[(k + 1) % n], by = ys[(k + 1) % n];
      const ex = bx - ax, ey = by - ay, length = Math.sqrt(ex * ex + ey * ey);
      if (length > 0) {
        // Outward normal of a counter-clockwise edge; the centre's distance outward.
        const nx = ey / length, ny = -ex / length, outward = nx * (cx - ax) + ny * (cy - ay);
        if (outward > r) this.addShadowPlane(nx, ny, nx * ax + ny * ay + this.slack);
        // The umbra needs every edge some disk point lies outside of.
        if (outward > -r) this.addUmbraPlane(nx, ny, nx * ax + ny * ay - this.slack);
      }
      const along = length > 0 ? Math.min(Math.max(((cx - ax) * ex + (cy - ay) * ey) / (length * length), 0), 1) : 0;
      const px = ax + along * ex, py = ay + along * ey, d2 = (px - cx) * (px - cx) + (py - cy) * (py - cy);
      if (d2 < nearest2) {
        nearest2 = d2;
        nearestX = px;
        nearestY = py;
      }
    }
    const distance = Math.sqrt(nearest2);
    if (distance > 0) {
      const nx = (cx - nearestX) / distance, ny = (cy - nearestY) / distance;
      this.addShadowPlane(nx, ny, nx * nearestX + ny * nearestY + this.slack);
    }
  }

  /** Adds `a·x + b·y ≤ c` (a region's side of the line, widened by the slack) to the shadow region's half-planes. */
  private addShadowPlane(a: number, b: number, c: number): void {
    setPlane(this.shadowPlanes, this.shadowPlaneCount++, a, b, c);
  }

  /** Adds `a·x + b·y ≤ c` (narrowed by the slack) to the umbra's half-planes. */
  private addUmbraPlane(a: number, b: number, c: number): void {
    setPlane(this.umbraPlanes, this.umbraPlaneCount++, a, b, c);
  }

  /** Marks in `mask` the tiles the loaded record's shadow region touches. */
  private markShadowRegion(mask: Uint8Array): void {
    this.clipBox(this.shadowPlanes, this.shadowPlaneCount);
    this.rasterize(mask, false);
  }

  /** Marks dark the tiles wholly inside the loaded record's umbra. */
  private markUmbra(): void {
    this.clipBox(this.umbraPlanes, this.umbraPlaneCount);
    this.rasterize(this.dark, true);
  }

  /** Marks in `mask` the tiles the loaded record's bounding box touches. */
  private markRecordBox(mask: Uint8Array): void {
    const xs = this.xs, ys = this.ys, p = this.polygon;
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (let k = 0; k < this.pointCount; k++) {
      minX = Math.min(minX, xs[k]);
      maxX = Math.max(maxX, xs[k]);
      minY = Math.min(minY, ys[k]);
      maxY = Math.max(maxY, ys[k]);
    }
    p[0] = minX - this.slack; p[1] = minY - this.slack;
    p[2] = maxX + this.slack; p[3] = minY - this.slack;
    p[4] = maxX + this.slack; p[5] = maxY + this.slack;
    p[6] = minX - this.slack; p[7] = maxY + this.slack;
    this.polygonCount = 4;
    this.rasterize(mask, false);
  }

  /** Sets the polygon to the light's box clipped by `count` half-planes. */
  private clipBox(planes: Float64Array, count: number): void {
    const p = this.polygon, x0 = this.minX, y0 = this.minY, x1 = x0 + TILE_GRID * this.tileWidth, y1 = y0 + TILE_GRID * this.tileHeight;
    p[0] = x0; p[1] = y0; p[2] = x1; p[3] = y0; p[4] = x1; p[5] = y1; p[6] = x0; p[7] = y1;
    this.polygonCount = 4;
    for (let k = 0; k < count && this.polygonCount > 0; k++) this.clip(planes[3 * k], planes[3 * k + 1], planes[3 * k + 2]);
  }

  /** Clips the polygon to `a·x + b·y ≤ c` (Sutherland–Hodgman; a convex polygon stays convex). */
  private clip(a: number, b: number, c: number): void {
    const from = this.polygon, to = this.clipped, n = this.polygonCount;
    let m = 0;
    for (let k = 0; k < n; k++) {
      const px = from[2 * k], py = from[2 * k + 1], q = (k + 1) % n, qx = from[2 * q], qy = from[2 * q + 1];
      const sp = a * px + b * py - c, sq = a * qx + b * qy - c;
      if (sp <= 0) {
        to[2 * m] = px;
        to[2 * m + 1] = py;
        m++;
      }
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
        const t = sp / (sp - sq);
        to[2 * m] = px + t * (qx - px);
        to[2 * m + 1] = py + t * (qy - py);
        m++;
      }
    }
    this.polygon = to;
    this.clipped = from;
    this.polygonCount = m;
  }

  /**
   * Marks in `mask` the tiles the convex polygon touches (`inner` false) or wholly covers (`inner`
   * true), row by row: within a row's band the polygon's left edge is convex and its right edge
   * concave in y, so the x it covers at every height of the band lies between the larger of its
   * left ends at the band's two sides and the smaller of the right ends (when it spans the band).
   */
  private rasterize(mask: Uint8Array, inner: boolean): void {
    const p = this.polygon, n = this.polygonCount;
    if (n < 3) return;
    let minY = Infinity, maxY = -Infinity;
    for (let k = 0; k < n; k++) {
      minY = Math.min(minY, p[2 * k + 1]);
      maxY = Math.max(maxY, p[2 * k + 1]);
    }
    const th = this.tileHeight, tw = this.tileWidth;
    const firstRow = Math.max(0, Math.floor((minY - this.minY) / th)), lastRow = Math.min(TILE_GRID - 1, Math.floor((maxY - this.minY) / th));
    for (let j = firstRow; j <= lastRow; j++) {
      const y0 = this.minY + j * th, y1 = y0 + th;
      let left: number, right: number;
      if (inner) {
        if (y0 < minY || y1 > maxY) continue;
        this.spanWithin(y0, y0);
        left = this.spanLeft;
        right = this.spanRight;
        this.spanWithin(y1, y1);
        left = Math.max(left, this.spanLeft);
        right = Math.min(right, this.spanRight);
        const first = Math.ceil((left - this.minX) / tw), last = Math.floor((right - this.minX) / tw) - 1;
        for (let i = Math.max(first, 0); i <= Math.min(last, TILE_GRID - 1); i++) mask[j * TILE_GRID + i] = 1;
      } else {
        this.spanWithin(Math.max(y0, minY), Math.min(y1, maxY));
        left = this.spanLeft;
        right = this.spanRight;
        const first = Math.floor((left - this.minX) / tw), last = Math.floor((right - this.minX) / tw);
        for (let i = Math.max(first, 0); i <= Math.min(last, TILE_GRID - 1); i++) mask[j * TILE_GRID + i] = 1;
      }
    }
  }

  /** Sets `spanLeft` and `spanRight` to the polygon's x range over heights [y0, y1] (within its own): its corners there and its crossings of both heights. */
  private spanWithin(y0: number, y1: number): void {
    const p = this.polygon, n = this.polygonCount;
    let left = Infinity, right = -Infinity;
    for (let k = 0; k < n; k++) {
      const px = p[2 * k], py = p[2 * k + 1];
      if (py >= y0 && py <= y1) {
        left = Math.min(left, px);
        right = Math.max(right, px);
      }
      const q = (k + 1) % n, qx = p[2 * q], qy = p[2 * q + 1];
      for (let side = 0; side < 2; side++) {
        const y = side === 0 ? y0 : y1;
        if ((py - y) * (qy - y) < 0) {
          const x = px + (y - py) / (qy - py) * (qx - px);
          left = Math.min(left, x);
          right = Math.max(right, x);
        }
      }
    }
    this.spanLeft = left;
    this.spanRight = right;
  }
}

/** Writes the half-plane `a·x + b·y ≤ c` as the `k`-th of `planes`. */
function setPlane(planes: Float64Array, k: number, a: number, b: number, c: number): void {
  planes[3 * k] = a;
  planes[3 * k + 1] = b;
  planes[3 * k + 2] = c;
}
