import type { Hull } from '../scene/Hull';

/**
 * Floats per point: world x, y, then the first point and point count of its hull. Edge i runs from
 * point i to the next point of its hull, so one record per point is all the shadow pass reads: it
 * finds a caster's records (an edge's start and the next point, or all of a hull's points) by number.
 */
export const POINT_FLOATS = 4;

/** Point capacity grows in whole rows of this many points, so the records fill a texture's rows exactly. */
export const POINT_ROW = 1024;

/**
 * The world-space data of every hull, packed for the GPU and independent of any light:
 * - `points`: each hull's world points, contiguous per hull, as {@link POINT_FLOATS} records that
 *   also carry the hull's point range; read by the shadow-mask pass (as a texture: the light is a
 *   uniform, so this changes only when a hull does) and the hull pass (as vertices);
 * - `triangleIndices`: each hull's triangulation as global point indices.
 *
 * Hull data is written lazily: `update` only refreshes the coarse bounds of hulls that changed
 * (constant time each) into flat arrays the hull grid reads without touching the hulls, and a hull is transformed and written by {@link ShadowGeometry.prepare} when some
 * light finds it in range, so hulls far from every light cost (almost) nothing. Only prepared
 * hulls' data is meaningful, and only they are drawn. Adding, removing or reshaping a hull
 * re-lays out everything.
 */
export class ShadowGeometry {
  points = new Float32Array(0);
  triangleIndices = new Uint32Array(0);
  pointCount = 0;
  triangleIndexCount = 0;
  /** Per row of {@link POINT_ROW} points: 1 when a hull written since the last `update` has points in it. */
  dirtyRows = new Uint8Array(0);
  /** Per hull, `Hull.coarseBounds` as of the last update: `[minX, minY, maxX, maxY]` at `4 × index`. */
  coarseBounds = new Float64Array(0);
  /** Per hull: 1 when it is enabled and valid (it may shadow a light). */
  castsShadow = new Uint8Array(0);
  /** Per hull: 1 when it is convex (and valid). */
  convex = new Uint8Array(0);
  /** Per hull: where its data sits in `points` (first point = first edge) and `triangleIndices`. */
  firstPoints = new Int32Array(0);
  pointCounts = new Int32Array(0);
  firstTriangleIndices = new Int32Array(0);
  triangleIndexCounts = new Int32Array(0);
  /** Per hull, its exact world bounds `[minX, minY, maxX, maxY]` at `4 × index`, as of its last {@link ShadowGeometry.prepare}. */
  worldBounds = new Float64Array(0);
  /** Edges of all valid hulls. */
  validEdgeCount = 0;
  private layoutHulls: Hull[] = [];
  /** Per hull: `hull.version` when `coarseBounds`, `castsShadow` and `convex` were last refreshed. */
  private refreshedVersions = new Float64Array(0);
  /** Per hull: `hull.version` when its points, triangles and `worldBounds` were last written. */
  private preparedVersions = new Float64Array(0);
  /** Per hull: its edges counted in `validEdgeCount`. */
  private countedEdges = new Int32Array(0);

  /** Forgets the layout so the next update rewrites and re-uploads everything (e.g. after a context loss). */
  invalidate(): void {
    this.layoutHulls = [];
  }

  /**
   * Lays the arrays out for `hulls` if they changed, and refreshes the per-hull flat arrays of the
   * hulls that changed. Reads one field of an unchanged hull: touching every hull's objects each
   * frame (bounds arrays, getters) cost more than everything else on ten thousand far hulls.
   */
  update(hulls: readonly Hull[]): void {
    this.dirtyRows.fill(0);
    // Indexed loops here and in other per-frame code: a for-of over thousands of hulls showed
    // iterator results on the heap every frame.
    if (hulls.length !== this.layoutHulls.length || !this.refresh(hulls)) {
      this.layOut(hulls);
      this.refresh(hulls);
    }
  }

  /**
   * Brings the world points, triangles and `worldBounds` of the hull at `index` in the last update's
   * list up to date (and marks their point rows dirty) if the hull changed since they were written.
   * Flat arrays only when it did not: the planner calls this for every hull in every light's range.
   */
  prepare(index: number): void {
    if (this.preparedVersions[index] === this.refreshedVersions[index]) return;
    this.preparedVersions[index] = this.refreshedVersions[index];
    const hull = this.layoutHulls[index];
    hull.updateWorld();
    this.writeHull(hull, index);
    const first = this.firstPoints[index];
    this.dirtyRows.fill(1, Math.floor(first / POINT_ROW), Math.floor((first + this.pointCounts[index] - 1) / POINT_ROW) + 1);
  }

  /** Refreshes the flat arrays of changed hulls; false when the list or a hull's shape no longer fits the layout. */
  private refresh(hulls: readonly Hull[]): boolean {
    const layout = this.layoutHulls;
    for (let i = 0; i < hulls.length; i++) {
      const hull = hulls[i];
      if (hull !== layout[i]) return false;
      if (hull.version === this.refreshedVersions[i]) continue;
      if (this.pointCounts[i] !== hull.edgeCount || this.triangleIndexCounts[i] !== hull.worldTriangles.length) return false;
      this.refreshHull(hull, i);
    }
    return true;
  }

  private refreshHull(hull: Hull, index: number): void {
    this.refreshedVersions[index] = hull.version;
    hull.updateCoarseBounds();
    const from = hull.coarseBounds, to = this.coarseBounds;
    to[4 * index] = from[0];
    to[4 * index + 1] = from[1];
    to[4 * index + 2] = from[2];
    to[4 * index + 3] = from[3];
    this.castsShadow[index] = hull.enabled && hull.valid ? 1 : 0;
    this.convex[index] = hull.convex ? 1 : 0;
    const edges = hull.valid ? hull.edgeCount : 0;
    this.validEdgeCount += edges - this.countedEdges[index];
    this.countedEdges[index] = edges;
  }

  private layOut(hulls: readonly Hull[]): void {
    this.layoutHulls = hulls.slice();
    this.allocatePerHull(hulls.length);
    let points = 0, triangleIndices = 0;
    for (let i = 0; i < hulls.length; i++) {
      this.firstPoints[i] = points;
      this.pointCounts[i] = hulls[i].edgeCount;
      this.firstTriangleIndices[i] = triangleIndices;
      this.triangleIndexCounts[i] = hulls[i].worldTriangles.length;
      points += this.pointCounts[i];
      triangleIndices += this.triangleIndexCounts[i];
    }
    this.pointCount = points;
    this.triangleIndexCount = triangleIndices;
    if (this.points.length < points * POINT_FLOATS) {
      const wanted = Math.max(points, Math.ceil(this.points.length / POINT_FLOATS * 1.5));
      this.points = new Float32Array(Math.ceil(wanted / POINT_ROW) * POINT_ROW * POINT_FLOATS);
      this.dirtyRows = new Uint8Array(this.points.length / (POINT_ROW * POINT_FLOATS));
    }
    if (this.triangleIndices.length < triangleIndices) {
      this.triangleIndices = new Uint32Array(Math.max(triangleIndices, Math.ceil(this.triangleIndices.length * 1.5)));
    }
  }

  /** Sizes the per-hull flat arrays for `count` hulls, every hull to be refreshed. */
  private allocatePerHull(count: number): void {
    if (this.castsShadow.length < count) {
      const capacity = Math.ceil(count * 1.5);
      this.coarseBounds = new Float64Array(4 * capacity);
      this.worldBounds = new Float64Array(4 * capacity);
      this.castsShadow = new Uint8Array(capacity);
      this.convex = new Uint8Array(capacity);
      this.firstPoints = new Int32Array(capacity);
      this.pointCounts = new Int32Array(capacity);
      this.firstTriangleIndices = new Int32Array(capacity);
      this.triangleIndexCounts = new Int32Array(capacity);
      this.refreshedVersions = new Float64Array(capacity);
      this.preparedVersions = new Float64Array(capacity);
      this.countedEdges = new Int32Array(capacity);
    }
    this.refreshedVersions.fill(-1);
    this.preparedVersions.fill(-1);
    this.countedEdges.fill(0);
    this.validEdgeCount = 0;
  }

  private writeHull(hull: Hull, index: number): void {
    const world = hull.worldPoints;
    const points = this.points;
    const first = this.firstPoints[index], count = this.pointCounts[index];
    for (let i = 0, k = first * POINT_FLOATS; i < count; i++, k += POINT_FLOATS) {
      points[k] = world[2 * i];
      points[k + 1] = world[2 * i + 1];
      points[k + 2] = first;
      points[k + 3] = count;
    }
    const triangles = hull.worldTriangles, firstIndex = this.firstTriangleIndices[index];
    for (let k = 0; k < triangles.length; k++) this.triangleIndices[firstIndex + k] = first + triangles[k];
    const from = hull.worldBounds, to = this.worldBounds;
    for (let k = 0; k < 4; k++) to[4 * index + k] = from[k];
  }
}
