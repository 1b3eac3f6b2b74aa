import type { RecordMarks } from './RecordMarks';
import { LISTED_RECORDS, TEXTURE_WIDTH, TILE_COLUMNS, TILE_COUNT, TILE_ROWS } from './shadowLayout';

/** Rows of the tile records texture per light (see shadowLayout, LISTED_RECORDS). */
export const TILE_RECORD_ROWS = TILE_COUNT / TEXTURE_WIDTH;

/**
 * Per light (filing row), the records its **listed** tiles read instead of walking the bins (see
 * shadowLayout, LISTED_RECORDS): of the records added since `beginLight` (nearest first), the
 * first LISTED_RECORDS that touch a lean tile, and per tile a mask of those whose shadow region or
 * box touches it, as `RecordMarks` marked them (widened by its slack). A lean tile is listed when
 * no record beyond those touches it: a record that hides anything from a pixel, or holds it, has the
 * pixel in its shadow region or box, so the pixel's tile lists every such record.
 *
 * A pixel finds its tile from its position in tile units, which may round across a tile's side:
 * so the tiles next to a lean tile get their masks too, and a record whose region holds a pixel
 * within the slack of a neighbour's side touches that neighbour (the marks are widened by it, far
 * more than the rounding).
 */
export class TileRecordLists {
  /** Per filing row, LISTED_RECORDS slots: its listed records, nearest first. */
  records = new Int32Array(LISTED_RECORDS);
  /** Per filing row, TILE_COUNT masks. */
  masks = new Uint32Array(TILE_COUNT);
  /** The masks as 16-bit halves, low first (little-endian, as every platform WebGL runs on): the tile records texture's data. */
  maskHalves = new Uint16Array(this.masks.buffer);
  /** Per filing row: 1 while its masks are all 0 (as they start). */
  private clearRows = new Uint8Array(1).fill(1);
  /** Per row of the tile records texture (TILE_RECORD_ROWS a filing row): 1 when written since `beginFrame`. */
  dirtyTextureRows = new Uint8Array(TILE_RECORD_ROWS);
  /** The listed tiles of the light last ended, per tile row. */
  readonly listed = new Int32Array(TILE_ROWS);
  /** The records added since `beginLight`: per record its index, its first and last tile row, and those rows' masks. */
  private spans = new Int32Array(1024);
  private spanLength = 0;
  /** Per tile row: the lean tiles and their neighbours, whose masks are written. */
  private readonly near = new Int32Array(TILE_ROWS);
  /** Per tile row: the lean tiles a record beyond the listed ones touches. */
  private readonly unlisted = new Int32Array(TILE_ROWS);

  /** Starts a frame: no texture row is dirty. */
  beginFrame(): void {
    this.dirtyTextureRows.fill(0);
  }

  /** Starts a light: no record added. */
  beginLight(): void {
    this.spanLength = 0;
  }

  /** Adds `record`, whose tiles `marks` holds (`recordTiles`, as marked since it was loaded). */
  addRecord(record: number, marks: RecordMarks): void {
    const first = marks.recordFirstRow, last = marks.recordLastRow;
    if (first > last) return;
    const needed = this.spanLength + 3 + last - first + 1;
    if (needed > this.spans.length) {
      const spans = new Int32Array(2 * needed);
      spans.set(this.spans);
      this.spans = spans;
    }
    const spans = this.spans;
    spans[this.spanLength++] = record;
    spans[this.spanLength++] = first;
    spans[this.spanLength++] = last;
    for (let j = first; j <= last; j++) spans[this.spanLength++] = marks.recordTiles[j];
  }

  /**
   * Ends the light of filing row `row`, whose lean tiles are `lean[at + j]`: lists its records,
   * writes its tiles' masks, marks its texture rows dirty and sets `listed`.
   */
  endLight(row: number, lean: Int32Array, at: number): void {
    this.ensureRow(row);
    // A light with no lean tile lists nothing: its masks stay as they are when already clear.
    if (!anyTile(lean, at) && this.clearRows[row] === 1) {
      this.listed.fill(0);
      return;
    }
    this.clearRows[row] = 0;
    this.findNear(lean, at);
    const spans = this.spans, masks = this.masks, near = this.near, unlisted = this.unlisted, tiles = row * TILE_COUNT;
    masks.fill(0, tiles, tiles + TILE_COUNT);
    unlisted.fill(0);
    let count = 0;
    for (let s = 0; s < this.spanLength;) {
      const record = spans[s], first = spans[s + 1], last = spans[s + 2], from = s + 3 - first;
      s = from + last + 1;
      if (!touchesAny(spans, from, first, last, lean, at)) continue;
      if (count === LISTED_RECORDS) {
        for (let j = first; j <= last; j++) unlisted[j] |= spans[from + j] & lean[at + j];
        continue;
      }
      const bit = 1 << count;
      this.records[row * LISTED_RECORDS + count++] = record;
      for (let j = first; j <= last; j++) {
        for (let m = spans[from + j] & near[j]; m !== 0; m &= m - 1) masks[tiles + j * TILE_COLUMNS + 31 - Math.clz32(m & -m)] |= bit;
      }
    }
    for (let j = 0; j < TILE_ROWS; j++) this.listed[j] = lean[at + j] & ~unlisted[j];
    if (count === 0) this.clearRows[row] = 1;
    this.dirtyTextureRows.fill(1, row * TILE_RECORD_ROWS, (row + 1) * TILE_RECORD_ROWS);
  }

  /** Copies filing row `row`'s listed records into `out` (LISTED_RECORDS long). */
  writeRecords(row: number, out: Int32Array): void {
    for (let k = 0; k < LISTED_RECORDS; k++) out[k] = this.records[row * LISTED_RECORDS + k];
  }

  /** Sets `near` to the lean tiles `lean[at + j]` and the tiles beside them (the 8 around each). */
  private findNear(lean: Int32Array, at: number): void {
    const near = this.near, widened = this.unlisted;
    for (let j = 0; j < TILE_ROWS; j++) {
      const l = lean[at + j];
      widened[j] = l | (l << 1) | (l >>> 1);
    }
    for (let j = 0; j < TILE_ROWS; j++) near[j] = widened[j] | (j > 0 ? widened[j - 1] : 0) | (j + 1 < TILE_ROWS ? widened[j + 1] : 0);
  }

  /** Grows the per-row arrays (at least doubling) to hold filing row `row`. */
  private ensureRow(row: number): void {
    if (this.records.length >= (row + 1) * LISTED_RECORDS) return;
    const rows = Math.max(row + 1, 2 * (this.records.length / LISTED_RECORDS));
    const records = new Int32Array(rows * LISTED_RECORDS), masks = new Uint32Array(rows * TILE_COUNT), dirty = new Uint8Array(rows * TILE_RECORD_ROWS);
    records.set(this.records);
    masks.set(this.masks);
    dirty.set(this.dirtyTextureRows);
    const clearRows = new Uint8Array(rows).fill(1);
    clearRows.set(this.clearRows);
    this.clearRows = clearRows;
    this.records = records;
    this.masks = masks;
    this.maskHalves = new Uint16Array(masks.buffer);
    this.dirtyTextureRows = dirty;
  }
}

/** Whether a tile row `tiles[at + j]` has a tile. */
function anyTile(tiles: Int32Array, at: number): boolean {
  for (let j = 0; j < TILE_ROWS; j++) if (tiles[at + j] !== 0) return true;
  return false;
}

/** Whether the record's rows `spans[from + j]`, `first ≤ j ≤ last`, touch a tile of `lean[at + j]`. */
function touchesAny(spans: Int32Array, from: number, first: number, last: number, lean: Int32Array, at: number): boolean {
  for (let j = first; j <= last; j++) if ((spans[from + j] & lean[at + j]) !== 0) return true;
  return false;
}
