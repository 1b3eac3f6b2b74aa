import { RECORD_POINTS, TILE_COLUMNS, TILE_ROWS } from './shadowLayout';
import { markSpan } from './tileMasks';

/** Room for a convex polygon clipped by the half-planes of one record: the box's 4 corners, one more per half-plane. */
const POLYGON_CAPACITY = 4 + 2 * RECORD_POINTS + RECORD_POINTS + 3;

/**
 * A convex polygon over a light's tile grid (see `RecordMarks`): the grid's box clipped by
 * half-planes, then marked into tile-row masks as the tiles it touches or wholly covers.
 */
export class TilePolygon {
  /**
   * The rasterization's x range per tile row (touched: ±Infinity between uses, `markTouched` puts
   * back what it wrote) and per tile row boundary (the polygon's chord there), in tile units.
   */
  private readonly rowLeft = new Float64Array(TILE_ROWS).fill(Infinity);
  private readonly rowRight = new Float64Array(TILE_ROWS).fill(-Infinity);
  private readonly chordLeft = new Float64Array(TILE_ROWS + 1);
  private readonly chordRight = new Float64Array(TILE_ROWS + 1);
  /**
   * Polygon scratch (x, y pairs), ping-ponged by the clipping, in tile units: u = (x − minX) / tile
   * width, v = (y − minY) / tile height, so tile row j is v ∈ [j, j + 1].
   */
  private polygon = new Float64Array(2 * POLYGON_CAPACITY);
  private clipped = new Float64Array(2 * POLYGON_CAPACITY);
  private polygonCount = 0;
  /** The polygon's least and greatest v, as `measurePolygonHeight` found them. */
  private polygonMinV = 0;
  private polygonMaxV = 0;
  /** The rows `markTouched` last looked at (the tiles it marked lie in them). */
  touchedFirstRow = 0;
  touchedLastRow = -1;
  /** The grid: its least corner and a tile's width and height, in world units. */
  private minX = 0;
  private minY = 0;
  private tileWidth = 1;
  private tileHeight = 1;

  /** Sets the grid the polygons are clipped to and marked in. */
  setGrid(minX: number, minY: number, tileWidth: number, tileHeight: number): void {
    this.minX = minX;
    this.minY = minY;
    this.tileWidth = tileWidth;
    this.tileHeight = tileHeight;
  }

  /** Sets the polygon to the light's box clipped by `count` half-planes (world units), in tile units. */
  clipBox(planes: Float64Array, count: number): void {
    const p = this.polygon;
    p[0] = 0; p[1] = 0; p[2] = TILE_COLUMNS; p[3] = 0; p[4] = TILE_COLUMNS; p[5] = TILE_ROWS; p[6] = 0; p[7] = TILE_ROWS;
    this.polygonCount = 4;
    for (let k = 0; k < count && this.polygonCount > 0; k++) this.clip(planes, k);
  }

  /**
   * Clips the polygon to the `k`-th of `planes`, `a·x + b·y ≤ c` in world units (Sutherland–Hodgman;
   * a convex polygon stays convex); a plane it lies within changes nothing.
   */
  private clip(planes: Float64Array, k: number): void {
    // The plane in tile units: x = minX + u · tile width, y = minY + v · tile height.
    const wa = planes[3 * k], wb = planes[3 * k + 1];
    const a = wa * this.tileWidth, b = wb * this.tileHeight, c = planes[3 * k + 2] - wa * this.minX - wb * this.minY;
    const from = this.polygon, to = this.clipped, n = this.polygonCount;
    let outside = false;
    for (let i = 0; i < n; i++) {
      if (a * from[2 * i] + b * from[2 * i + 1] > c) {
        outside = true;
        break;
      }
    }
    if (!outside) return;
    let m = 0, px = from[2 * n - 2], py = from[2 * n - 1], sp = a * px + b * py - c;
    for (let i = 0; i < n; i++) {
      const qx = from[2 * i], qy = from[2 * i + 1], sq = a * qx + b * qy - c;
      // The edge from the previous corner p to q: its crossing, then q if inside.
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
        const t = sp / (sp - sq);
        to[2 * m] = px + t * (qx - px);
        to[2 * m + 1] = py + t * (qy - py);
        m++;
      }
      if (sq <= 0) {
        to[2 * m] = qx;
        to[2 * m + 1] = qy;
        m++;
      }
      px = qx;
      py = qy;
      sp = sq;
    }
    this.polygon = to;
    this.clipped = from;
    this.polygonCount = m;
  }

  /** Sets `polygonMinV` and `polygonMaxV` (fields, not a result: see Hot-path rules in docs/architecture.md). */
  private measurePolygonHeight(): void {
    const p = this.polygon;
    let minV = Infinity, maxV = -Infinity;
    for (let k = 0; k < this.polygonCount; k++) {
      minV = Math.min(minV, p[2 * k + 1]);
      maxV = Math.max(maxV, p[2 * k + 1]);
    }
    this.polygonMinV = minV;
    this.polygonMaxV = maxV;
  }

  /**
   * Marks in `mask` (and in `alsoInto`) the tiles the convex polygon touches, in rows from
   * `touchedFirstRow` to `touchedLastRow`: per tile row, the x range of its edges'
   * parts within the row's band (closed: an edge ending on a boundary is in both rows), which for a
   * convex polygon is its own.
   */
  markTouched(mask: Int32Array, alsoInto: Int32Array | null): void {
    const p = this.polygon, n = this.polygonCount, left = this.rowLeft, right = this.rowRight;
    this.touchedFirstRow = TILE_ROWS;
    this.touchedLastRow = -1;
    if (n < 3) return;
    let firstRow = TILE_ROWS, lastRow = -1;
    for (let k = 0; k < n; k++) {
      const pu = p[2 * k], pv = p[2 * k + 1], q = k + 1 < n ? k + 1 : 0, qu = p[2 * q], qv = p[2 * q + 1];
      const low = Math.min(pv, qv), high = Math.max(pv, qv), flat = low === high, slope = flat ? 0 : (qu - pu) / (qv - pv);
      const from = Math.max(0, Math.ceil(low) - 1), to = Math.min(TILE_ROWS - 1, Math.floor(high));
      if (from < firstRow) firstRow = from;
      if (to > lastRow) lastRow = to;
      for (let j = from; j <= to; j++) {
        // The edge's ends within the band [j, j + 1] (a flat edge: its two ends).
        const ua = flat ? pu : pu + ((j > low ? j : low) - pv) * slope, ub = flat ? qu : pu + ((j + 1 < high ? j + 1 : high) - pv) * slope;
        const least = ua < ub ? ua : ub, most = ua < ub ? ub : ua;
        if (least < left[j]) left[j] = least;
        if (most > right[j]) right[j] = most;
      }
    }
    this.touchedFirstRow = firstRow;
    this.touchedLastRow = lastRow;
    for (let j = firstRow; j <= lastRow; j++) {
      const first = Math.max(0, Math.floor(left[j])), last = Math.min(TILE_COLUMNS - 1, Math.floor(right[j]));
      if (first <= last) {
        markSpan(mask, j, first, last);
        if (alsoInto !== null) markSpan(alsoInto, j, first, last);
      }
      left[j] = Infinity;
      right[j] = -Infinity;
    }
  }

  /**
   * Sets `chordLeft[b]` and `chordRight[b]`, for the tile row boundaries `first ≤ b ≤ last`, to the
   * ends of the convex polygon's chord at that height where its edges cross it (no corner on it),
   * and to Infinity and −Infinity elsewhere: one pass over the edges, a multiplication per crossing.
   */
  private chordAt(first: number, last: number): void {
    const p = this.polygon, n = this.polygonCount;
    const left = this.chordLeft, right = this.chordRight;
    left.fill(Infinity, first, last + 1);
    right.fill(-Infinity, first, last + 1);
    for (let k = 0; k < n; k++) {
      const px = p[2 * k], py = p[2 * k + 1], q = k + 1 < n ? k + 1 : 0, qx = p[2 * q], qy = p[2 * q + 1];
      if (py === qy) continue;
      const low = Math.min(py, qy), high = Math.max(py, qy), slope = (qx - px) / (qy - py);
      for (let b = Math.max(first, Math.floor(low)), end = Math.min(last, Math.ceil(high)); b <= end; b++) {
        if (b <= low || b >= high) continue;
        const x = px + (b - py) * slope;
        if (x < left[b]) left[b] = x;
        if (x > right[b]) right[b] = x;
      }
    }
  }

  /**
   * Marks in `mask` the tiles the convex polygon wholly covers: within a row's band its left edge is
   * convex and its right edge concave in y, so the x it covers at every height of the band lies
   * between the larger of its chord's left ends at the band's two sides and the smaller of the right
   * ends (when it spans the band).
   */
  markCovered(mask: Int32Array): void {
    const p = this.polygon, n = this.polygonCount;
    if (n < 3) return;
    this.measurePolygonHeight();
    // The tile row boundaries within the polygon's height.
    const first = Math.max(0, Math.ceil(this.polygonMinV)), last = Math.min(TILE_ROWS, Math.floor(this.polygonMaxV));
    if (last - first < 1) return;
    this.chordAt(first, last);
    const left = this.chordLeft, right = this.chordRight;
    for (let k = 0; k < n; k++) {
      // A corner on a boundary is that chord's end.
      const pu = p[2 * k], pv = p[2 * k + 1], b = Math.round(pv);
      if (b >= first && b <= last && b === pv) {
        if (pu < left[b]) left[b] = pu;
        if (pu > right[b]) right[b] = pu;
      }
    }
    for (let j = first; j < last; j++) {
      const from = Math.max(left[j], left[j + 1]), to = Math.min(right[j], right[j + 1]);
      const firstTile = Math.max(0, Math.ceil(from)), lastTile = Math.min(TILE_COLUMNS - 1, Math.floor(to) - 1);
      if (firstTile <= lastTile) markSpan(mask, j, firstTile, lastTile);
    }
  }
}
