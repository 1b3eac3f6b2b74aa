import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import type { Hull } from '../scene/Hull';
import { DirectionalLight, type Light } from '../scene/lights';
import { HullGrid } from './HullGrid';
import { isInsidePolygon } from './polygon';
import { scissorOf } from './scissor';
import { DirectionalStrips, DISTANCE_BUCKETS, grow, ShadowBins } from './ShadowBins';
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
  /** A directional light's strips over the view (its bins). */
  readonly strips = new DirectionalStrips();
}

/**
 * Decides each frame which lights are drawn and, per light, which hulls shadow it: a light is
 * skipped when disabled, black, off screen, or when its centre is inside a hull that shadows it
 * (one it does not ignore, in one of its `shadowLayers`). The shadow bins of all drawn lights share the arrays of one {@link ShadowBins}, reused
 * from frame to frame.
 */
export class FramePlan {
  /** The records in range of each shadowed light, filed into angular bins. */
  readonly bins = new ShadowBins();
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  /** Indices of the hulls in range of the current light: the first `inRangeCount` entries. */
  private hullsInRange = new Int32Array(64);
  private inRangeCount = 0;
  private readonly grid = new HullGrid();
  /** Box around the bounds of every light placed this frame that casts shadows: the grid files only hulls inside it. */
  private readonly reach = new Float64Array(4);
  private readonly inverseViewProjection = mat4.create();
  /** The box a directional light's search covers: the view swept upstream. */
  private readonly upstreamBox = new Float64Array(4);

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.bins.reset();
    this.drawCount = 0;
    const placed = this.placeLights(lights, viewProjection, targetWidth, targetHeight);
    this.grid.build(geometry.coarseBounds, geometry.castsShadow, hulls.length, this.reach);
    // Keeps the placed lights whose centre is not inside a hull, in order.
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i];
      if (draw.light instanceof DirectionalLight) this.collectDirectionalHulls(draw, hulls, geometry);
      else if (!this.collectHulls(draw, hulls, geometry)) continue;
      this.draws[i] = this.draws[this.drawCount];
      this.draws[this.drawCount++] = draw;
    }
  }

  /**
   * Puts the enabled, visible, on-screen lights' quads, bounds and scissors in the first draws and
   * their shadow casters' bounds together in `reach`; returns how many.
   */
  private placeLights(lights: readonly Light[], viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number): number {
    const reach = this.reach;
    reach[0] = reach[1] = Infinity;
    reach[2] = reach[3] = -Infinity;
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
      if (!light.castsShadows) continue;
      const b = light instanceof DirectionalLight ? writeUpstreamBox(draw, this.upstreamBox) : draw.bounds;
      if (b[0] < reach[0]) reach[0] = b[0];
      if (b[1] < reach[1]) reach[1] = b[1];
      if (b[2] > reach[2]) reach[2] = b[2];
      if (b[3] > reach[3]) reach[3] = b[3];
    }
    return placed;
  }

  /** Files the records of the hulls in range into the light's bins; false when the light centre is inside a hull. */
  private collectHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light;
    this.inRangeCount = 0;
    if (light.castsShadows && !this.findHullsInRange(draw, hulls, geometry)) return false;
    const count = this.inRangeCount, inRange = this.hullsInRange;
    draw.hullCount = count;
    if (count === 0) return true;
    const bins = this.bins;
    bins.beginLight(light.position[0], light.position[1], light.radius, draw.reach);
    for (let i = 0; i < count; i++) bins.addHull(geometry, inRange[i]);
    draw.binRow = bins.endLight(geometry);
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
    const layers = geometry.layers, shadowLayers = light.shadowLayers;
    for (let i = 0; i < count; i++) {
      const index = grid.found[i];
      if ((layers[index] & shadowLayers) === 0) continue;
      if (light.ignoredHulls.size > 0 && light.ignoredHulls.has(hulls[index])) continue;
      geometry.prepare(index);
      if (bins.addDirectionalHull(geometry, index)) draw.hullCount++;
    }
    if (draw.hullCount > 0) draw.binRow = bins.endLight(geometry);
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
   * Fills `hullsInRange` with the hulls whose exact bounds overlap the light's, transforming each
   * candidate the grid finds by its coarse bounds first (see `ShadowGeometry.prepare`), so every
   * change reaches the light this frame; false when the light centre is inside one of them. Reads
   * the geometry's flat arrays, not the hulls: this runs for every hull in every light's range.
   */
  private findHullsInRange(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light;
    const lx = light.position[0], ly = light.position[1];
    const b = draw.bounds;
    const grid = this.grid;
    const count = grid.search(b);
    this.hullsInRange = grow(this.hullsInRange, 0, count);
    const inRange = this.hullsInRange, bounds = geometry.worldBounds, layers = geometry.layers;
    const shadowLayers = light.shadowLayers;
    for (let i = 0; i < count; i++) {
      const index = grid.found[i];
      if ((layers[index] & shadowLayers) === 0) continue;
      if (light.ignoredHulls.size > 0 && light.ignoredHulls.has(hulls[index])) continue;
      geometry.prepare(index);
      const k = 4 * index;
      if (bounds[k] > b[2] || bounds[k + 2] < b[0] || bounds[k + 1] > b[3] || bounds[k + 3] < b[1]) continue;
      if (bounds[k] <= lx && lx <= bounds[k + 2] && bounds[k + 1] <= ly && ly <= bounds[k + 3]
        && hulls[index].closed && isInsidePolygon(hulls[index].worldPoints, light.position)) return false;
      inRange[this.inRangeCount++] = index;
    }
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
