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

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.indexCount = 0;
    this.edgeCount = 0;
    this.drawCount = 0;
    this.grid.build(hulls);
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      if (!light.enabled || light.intensity === 0 || light.range === 0) continue;
      const draw = this.nextDraw();
      draw.light = light;
      light.writeQuad(draw.quad);
      writeBounds(draw);
      if (!scissorOf(draw.bounds, viewProjection, targetWidth, targetHeight, draw.scissor)) continue;
      if (!this.collectHulls(draw, hulls, geometry)) continue;
      this.drawCount++;
    }
  }

  private nextDraw(): LightDraw {
    if (this.draws.length === this.drawCount) this.draws.push(new LightDraw());
    return this.draws[this.drawCount];
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

  /** Fills `slotsInRange`; false when the light centre is inside one of them. */
  private findHullsInRange(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): boolean {
    const light = draw.light;
    const lx = light.position[0], ly = light.position[1];
    const grid = this.grid;
    const count = grid.search(draw.bounds);
    for (let i = 0; i < count; i++) {
      const hull = hulls[grid.found[i]];
      if (light.ignoredHulls.size > 0 && light.ignoredHulls.has(hull)) continue;
      const h = hull.worldBounds;
      const slot = geometry.slotOf(hull)!;
      if (h[0] <= lx && lx <= h[2] && h[1] <= ly && ly <= h[3]
        && isInsidePolygon(hull.worldPoints, lx, ly, 0, slot.pointCount)) return false;
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

