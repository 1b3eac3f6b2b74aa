import type { Hull } from '../scene/Hull';
import { DirectionalLight } from '../scene/DirectionalLight';
import type { Light, ShadowType } from '../scene/Light';
import type { LightDraw } from './lightPlacement';
import { type BinSpan, bucketWidthOf, type FiledDisk, type ShadowBins } from './ShadowBins';
import { MOVING_LIST, STILL_LIST, TILE_COLUMNS, TILE_ROWS } from './shadowLayout';

/** A filing's `movingCount` when its moving list in the bins is not known to be written. */
const UNWRITTEN = -1;

/**
 * How many frames a moving light's filing should last at the speed it last moved: its margin is
 * that many frames of travel (see {@link LightFiling}).
 */
const MARGIN_FRAMES = 8;
/** A filing's margin is at most this share of the light's reach: a fast light is filed more often rather than with ever wider bins. */
const MAX_MARGIN_SHARE = 1 / 16;
/**
 * And at most this share of the light's disk radius: the bins a hull near the light covers widen
 * with the filed disk (and the hulls within it are in every bin), which every pixel pays for. A
 * hard light (radius 0) that moves is filed every frame.
 */
const MAX_MARGIN_RADIUS_SHARE = 1 / 4;

/**
 * The lights' filings, kept from frame to frame: one per light placed, each on a row of the bins
 * (and of the tile classes) of its own, freed when its light is not placed in a frame.
 */
export class FilingTable {
  /** Filings by light, and by their row of bins (null where free). */
  private readonly byLight = new Map<Light, LightFiling>();
  private readonly byRow: (LightFiling | null)[] = [];
  private readonly freeRows: number[] = [];
  /** The filings' spans that hold entries, in order of their first entry, while they are packed. */
  private readonly spansInOrder: BinSpan[] = [];

  constructor(private readonly bins: ShadowBins) {}

  /** The light's filing, a new one (on a free row) when it has none. */
  of(light: Light): LightFiling {
    let filing = this.byLight.get(light);
    if (filing) return filing;
    const row = this.freeRows.length > 0 ? this.freeRows.pop()! : this.byRow.length;
    filing = new LightFiling(light, row);
    this.byLight.set(light, filing);
    this.byRow[row] = filing;
    return filing;
  }

  /** Frees the rows and spans of the filings not used in `frame` (their lights off screen, disabled, removed). */
  releaseUnused(frame: number): void {
    for (let row = 0; row < this.byRow.length; row++) {
      const filing = this.byRow[row];
      if (!filing || filing.usedFrame === frame) continue;
      this.releaseSpansOf(filing);
      this.byLight.delete(filing.light);
      this.byRow[row] = null;
      this.freeRows.push(row);
    }
  }

  /** Packs the filings' spans that hold entries (see `ShadowBins.pack`), in order of their first entry. */
  packSpans(): void {
    const spans = this.spansInOrder;
    spans.length = 0;
    for (let row = 0; row < this.byRow.length; row++) {
      const filing = this.byRow[row];
      if (filing && filing.stillSpan.entryCapacity > 0) spans.push(filing.stillSpan);
      if (filing && filing.movingSpan.entryCapacity > 0) spans.push(filing.movingSpan);
    }
    spans.sort(byFirstEntry);
    this.bins.pack(spans);
  }

  /** Marks every filing as not current and gives up its spans (after a new layout). */
  forget(): void {
    for (let row = 0; row < this.byRow.length; row++) {
      const filing = this.byRow[row];
      if (filing) filing.current = false;
    }
    this.releaseSpans();
  }

  /** Gives up every filing's spans (after a new layout, or when every light is filed anew: the spans are then laid out afresh). */
  releaseSpans(): void {
    for (let row = 0; row < this.byRow.length; row++) {
      const filing = this.byRow[row];
      if (filing) this.releaseSpansOf(filing);
    }
  }

  private releaseSpansOf(filing: LightFiling): void {
    this.bins.releaseSpan(filing.stillSpan);
    this.bins.releaseSpan(filing.movingSpan);
  }
}

function byFirstEntry(a: BinSpan, b: BinSpan): number {
  return a.firstEntry - b.firstEntry;
}

/**
 * A light's filing as of the frame it was made (see `ShadowCache`): what it depends on, and what
 * it gave: the still hulls' count, its row of bins and the spans of
 * its two lists' entries.
 *
 * A point light is filed for a disk and a reach a margin wider than its own, around its centre
 * then (the bins' origin): every segment from a pixel in its reach to its disk is one from a pixel
 * in the wider reach to the wider disk, so the filing holds, unchanged, while the light's disk and
 * reach stay inside the wider ones and its quad inside the filed bounds; the shader takes bins and
 * distance buckets from the origin (the chunk shadow-visibility). The margin is 0 for a light that
 * has not moved, and for one that moved, {@link MARGIN_FRAMES} frames of the speed it moved at
 * between its last two filings, at most {@link MAX_MARGIN_SHARE} of its reach and
 * {@link MAX_MARGIN_RADIUS_SHARE} of its radius: a light that keeps moving is filed anew every few
 * frames, and its bins are wider by the margin's angle, which costs its pixels a few more hulls to
 * look at. A light is filed without a margin when a hull within its last filing's bounds started or
 * stopped moving (whether or not the light also left it).
 */
export class LightFiling {
  /** Whether the filing still holds: false until made, and once something it depends on changed. */
  current = false;
  /** Hulls in the still hulls' list, and in the moving list as last written ({@link UNWRITTEN}: not known). */
  stillCount = 0;
  /** The still hulls' records, and whether they were left unclassified (the budget spent, see `ShadowCache.classificationBudget`). */
  stillRecords = 0;
  unclassified = false;
  movingCount = UNWRITTEN;
  readonly stillSpan: BinSpan;
  readonly movingSpan: BinSpan;
  /** The last frame the light was placed in. */
  usedFrame = 0;
  /** The centre the bins were filed around: the light's centre when filed. */
  originX = 0;
  originY = 0;
  /** The disk radius and the reach the bins were filed for: the light's, plus the margin. */
  filedRadius = 0;
  filedReach = 0;
  /** The width of the lists' distance buckets: the filed reach's (see `bucketWidthOf`). */
  bucketWidth = 1;
  /** The light's quad bounds when filed, a margin wider: the hulls were searched in this box. */
  readonly filedBounds = new Float64Array(4);
  /** Whether a hull near the light changed while the last filing held (it ended it, or would have). */
  private endedByHulls = false;
  /** The frame the filing was last recorded (0: never): the shadow cache files it in that frame. */
  filedFrame = 0;
  private castsShadows = false;
  private shadowLayers = 0;
  private shadowType: ShadowType = 'solid';
  private readonly ignoredHulls: Hull[] = [];

  constructor(readonly light: Light, readonly row: number) {
    this.stillSpan = new EntrySpan(row, STILL_LIST);
    this.movingSpan = new EntrySpan(row, MOVING_LIST);
  }

  /** Records what the filing about to be made this frame depends on (`draw` is the light's, placed this frame), with its margin. */
  record(draw: LightDraw, frame: number): void {
    const light = this.light, x = light.position[0], y = light.position[1];
    const dx = x - this.originX, dy = y - this.originY;
    const moved = this.filedFrame > 0 ? Math.sqrt(dx * dx + dy * dy) : 0;
    const speed = moved / Math.max(1, frame - this.filedFrame);
    const margin = light instanceof DirectionalLight || this.endedByHulls ? 0 : Math.min(MARGIN_FRAMES * speed, MAX_MARGIN_SHARE * draw.reach, MAX_MARGIN_RADIUS_SHARE * light.radius);
    this.endedByHulls = false;
    this.filedFrame = frame;
    this.current = true;
    this.originX = x;
    this.originY = y;
    this.filedRadius = light.radius + margin;
    this.filedReach = draw.reach + margin;
    this.bucketWidth = bucketWidthOf(this.filedReach);
    this.movingCount = UNWRITTEN;
    const b = draw.bounds, own = this.filedBounds;
    own[0] = b[0] - margin;
    own[1] = b[1] - margin;
    own[2] = b[2] + margin;
    own[3] = b[3] + margin;
    this.castsShadows = light.castsShadows;
    this.shadowLayers = light.shadowLayers;
    this.shadowType = light.shadowType;
    this.ignoredHulls.length = 0;
    light.ignoredHulls.forEach(this.addIgnoredHull, this);
  }

  /**
   * Whether the filing holds for the light placed as `draw`: its disk, reach and quad within the
   * filed ones (a directional light's filing never holds: its strips follow the view).
   */
  matches(draw: LightDraw): boolean {
    const light = this.light;
    if (light instanceof DirectionalLight || light.castsShadows !== this.castsShadows || light.shadowLayers !== this.shadowLayers
      || light.shadowType !== this.shadowType || !this.sameIgnoredHulls()) return false;
    const dx = light.position[0] - this.originX, dy = light.position[1] - this.originY;
    const moved = Math.sqrt(dx * dx + dy * dy), b = draw.bounds, own = this.filedBounds;
    return moved + light.radius <= this.filedRadius && moved + draw.reach <= this.filedReach
      && b[0] >= own[0] && b[1] >= own[1] && b[2] <= own[2] && b[3] <= own[3];
  }

  /** Marks the filing as not current because a hull within its bounds changed. */
  endByHulls(): void {
    this.current = false;
    this.endedByHulls = true;
  }

  /** Writes the disk, reach and bucket width the filing was made for into `out`, and returns it. */
  writeDisk(out: FiledDisk): FiledDisk {
    out[0] = this.originX;
    out[1] = this.originY;
    out[2] = this.filedRadius;
    out[3] = this.filedReach;
    out[4] = this.bucketWidth;
    return out;
  }

  /** Writes the bins' origin, the disk radius they were filed for and their bucket width (the shader's `u_binning` for a light with a centre). */
  writeBinning(out: Float32Array): void {
    out[0] = this.originX;
    out[1] = this.originY;
    out[2] = this.filedRadius;
    out[3] = this.bucketWidth;
  }

  /** Writes the tile grid's corner (least x and y) and a tile's width and height (the light pass's `u_tiles`): the filed bounds cut into TILE_COLUMNS × TILE_ROWS tiles. */
  writeTiles(out: Float32Array): void {
    const b = this.filedBounds;
    out[0] = b[0];
    out[1] = b[1];
    out[2] = (b[2] - b[0]) / TILE_COLUMNS;
    out[3] = (b[3] - b[1]) / TILE_ROWS;
  }

  /** Whether `light.ignoredHulls` holds the hulls it held when filed: as many, and each of those. */
  private sameIgnoredHulls(): boolean {
    const now = this.light.ignoredHulls;
    if (now.size !== this.ignoredHulls.length) return false;
    for (let i = 0; i < this.ignoredHulls.length; i++) if (!now.has(this.ignoredHulls[i])) return false;
    return true;
  }

  private addIgnoredHull(hull: Hull): void {
    this.ignoredHulls.push(hull);
  }
}

/** One of a filing's two lists (see {@link BinSpan}). */
class EntrySpan implements BinSpan {
  firstEntry = 0;
  entryCapacity = 0;

  constructor(readonly row: number, readonly list: number) {}
}
