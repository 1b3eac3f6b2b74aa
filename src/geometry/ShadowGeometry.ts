import type { Hull } from '../scene/Hull';

/**
 * Floats per point: world x, y, then the first point and point count of its hull. Edge i runs from
 * point i to the next point of its hull, so one record per point is all the shadow pass reads: it
 * draws each edge as an instance that fetches its record (and the next point) by the edge number.
 */
export const POINT_FLOATS = 4;

/** Point capacity grows in whole rows of this many points, so the records fill a texture's rows exactly. */
export const POINT_ROW = 1024;

/** Where one hull's data sits in the shared arrays. */
export interface HullSlot {
  /** First point (= first edge) of the hull in `points`. */
  firstPoint: number;
  pointCount: number;
  /** First index of the hull's triangles in `triangleIndices`. */
  firstTriangleIndex: number;
  triangleIndexCount: number;
  /** `hull.version` when the slot was last written. */
  version: number;
}

/**
 * The world-space data of every hull, packed for the GPU and independent of any light:
 * - `points`: each hull's world points, contiguous per hull, as {@link POINT_FLOATS} records that
 *   also carry the hull's point range; read by the shadow-mask pass (as a texture: the light is a
 *   uniform, so this changes only when a hull does) and the hull pass (as vertices);
 * - `triangleIndices`: each hull's triangulation as global point indices.
 *
 * `update` rewrites only hulls whose version changed and reports the dirty point range; adding,
 * removing or reshaping a hull re-lays out everything.
 */
export class ShadowGeometry {
  points = new Float32Array(0);
  triangleIndices = new Uint32Array(0);
  pointCount = 0;
  triangleIndexCount = 0;
  /** Point range `[dirtyFirst, dirtyEnd)` changed by the last update (empty when equal). */
  dirtyFirst = 0;
  dirtyEnd = 0;
  /** True when the last update re-laid out the arrays (so everything must be uploaded). */
  relaidOut = false;
  private readonly slots = new Map<Hull, HullSlot>();
  private layoutHulls: Hull[] = [];

  /** Forgets the layout so the next update rewrites and re-uploads everything (e.g. after a context loss). */
  invalidate(): void {
    this.layoutHulls = [];
    this.slots.clear();
  }

  /** The slot of a hull, or undefined for a hull not in the last update. */
  slotOf(hull: Hull): HullSlot | undefined {
    return this.slots.get(hull);
  }

  /** Brings the arrays up to date with `hulls`, touching only what changed. */
  update(hulls: readonly Hull[]): void {
    this.dirtyFirst = Infinity;
    this.dirtyEnd = 0;
    this.relaidOut = this.needsLayout(hulls);
    if (this.relaidOut) this.layOut(hulls);
    // Indexed loops here and in other per-frame code: a for-of over thousands of hulls showed
    // iterator results on the heap every frame.
    for (let i = 0; i < hulls.length; i++) {
      const hull = hulls[i];
      const slot = this.slots.get(hull)!;
      const moved = hull.updateWorld();
      if (!moved && slot.version === hull.version && !this.relaidOut) continue;
      slot.version = hull.version;
      this.writeHull(hull, slot);
      if (slot.firstPoint < this.dirtyFirst) this.dirtyFirst = slot.firstPoint;
      if (slot.firstPoint + slot.pointCount > this.dirtyEnd) this.dirtyEnd = slot.firstPoint + slot.pointCount;
    }
    if (this.dirtyEnd === 0) this.dirtyFirst = 0;
  }

  private needsLayout(hulls: readonly Hull[]): boolean {
    if (hulls.length !== this.layoutHulls.length) return true;
    for (let i = 0; i < hulls.length; i++) {
      const hull = hulls[i];
      const slot = this.slots.get(hull);
      if (this.layoutHulls[i] !== hull || !slot || slot.pointCount !== hull.edgeCount
        || slot.triangleIndexCount !== hull.worldTriangles.length) return true;
    }
    return false;
  }

  private layOut(hulls: readonly Hull[]): void {
    this.slots.clear();
    this.layoutHulls = hulls.slice();
    let points = 0, triangleIndices = 0;
    for (const hull of hulls) {
      hull.updateWorld();
      const slot: HullSlot = {
        firstPoint: points, pointCount: hull.edgeCount,
        firstTriangleIndex: triangleIndices, triangleIndexCount: hull.worldTriangles.length, version: -1,
      };
      this.slots.set(hull, slot);
      points += slot.pointCount;
      triangleIndices += slot.triangleIndexCount;
    }
    this.pointCount = points;
    this.triangleIndexCount = triangleIndices;
    if (this.points.length < points * POINT_FLOATS) {
      const wanted = Math.max(points, Math.ceil(this.points.length / POINT_FLOATS * 1.5));
      this.points = new Float32Array(Math.ceil(wanted / POINT_ROW) * POINT_ROW * POINT_FLOATS);
    }
    if (this.triangleIndices.length < triangleIndices) {
      this.triangleIndices = new Uint32Array(Math.max(triangleIndices, Math.ceil(this.triangleIndices.length * 1.5)));
    }
  }

  private writeHull(hull: Hull, slot: HullSlot): void {
    const world = hull.worldPoints;
    const points = this.points;
    for (let i = 0, k = slot.firstPoint * POINT_FLOATS; i < slot.pointCount; i++, k += POINT_FLOATS) {
      points[k] = world[2 * i];
      points[k + 1] = world[2 * i + 1];
      points[k + 2] = slot.firstPoint;
      points[k + 3] = slot.pointCount;
    }
    const triangles = hull.worldTriangles;
    for (let k = 0; k < triangles.length; k++) this.triangleIndices[slot.firstTriangleIndex + k] = slot.firstPoint + triangles[k];
  }
}
