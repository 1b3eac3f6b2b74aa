import type { ShadowGeometry } from './ShadowGeometry';
import { BIN_COUNT, BIN_FLOATS, ENTRY_FLOATS, ENTRY_MAX_RECORDS, entryCode, TEXTURE_WIDTH } from './shadowLayout';

/** Distance buckets of the counting sort that orders each bin's list, nearest first. */
export const DISTANCE_BUCKETS = 32;

/** The width of a light's distance buckets: a light adds nothing beyond its (filed) `reach`. */
export function bucketWidthOf(reach: number): number {
  return Math.max(reach, 1e-9) / DISTANCE_BUCKETS;
}
/** Pseudo-angle margin on each side of a hull's bins, far above the shader's float32 rounding (~1e-6). */
const ANGLE_MARGIN = 1e-3;
/** asin(x) ≤ x + ASIN_CUBIC · x³ on [0, 1] (see `addHull`). */
const ASIN_CUBIC = Math.PI / 2 - 1;

/**
 * A light's disk and reach as its bins and tiles are filed for: `[x, y, radius, reach, bucketWidth]`.
 * An array, not arguments (see Hot-path rules in docs/architecture.md).
 */
export type FiledDisk = Float64Array;

/**
 * Per shadowed light, the hulls that can hide part of its disk, filed into angular bins around its
 * centre (see shadowLayout), in two lists per bin (the still hulls and the moving ones, each filed
 * between a `beginLight` and an `endLight` into its own {@link BinSpan}), each ordered nearest
 * first. A pixel looks up the bin of its direction from the light and visits each list until the
 * hulls are farther than itself.
 *
 * Which pixels a hull can shade: a segment from a pixel p to a disk point q meets the hull only if p
 * lies on a ray from q through a hull point h, beyond it. Seen from the centre c, such a p lies
 * between the directions of h and of the ray, which differ by at most asin(r / |h − c|). With the
 * hull inside a circle of radius ρ at distance d from c, its points lie within asin(ρ / d) of the
 * circle's direction and at least d − ρ from c: so its bins are those within asin(ρ / d) +
 * asin(r / (d − ρ)) of that direction. A hull reaching into the disk (d − ρ ≤ r) is filed in every bin.
 * And since a segment between two points within distance ρ' ≥ r of c stays within ρ', a pixel
 * nearer to c than d − ρ > r is never shaded by the hull: that bound orders the lists (0 for a hull
 * reaching into the disk, which may shade any pixel). The order is by buckets of that distance: a
 * pixel stops at the first entry whose bound exceeds its own distance by a bucket's width.
 *
 * Costs one square root and six divisions per light and hull in range, and writes about
 * 1 + (angular width of the hull's shadow) / (bin width) entries. All arrays are reused from frame
 * to frame.
 */
export class ShadowBins {
  /** Rows of {@link BIN_COUNT} bins, one per light's {@link BinSpan.row}. */
  bins = new Float32Array(BIN_COUNT * BIN_FLOATS * 8);
  /** Per row of `bins`: 1 when written since the last {@link ShadowBins.beginFrame}. */
  dirtyBinRows = new Uint8Array(8);
  /** The entries of every light's span, in whole rows of the entries texture. */
  entries = new Float32Array(TEXTURE_WIDTH * ENTRY_FLOATS);
  /** Per row of the entries texture ({@link TEXTURE_WIDTH} entries): 1 when written since the last {@link ShadowBins.beginFrame}. */
  dirtyEntryRows = new Uint8Array(1);
  /** End of the last span handed out. */
  private entryEnd = 0;
  /** Entries in spans not released. */
  private liveEntries = 0;
  /** Candidates of the current light, in parallel arrays: hull, distance bucket, first bin and bin count. */
  private candidateHulls = new Int32Array(64);
  private candidateBuckets = new Uint8Array(64);
  private candidateFirstBins = new Uint8Array(64);
  private candidateBinCounts = new Uint8Array(64);
  /** Candidate numbers in order of their bucket. */
  private order = new Int32Array(64);
  private candidateCount = 0;
  private readonly bucketCursors = new Int32Array(DISTANCE_BUCKETS);
  private readonly binCursors = new Int32Array(BIN_COUNT);
  private strips: DirectionalStrips | null = null;
  private lightX = 0;
  private lightY = 0;
  private lightRadius = 0;
  private bucketWidth = 1;

  /**
   * Starts a frame: nothing is dirty. Returns true when released spans fill more than half the
   * entries: the caller should then {@link ShadowBins.pack} the spans.
   */
  beginFrame(): boolean {
    this.dirtyBinRows.fill(0);
    this.dirtyEntryRows.fill(0);
    return this.entryEnd > 2 * this.liveEntries + TEXTURE_WIDTH;
  }

  /**
   * Moves `spans`, every span not released, in order of their first entry, to lie one after the
   * other from the first entry, and their lists' first entries in the bins with them: the entries stay as they were, no
   * light is filed anew. Marks every row dirty.
   */
  pack(spans: readonly BinSpan[]): void {
    const entries = this.entries, bins = this.bins;
    let end = 0;
    for (let i = 0; i < spans.length; i++) {
      const span = spans[i], shift = span.firstEntry - end;
      entries.copyWithin(end * ENTRY_FLOATS, span.firstEntry * ENTRY_FLOATS, (span.firstEntry + span.entryCapacity) * ENTRY_FLOATS);
      for (let b = span.row * BIN_COUNT * BIN_FLOATS + span.list, last = b + BIN_COUNT * BIN_FLOATS; b < last; b += BIN_FLOATS) bins[b] -= shift;
      span.firstEntry = end;
      end += span.entryCapacity;
      this.dirtyBinRows[span.row] = 1;
    }
    this.entryEnd = end;
    this.dirtyEntryRows.fill(1);
  }

  /** Gives up a row's span of entries (its entries are left as they are, unused); once none is left, spans start again from the first entry. */
  releaseSpan(span: BinSpan): void {
    this.liveEntries -= span.entryCapacity;
    span.entryCapacity = 0;
    if (this.liveEntries === 0) this.entryEnd = 0;
  }

  /**
   * Starts a list of the light filed for `disk` (see {@link FiledDisk}), ordered by distance buckets
   * of its bucket width ({@link bucketWidthOf} its reach: it adds nothing farther).
   */
  beginLight(disk: FiledDisk): void {
    this.lightX = disk[0];
    this.lightY = disk[1];
    this.lightRadius = disk[2];
    this.bucketWidth = disk[4];
    this.candidateCount = 0;
  }

  /** Adds the hulls `indices[0 .. count)` (prepared) as candidates of the current light. */
  addHulls(geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    for (let i = 0; i < count; i++) this.addHull(geometry, indices[i]);
  }

  /** Adds the hull at `index` (prepared) as a candidate of the current light. */
  private addHull(geometry: ShadowGeometry, index: number): void {
    const circles = geometry.circles;
    const dx = circles[3 * index] - this.lightX, dy = circles[3 * index + 1] - this.lightY, hullRadius = circles[3 * index + 2];
    const distance = Math.sqrt(dx * dx + dy * dy), nearest = distance - hullRadius, radius = this.lightRadius;
    let bucket = 0, firstBin = 0, binCount = BIN_COUNT;
    if (nearest > radius) {
      bucket = Math.min(DISTANCE_BUCKETS - 1, Math.floor(nearest / this.bucketWidth));
      // No helper calls here, only arithmetic (see Hot-path rules in docs/architecture.md).
      // asin(x) ≤ x + ASIN_CUBIC · x³ on [0, 1] (the series' coefficients are positive and sum to
      // π/2 at 1): within 0.6% below x = 0.3, no trigonometry per hull.
      const hullSine = Math.min(hullRadius / distance, 1), diskSine = Math.min(radius / nearest, 1);
      const halfWidth = hullSine + ASIN_CUBIC * hullSine * hullSine * hullSine + diskSine + ASIN_CUBIC * diskSine * diskSine * diskSine + ANGLE_MARGIN;
      if (halfWidth < MAX_TURNED_HALF_WIDTH) {
        // The directions within halfWidth of (dx, dy) lie between it turned by ± atan(t) ≥ halfWidth:
        // their pseudo-angles (see shadowLayout's bins), which grow with the angle, bound the bins.
        // (Adding halfWidth to the pseudo-angle would do too, as it grows at most 1 per radian, but
        // half as fast diagonally.) t ≥ tan(halfWidth) by Becker–Stark: π²x / (π² − 4x²).
        const t = (PI_SQUARED * halfWidth) / (PI_SQUARED - 4 * halfWidth * halfWidth);
        let from = 0, to = 0;
        for (let side = -1; side <= 1; side += 2) {
          const x = dx - side * t * dy, y = dy + side * t * dx, p = y / (Math.abs(x) + Math.abs(y));
          const bin = Math.floor((x < 0 ? 2 - p : y < 0 ? 4 + p : p) * (BIN_COUNT / 4));
          if (side < 0) from = bin;
          else to = bin;
        }
        if (to < from) to += BIN_COUNT;
        firstBin = from;
        binCount = to - from + 1;
      }
    }
    const i = this.candidateCount++;
    if (i === this.candidateHulls.length) this.growCandidates();
    this.candidateHulls[i] = index;
    this.candidateBuckets[i] = bucket;
    this.candidateFirstBins[i] = firstBin;
    this.candidateBinCounts[i] = binCount;
  }

  /**
   * Files the current light's candidates into `span`'s list of the bins of `span.row` and its span of
   * entries, moving the span to the end when they no longer fit, and marks what it wrote dirty.
   */
  endLight(geometry: ShadowGeometry, span: BinSpan): void {
    const row = span.row, rowFloats = BIN_COUNT * BIN_FLOATS;
    this.markBinRow(row);
    this.sortByBucket();
    const count = this.candidateCount, firstBins = this.candidateFirstBins, binCounts = this.candidateBinCounts, hulls = this.candidateHulls;
    const recordCounts = geometry.recordCounts, firstRecords = geometry.firstRecords, convex = geometry.convex;
    // Entries per bin, as differences from the previous bin: constant time per candidate.
    const cursors = this.binCursors.fill(0);
    let total = 0, wrapping = 0;
    for (let i = 0; i < count; i++) {
      const entries = recordCounts[hulls[i]] <= ENTRY_MAX_RECORDS ? 1 : Math.ceil(recordCounts[hulls[i]] / ENTRY_MAX_RECORDS);
      const first = firstBins[i], end = first + binCounts[i];
      total += entries * binCounts[i];
      cursors[first] += entries;
      if (end < BIN_COUNT) cursors[end] -= entries;
      else if (end > BIN_COUNT) {
        wrapping += entries;
        cursors[end - BIN_COUNT] -= entries;
      }
    }
    if (total > span.entryCapacity) this.moveSpan(span, total);
    const firstEntry = span.firstEntry;
    this.dirtyEntryRows.fill(1, Math.floor(firstEntry / TEXTURE_WIDTH), Math.floor((firstEntry + total - 1) / TEXTURE_WIDTH) + 1);
    const bins = this.bins;
    for (let bin = 0, start = firstEntry, size = wrapping; bin < BIN_COUNT; bin++) {
      size += cursors[bin];
      const b = row * rowFloats + bin * BIN_FLOATS + span.list;
      bins[b] = start;
      bins[b + 1] = size;
      cursors[bin] = start;
      start += size;
    }
    const entries = this.entries, order = this.order, circles = geometry.circles;
    for (let n = 0; n < count; n++) {
      const i = order[n], hull = hulls[i], binCount = binCounts[i];
      const x = circles[3 * hull], y = circles[3 * hull + 1], hullRadius = circles[3 * hull + 2];
      const fan = convex[hull] === 1 && recordCounts[hull] <= ENTRY_MAX_RECORDS;
      for (let record = firstRecords[hull], end = record + recordCounts[hull]; record < end; record += ENTRY_MAX_RECORDS) {
        const code = entryCode(record, Math.min(ENTRY_MAX_RECORDS, end - record), fan);
        for (let k = 0, bin = firstBins[i]; k < binCount; k++) {
          const e = cursors[bin]++ * ENTRY_FLOATS;
          entries[e] = code;
          entries[e + 1] = x;
          entries[e + 2] = y;
          entries[e + 3] = hullRadius;
          if (++bin === BIN_COUNT) bin = 0;
        }
      }
    }
  }

  /** Empties `span`'s list in every bin of its row (a list no hull is filed in), and marks the row dirty. */
  emptyList(span: BinSpan): void {
    this.markBinRow(span.row);
    const bins = this.bins;
    for (let b = span.row * BIN_COUNT * BIN_FLOATS + span.list, last = b + BIN_COUNT * BIN_FLOATS; b < last; b += BIN_FLOATS) {
      bins[b] = span.firstEntry;
      bins[b + 1] = 0;
    }
  }

  /** Marks the bins' `row` dirty, growing the bins to hold it. */
  private markBinRow(row: number): void {
    const rowFloats = BIN_COUNT * BIN_FLOATS;
    if (this.bins.length < (row + 1) * rowFloats) {
      this.bins = grow(this.bins, this.bins.length, (row + 1) * rowFloats - this.bins.length, rowFloats);
      this.dirtyBinRows = grow(this.dirtyBinRows, this.dirtyBinRows.length, this.bins.length / rowFloats - this.dirtyBinRows.length);
    }
    this.dirtyBinRows[row] = 1;
  }

  /**
   * Gives `span` room for `entries` at the end, an eighth more than asked so that a light whose
   * entries grow a little from frame to frame mostly stays put.
   */
  private moveSpan(span: BinSpan, entries: number): void {
    this.releaseSpan(span);
    const capacity = entries + (entries >> 3), rowFloats = TEXTURE_WIDTH * ENTRY_FLOATS;
    span.firstEntry = this.entryEnd;
    span.entryCapacity = capacity;
    this.entryEnd += capacity;
    this.liveEntries += capacity;
    if (this.entryEnd * ENTRY_FLOATS > this.entries.length) {
      // A grown texture is allocated and uploaded whole: no rows need marking.
      this.entries = grow(this.entries, span.firstEntry * ENTRY_FLOATS, capacity * ENTRY_FLOATS, rowFloats);
      this.dirtyEntryRows = new Uint8Array(this.entries.length / rowFloats);
    }
  }

  /**
   * Starts the row of a directional light (see `DirectionalLight`) travelling along the unit
   * (travelX, travelY), of angular radius α, over the view `strips` describes: its bins are strips
   * of the view parallel to the travel, {@link DirectionalStrips.width} wide from
   * {@link DirectionalStrips.perpBase} across it (a pixel's strip is its coordinate along
   * (−travelY, travelX), less the base, over the width), each strip's list ordered upstream first.
   */
  beginDirectional(strips: DirectionalStrips): void {
    this.strips = strips;
    this.bucketWidth = strips.bucketWidth;
    this.candidateCount = 0;
  }

  /**
   * Adds the hull at `index` (prepared) as a candidate of the current directional light when its
   * shadow can reach the view; false when it cannot. A hull in a circle of radius ρ around a point
   * at `a` along the travel and `q` across it hides from a pixel downstream only directions within α
   * of the light's, so it shades only pixels within ρ + (distance downstream) × tan α of q across
   * (plus ρ / cos α − ρ, which the margin covers for α ≤ 45°), and none upstream of a − ρ: its
   * strips are those that span reaches up to the view's far end, and a − ρ orders the lists.
   */
  addDirectionalHull(geometry: ShadowGeometry, index: number): boolean {
    const strips = this.strips!, circles = geometry.circles;
    const x = circles[3 * index], y = circles[3 * index + 1], hullRadius = circles[3 * index + 2];
    const upstreamEnd = x * strips.travelX + y * strips.travelY - hullRadius;
    if (upstreamEnd >= strips.alongEnd) return false;
    const across = y * strips.travelX - x * strips.travelY;
    const reach = hullRadius * (1 + STRIP_MARGIN) + (strips.alongEnd - upstreamEnd) * strips.tangent + strips.width * STRIP_MARGIN;
    const from = Math.floor((across - reach - strips.perpBase) / strips.width), to = Math.floor((across + reach - strips.perpBase) / strips.width);
    if (to < 0 || from >= BIN_COUNT) return false;
    const first = Math.max(0, from), last = Math.min(BIN_COUNT - 1, to);
    const i = this.candidateCount++;
    if (i === this.candidateHulls.length) this.growCandidates();
    this.candidateHulls[i] = index;
    this.candidateBuckets[i] = Math.max(0, Math.min(DISTANCE_BUCKETS - 1, Math.floor((upstreamEnd - strips.alongBase) / strips.bucketWidth)));
    this.candidateFirstBins[i] = first;
    this.candidateBinCounts[i] = last - first + 1;
    return true;
  }

  /** Fills `order` with the candidates by distance bucket (a counting sort: stable, linear). */
  private sortByBucket(): void {
    const cursors = this.bucketCursors.fill(0), buckets = this.candidateBuckets, count = this.candidateCount;
    for (let i = 0; i < count; i++) cursors[buckets[i]]++;
    for (let bucket = 0, start = 0; bucket < DISTANCE_BUCKETS; bucket++) {
      const size = cursors[bucket];
      cursors[bucket] = start;
      start += size;
    }
    for (let i = 0; i < count; i++) this.order[cursors[buckets[i]]++] = i;
  }

  private growCandidates(): void {
    const used = this.candidateCount;
    this.candidateHulls = grow(this.candidateHulls, used, used);
    this.candidateBuckets = grow(this.candidateBuckets, used, used);
    this.candidateFirstBins = grow(this.candidateFirstBins, used, used);
    this.candidateBinCounts = grow(this.candidateBinCounts, used, used);
    this.order = new Int32Array(this.candidateHulls.length);
  }
}

/**
 * Where one of a light's lists lives, kept from frame to frame: its row of bins, the list's place in
 * each bin, and its span of entries.
 */
export interface BinSpan {
  /** The light's row in {@link ShadowBins.bins}. */
  readonly row: number;
  /** Which list of each bin the span holds, as its first float in the bin: `STILL_LIST` or `MOVING_LIST` (shadowLayout). */
  readonly list: number;
  /** The first entry of its span and how many entries the span holds (0: no span yet). */
  firstEntry: number;
  entryCapacity: number;
}

/**
 * The strips of a directional light over the view, set by the shadow cache (see
 * {@link ShadowBins.beginDirectional}); `alongBase`, `perpBase`, `width` and `bucketWidth` reach the
 * shader as a uniform.
 */
export class DirectionalStrips {
  /** The unit direction the light travels. */
  travelX = 1;
  travelY = 0;
  /** tan α, α the light's angular radius. */
  tangent = 0;
  /** The view's least coordinate across the travel (along (−travelY, travelX)), where strip 0 starts. */
  perpBase = 0;
  /** Width of a strip: the view's extent across the travel over {@link BIN_COUNT}. */
  width = 1;
  /** The least coordinate along the travel of any hull searched: where the first distance bucket starts. */
  alongBase = 0;
  /** The view's greatest coordinate along the travel: hulls wholly beyond it shade nothing in view. */
  alongEnd = 0;
  /** Width of a distance bucket: (alongEnd − alongBase) / {@link DISTANCE_BUCKETS}. */
  bucketWidth = 1;
}

/** A strip's share of margin on each side of a hull's strips, and of its radius (see `addDirectionalHull`). */
const STRIP_MARGIN = 1e-3;

/** The widest half width of a hull's bins taken from its turned directions (below π/2, where the tangent's bound is finite); wider ones take every bin. */
const MAX_TURNED_HALF_WIDTH = 1.5;

/** π², for the Becker–Stark bound of the tangent (x + 0.41 x³ near 0 against tan's x + 0.33 x³). */
const PI_SQUARED = Math.PI * Math.PI;

/** `array`, or a grown copy of its first `used` entries, with room for `extra` more (length a multiple of `granule`). */
export function grow<T extends Int32Array<ArrayBuffer> | Float64Array<ArrayBuffer> | Float32Array<ArrayBuffer> | Uint32Array<ArrayBuffer> | Uint8Array<ArrayBuffer>>(array: T, used: number, extra: number, granule = 1): T {
  if (used + extra <= array.length) return array;
  const grown = new (array.constructor as new (length: number) => T)(Math.ceil(Math.max(used + extra, array.length * 2) / granule) * granule);
  grown.set(array.subarray(0, used));
  return grown;
}
