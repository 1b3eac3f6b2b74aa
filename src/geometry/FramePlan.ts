import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import type { Hull } from '../scene/Hull';
import { DirectionalLight, type Light } from '../scene/lights';
import { HullGrid } from './HullGrid';
import { isInsidePolygon } from './polygon';
import { scissorOf } from './scissor';
import { type BinSpan, DirectionalStrips, DISTANCE_BUCKETS, ShadowBins } from './ShadowBins';
import { BIN_COUNT } from './shadowLayout';
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
  /** Number of hulls in range that shadow this light. */
  hullCount = 0;
  /** The light's row in the plan's `bins`, when `hullCount > 0`. */
  binRow = 0;
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
 * A point light's filing (its bins, entries, hull count, or that it is skipped) is kept from one
 * frame to the next while it is drawn, and filed anew only when something it depends on changed:
 * the light's disk, reach or quad left the ones it was filed for (a moving light's are a margin
 * wider, see {@link LightFiling}), its shadow layers, ignored hulls or `castsShadows` changed, a
 * hull whose coarse bounds (before or after the change) overlap the filed bounds changed, or the
 * hulls' layout did. A filing without a margin equals a new one but for the order of hulls within
 * a distance bucket. Directional lights are filed every frame: their strips follow the view.
 */
export class FramePlan {
  /** The records in range of each shadowed light, filed into angular bins. */
  readonly bins = new ShadowBins();
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  /** Lights filed anew by the last {@link FramePlan.build} (the others drawn kept their filing). */
  filedCount = 0;
  private readonly grid = new HullGrid();
  /** Box around the bounds of every light to be filed this frame that casts shadows: the grid files only hulls inside it. */
  private readonly reach = new Float64Array(4);
  private readonly inverseViewProjection = mat4.create();
  /** The centre of the light being filed or checked, for `isInsideHull`. */
  private readonly centre = new Float64Array(2);
  /** The box a directional light's search covers: the view swept upstream. */
  private readonly upstreamBox = new Float64Array(4);
  /** Filings by light, and by their row of bins (null where free). */
  private readonly filings = new Map<Light, LightFiling>();
  private readonly filingsByRow: (LightFiling | null)[] = [];
  private readonly freeRows: number[] = [];
  /** The filings with a span, in order of their first entry, while their spans are packed. */
  private readonly spansInOrder: LightFiling[] = [];
  /** The draws (by number) whose light moved within its kept filing this frame, `movedCount` of them: their centres are checked against the hulls. */
  private moved = new Int32Array(64);
  private movedCount = 0;
  /** The geometry layout the filings were made for. */
  private layoutVersion = -1;
  private frame = 0;

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.frame++;
    this.drawCount = 0;
    this.filedCount = 0;
    const crowded = this.bins.beginFrame();
    if (geometry.layoutVersion !== this.layoutVersion) this.forgetFilings();
    else if (crowded) this.packSpans();
    this.layoutVersion = geometry.layoutVersion;
    const placed = this.placeLights(lights, viewProjection, targetWidth, targetHeight);
    const toFile = this.findFilingsToRedo(placed, geometry);
    // Every light filed anew: their spans are laid out afresh, packed from the first entry.
    if (toFile === placed) this.releaseSpans();
    if (toFile > 0 || this.movedCount > 0) this.grid.build(geometry.coarseBounds, geometry.castsShadow, hulls.length, this.reach);
    this.checkMovedCentres(hulls, geometry);
    // Keeps the placed lights whose centre is not inside a hull, in order.
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i], filing = draw.filing;
      if (filing.filedFrame === this.frame) {
        this.filedCount++;
        if (draw.light instanceof DirectionalLight) this.collectDirectionalHulls(draw, hulls, geometry);
        else filing.skipped = !this.collectHulls(draw, hulls, geometry);
        filing.hullCount = draw.hullCount;
      }
      if (filing.skipped) continue;
      draw.hullCount = filing.hullCount;
      draw.binRow = filing.row;
      this.draws[i] = this.draws[this.drawCount];
      this.draws[this.drawCount++] = draw;
    }
    this.releaseUnusedFilings();
  }

  /**
   * Gives each placed light its filing, marks the filings whose light or whose hulls changed (see
   * {@link FramePlan}) as not current and records them anew (to be filed), lists in `moved` the
   * kept filings of lights that moved, and puts the bounds of both kinds of light's shadow casters
   * together in `reach`; returns how many are to be filed.
   */
  private findFilingsToRedo(placed: number, geometry: ShadowGeometry): number {
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i];
      const filing = this.filingOf(draw.light);
      draw.filing = filing;
      filing.usedFrame = this.frame;
      if (filing.current && !filing.matches(draw)) filing.current = false;
    }
    // Every changed hull against every filing, kept or left by its light (the next one then has no
    // margin, see LightFiling): few changes in a scene that keeps many.
    const boxes = geometry.changedBoxes, changed = geometry.changedCount;
    for (let i = 0; i < placed; i++) {
      const filing = this.draws[i].filing, b = filing.filedBounds;
      for (let k = 0; k < changed; k++) {
        if (boxes[4 * k] > b[2] || boxes[4 * k + 2] < b[0] || boxes[4 * k + 1] > b[3] || boxes[4 * k + 3] < b[1]) continue;
        filing.endByHulls();
        break;
      }
    }
    const reach = this.reach;
    reach[0] = reach[1] = Infinity;
    reach[2] = reach[3] = -Infinity;
    let count = 0;
    this.movedCount = 0;
    if (this.moved.length < placed) this.moved = new Int32Array(2 * placed);
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i], filing = draw.filing;
      let b: Float64Array;
      if (!filing.current) {
        count++;
        filing.record(draw, this.frame);
        if (!draw.light.castsShadows) continue;
        b = draw.light instanceof DirectionalLight ? writeUpstreamBox(draw, this.upstreamBox) : filing.filedBounds;
      } else if (!filing.skipped && filing.centreMoved()) {
        this.moved[this.movedCount++] = i;
        b = draw.bounds;
      } else continue;
      if (b[0] < reach[0]) reach[0] = b[0];
      if (b[1] < reach[1]) reach[1] = b[1];
      if (b[2] > reach[2]) reach[2] = b[2];
      if (b[3] > reach[3]) reach[3] = b[3];
    }
    return count;
  }

  /**
   * Checks the centres of the lights that moved within their kept filing (see `moved`): a light
   * whose centre is now inside a hull that shadows it is filed anew (which skips it).
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
      this.bins.releaseSpan(filing);
      this.filings.delete(filing.light);
      this.filingsByRow[row] = null;
      this.freeRows.push(row);
    }
  }

  /** Packs the spans of the filings that have one (see `ShadowBins.pack`), in order of their first entry. */
  private packSpans(): void {
    const spans = this.spansInOrder;
    spans.length = 0;
    for (let row = 0; row < this.filingsByRow.length; row++) {
      const filing = this.filingsByRow[row];
      if (filing && filing.entryCapacity > 0) spans.push(filing);
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
      if (filing) this.bins.releaseSpan(filing);
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

  /** Files the records of the hulls in range into the light's bins; false when the light centre is inside a hull. */
  private collectHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light, filing = draw.filing;
    draw.hullCount = 0;
    if (!light.castsShadows) return true;
    this.bins.beginLight(filing.originX, filing.originY, filing.filedRadius, filing.filedReach);
    if (!this.addHullsInRange(draw, hulls, geometry)) return false;
    if (draw.hullCount > 0) this.bins.endLight(geometry, draw.filing);
    return true;
  }

  /**
   * Files the hulls whose shadow can reach the view into a directional light's strips (see
   * `ShadowBins.addDirectionalHull`): those the grid finds upstream of the view, in its layers and
   * not ignored. Never skips the light: it has no centre to be inside a hull.
   */
  private collectDirectionalHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const light = draw.light as DirectionalLight;
    draw.hullCount = 0;
    if (!light.castsShadows) return;
    const strips = draw.strips, bins = this.bins, grid = this.grid;
    const box = writeUpstreamBox(draw, this.upstreamBox);
    const count = grid.search(box);
    writeStrips(draw, light, grid.extent, strips);
    bins.beginDirectional(strips);
    for (let i = 0; i < count; i++) {
      const index = grid.found[i];
      if (!shadows(light, hulls, geometry, index)) continue;
      geometry.prepare(index);
      if (bins.addDirectionalHull(geometry, index)) draw.hullCount++;
    }
    if (draw.hullCount > 0) bins.endLight(geometry, draw.filing);
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
   * Adds to the light's bins, as candidates, the hulls whose exact bounds overlap its filed bounds
   * and whose circle reaches within its filed reach of its centre (see `LightFiling`), transforming
   * each candidate the grid finds by its coarse bounds first (see `ShadowGeometry.prepare`), so every
   * change reaches the light this frame; counts them in `draw.hullCount`. False when the light
   * centre is inside one of them. Reads the geometry's flat arrays, not the hulls: this runs for
   * every hull in every light's range.
   */
  private addHullsInRange(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light, filing = draw.filing;
    const lx = filing.originX, ly = filing.originY;
    this.centre[0] = lx;
    this.centre[1] = ly;
    const b = filing.filedBounds;
    const grid = this.grid;
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
      if (isInsideHull(hulls, geometry, index, this.centre)) return false;
      found[added++] = index;
    }
    // Filed in a loop of its own: inlined here, the bins' arithmetic would pass doubles to helpers
    // V8 no longer inlines (its budget per function spent), boxing them for every hull.
    this.bins.addHulls(geometry, found, added);
    draw.hullCount = added;
    return true;
  }
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
 * How many frames a moving light's filing should last at the speed it last moved: its margin is
 * that many frames of travel (see {@link LightFiling}).
 */
const MARGIN_FRAMES = 8;
/** A filing's margin is at most this share of the light's reach: a fast light is filed more often rather than with ever wider bins. */
const MAX_MARGIN_SHARE = 1 / 16;

/**
 * A light's filing as of the frame it was made (see {@link FramePlan}): what it depends on, and what
 * it gave: the hull count, whether the light is skipped, its row of bins and span of entries.
 *
 * A point light is filed for a disk and a reach a margin wider than its own, around its centre
 * then (the bins' origin): every segment from a pixel in its reach to its disk is one from a pixel
 * in the wider reach to the wider disk, so the filing holds, unchanged, while the light's disk and
 * reach stay inside the wider ones and its quad inside the filed bounds; the shader takes bins and
 * distance buckets from the origin (the chunk shadow-visibility). The margin is 0 for a light that
 * has not moved, and for one that moved, {@link MARGIN_FRAMES} frames of the speed it moved at
 * between its last two filings, at most {@link MAX_MARGIN_SHARE} of its reach: a light that keeps
 * moving is filed anew every few frames, and its bins are wider by the margin's angle, which costs
 * its pixels a few more hulls to look at. A light is filed without a margin when a hull within its
 * last filing's bounds changed (whether or not the light also left it): where hulls keep changing,
 * no filing lasts, and wider bins would only cost.
 */
class LightFiling implements BinSpan {
  /** Whether the filing still holds: false until made, and once something it depends on changed. */
  current = false;
  skipped = false;
  hullCount = 0;
  firstEntry = 0;
  entryCapacity = 0;
  /** The last frame the light was placed in. */
  usedFrame = 0;
  /** The centre the bins were filed around: the light's centre when filed. */
  originX = 0;
  originY = 0;
  /** The disk radius and the reach the bins were filed for: the light's, plus the margin. */
  filedRadius = 0;
  filedReach = 0;
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
  private readonly ignoredHulls: Hull[] = [];

  constructor(readonly light: Light, readonly row: number) {}

  /** Records what the filing about to be made this frame depends on (`draw` is the light's, placed this frame), with its margin. */
  record(draw: LightDraw, frame: number): void {
    const light = this.light, x = light.position[0], y = light.position[1];
    const dx = x - this.originX, dy = y - this.originY;
    const moved = this.filedFrame > 0 ? Math.sqrt(dx * dx + dy * dy) : 0;
    const speed = moved / Math.max(1, frame - this.filedFrame);
    const margin = light instanceof DirectionalLight || this.endedByHulls ? 0 : Math.min(MARGIN_FRAMES * speed, MAX_MARGIN_SHARE * draw.reach);
    this.endedByHulls = false;
    this.filedFrame = frame;
    this.current = true;
    this.originX = this.checkedX = x;
    this.originY = this.checkedY = y;
    this.filedRadius = light.radius + margin;
    this.filedReach = draw.reach + margin;
    const b = draw.bounds, own = this.filedBounds;
    own[0] = b[0] - margin;
    own[1] = b[1] - margin;
    own[2] = b[2] + margin;
    own[3] = b[3] + margin;
    this.castsShadows = light.castsShadows;
    this.shadowLayers = light.shadowLayers;
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
    if (light instanceof DirectionalLight || light.castsShadows !== this.castsShadows
      || light.shadowLayers !== this.shadowLayers || !this.sameIgnoredHulls()) return false;
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

  /** Writes the bins' origin and the disk radius they were filed for (the shader's `u_binning` for a light with a centre). */
  writeBinning(out: Float32Array): void {
    out[0] = this.originX;
    out[1] = this.originY;
    out[2] = this.filedRadius;
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
