import type { ShadowGeometry } from './ShadowGeometry';
import { BIN_COUNT, BIN_FLOATS, ENTRY_FLOATS, RECORD_FLOATS, RECORD_TEXELS, TEXTURE_WIDTH } from './shadowLayout';

const TWO_PI = 2 * Math.PI;

/**
 * Per shadowed light, the records that can hide part of its disk, filed into angular bins around
 * its centre (see shadowLayout), each bin's list nearest first. A pixel looks up the bin of its
 * direction from the light and visits that list until the records are farther than itself.
 *
 * Which pixels a record can shade: a segment from a pixel p to a disk point q meets the record only
 * if p lies on a ray from q through the record, beyond it. Seen from the centre c, such a p lies
 * between the direction of its record point h and the ray's direction, which differ by at most
 * asin(r / |h − c|): so the record's bins are its angular extent from c widened by asin(r / d),
 * with d its distance from c; a record that reaches into the disk (d ≤ r) is filed in every bin.
 * And since a segment between two points within distance ρ ≥ r of c stays within ρ, a pixel nearer
 * to c than d > r is never shaded by the record: that is the `distance` the lists are sorted by
 * (0 for a record reaching into the disk, which may shade any pixel).
 *
 * All arrays are reused from frame to frame.
 */
export class ShadowBins {
  /** Rows of {@link BIN_COUNT} bins, one per shadowed light. */
  bins = new Float32Array(BIN_COUNT * BIN_FLOATS * 8);
  rowCount = 0;
  /** Entries of all rows' bins, in whole rows of {@link TEXTURE_WIDTH}. */
  entries = new Float32Array(TEXTURE_WIDTH * ENTRY_FLOATS);
  entryCount = 0;
  /** Candidates of the current light: record, distance, first bin and bin count, in parallel arrays. */
  private candidateRecords = new Int32Array(64);
  private candidateDistances = new Float64Array(64);
  private candidateFirstBins = new Int32Array(64);
  private candidateBinCounts = new Int32Array(64);
  private order = new Int32Array(64);
  private candidateCount = 0;
  private readonly binCursors = new Int32Array(BIN_COUNT);
  private lightX = 0;
  private lightY = 0;
  private lightRadius = 0;

  /** Starts a frame: no rows, no entries. */
  reset(): void {
    this.rowCount = 0;
    this.entryCount = 0;
  }

  /** Starts the row of the light with the given centre and disk radius. */
  beginLight(x: number, y: number, radius: number): void {
    this.lightX = x;
    this.lightY = y;
    this.lightRadius = radius;
    this.candidateCount = 0;
  }

  /** Adds the records of the hull at `index` (prepared) as candidates of the current light. */
  addHull(geometry: ShadowGeometry, index: number): void {
    const first = geometry.firstRecords[index], end = first + geometry.recordCounts[index];
    for (let record = first; record < end; record++) this.addRecord(geometry, record);
  }

  /** Files the current light's candidates into its row; returns the row. */
  endLight(geometry: ShadowGeometry): number {
    const row = this.rowCount++;
    this.bins = grow(this.bins, row * BIN_COUNT * BIN_FLOATS, BIN_COUNT * BIN_FLOATS);
    const count = this.candidateCount, order = this.order;
    for (let i = 0; i < count; i++) order[i] = i;
    sortByKey(order, count, this.candidateDistances);
    const cursors = this.binCursors.fill(0);
    let total = 0;
    for (let i = 0; i < count; i++) {
      const first = this.candidateFirstBins[i], binCount = this.candidateBinCounts[i];
      total += binCount;
      for (let k = 0; k < binCount; k++) cursors[(first + k) % BIN_COUNT]++;
    }
    const firstEntry = this.entryCount;
    this.entries = grow(this.entries, firstEntry * ENTRY_FLOATS, total * ENTRY_FLOATS, TEXTURE_WIDTH * ENTRY_FLOATS);
    const bins = this.bins;
    for (let bin = 0, start = firstEntry; bin < BIN_COUNT; bin++) {
      const b = (row * BIN_COUNT + bin) * BIN_FLOATS;
      bins[b] = start;
      bins[b + 1] = cursors[bin];
      start += cursors[bin];
      cursors[bin] = bins[b];
    }
    const entries = this.entries;
    for (let i = 0; i < count; i++) {
      const candidate = order[i];
      const record = this.candidateRecords[candidate], distance = this.candidateDistances[candidate];
      const first = this.candidateFirstBins[candidate], binCount = this.candidateBinCounts[candidate];
      for (let k = 0; k < binCount; k++) {
        const e = cursors[(first + k) % BIN_COUNT]++ * ENTRY_FLOATS;
        entries[e] = record * RECORD_TEXELS;
        entries[e + 1] = geometry.recordPointCounts[record];
        entries[e + 2] = distance;
        entries[e + 3] = 0;
      }
    }
    this.entryCount += total;
    return row;
  }

  /** Computes a record's distance and bins from the current light and adds it. */
  private addRecord(geometry: ShadowGeometry, record: number): void {
    const points = geometry.records, base = record * RECORD_FLOATS, count = geometry.recordPointCounts[record];
    const cx = this.lightX, cy = this.lightY;
    let nearest2 = Infinity;
    const firstAngle = Math.atan2(points[base + 1] - cy, points[base] - cx);
    let low = 0, high = 0;
    for (let i = 0; i < count; i++) {
      const ax = points[base + 2 * i] - cx, ay = points[base + 2 * i + 1] - cy;
      const j = i + 1 === count ? 0 : i + 1;
      const bx = points[base + 2 * j] - cx, by = points[base + 2 * j + 1] - cy;
      const distance2 = segmentDistance2(ax, ay, bx, by);
      if (distance2 < nearest2) nearest2 = distance2;
      let angle = Math.atan2(ay, ax) - firstAngle;
      if (angle > Math.PI) angle -= TWO_PI;
      else if (angle < -Math.PI) angle += TWO_PI;
      if (angle < low) low = angle;
      if (angle > high) high = angle;
    }
    const distance = Math.sqrt(nearest2);
    let firstBin = 0, binCount = BIN_COUNT;
    if (distance > this.lightRadius) {
      const widen = Math.asin(this.lightRadius / distance);
      // One bin more on each side: the shader's atan and this one's may round a direction on a
      // bin border differently.
      const from = Math.floor(((firstAngle + low - widen + Math.PI) / TWO_PI) * BIN_COUNT) - 1;
      const to = Math.floor(((firstAngle + high + widen + Math.PI) / TWO_PI) * BIN_COUNT) + 1;
      if (to - from + 1 < BIN_COUNT) {
        firstBin = ((from % BIN_COUNT) + BIN_COUNT) % BIN_COUNT;
        binCount = to - from + 1;
      }
    }
    const reachesPixelsAt = distance > this.lightRadius ? distance : 0;
    const i = this.candidateCount++;
    if (i === this.candidateRecords.length) this.growCandidates();
    this.candidateRecords[i] = record;
    this.candidateDistances[i] = reachesPixelsAt;
    this.candidateFirstBins[i] = firstBin;
    this.candidateBinCounts[i] = binCount;
  }

  private growCandidates(): void {
    const used = this.candidateCount;
    this.candidateRecords = grow(this.candidateRecords, used, used);
    this.candidateDistances = grow(this.candidateDistances, used, used);
    this.candidateFirstBins = grow(this.candidateFirstBins, used, used);
    this.candidateBinCounts = grow(this.candidateBinCounts, used, used);
    this.order = new Int32Array(this.candidateRecords.length);
  }
}

/** Squared distance from the origin to the segment a–b. */
function segmentDistance2(ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax, ey = by - ay;
  const length2 = ex * ex + ey * ey;
  const t = length2 > 0 ? Math.min(1, Math.max(0, -(ax * ex + ay * ey) / length2)) : 0;
  const x = ax + t * ex, y = ay + t * ey;
  return x * x + y * y;
}

/** Sorts `order[0..count)` by `keys[order[i]]`, ascending, in place (heapsort: no allocation, no recursion). */
export function sortByKey(order: Int32Array, count: number, keys: Float64Array): void {
  for (let start = (count >> 1) - 1; start >= 0; start--) siftDown(order, start, count, keys);
  for (let end = count - 1; end > 0; end--) {
    const top = order[0];
    order[0] = order[end];
    order[end] = top;
    siftDown(order, 0, end, keys);
  }
}

function siftDown(order: Int32Array, root: number, count: number, keys: Float64Array): void {
  const item = order[root], key = keys[item];
  let i = root;
  for (;;) {
    let child = 2 * i + 1;
    if (child >= count) break;
    if (child + 1 < count && keys[order[child + 1]] > keys[order[child]]) child++;
    if (keys[order[child]] <= key) break;
    order[i] = order[child];
    i = child;
  }
  order[i] = item;
}

/** `array`, or a grown copy of its first `used` entries, with room for `extra` more (length a multiple of `granule`). */
export function grow<T extends Int32Array<ArrayBuffer> | Float64Array<ArrayBuffer> | Float32Array<ArrayBuffer> | Uint32Array<ArrayBuffer> | Uint8Array<ArrayBuffer>>(array: T, used: number, extra: number, granule = 1): T {
  if (used + extra <= array.length) return array;
  const grown = new (array.constructor as new (length: number) => T)(Math.ceil(Math.max(used + extra, array.length * 2) / granule) * granule);
  grown.set(array.subarray(0, used));
  return grown;
}
