import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import type { Hull } from '../scene/Hull';
import { DirectionalLight, type Light, type ShadowType } from '../scene/lights';
import { HullGrid } from '../geometry/HullGrid';
import { LightTiles } from './LightTiles';
import { isInsidePolygon } from '../geometry/polygon';
import { scissorOf } from './scissor';
import { type BinSpan, bucketWidthOf, DirectionalStrips, DISTANCE_BUCKETS, type FiledDisk, grow, ShadowBins } from './ShadowBins';
import { BIN_COUNT, MOVING_LIST, SHADOW_TYPE_CODES, STATIC_LIST, TILE_CLASS_COUNT, TILE_GRID } from './shadowLayout';
import type { ShadowGeometry } from './ShadowGeometry';

/** What the passes need to draw one light: its quad, scissor, and the row of its shadow bins. */
export class LightDraw {
  light!: Light;
  /** `[cornerX, cornerY, axisXx, axisXy, axisYx, axisYy]`, see `Light.writeQuad`. */
  readonly quad = new Float32Array(6);
  /** `[minX, minY, maxX, maxY]` of the quad and the light centre, in world units. */
  readonly bounds = new Float64Array(4);
  /** `[x, y, width, height]` in lightmap pixels. */
  readonly scissor = new Int32Array(4);
  /** Distance from the light's position beyond which it adds nothing (`Light.reach`). */
  reach = 0;
  /** Number of hulls in range that shadow this light (in both its lists). */
  hullCount = 0;
  /** The light's row in the plan's `bins` and its `tiles`, when `hullCount > 0`. */
  binRow = 0;
  /** A shadowed point light's tiles of each class (indexed by TILE_CLASSES), when `hullCount > 0`. */
  readonly tileCounts = new Int32Array(TILE_CLASS_COUNT);
  /** Per class of its tiles, where its rectangles' indices start in the plan's `tiles.rectangles` and how many (`LightTiles.writeLists`), when `hullCount > 0`. */
  readonly tileLists = new Int32Array(2 * TILE_CLASS_COUNT);
  /** The light's filing, kept from frame to frame. */
  filing!: LightFiling;
  /** A directional light's strips over the view (its bins). */
  readonly strips = new DirectionalStrips();
}

/**
 * Decides each frame which lights are drawn and, per light, which hulls shadow it: a light is
 * skipped when disabled, black, off screen, or when its centre is inside a hull that shadows it
 * (one it does not ignore, in one of its `shadowLayers`). The shadow bins of all drawn lights share
 * the arrays of one {@link ShadowBins}.
 *
 * Each bin holds two lists (see shadowLayout): the hulls that stood still for the last
 * {@link MOVING_FRAMES} frames, and the moving ones, those that changed within them. A point
 * light's filing (its still hulls' list, their count, or that a still hull holds its centre) is
 * kept from one frame to the next while it is drawn, and filed anew only when something it depends
 * on changed: the light's disk, reach or quad left the ones it was filed for (a moving light's are a
 * margin wider, see {@link LightFiling}), its shadow layers, ignored hulls or `castsShadows`
 * changed, a hull whose coarse bounds overlap the filed bounds started or stopped moving (a still
 * hull's before and after its first change), or the hulls' layout changed. Its list of moving hulls
 * is filed every frame, around the same origin, for the same disk and reach; a light whose centre
 * is inside a moving hull is skipped for that frame. A filing without a margin holds the same hulls
 * as a new one (split between the lists otherwise) but for their order within a distance bucket.
 * Directional lights are filed every frame, every hull in the first list: their strips follow the
 * view.
 */
export class FramePlan {
  /** The records in range of each shadowed light, filed into angular bins. */
  readonly bins = new ShadowBins();
  /**
   * The most hull records the plan classifies into tiles per frame (see {@link LightTiles}): a light
   * whose still hulls do not fit what is left is drawn with every tile exact and classified in a later
   * frame; a classified light whose moving hulls do not fit has every lit tile exact for the frame.
   */
  classificationBudget = DEFAULT_CLASSIFICATION_BUDGET;
  /** Shadowed point lights of the last {@link FramePlan.build} drawn unclassified, the budget spent. */
  unclassifiedCount = 0;
  /** The tile classes of each shadowed light but the directional ones, in the rows of its bins. */
  readonly tiles = new LightTiles();
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  /** Lights filed anew by the last {@link FramePlan.build} (the others drawn kept their filing). */
  filedCount = 0;
  /** The still hulls, those that cast shadows and stood still for {@link MOVING_FRAMES} frames. */
  private readonly grid = new HullGrid();
  /** The moving hulls that cast shadows (see `movingHulls`). */
  private readonly movingGrid = new HullGrid();
  /** Box around the bounds of every light to be filed this frame that casts shadows: the grid files only hulls inside it. */
  private readonly reach = new Float64Array(4);
  /** Box around the filed bounds of every placed light that casts shadows: the moving grid files only hulls inside it. */
  private readonly movingReach = new Float64Array(4);
  /** Per hull (by index in the layout): the last frame it changed, {@link NEVER} when it has not since the layout. */
  private hullChangedFrames = new Int32Array(0);
  /** The moving hulls, `movingHullCount` of them: those that changed within the last {@link MOVING_FRAMES} frames. */
  private movingHulls = new Int32Array(64);
  private movingHullCount = 0;
  /** Per hull: 1 when it casts shadows and stands still; and when it casts shadows and moves (what the two grids file). */
  private stillCasters = new Uint8Array(0);
  private movingCasters = new Uint8Array(0);
  /** Boxes (`[minX, minY, maxX, maxY]` each) of the hulls that started or stopped moving this frame, `endingCount` of them: the filings they overlap end. */
  private endingBoxes = new Float64Array(64);
  private endingCount = 0;
  private readonly inverseViewProjection = mat4.create();
  /** The filed disk of the light being filed or classified. */
  private readonly filedDisk: FiledDisk = new Float64Array(5);
  /** The centre of the light being filed or checked, for `isInsideHull`. */
  private readonly centre = new Float64Array(2);
  /** The box a directional light's search covers: the view swept upstream. */
  private readonly upstreamBox = new Float64Array(4);
  /** The box of the hulls both grids filed, for a directional light's strips. */
  private readonly hullsExtent = new Float64Array(4);
  /** Filings by light, and by their row of bins (null where free). */
  private readonly filings = new Map<Light, LightFiling>();
  private readonly filingsByRow: (LightFiling | null)[] = [];
  private readonly freeRows: number[] = [];
  /** The filings' spans that hold entries, in order of their first entry, while they are packed. */
  private readonly spansInOrder: BinSpan[] = [];
  /** The draws (by number) whose light moved within its kept filing this frame, `movedCount` of them: their centres are checked against the hulls. */
  private moved = new Int32Array(64);
  private movedCount = 0;
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
      this.forgetFilings();
      this.forgetHullChanges(geometry, hulls.length);
    } else if (crowded) this.packSpans();
    this.layoutVersion = geometry.layoutVersion;
    this.updateMovingHulls(geometry);
    const placed = this.placeLights(lights, viewProjection, targetWidth, targetHeight);
    const toFile = this.findFilingsToRedo(placed);
    // Every light filed anew: their spans are laid out afresh, packed from the first entry.
    if (toFile === placed) this.releaseSpans();
    if (toFile > 0 || this.movedCount > 0 || this.unclassifiedKept) this.grid.build(geometry.coarseBounds, this.stillCasters, hulls.length, this.reach);
    if (this.movingHullCount > 0) this.movingGrid.build(geometry.coarseBounds, this.movingCasters, hulls.length, this.movingReach);
    this.checkMovedCentres(hulls, geometry);
    // Keeps the placed lights whose centre is not inside a hull, in order.
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i], filing = draw.filing;
      if (filing.filedFrame === this.frame) {
        this.filedCount++;
        if (draw.light instanceof DirectionalLight) this.collectDirectionalHulls(draw, hulls, geometry);
        else filing.skipped = !this.collectHulls(draw, hulls, geometry);
      } else if (filing.unclassified && !filing.skipped && filing.stillRecords <= this.budgetLeft) {
        this.classifyKept(draw, hulls, geometry);
      }
      if (filing.skipped || !this.fileMovingHulls(draw, hulls, geometry)) continue;
      draw.hullCount = filing.hullCount + filing.movingCount;
      draw.binRow = filing.row;
      if (draw.hullCount > 0 && !(draw.light instanceof DirectionalLight)) {
        this.tiles.writeCounts(filing.row, draw.tileCounts);
        this.tiles.writeLists(filing.row, draw.tileLists);
        if (filing.unclassified) this.unclassifiedCount++;
      }
      this.draws[i] = this.draws[this.drawCount];
      this.draws[this.drawCount++] = draw;
    }
    this.releaseUnusedFilings();
  }

  /**
   * Gives each placed light its filing, marks the filings whose light or whose hulls changed (see
   * {@link FramePlan}) as not current and records them anew (to be filed), lists in `moved` the
   * kept filings of lights that moved, and puts the bounds of both kinds of light's shadow casters
   * together in `reach`, and those of every placed light that casts shadows in `movingReach`;
   * returns how many are to be filed.
   */
  private findFilingsToRedo(placed: number): number {
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i];
      const filing = this.filingOf(draw.light);
      draw.filing = filing;
      filing.usedFrame = this.frame;
      if (filing.current && !filing.matches(draw)) filing.current = false;
    }
    // Every hull that started or stopped moving against every filing, kept or left by its light (the
    // next one then has no margin, see LightFiling): few in a scene that keeps many.
    const boxes = this.endingBoxes, ending = this.endingCount;
    for (let i = 0; i < placed; i++) {
      const filing = this.draws[i].filing, b = filing.filedBounds;
      for (let k = 0; k < ending; k++) {
        if (boxes[4 * k] > b[2] || boxes[4 * k + 2] < b[0] || boxes[4 * k + 1] > b[3] || boxes[4 * k + 3] < b[1]) continue;
        filing.endByHulls();
        break;
      }
    }
    const reach = this.reach, movingReach = this.movingReach;
    emptyBox(reach);
    emptyBox(movingReach);
    let count = 0;
    this.movedCount = 0;
    this.unclassifiedKept = false;
    if (this.moved.length < placed) this.moved = new Int32Array(2 * placed);
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i], filing = draw.filing;
      if (!filing.current) {
        count++;
        filing.record(draw, this.frame);
      } else if (!filing.skipped && filing.centreMoved()) {
        this.moved[this.movedCount++] = i;
        extendBox(reach, draw.bounds);
      }
      if (!draw.light.castsShadows) continue;
      const b = draw.light instanceof DirectionalLight ? writeUpstreamBox(draw, this.upstreamBox) : filing.filedBounds;
      if (filing.filedFrame === this.frame || filing.unclassified) extendBox(reach, b);
      if (filing.filedFrame !== this.frame && filing.unclassified) this.unclassifiedKept = true;
      extendBox(movingReach, b);
    }
    return count;
  }

  /**
   * Sorts the hulls that changed this frame and those that stood still for {@link MOVING_FRAMES}
   * frames between moving and still (the two grids' casters), and lists in `endingBoxes` the boxes of
   * those that started or stopped moving: a still hull's before and after its change, where the
   * still hulls' lists may hold it; a hull that stopped, where they now should.
   */
  private updateMovingHulls(geometry: ShadowGeometry): void {
    const frame = this.frame, changedFrames = this.hullChangedFrames, castsShadow = geometry.castsShadow;
    this.endingCount = 0;
    for (let m = 0; m < this.movingHullCount;) {
      const index = this.movingHulls[m];
      if (frame - changedFrames[index] <= MOVING_FRAMES) {
        m++;
        continue;
      }
      this.movingHulls[m] = this.movingHulls[--this.movingHullCount];
      this.movingCasters[index] = 0;
      this.stillCasters[index] = castsShadow[index];
      if (castsShadow[index] !== 0) this.addEndingBox(geometry.coarseBounds, 4 * index);
    }
    for (let k = 0; k < geometry.changedCount; k++) {
      const index = geometry.changedIndices[k];
      if (frame - changedFrames[index] > MOVING_FRAMES) {
        if (this.movingHullCount === this.movingHulls.length) this.movingHulls = grow(this.movingHulls, this.movingHullCount, this.movingHullCount);
        this.movingHulls[this.movingHullCount++] = index;
        if (this.stillCasters[index] !== 0) this.addEndingBox(geometry.changedBoxes, 4 * k);
      }
      changedFrames[index] = frame;
      this.stillCasters[index] = 0;
      this.movingCasters[index] = castsShadow[index];
    }
  }

  /** Adds `boxes[at .. at + 3]` to `endingBoxes`. */
  private addEndingBox(boxes: Float64Array, at: number): void {
    const k = 4 * this.endingCount++;
    if (k === this.endingBoxes.length) this.endingBoxes = grow(this.endingBoxes, k, k);
    for (let i = 0; i < 4; i++) this.endingBoxes[k + i] = boxes[at + i];
  }

  /** After a new layout: every hull stands still. */
  private forgetHullChanges(geometry: ShadowGeometry, hullCount: number): void {
    if (this.hullChangedFrames.length < hullCount) {
      const capacity = Math.ceil(hullCount * 1.5);
      this.hullChangedFrames = new Int32Array(capacity);
      this.stillCasters = new Uint8Array(capacity);
      this.movingCasters = new Uint8Array(capacity);
    }
    this.hullChangedFrames.fill(NEVER);
    this.stillCasters.set(geometry.castsShadow.subarray(0, hullCount));
    this.movingCasters.fill(0);
    this.movingHullCount = 0;
  }

  /**
   * Checks the centres of the lights that moved within their kept filing (see `moved`): a light
   * whose centre is now inside a still hull that shadows it is filed anew (which skips it). The
   * moving hulls are checked with every light each frame (`fileMovingHulls`).
   */
  private checkMovedCentres(hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const grid = this.grid, box = this.reach, centre = this.centre;
    for (let m = 0; m < this.movedCount; m++) {
      const draw = this.draws[this.moved[m]], filing = draw.filing, light = draw.light;
      centre[0] = box[0] = box[2] = light.position[0];
      centre[1] = box[1] = box[3] = light.position[1];
      const count = grid.search(box);
      let inside = false;
      for (let i = 0; i < count && !inside; i++) {
        const index = grid.found[i];
        if (!shadows(light, hulls, geometry, index)) continue;
        geometry.prepare(index);
        inside = isInsideHull(hulls, geometry, index, centre);
      }
      if (inside) filing.record(draw, this.frame);
      else filing.checked();
    }
  }

  /** The light's filing, a new one (on a free row) when it has none. */
  private filingOf(light: Light): LightFiling {
    let filing = this.filings.get(light);
    if (filing) return filing;
    const row = this.freeRows.length > 0 ? this.freeRows.pop()! : this.filingsByRow.length;
    filing = new LightFiling(light, row);
    this.filings.set(light, filing);
    this.filingsByRow[row] = filing;
    return filing;
  }

  /** Frees the rows and spans of the lights not placed this frame (off screen, disabled, removed). */
  private releaseUnusedFilings(): void {
    for (let row = 0; row < this.filingsByRow.length; row++) {
      const filing = this.filingsByRow[row];
      if (!filing || filing.usedFrame === this.frame) continue;
      this.bins.releaseSpan(filing.stillSpan);
      this.bins.releaseSpan(filing.movingSpan);
      this.filings.delete(filing.light);
      this.filingsByRow[row] = null;
      this.freeRows.push(row);
    }
  }

  /** Packs the filings' spans that hold entries (see `ShadowBins.pack`), in order of their first entry. */
  private packSpans(): void {
    const spans = this.spansInOrder;
    spans.length = 0;
    for (let row = 0; row < this.filingsByRow.length; row++) {
      const filing = this.filingsByRow[row];
      if (filing && filing.stillSpan.entryCapacity > 0) spans.push(filing.stillSpan);
      if (filing && filing.movingSpan.entryCapacity > 0) spans.push(filing.movingSpan);
    }
    spans.sort(byFirstEntry);
    this.bins.pack(spans);
  }

  /** Marks every filing as not current and gives up its span (after a new layout). */
  private forgetFilings(): void {
    for (let row = 0; row < this.filingsByRow.length; row++) {
      const filing = this.filingsByRow[row];
      if (filing) filing.current = false;
    }
    this.releaseSpans();
  }

  /** Gives up every filing's span (after a new layout, or when every light is filed anew: the spans are then laid out afresh). */
  private releaseSpans(): void {
    for (let row = 0; row < this.filingsByRow.length; row++) {
      const filing = this.filingsByRow[row];
      if (!filing) continue;
      this.bins.releaseSpan(filing.stillSpan);
      this.bins.releaseSpan(filing.movingSpan);
    }
  }

  /** Puts the enabled, visible, on-screen lights' quads, bounds and scissors in the first draws; returns how many. */
  private placeLights(lights: readonly Light[], viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number): number {
    let placed = 0;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      if (!light.enabled || light.intensity === 0 || light.range === 0) continue;
      if (this.draws.length === placed) this.draws.push(new LightDraw());
      const draw = this.draws[placed];
      draw.light = light;
      draw.reach = light.reach();
      if (light instanceof DirectionalLight) this.writeViewQuad(viewProjection, draw.quad);
      else light.writeQuad(draw.quad);
      writeBounds(draw);
      if (!scissorOf(draw.bounds, viewProjection, targetWidth, targetHeight, draw.scissor)) continue;
      placed++;
    }
    return placed;
  }

  /**
   * Files the still hulls in range into the light's first list (empty when it has none, as the
   * moving list may not be); false when the light's centre is inside one.
   */
  private collectHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light, filing = draw.filing;
    filing.hullCount = 0;
    filing.unclassified = false;
    if (!light.castsShadows) return true;
    const count = this.findHullsInRange(draw, hulls, geometry, this.grid);
    if (count < 0) return false;
    filing.hullCount = count;
    this.bins.beginLight(filing.writeDisk(this.filedDisk));
    this.bins.addHulls(geometry, this.grid.found, count);
    this.bins.endLight(geometry, filing.stillSpan);
    this.beginTiles(filing);
    const records = recordsOf(geometry, this.grid.found, count);
    filing.stillRecords = records;
    filing.unclassified = records > this.budgetLeft;
    if (filing.unclassified) this.tiles.endUnclassified(filing.row);
    else this.classifyStillHulls(filing, geometry, count);
    return true;
  }

  /** Classifies the tiles of a kept filing left unclassified, its still hulls (`stillRecords`) fitting what is left of the budget. */
  private classifyKept(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const filing = draw.filing, count = this.findHullsInRange(draw, hulls, geometry, this.grid);
    if (count < 0) return;
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
   * did. False when the light's centre is inside one (the light is skipped this frame). A directional
   * light's moving list stays empty: its first list holds every hull.
   */
  private fileMovingHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light, filing = draw.filing;
    let count = 0;
    if (light.castsShadows && this.movingHullCount > 0 && !(light instanceof DirectionalLight)) {
      count = this.findHullsInRange(draw, hulls, geometry, this.movingGrid);
      if (count < 0) {
        filing.movingCount = UNWRITTEN;
        return false;
      }
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
    return true;
  }

  /** Adds the `count` moving hulls the moving grid found to a classified light's tiles, when they fit the budget (see {@link FramePlan.classificationBudget}). */
  private classifyMovingHulls(filing: LightFiling, geometry: ShadowGeometry, count: number): void {
    if (filing.unclassified) return;
    const found = this.movingGrid.found, records = recordsOf(geometry, found, count);
    this.beginTiles(filing);
    if (records > this.budgetLeft) {
      this.tiles.addUnknownHulls(filing.row);
      return;
    }
    this.budgetLeft -= records;
    this.tiles.addMovingHulls(filing.row, geometry, found, count);
  }

  /**
   * Files the hulls whose shadow can reach the view into a directional light's strips (see
   * `ShadowBins.addDirectionalHull`): those the grid finds upstream of the view, in its layers and
   * not ignored. Never skips the light: it has no centre to be inside a hull.
   */
  private collectDirectionalHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const light = draw.light as DirectionalLight, filing = draw.filing;
    filing.hullCount = 0;
    if (!light.castsShadows) return;
    const box = writeUpstreamBox(draw, this.upstreamBox), extent = this.hullsExtent;
    extent.set(this.grid.extent);
    if (this.movingHullCount > 0) extendBox(extent, this.movingGrid.extent);
    writeStrips(draw, light, extent, draw.strips);
    this.bins.beginDirectional(draw.strips);
    this.addDirectionalHulls(draw, hulls, geometry, this.grid, box);
    if (this.movingHullCount > 0) this.addDirectionalHulls(draw, hulls, geometry, this.movingGrid, box);
    this.bins.endLight(geometry, filing.stillSpan);
  }

  /** Adds the hulls `grid` finds in `box` whose shadow can reach the view to the directional light's candidates, counting them in its filing. */
  private addDirectionalHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry, grid: HullGrid, box: Float64Array): void {
    const light = draw.light, count = grid.search(box);
    for (let i = 0; i < count; i++) {
      const index = grid.found[i];
      if (!shadows(light, hulls, geometry, index)) continue;
      geometry.prepare(index);
      if (this.bins.addDirectionalHull(geometry, index)) draw.filing.hullCount++;
    }
  }

  /** Writes the view rectangle's world quad: clip space's corner (−1, −1) and its two edges, through the inverse view-projection. */
  private writeViewQuad(viewProjection: ReadonlyMat4, quad: Float32Array): void {
    const inverse = mat4.invert(this.inverseViewProjection, viewProjection) ?? mat4.identity(this.inverseViewProjection);
    // The views are affine in x and y (w = 1): the world point of clip (x, y) is m·(x, y, 0, 1).
    const m = inverse;
    quad[0] = -m[0] - m[4] + m[12];
    quad[1] = -m[1] - m[5] + m[13];
    quad[2] = 2 * m[0];
    quad[3] = 2 * m[1];
    quad[4] = 2 * m[4];
    quad[5] = 2 * m[5];
  }

  /**
   * Leaves in `grid.found` the hulls of `grid` whose exact bounds overlap the light's filed bounds
   * and whose circle reaches within its filed reach of its centre (see `LightFiling`), transforming
   * each candidate the grid finds by its coarse bounds first (see `ShadowGeometry.prepare`), so every
   * change reaches the light this frame; returns how many, or -1 when the light centre is inside one
   * of them. Reads the geometry's flat arrays, not the hulls: this runs for every hull in every
   * light's range. (The bins file them in a loop of their own, `ShadowBins.addHulls`: inlined here,
   * their arithmetic would pass doubles to helpers V8 no longer inlines, boxing them for every hull.)
   */
  private findHullsInRange(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry, grid: HullGrid): number {
    const light = draw.light, filing = draw.filing;
    const lx = filing.originX, ly = filing.originY;
    this.centre[0] = lx;
    this.centre[1] = ly;
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
      if (isInsideHull(hulls, geometry, index, this.centre)) return -1;
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
 * The box a directional light's hulls are searched in: the view's bounds, swept without end against
 * the travel and across it (a far hull's penumbra widens without end), bounded only on the side the
 * light travels to in each axis along which it moves.
 */
function writeUpstreamBox(draw: LightDraw, box: Float64Array): Float64Array {
  const b = draw.bounds, rotation = draw.light.rotation;
  const travelX = Math.cos(rotation), travelY = Math.sin(rotation);
  box[0] = travelX < 0 ? b[0] : -Infinity;
  box[1] = travelY < 0 ? b[1] : -Infinity;
  box[2] = travelX > 0 ? b[2] : Infinity;
  box[3] = travelY > 0 ? b[3] : Infinity;
  return box;
}

/**
 * Sets a directional light's strips over the view quad of `draw`, with the first distance bucket
 * at the least coordinate along the travel of the view and of `hulls`, the box of the hulls searched
 * (a hull's circle may reach a little further: it goes in the first bucket). Doubles go through
 * objects, not arguments: V8 boxes a double passed to a function it does not inline.
 */
function writeStrips(draw: LightDraw, light: DirectionalLight, hulls: Float64Array, strips: DirectionalStrips): void {
  const travelX = Math.cos(light.rotation), travelY = Math.sin(light.rotation), q = draw.quad;
  strips.travelX = travelX;
  strips.travelY = travelY;
  strips.tangent = Math.tan(light.angularSize / 2);
  let perpMin = Infinity, perpMax = -Infinity, alongMin = Infinity, alongMax = -Infinity;
  for (let corner = 0; corner < 4; corner++) {
    const x = q[0] + (corner & 1 ? q[2] : 0) + (corner & 2 ? q[4] : 0), y = q[1] + (corner & 1 ? q[3] : 0) + (corner & 2 ? q[5] : 0);
    const along = x * travelX + y * travelY, across = y * travelX - x * travelY;
    perpMin = Math.min(perpMin, across);
    perpMax = Math.max(perpMax, across);
    alongMin = Math.min(alongMin, along);
    alongMax = Math.max(alongMax, along);
  }
  strips.perpBase = perpMin;
  strips.width = Math.max(perpMax - perpMin, 1e-9) / BIN_COUNT;
  strips.alongEnd = alongMax;
  // HullGrid.leastAlong inline: its arguments would be boxed.
  const hullsFrom = hulls[0] > hulls[2] ? Infinity
    : (travelX < 0 ? hulls[2] : hulls[0]) * travelX + (travelY < 0 ? hulls[3] : hulls[1]) * travelY;
  strips.alongBase = Math.min(alongMin, hullsFrom);
  strips.bucketWidth = Math.max(alongMax - strips.alongBase, 1e-9) / DISTANCE_BUCKETS;
}

/** The bounds of the light's quad and, but for a directional light (which has none), its centre. */
function writeBounds(draw: LightDraw): void {
  const q = draw.quad, light = draw.light;
  const directional = light instanceof DirectionalLight;
  // A quad corner stands in for a directional light's centre: it changes nothing.
  const lx = directional ? q[0] : light.position[0], ly = directional ? q[1] : light.position[1];
  const b = draw.bounds;
  b[0] = Math.min(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[1] = Math.min(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
  b[2] = Math.max(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[3] = Math.max(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
}

/** Sets `box` to the empty box (inside out), which {@link extendBox} grows. */
function emptyBox(box: Float64Array): void {
  box[0] = box[1] = Infinity;
  box[2] = box[3] = -Infinity;
}

/** Grows `box` to hold `other` (both `[minX, minY, maxX, maxY]`). */
function extendBox(box: Float64Array, other: Float64Array): void {
  if (other[0] < box[0]) box[0] = other[0];
  if (other[1] < box[1]) box[1] = other[1];
  if (other[2] > box[2]) box[2] = other[2];
  if (other[3] > box[3]) box[3] = other[3];
}

/** Whether the hull at `index` shadows `light`: it is in one of the light's shadow layers and not ignored by it. */
function shadows(light: Light, hulls: readonly Hull[], geometry: ShadowGeometry, index: number): boolean {
  return (geometry.layers[index] & light.shadowLayers) !== 0 && !(light.ignoredHulls.size > 0 && light.ignoredHulls.has(hulls[index]));
}

/**
 * Whether `point` is inside the closed hull at `index` (prepared): its exact bounds first, then its
 * outline. The point comes in an array: V8 boxes a double passed to a function it does not inline.
 */
function isInsideHull(hulls: readonly Hull[], geometry: ShadowGeometry, index: number, point: Float64Array): boolean {
  const bounds = geometry.worldBounds, k = 4 * index, x = point[0], y = point[1];
  if (bounds[k] > x || x > bounds[k + 2] || bounds[k + 1] > y || y > bounds[k + 3] || !hulls[index].closed) return false;
  return isInsidePolygon(hulls[index].worldPoints, point);
}

function byFirstEntry(a: BinSpan, b: BinSpan): number {
  return a.firstEntry - b.firstEntry;
}

/**
 * A hull that changed within this many frames is a moving one: filed into every light's moving list
 * each frame rather than kept in the filings (which it would end at every change). A hull that
 * starts or stops moving ends the filings it overlaps once.
 */
const MOVING_FRAMES = 30;
/**
 * Records classified into tiles per frame by default: about a millisecond of JavaScript on the
 * bench's machine (docs/performance.md), some twenty torches among walls a frame, and a level's
 * walking lamps every frame.
 */
const DEFAULT_CLASSIFICATION_BUDGET = 1024;
/** `hullChangedFrames` of a hull that has not changed since the layout: it stands still. */
const NEVER = -(2 ** 30);
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
 * A light's filing as of the frame it was made (see {@link FramePlan}): what it depends on, and what
 * it gave: the still hulls' count, whether the light is skipped, its row of bins and the spans of
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
class LightFiling {
  /** Whether the filing still holds: false until made, and once something it depends on changed. */
  current = false;
  skipped = false;
  /** Hulls in the still hulls' list, and in the moving list as last written ({@link UNWRITTEN}: not known). */
  hullCount = 0;
  /** The still hulls' records, and whether they were left unclassified (the budget spent, see {@link FramePlan.classificationBudget}). */
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
  /** The frame the filing was last recorded (0: never): the plan files it in that frame. */
  filedFrame = 0;
  /** The light's centre when last checked against the hulls. */
  private checkedX = 0;
  private checkedY = 0;
  private castsShadows = false;
  private shadowLayers = 0;
  private shadowType: ShadowType = 'solid';
  private readonly ignoredHulls: Hull[] = [];

  constructor(readonly light: Light, readonly row: number) {
    this.stillSpan = new EntrySpan(row, STATIC_LIST);
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
    this.originX = this.checkedX = x;
    this.originY = this.checkedY = y;
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
   * filed ones, a skipped light's centre where it was (a directional light's filing never holds:
   * its strips follow the view).
   */
  matches(draw: LightDraw): boolean {
    const light = this.light;
    if (light instanceof DirectionalLight || light.castsShadows !== this.castsShadows || light.shadowLayers !== this.shadowLayers
      || light.shadowType !== this.shadowType || !this.sameIgnoredHulls()) return false;
    const dx = light.position[0] - this.originX, dy = light.position[1] - this.originY;
    if (this.skipped) return dx === 0 && dy === 0;
    const moved = Math.sqrt(dx * dx + dy * dy), b = draw.bounds, own = this.filedBounds;
    return moved + light.radius <= this.filedRadius && moved + draw.reach <= this.filedReach
      && b[0] >= own[0] && b[1] >= own[1] && b[2] <= own[2] && b[3] <= own[3];
  }

  /** Marks the filing as not current because a hull within its bounds changed. */
  endByHulls(): void {
    this.current = false;
    this.endedByHulls = true;
  }

  /** Whether the light's centre moved since the filing was made or last {@link LightFiling.checked}. */
  centreMoved(): boolean {
    return this.light.position[0] !== this.checkedX || this.light.position[1] !== this.checkedY;
  }

  /** Notes that the light's centre, where it is now, was found inside no hull that shadows it. */
  checked(): void {
    this.checkedX = this.light.position[0];
    this.checkedY = this.light.position[1];
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

  /** Writes the tile grid's corner (least x and y) and a tile's width and height (the light pass's `u_tiles`): the filed bounds cut into TILE_GRID² tiles. */
  writeTiles(out: Float32Array): void {
    const b = this.filedBounds;
    out[0] = b[0];
    out[1] = b[1];
    out[2] = (b[2] - b[0]) / TILE_GRID;
    out[3] = (b[3] - b[1]) / TILE_GRID;
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
