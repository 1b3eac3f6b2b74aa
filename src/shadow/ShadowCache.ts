import type { ReadonlyMat4 } from 'gl-matrix';
import { boxesOverlap, emptyBox, extendBox } from '../geometry/boxes';
import { HullGrid } from '../geometry/HullGrid';
import type { Hull } from '../scene/Hull';
import { DirectionalLight } from '../scene/DirectionalLight';
import type { Light } from '../scene/Light';
import { shadows } from './casters';
import { DirectionalFiling } from './directionalFiling';
import { FilingTable, type LightFiling } from './filings';
import { HullMotion, MOVING_FRAMES } from './HullMotion';
import { LightTiles } from './LightTiles';
import { type LightDraw, LightPlacement } from './lightPlacement';
import { type FiledDisk, ShadowBins } from './ShadowBins';
import { SHADOW_TYPE_CODES, TILE_CLASSES } from './shadowLayout';
import type { ShadowGeometry } from './ShadowGeometry';

export { LightDraw } from './lightPlacement';

/**
 * The shadow state kept from frame to frame (each light's filing, tile classes and bins, the hulls'
 * motion), brought up to date by {@link ShadowCache.build} once per frame, which redoes only what
 * changed. It decides which lights are drawn and, per light, which hulls shadow it: a light is
 * skipped when disabled, black or off screen. A light whose centre is inside a hull is drawn like
 * any other: the part of its disk inside hulls is hidden from every pixel outside them, as the
 * exact program computes (a disk wholly inside one is dark outside it). The shadow bins of all
 * drawn lights share the arrays of one {@link ShadowBins}.
 *
 * Each bin holds two lists (see shadowLayout): the hulls that stood still for the last
 * {@link MOVING_FRAMES} frames, and the moving ones, those that changed within them. A point
 * light's filing (its still hulls' list and their count) is
 * kept from one frame to the next while it is drawn, and filed anew only when something it depends
 * on changed: the light's disk, reach or quad left the ones it was filed for (a moving light's are a
 * margin wider, see {@link LightFiling}), its shadow layers, ignored hulls or `castsShadows`
 * changed, a hull whose coarse bounds overlap the filed bounds started or stopped moving (a still
 * hull's before and after its first change), or the hulls' layout changed. Its list of moving hulls
 * is filed every frame, around the same origin, for the same disk and reach. A filing without a margin holds the same hulls
 * as a new one (split between the lists otherwise) but for their order within a distance bucket.
 * Directional lights are filed every frame, every hull in the first list: their strips follow the
 * view.
 */
export class ShadowCache {
  /** The records in range of each shadowed light, filed into angular bins. */
  readonly bins = new ShadowBins();
  /**
   * The most hull records the cache classifies into tiles per frame (see {@link LightTiles}): a light
   * whose still hulls do not fit what is left is drawn with every tile exact and classified in a later
   * frame; a classified light whose moving hulls do not fit has every lit tile exact for the frame.
   */
  classificationBudget = DEFAULT_CLASSIFICATION_BUDGET;
  /** Shadowed point lights of the last {@link ShadowCache.build} drawn unclassified, the budget spent. */
  unclassifiedCount = 0;
  /** The tile classes of each shadowed light but the directional ones, in the rows of its bins. */
  readonly tiles = new LightTiles();
  /** The lights to draw, the first `drawCount` of them, in the lights' order. */
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  /** Lights filed anew by the last {@link ShadowCache.build} (the others drawn kept their filing). */
  filedCount = 0;
  /** The still hulls, those that cast shadows and stood still for {@link MOVING_FRAMES} frames. */
  private readonly grid = new HullGrid();
  /** The moving hulls that cast shadows (see {@link HullMotion}). */
  private readonly movingGrid = new HullGrid();
  private readonly motion = new HullMotion();
  private readonly placement = new LightPlacement();
  private readonly filings = new FilingTable(this.bins);
  private readonly directional = new DirectionalFiling();
  /** Box around the bounds of every light to be filed this frame that casts shadows: the grid files only hulls inside it. */
  private readonly reach = new Float64Array(4);
  /** Box around the filed bounds of every placed light that casts shadows: the moving grid files only hulls inside it. */
  private readonly movingReach = new Float64Array(4);
  /** The filed disk of the light being filed or classified. */
  private readonly filedDisk: FiledDisk = new Float64Array(5);
  /** The geometry layout the filings were made for. */
  private layoutVersion = -1;
  private frame = 0;
  /** What is left of this frame's classification budget, in records. */
  private budgetLeft = 0;
  /** Whether a kept filing of a light placed this frame is unclassified (the still grid is built for it). */
  private unclassifiedKept = false;

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.frame++;
    this.drawCount = 0;
    this.filedCount = 0;
    this.unclassifiedCount = 0;
    this.budgetLeft = this.classificationBudget;
    const crowded = this.bins.beginFrame();
    this.tiles.beginFrame();
    if (geometry.layoutVersion !== this.layoutVersion) {
      this.filings.forget();
      this.motion.forget(geometry, hulls.length);
    } else if (crowded) this.filings.packSpans();
    this.layoutVersion = geometry.layoutVersion;
    const motion = this.motion;
    motion.update(geometry, this.frame);
    const placed = this.placement.place(this.draws, lights, viewProjection, targetWidth, targetHeight);
    const toFile = this.findFilingsToRedo(placed);
    // Every light filed anew: their spans are laid out afresh, packed from the first entry.
    if (toFile === placed) this.filings.releaseSpans();
    if (toFile > 0 || this.unclassifiedKept) this.grid.build(geometry.coarseBounds, motion.stillCasters, hulls.length, this.reach);
    if (motion.movingCount > 0) this.movingGrid.build(geometry.coarseBounds, motion.movingCasters, hulls.length, this.movingReach);
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i], filing = draw.filing;
      if (filing.filedFrame === this.frame) {
        this.filedCount++;
        if (draw.light instanceof DirectionalLight) this.directional.file(draw, hulls, geometry, this.bins, this.grid, motion.movingCount > 0 ? this.movingGrid : null);
        else this.collectHulls(draw, hulls, geometry);
      } else if (filing.unclassified && filing.stillRecords <= this.budgetLeft) {
        this.classifyKept(draw, hulls, geometry);
      }
      this.fileMovingHulls(draw, hulls, geometry);
      this.writeOutput(draw);
    }
    this.drawCount = placed;
    this.filings.releaseUnused(this.frame);
  }

  /** Writes what the passes read of a drawn light's filing and tiles into its draw. */
  private writeOutput(draw: LightDraw): void {
    const filing = draw.filing;
    draw.hullCount = filing.stillCount + filing.movingCount;
    draw.binRow = filing.row;
    if (draw.hullCount === 0 || draw.light instanceof DirectionalLight) return;
    filing.writeBinning(draw.binning);
    filing.writeTiles(draw.tileFrame);
    this.tiles.writeCounts(filing.row, draw.tileCounts);
    this.tiles.writeLists(filing.row, draw.tileLists);
    if (draw.tileCounts[TILE_CLASSES.listed] > 0) this.tiles.lists.writeRecords(filing.row, draw.listedRecords);
    draw.closedForm = this.tiles.closedFormSuffices(filing.row);
    if (filing.unclassified) this.unclassifiedCount++;
  }

  /**
   * Gives each placed light its filing, marks the filings whose light or whose hulls changed (see
   * {@link ShadowCache}) as not current and records them anew (to be filed), and puts the bounds of
   * the lights to be filed (and of those left unclassified) together in `reach`, and those of every
   * placed light that casts shadows in `movingReach`; returns how many are to be filed.
   */
  private findFilingsToRedo(placed: number): number {
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i];
      const filing = this.filings.of(draw.light);
      draw.filing = filing;
      filing.usedFrame = this.frame;
      if (filing.current && !filing.matches(draw)) filing.current = false;
    }
    // Every hull that started or stopped moving against every filing, kept or left by its light (the
    // next one then has no margin, see LightFiling): few in a scene that keeps many.
    const boxes = this.motion.endingBoxes, ending = this.motion.endingCount;
    for (let i = 0; i < placed; i++) {
      const filing = this.draws[i].filing;
      for (let k = 0; k < ending; k++) {
        if (!boxesOverlap(boxes, k, filing.filedBounds)) continue;
        filing.endByHulls();
        break;
      }
    }
    const reach = this.reach, movingReach = this.movingReach;
    emptyBox(reach);
    emptyBox(movingReach);
    let count = 0;
    this.unclassifiedKept = false;
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i], filing = draw.filing;
      if (!filing.current) {
        count++;
        filing.record(draw, this.frame);
      }
      if (!draw.light.castsShadows) continue;
      const b = draw.light instanceof DirectionalLight ? this.directional.searchBox(draw) : filing.filedBounds;
      if (filing.filedFrame === this.frame || filing.unclassified) extendBox(reach, b);
      if (filing.filedFrame !== this.frame && filing.unclassified) this.unclassifiedKept = true;
      extendBox(movingReach, b);
    }
    return count;
  }

  /**
   * Files the still hulls in range into the light's first list (empty when it has none, as the
   * moving list may not be).
   */
  private collectHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const light = draw.light, filing = draw.filing;
    filing.stillCount = 0;
    filing.unclassified = false;
    if (!light.castsShadows) return;
    const count = this.findHullsInRange(draw, hulls, geometry, this.grid);
    filing.stillCount = count;
    this.bins.beginLight(filing.writeDisk(this.filedDisk));
    this.bins.addHulls(geometry, this.grid.found, count);
    this.bins.endLight(geometry, filing.stillSpan);
    this.beginTiles(filing);
    const records = recordsOf(geometry, this.grid.found, count);
    filing.stillRecords = records;
    filing.unclassified = records > this.budgetLeft;
    if (filing.unclassified) this.tiles.endUnclassified(filing.row, geometry, this.grid.found, count);
    else this.classifyStillHulls(filing, geometry, count);
  }

  /** Classifies the tiles of a kept filing left unclassified, its still hulls (`stillRecords`) fitting what is left of the budget. */
  private classifyKept(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const filing = draw.filing, count = this.findHullsInRange(draw, hulls, geometry, this.grid);
    filing.unclassified = false;
    this.beginTiles(filing);
    this.classifyStillHulls(filing, geometry, count);
  }

  /** Classifies a filing's tiles by the `count` still hulls the grid found, from the budget. */
  private classifyStillHulls(filing: LightFiling, geometry: ShadowGeometry, count: number): void {
    this.budgetLeft -= filing.stillRecords;
    this.tiles.addStillHulls(geometry, this.grid.found, count);
    this.tiles.endLight(filing.row);
  }

  /** Starts classifying the tiles of a point light's filing (see `LightTiles`): its filed bounds, disk and reach. */
  private beginTiles(filing: LightFiling): void {
    const light = filing.light;
    this.tiles.beginLight(filing.filedBounds, filing.writeDisk(this.filedDisk), light.isConfinedToRangeDisk(), SHADOW_TYPE_CODES[light.shadowType]);
  }

  /**
   * Files the moving hulls in range into a point light's moving list, around its filing's origin, for
   * its filed disk and reach (see {@link LightFiling}); writes the list only when it holds hulls or
   * did. A directional light's moving list stays empty: its first list holds every hull.
   */
  private fileMovingHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const light = draw.light, filing = draw.filing;
    let count = 0;
    if (light.castsShadows && this.motion.movingCount > 0 && !(light instanceof DirectionalLight)) {
      count = this.findHullsInRange(draw, hulls, geometry, this.movingGrid);
    }
    if (count > 0) {
      this.bins.beginLight(filing.writeDisk(this.filedDisk));
      this.bins.addHulls(geometry, this.movingGrid.found, count);
      this.bins.endLight(geometry, filing.movingSpan);
      this.classifyMovingHulls(filing, geometry, count);
    } else if (filing.movingCount !== 0) {
      this.bins.emptyList(filing.movingSpan);
      if (!(light instanceof DirectionalLight)) this.tiles.restoreKept(filing.row);
    }
    filing.movingCount = count;
  }

  /**
   * Adds the `count` moving hulls the moving grid found to a classified light's tiles, when they fit
   * the budget (see {@link ShadowCache.classificationBudget}); to an unclassified light's, whether
   * they make its exact tiles general.
   */
  private classifyMovingHulls(filing: LightFiling, geometry: ShadowGeometry, count: number): void {
    const found = this.movingGrid.found;
    this.beginTiles(filing);
    if (filing.unclassified) {
      this.tiles.addUnclassifiedMovingHulls(filing.row, geometry, found, count);
      return;
    }
    const records = recordsOf(geometry, found, count);
    if (records > this.budgetLeft) {
      this.tiles.addUnknownHulls(filing.row);
      return;
    }
    this.budgetLeft -= records;
    this.tiles.addMovingHulls(filing.row, geometry, found, count);
  }

  /**
   * Leaves in `grid.found` the hulls of `grid` whose exact bounds overlap the light's filed bounds
   * and whose circle reaches within its filed reach of its centre (see `LightFiling`), transforming
   * each candidate the grid finds by its coarse bounds first (see `ShadowGeometry.prepare`), so every
   * change reaches the light this frame; returns how many. Reads the geometry's flat arrays, not the hulls: this runs for every hull in every
   * light's range. (The bins file them in a loop of their own, `ShadowBins.addHulls`: see Hot-path
   * rules in docs/architecture.md.)
   */
  private findHullsInRange(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry, grid: HullGrid): number {
    const light = draw.light, filing = draw.filing;
    const lx = filing.originX, ly = filing.originY;
    const b = filing.filedBounds;
    const count = grid.search(b), found = grid.found;
    const bounds = geometry.worldBounds, circles = geometry.circles, reach = filing.filedReach;
    let added = 0;
    for (let i = 0; i < count; i++) {
      const index = found[i];
      if (!shadows(light, hulls, geometry, index)) continue;
      geometry.prepare(index);
      const k = 4 * index;
      if (bounds[k] > b[2] || bounds[k + 2] < b[0] || bounds[k + 1] > b[3] || bounds[k + 3] < b[1]) continue;
      // Beyond the reach: the segments from the pixels within it to the disk stay within it too.
      const dx = circles[3 * index] - lx, dy = circles[3 * index + 1] - ly, beyond = reach + circles[3 * index + 2];
      if (dx * dx + dy * dy >= beyond * beyond) continue;
      found[added++] = index;
    }
    return added;
  }
}

/** The records of the `count` hulls at `indices`. */
function recordsOf(geometry: ShadowGeometry, indices: Int32Array, count: number): number {
  let records = 0;
  for (let i = 0; i < count; i++) records += geometry.recordCounts[indices[i]];
  return records;
}

/**
 * Records classified into tiles per frame by default: one to two milliseconds of JavaScript on the
 * bench's machine (docs/performance.md), some twenty torches among walls a frame, and a level's
 * walking lamps every frame.
 */
const DEFAULT_CLASSIFICATION_BUDGET = 1024;
