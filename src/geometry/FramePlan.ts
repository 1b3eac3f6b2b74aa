import type { ReadonlyMat4 } from 'gl-matrix';
import type { Hull } from '../scene/Hull';
import type { Light } from '../scene/lights';
import { HullGrid } from './HullGrid';
import { isInsidePolygon } from './polygon';
import { scissorOf } from './scissor';
import { INDICES_PER_EDGE, VERTICES_PER_EDGE, type HullSlot, type ShadowGeometry } from './ShadowGeometry';

/** What the passes need to draw one light: its quad, scissor and the index ranges of the hulls in its range. */
export class LightDraw {
  light!: Light;
  /** `[cornerX, cornerY, axisXx, axisXy, axisYx, axisYy]`, see `Light.writeQuad`. */
  readonly quad = new Float32Array(6);
  /** `[minX, minY, maxX, maxY]` of the quad and the light centre, in world units. */
  readonly bounds = new Float64Array(4);
  /** `[x, y, width, height]` in lightmap pixels. */
  readonly scissor = new Int32Array(4);
  /** Offset and count, in the plan's `indices`, of the shadow-quad indices of the edges in range. */
  edgeIndexOffset = 0;
  edgeIndexCount = 0;
  /** Offset and count, in the plan's `indices`, of the triangles of the hulls in range. */
  triangleIndexOffset = 0;
  triangleIndexCount = 0;
  /** Number of hulls in range that shadow this light. */
  hullCount = 0;
}

/**
 * Decides each frame which lights are drawn and, per light, which hulls shadow it: a light is
 * skipped when disabled, black, off screen, or when its centre is inside a hull it does not
 * ignore. The index lists of all drawn lights share one array, reused from frame to frame.
 */
export class FramePlan {
  indices = new Uint32Array(1024);
  indexCount = 0;
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  private readonly slotsInRange: HullSlot[] = [];
  private readonly grid = new HullGrid();

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.indexCount = 0;
    this.drawCount = 0;
    this.grid.build(hulls);
    for (const light of lights) {
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
    inRange.length = 0;
    if (light.castsShadows && !this.findHullsInRange(draw, hulls, geometry)) return false;
    draw.hullCount = inRange.length;
    draw.edgeIndexOffset = this.indexCount;
    for (const slot of inRange) this.appendEdges(slot.firstPoint, slot.pointCount);
    draw.edgeIndexCount = this.indexCount - draw.edgeIndexOffset;
    draw.triangleIndexOffset = this.indexCount;
    for (const slot of inRange) this.appendTriangles(geometry, slot);
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
        && isInsidePolygon(geometry.points, lx, ly, slot.firstPoint, slot.pointCount)) return false;
      this.slotsInRange.push(slot);
    }
    return true;
  }

  private appendTriangles(geometry: ShadowGeometry, slot: HullSlot): void {
    this.ensureCapacity(slot.triangleIndexCount);
    const source = geometry.triangleIndices;
    const indices = this.indices;
    let k = this.indexCount;
    for (let i = slot.firstTriangleIndex, end = i + slot.triangleIndexCount; i < end; i++) indices[k++] = source[i];
    this.indexCount = k;
  }

  private appendEdges(firstEdge: number, edgeCount: number): void {
    this.ensureCapacity(edgeCount * INDICES_PER_EDGE);
    const indices = this.indices;
    let k = this.indexCount;
    for (let e = firstEdge; e < firstEdge + edgeCount; e++) {
      const base = e * VERTICES_PER_EDGE;
      indices[k++] = base;
      indices[k++] = base + 1;
      indices[k++] = base + 2;
      indices[k++] = base + 2;
      indices[k++] = base + 3;
      indices[k++] = base;
    }
    this.indexCount = k;
  }

  private ensureCapacity(extra: number): void {
    if (this.indexCount + extra <= this.indices.length) return;
    const grown = new Uint32Array(Math.max(this.indexCount + extra, this.indices.length * 2));
    grown.set(this.indices.subarray(0, this.indexCount));
    this.indices = grown;
  }
}

function writeBounds(draw: LightDraw): void {
  const q = draw.quad;
  const [lx, ly] = draw.light.position;
  const b = draw.bounds;
  b[0] = Math.min(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[1] = Math.min(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
  b[2] = Math.max(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[3] = Math.max(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
}

