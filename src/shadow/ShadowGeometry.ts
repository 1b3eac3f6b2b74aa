import type { Hull } from '../scene/Hull';
import { RECORD_FLOATS, RECORD_POINTS, RECORDS_PER_ROW, recordTag } from './shadowLayout';

/**
 * The world-space data of every hull, packed for the GPU and independent of any light: each hull's
 * convex records (see shadowLayout), contiguous per hull, read by the light pass as a texture (the
 * light is a uniform, so this changes only when a hull does).
 *
 * Hull data is written lazily: `update` only refreshes the coarse bounds of hulls that changed
 * (constant time each) into flat arrays the hull grid reads without touching the hulls, and a hull
 * is transformed and written by {@link ShadowGeometry.prepare} when some light finds it in range,
 * so hulls far from every light cost (almost) nothing. Only prepared hulls' data is meaningful, and
 * only they are drawn. Adding, removing or reshaping a hull re-lays out everything.
 */
export class ShadowGeometry {
  /** {@link RECORD_FLOATS} floats per record, whole rows of {@link RECORDS_PER_ROW} records. */
  records = new Float32Array(0);
  /** Per record, its tag (`recordTag`): its hull and its outline edges; rows as in `records`. */
  recordTags = new Float32Array(0);
  /** Per record: its number of points (3..{@link RECORD_POINTS}). */
  recordPointCounts = new Uint8Array(0);
  recordCount = 0;
  /** Per row of {@link RECORDS_PER_ROW} records: 1 when a hull written since the last `update` has records in it. */
  dirtyRows = new Uint8Array(0);
  /** Per hull, `Hull.coarseBounds` as of the last update: `[minX, minY, maxX, maxY]` at `4 × index`. */
  coarseBounds = new Float64Array(0);
  /** Per hull: 1 when it is enabled and valid (it may shadow a light). */
  castsShadow = new Uint8Array(0);
  /** Per hull: 1 when it is convex (and valid). */
  convex = new Uint8Array(0);
  /** Per hull: `Hull.layers`. */
  layers = new Uint32Array(0);
  /** Per hull: where its records sit in `records`, and how many. */
  firstRecords = new Int32Array(0);
  recordCounts = new Int32Array(0);
  /** Per hull, its exact world bounds `[minX, minY, maxX, maxY]` at `4 × index`, as of its last {@link ShadowGeometry.prepare}. */
  worldBounds = new Float64Array(0);
  /** Per hull, a circle around its world points `[x, y, radius]` at `3 × index` (the centre of its bounds), as of its last {@link ShadowGeometry.prepare}. */
  circles = new Float64Array(0);
  /** Edges of all valid hulls. */
  validEdgeCount = 0;
  /** Counts the layouts: every hull's index and records may differ from one layout to the next. */
  layoutVersion = 0;
  /** Counts the changes to the records: a new layout, or a hull written by {@link ShadowGeometry.prepare}. */
  recordsVersion = 0;
  /**
   * Per hull the last `update` refreshed without a new layout, the box around its coarse bounds
   * before and after (`[minX, minY, maxX, maxY]` at `4 × k` for the k-th): every light whose range
   * that box misses is unaffected by the change; the k-th hull's index is `changedIndices[k]`.
   */
  changedBoxes = new Float64Array(0);
  changedIndices = new Int32Array(0);
  changedCount = 0;
  private layoutHulls: Hull[] = [];
  /** Per hull: `hull.version` when `coarseBounds`, `castsShadow` and `convex` were last refreshed. */
  private refreshedVersions = new Float64Array(0);
  /** Per hull: `hull.version` when its records, `worldBounds` and `circles` were last written. */
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
    this.changedCount = 0;
    // Indexed loops here and in other per-frame code: a for-of over thousands of hulls showed
    // iterator results on the heap every frame.
    if (hulls.length !== this.layoutHulls.length || !this.refresh(hulls)) {
      this.layOut(hulls);
      this.refresh(hulls);
      this.changedCount = 0;
    }
  }

  /**
   * Brings the records, `worldBounds` and `circles` of the hull at `index` in the last update's
   * list up to date (and marks their point rows dirty) if the hull changed since they were written.
   * Flat arrays only when it did not: the planner calls this for every hull in every light's range.
   */
  prepare(index: number): void {
    if (this.preparedVersions[index] === this.refreshedVersions[index]) return;
    this.preparedVersions[index] = this.refreshedVersions[index];
    this.recordsVersion++;
    const hull = this.layoutHulls[index];
    hull.updateWorld();
    this.writeHull(hull, index);
    const first = this.firstRecords[index];
    this.dirtyRows.fill(1, Math.floor(first / RECORDS_PER_ROW), Math.floor((first + this.recordCounts[index] - 1) / RECORDS_PER_ROW) + 1);
  }

  /** Refreshes the flat arrays of changed hulls; false when the list or a hull's shape no longer fits the layout. */
  private refresh(hulls: readonly Hull[]): boolean {
    const layout = this.layoutHulls;
    for (let i = 0; i < hulls.length; i++) {
      const hull = hulls[i];
      if (hull !== layout[i]) return false;
      if (hull.version === this.refreshedVersions[i]) continue;
      if (this.recordCounts[i] !== recordCountOf(hull)) return false;
      this.refreshHull(hull, i);
    }
    return true;
  }

  private refreshHull(hull: Hull, index: number): void {
    this.refreshedVersions[index] = hull.version;
    hull.updateCoarseBounds();
    const from = hull.coarseBounds, to = this.coarseBounds;
    const changed = this.changedCount++, box = this.changedBoxes;
    this.changedIndices[changed] = index;
    box[4 * changed] = Math.min(from[0], to[4 * index]);
    box[4 * changed + 1] = Math.min(from[1], to[4 * index + 1]);
    box[4 * changed + 2] = Math.max(from[2], to[4 * index + 2]);
    box[4 * changed + 3] = Math.max(from[3], to[4 * index + 3]);
    to[4 * index] = from[0];
    to[4 * index + 1] = from[1];
    to[4 * index + 2] = from[2];
    to[4 * index + 3] = from[3];
    this.castsShadow[index] = hull.enabled && hull.valid ? 1 : 0;
    this.convex[index] = hull.convex ? 1 : 0;
    this.layers[index] = hull.layers;
    const edges = hull.valid ? hull.edgeCount : 0;
    this.validEdgeCount += edges - this.countedEdges[index];
    this.countedEdges[index] = edges;
  }

  private layOut(hulls: readonly Hull[]): void {
    this.layoutHulls = hulls.slice();
    this.layoutVersion++;
    this.recordsVersion++;
    // Records of hulls not yet prepared stay zero (no outline in the debug wireframe) rather than stale.
    this.records.fill(0);
    this.allocatePerHull(hulls.length);
    let records = 0;
    for (let i = 0; i < hulls.length; i++) {
      this.firstRecords[i] = records;
      this.recordCounts[i] = recordCountOf(hulls[i]);
      records += this.recordCounts[i];
    }
    this.recordCount = records;
    if (this.recordPointCounts.length < records) {
      const wanted = Math.max(records, Math.ceil(this.recordPointCounts.length * 1.5));
      const rows = Math.ceil(wanted / RECORDS_PER_ROW);
      this.records = new Float32Array(rows * RECORDS_PER_ROW * RECORD_FLOATS);
      this.recordTags = new Float32Array(rows * RECORDS_PER_ROW);
      this.recordPointCounts = new Uint8Array(rows * RECORDS_PER_ROW);
      this.dirtyRows = new Uint8Array(rows);
    }
  }

  /** Sizes the per-hull flat arrays for `count` hulls, every hull to be refreshed. */
  private allocatePerHull(count: number): void {
    if (this.castsShadow.length < count) {
      const capacity = Math.ceil(count * 1.5);
      this.coarseBounds = new Float64Array(4 * capacity);
      this.worldBounds = new Float64Array(4 * capacity);
      this.circles = new Float64Array(3 * capacity);
      this.castsShadow = new Uint8Array(capacity);
      this.convex = new Uint8Array(capacity);
      this.layers = new Uint32Array(capacity);
      this.firstRecords = new Int32Array(capacity);
      this.recordCounts = new Int32Array(capacity);
      this.refreshedVersions = new Float64Array(capacity);
      this.preparedVersions = new Float64Array(capacity);
      this.countedEdges = new Int32Array(capacity);
      this.changedBoxes = new Float64Array(4 * capacity);
      this.changedIndices = new Int32Array(capacity);
    }
    this.refreshedVersions.fill(-1);
    this.preparedVersions.fill(-1);
    this.countedEdges.fill(0);
    this.validEdgeCount = 0;
  }

  /** Writes the hull's records (see {@link recordCountOf}) and tags, and copies its world bounds. */
  private writeHull(hull: Hull, index: number): void {
    const world = hull.worldPoints, count = hull.pointCount;
    const first = this.firstRecords[index];
    let record = first;
    if (!hull.closed) {
      for (let i = 0; i + 1 < count; i++, record++) {
        this.writeSegmentBox(record, world, i);
        this.recordTags[record] = recordTag(first, 0);
      }
    } else if (hull.convex) {
      // A fan: the first record takes points 0..3, each next one point 0, the previous record's last
      // point and up to RECORD_POINTS - 2 new ones.
      this.startRecord(record);
      for (let i = 0; i < Math.min(count, RECORD_POINTS); i++) this.addPoint(record, world, i);
      for (let last = RECORD_POINTS - 1; last < count - 1; last += RECORD_POINTS - 2) {
        this.startRecord(++record);
        this.addPoint(record, world, 0);
        for (let i = last; i < Math.min(count, last + RECORD_POINTS - 1); i++) this.addPoint(record, world, i);
      }
      for (let k = first; k <= record; k++) this.recordTags[k] = recordTag(first, this.fanOutlineEdges(k, k === first, k === record));
    } else {
      const triangles = hull.worldTriangles;
      for (let k = 0; k < triangles.length; k += 3, record++) {
        // Records have positive area: the triangulation keeps the hull's winding, but say so here.
        const flip = isClockwise(world, triangles[k], triangles[k + 1], triangles[k + 2]);
        const a = triangles[k], b = triangles[k + (flip ? 2 : 1)], c = triangles[k + (flip ? 1 : 2)];
        this.startRecord(record);
        this.addPoint(record, world, a);
        this.addPoint(record, world, b);
        this.addPoint(record, world, c);
        // Edges a–b, b–c, then c–c (no length) and c–a.
        const outline = (isOutlineEdge(a, b, count) ? 1 : 0) | (isOutlineEdge(b, c, count) ? 2 : 0) | (isOutlineEdge(c, a, count) ? 8 : 0);
        this.recordTags[record] = recordTag(first, outline);
      }
    }
    const from = hull.worldBounds, to = this.worldBounds;
    for (let k = 0; k < 4; k++) to[4 * index + k] = from[k];
    const cx = (from[0] + from[2]) / 2, cy = (from[1] + from[3]) / 2;
    let farthest2 = 0;
    for (let i = 0; i < count; i++) {
      const dx = world[2 * i] - cx, dy = world[2 * i + 1] - cy;
      farthest2 = Math.max(farthest2, dx * dx + dy * dy);
    }
    // An open hull's boxes reach their half width past its points.
    const margin = hull.closed ? 0 : segmentBoxHalfWidth(Math.max(-from[0], -from[1], from[2], from[3]));
    this.circles[3 * index] = cx;
    this.circles[3 * index + 1] = cy;
    this.circles[3 * index + 2] = Math.sqrt(farthest2) + margin;
  }

  /**
   * Writes the segment from world point `i` to point `i + 1` of an open hull as a box around it, as
   * thin as float rounding allows: a record must have an inside, and any line that crosses the
   * segment crosses the box, so the boxes of a polyline block all that it blocks (joints included).
   */
  private writeSegmentBox(record: number, world: Float32Array, i: number): void {
    const ax = world[2 * i], ay = world[2 * i + 1], bx = world[2 * i + 2], by = world[2 * i + 3];
    const halfWidth = segmentBoxHalfWidth(Math.max(Math.abs(ax), Math.abs(ay), Math.abs(bx), Math.abs(by)));
    const length = Math.hypot(bx - ax, by - ay);
    // The left normal (counter-clockwise in x-right, y-up axes) times the half width.
    const nx = (-(by - ay) / length) * halfWidth, ny = ((bx - ax) / length) * halfWidth;
    const records = this.records, k = record * RECORD_FLOATS;
    records[k] = ax - nx;
    records[k + 1] = ay - ny;
    records[k + 2] = bx - nx;
    records[k + 3] = by - ny;
    records[k + 4] = bx + nx;
    records[k + 5] = by + ny;
    records[k + 6] = ax + nx;
    records[k + 7] = ay + ny;
    this.recordPointCounts[record] = RECORD_POINTS;
  }

  /**
   * The outline edges of a convex hull's fan record: all of its edges of some length but the
   * diagonals to the apex (point 0), which close every record but the last and open every one but
   * the first.
   */
  private fanOutlineEdges(record: number, isFirst: boolean, isLast: boolean): number {
    const points = this.recordPointCounts[record];
    let mask = 0;
    for (let k = 0; k < points - 1; k++) mask |= 1 << k;
    if (!isFirst) mask &= ~1;
    if (isLast) mask |= 1 << (RECORD_POINTS - 1);
    return mask;
  }

  private startRecord(record: number): void {
    this.recordPointCounts[record] = 0;
  }

  /** Appends world point `point` to `record`, repeating it over the record's unused slots. */
  private addPoint(record: number, world: Float32Array, point: number): void {
    const slot = this.recordPointCounts[record]++;
    const x = world[2 * point], y = world[2 * point + 1], records = this.records;
    for (let k = record * RECORD_FLOATS + 2 * slot, end = (record + 1) * RECORD_FLOATS; k < end; k += 2) {
      records[k] = x;
      records[k + 1] = y;
    }
  }
}

/**
 * Half the width of the box an open hull's segment is drawn as, for coordinates up to `magnitude`
 * in absolute value: 2^-10 world units, small enough that the shadow differs from the segment's by
 * less than the shader's other limits a pixel away from an end; and at least 16 float32 steps at
 * that magnitude (2^-19 of it, from 512 on), so that rounding cannot close the box.
 */
function segmentBoxHalfWidth(magnitude: number): number {
  return Math.max(2 ** -10, magnitude * 2 ** -19);
}

/**
 * Records of a hull: one per {@link RECORD_POINTS}-point fan piece of a convex hull, one per
 * triangle of a concave one, one box per segment of an open one.
 */
function recordCountOf(hull: Hull): number {
  if (!hull.valid) return 0;
  if (!hull.closed) return hull.edgeCount;
  if (hull.convex) return 1 + Math.max(0, Math.ceil((hull.edgeCount - RECORD_POINTS) / (RECORD_POINTS - 2)));
  return hull.worldTriangles.length / 3;
}

/** Whether points `a` and `b` of a closed outline of `count` points are neighbours on it. */
function isOutlineEdge(a: number, b: number, count: number): boolean {
  const step = Math.abs(a - b);
  return step === 1 || step === count - 1;
}

/** Whether the triangle of points a, b, c has negative area (a boolean, not the signed area: see Hot-path rules in docs/architecture.md). */
function isClockwise(world: Float32Array, a: number, b: number, c: number): boolean {
  const ax = world[2 * a], ay = world[2 * a + 1];
  return (world[2 * b] - ax) * (world[2 * c + 1] - ay) - (world[2 * b + 1] - ay) * (world[2 * c] - ax) < 0;
}
