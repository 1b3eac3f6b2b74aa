import type { ReadonlyMat4 } from 'gl-matrix';
import type { Hull } from '../scene/Hull';
import type { Light } from '../scene/lights';
import { HullGrid } from './HullGrid';
import { isInsidePolygon } from './polygon';
import { scissorOf } from './scissor';
import type { HullSlot, ShadowGeometry } from './ShadowGeometry';

/** What the passes need to draw one light: its quad, scissor, and the edges and triangles of the hulls in its range. */
export class LightDraw {
  light!: Light;
  /** `[cornerX, cornerY, axisXx, axisXy, axisYx, axisYy]`, see `Light.writeQuad`. */
  readonly quad = new Float32Array(6);
  /** `[minX, minY, maxX, maxY]` of the quad and the light centre, in world units. */
  readonly bounds = new Float64Array(4);
  /** `[x, y, width, height]` in lightmap pixels. */
  readonly scissor = new Int32Array(4);
  /** Offset and count, in the plan's `edges`, of the numbers of the edges in range (one shadow quad instance each). */
  edgeOffset = 0;
  edgeCount = 0;
  /** Offset and count, in the plan's `indices`, of the triangles of the hulls in range. */
  triangleIndexOffset = 0;
  triangleIndexCount = 0;
  /** Number of hulls in range that shadow this light. */
  hullCount = 0;
}

/**
 * Decides each frame which lights are drawn and, per light, which hulls shadow it: a light is
 * skipped when disabled, black, off screen, or when its centre is inside a hull it does not
 * ignore. The edge and triangle lists of all drawn lights share two arrays, reused from frame to frame.
 */
export class FramePlan {
  /** Triangle indices (global point numbers) of the hulls in range, per light. */
  indices = new Uint32Array(1024);
  indexCount = 0;
  /** Edge numbers (= global point numbers of their start) of the hulls in range, per light. */
  edges = new Uint32Array(1024);
  edgeCount = 0;
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  /** Slots of the hulls in range of the current light: the first `inRangeCount` entries (never truncated, which would free the backing store). */
  private readonly slotsInRange: HullSlot[] = [];
  private inRangeCount = 0;
  private readonly grid = new HullGrid();
  /** Box around the bounds of every light placed this frame that casts shadows: the grid files only hulls inside it. */
  private readonly reach = new Float64Array(4);

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.indexCount = 0;
    this.edgeCount = 0;
    this.drawCount = 0;
    const placed = this.placeLights(lights, viewProjection, targetWidth, targetHeight);
    this.grid.build(geometry.coarseBounds, geometry.castsShadow, hulls.length, this.reach);
    // Keeps the placed lights whose centre is not inside a hull, in order.
    for (let i = 0; i < placed; i++) {
      const draw = this.draws[i];
      if (!this.collectHulls(draw, hulls, geometry)) continue;
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
      light.writeQuad(draw.quad);
      writeBounds(draw);
      if (!scissorOf(draw.bounds, viewProjection, targetWidth, targetHeight, draw.scissor)) continue;
      placed++;
      if (!light.castsShadows) continue;
      const b = draw.bounds;
      if (b[0] < reach[0]) reach[0] = b[0];
      if (b[1] < reach[1]) reach[1] = b[1];
      if (b[2] > reach[2]) reach[2] = b[2];
      if (b[3] > reach[3]) reach[3] = b[3];
    }
    return placed;
  }

  /** Appends the index lists of the hulls in range; false when the light centre is inside a hull. */
  private collectHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light;
    const inRange = this.slotsInRange;
    this.inRangeCount = 0;
    if (light.castsShadows && !this.findHullsInRange(draw, hulls, geometry)) return false;
    const count = this.inRangeCount;
    draw.hullCount = count;
    draw.edgeOffset = this.edgeCount;
    for (let i = 0; i < count; i++) this.appendEdges(inRange[i].firstPoint, inRange[i].pointCount);
    draw.edgeCount = this.edgeCount - draw.edgeOffset;
    draw.triangleIndexOffset = this.indexCount;
    for (let i = 0; i < count; i++) this.appendTriangles(geometry, inRange[i]);
    draw.triangleIndexCount = this.indexCount - draw.triangleIndexOffset;
    return true;
  }

  /**
   * Fills `slotsInRange` with the hulls whose exact bounds overlap the light's, transforming each
   * candidate the grid finds by its coarse bounds first (see `ShadowGeometry.prepare`), so every
   * change reaches the light this frame; false when the light centre is inside one of them.
   */
  private findHullsInRange(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light;
    const lx = light.position[0], ly = light.position[1];
    const b = draw.bounds;
    const grid = this.grid;
    const count = grid.search(b);
    for (let i = 0; i < count; i++) {
      const index = grid.found[i];
      const hull = hulls[index];
      if (light.ignoredHulls.size > 0 && light.ignoredHulls.has(hull)) continue;
      const slot = geometry.prepare(index);
      const h = hull.worldBounds;
      if (h[0] > b[2] || h[2] < b[0] || h[1] > b[3] || h[3] < b[1]) continue;
      if (h[0] <= lx && lx <= h[2] && h[1] <= ly && ly <= h[3]
        && isInsidePolygon(hull.worldPoints, light.position, 0, slot.pointCount)) return false;
      if (this.inRangeCount === this.slotsInRange.length) this.slotsInRange.push(slot);
      else this.slotsInRange[this.inRangeCount] = slot;
      this.inRangeCount++;
    }
    return true;
  }

  private appendTriangles(geometry: ShadowGeometry, slot: HullSlot): void {
    this.indices = ensureCapacity(this.indices, this.indexCount, slot.triangleIndexCount);
    const source = geometry.triangleIndices;
    const indices = this.indices;
    let k = this.indexCount;
    for (let i = slot.firstTriangleIndex, end = i + slot.triangleIndexCount; i < end; i++) indices[k++] = source[i];
    this.indexCount = k;
  }

  private appendEdges(firstEdge: number, edgeCount: number): void {
    this.edges = ensureCapacity(this.edges, this.edgeCount, edgeCount);
    const edges = this.edges;
    let k = this.edgeCount;
    for (let e = firstEdge, end = firstEdge + edgeCount; e < end; e++) edges[k++] = e;
    this.edgeCount = k;
  }
}

/** `array`, or a grown copy of its first `used` entries, with room for `extra` more. */
function ensureCapacity(array: Uint32Array<ArrayBuffer>, used: number, extra: number): Uint32Array<ArrayBuffer> {
  if (used + extra <= array.length) return array;
  const grown = new Uint32Array(Math.max(used + extra, array.length * 2));
  grown.set(array.subarray(0, used));
  return grown;
}

function writeBounds(draw: LightDraw): void {
  const q = draw.quad;
  const lx = draw.light.position[0], ly = draw.light.position[1];
  const b = draw.bounds;
  b[0] = Math.min(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[1] = Math.min(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
  b[2] = Math.max(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[3] = Math.max(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
}

