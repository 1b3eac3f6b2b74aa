import { RECORD_FLOATS, RECORD_POINTS, SHADOW_TYPE_CODES, TILE_COLUMNS, TILE_ROWS } from './shadowLayout';
import type { FiledDisk } from './ShadowBins';
import { FULL_ROW, markSpan } from './tileMasks';
import { TilePolygon } from './TilePolygon';

/**
 * Slack of the geometric tests, relative to the scale of the light's box: float32 rounding in the
 * shader is about 1e-7 of the coordinates, so a pixel this far inside a region is classified as
 * the shader would shade it.
 */
const RELATIVE_SLACK = 1e-5;
/** The shader's radius for a hard light (shadow-visibility's MIN_RADIUS). */
const MIN_RADIUS = 1e-3;

/**
 * What the records added for one light prove about its tiles (its filed bounds cut into
 * TILE_COLUMNS × TILE_ROWS tiles), as masks per tile row (see `tileMasks`): the tiles some record
 * may shadow (`shadowed`), those some record hides the whole disk from (`darkened`), those a
 * record's box touches (`occupied`) and, for an Illuminated light, those wholly inside a record
 * (`inside`). Proven, never guessed, by two convex regions per record P of disk D (centre o,
 * radius R, with D and P apart):
 *
 * - **The shadow region** S(P), the points from which some segment to D meets P, lies on P's side
 *   of every line that separates P from D: the tangents from P's corners to D that have P and D on
 *   opposite sides, P's edges that face the whole disk, and the line through P's point nearest o.
 *   (For x beyond such a line, a segment from x to a point of D stays off P's side.) A tile that
 *   this clipped region misses is lit by P; a disk that meets P may shadow any point.
 * - **The umbra** with P, U(P) ∪ P, the points whose every segment to D meets P, is convex (the
 *   intersection over d ∈ D of the point shadows, each convex) and is exactly the intersection of
 *   the tangents from P's corners to D that have P and D on the same side, and the inner sides of
 *   P's edges that some point of D lies outside of: for each d its point shadow is bounded by the
 *   two lines from d through P's silhouette corners and by P's edges facing d, whose extremes over
 *   D are those tangents and edges. A tile wholly inside is dark (inside P too, for a Solid light).
 * - **In front.** From a point x of S(P), the disk lies wholly beyond P in P's wedge (the lean
 *   program's one case): S(P) lies on P's side of a line that separates P from D (above), so x
 *   and P lie on one side of it and D on the other, and every ray from x that meets P meets it
 *   before the line and D after. From a point outside S(P), P hides nothing. So an exact tile is
 *   lean unless a record meets the disk (then every exact tile is general, `diskMet`) or, for an
 *   Occluded light, a record's box touches the tile (a pixel inside a hull takes the holder pass).
 */
export class RecordMarks {
  /** Per tile row of the light being classified: the tiles it may be shadowed in, dark in, with a record in them. */
  readonly shadowed = new Int32Array(TILE_ROWS);
  readonly darkened = new Int32Array(TILE_ROWS);
  readonly occupied = new Int32Array(TILE_ROWS);
  /** Per tile row of the light being classified, for an Illuminated light: the tiles wholly inside a record. */
  readonly inside = new Int32Array(TILE_ROWS);
  /** The light being classified: its disk's centre and its reach. */
  centreX = 0;
  centreY = 0;
  reach = 0;
  /** Whether the light shades the inside of hulls as the outside (Solid). */
  solid = true;
  /** Whether a record added since `begin` met the disk: every exact tile is then general. */
  diskMet = false;
  /**
   * Whether a record added since `begin` holds the whole disk, for a light that is not Occluded:
   * every segment from a pixel outside that record to the disk ends inside it, so every tile is
   * dark but where a hull may hold the pixel (see `loadRecord`).
   */
  diskHidden = false;
  /** How many records loaded since `begin` reach into the disk. */
  recordsMeetingDisk = 0;
  /**
   * The tiles the loaded record's shadow region and box touch (as marked since it was loaded), per
   * tile row, set in rows `recordFirstRow` to `recordLastRow` only (see `TileRecordLists`).
   */
  readonly recordTiles = new Int32Array(TILE_ROWS);
  recordFirstRow = 0;
  recordLastRow = -1;
  /** The convex polygons of the records' regions, in the light's tile units. */
  private readonly region = new TilePolygon();
  /** The loaded record's corners without repeats, `pointCount` of them, counter-clockwise. */
  private readonly xs = new Float64Array(RECORD_POINTS);
  private readonly ys = new Float64Array(RECORD_POINTS);
  private pointCount = 0;
  /** Half-planes `a·x + b·y ≤ c`: the shadow region's and the umbra's, for the loaded record. */
  private readonly shadowPlanes = new Float64Array(3 * (3 * RECORD_POINTS + 2));
  /** The corners the shadow region's tangents touch: how many, and the first two. */
  private tangentCorners = 0;
  private readonly tangentX = new Float64Array(2);
  private readonly tangentY = new Float64Array(2);
  private shadowPlaneCount = 0;
  private readonly umbraPlanes = new Float64Array(3 * (3 * RECORD_POINTS));
  /** The half-planes of the loaded record's inside, its edges moved in by the slack. */
  private readonly insidePlanes = new Float64Array(3 * RECORD_POINTS);
  private umbraPlaneCount = 0;
  /** The plane being added, `[a, b, c]`. */
  private readonly plane = new Float64Array(3);
  /** The box being marked occupied, `[minX, minY, maxX, maxY]`. */
  private readonly box = new Float64Array(4);
  /** The light's box, tile size, disk radius, slack, whether it is confined to its range disk. */
  private minX = 0;
  private minY = 0;
  private tileWidth = 1;
  private tileHeight = 1;
  private radius = 0;
  private slack = 0;
  private confined = true;
  /** Whether a pixel inside a hull takes the holder pass (an Occluded light). */
  private holderPass = false;

  /**
   * Starts a light, no tile marked: its box `[minX, minY, maxX, maxY]` (the grid), its filed disk
   * and reach (`[x, y, radius, reach, …]`, see {@link FiledDisk}); `confined`: it adds nothing
   * beyond its reach; `shadowType`: how it treats the inside of hulls (SHADOW_TYPE_CODES).
   */
  begin(bounds: Float64Array, disk: FiledDisk, confined: boolean, shadowType: number): void {
    const x = disk[0], y = disk[1], radius = disk[2], reach = disk[3];
    this.minX = bounds[0];
    this.minY = bounds[1];
    this.tileWidth = Math.max(bounds[2] - bounds[0], 1e-9) / TILE_COLUMNS;
    this.tileHeight = Math.max(bounds[3] - bounds[1], 1e-9) / TILE_ROWS;
    this.region.setGrid(this.minX, this.minY, this.tileWidth, this.tileHeight);
    this.centreX = x;
    this.centreY = y;
    this.slack = RELATIVE_SLACK * Math.max(Math.abs(bounds[0]), Math.abs(bounds[1]), Math.abs(bounds[2]), Math.abs(bounds[3]), bounds[2] - bounds[0], bounds[3] - bounds[1]);
    this.radius = Math.max(radius, MIN_RADIUS) + this.slack;
    this.reach = reach;
    this.confined = confined;
    this.solid = shadowType === SHADOW_TYPE_CODES.solid;
    this.holderPass = shadowType === SHADOW_TYPE_CODES.occluded;
    this.diskMet = false;
    this.diskHidden = false;
    this.recordsMeetingDisk = 0;
    this.shadowed.fill(0);
    this.darkened.fill(0);
    this.occupied.fill(0);
    this.inside.fill(0);
  }

  /**
   * Whether a record of hull `hull` may reach into the filed disk: whether its circle in `circles`
   * (ShadowGeometry's, which holds its points) meets the disk widened by the slack. When no hull's
   * does, no record meets the disk, which the lean program needs (see {@link RecordMarks.generalMask}).
   */
  hullMayMeetDisk(circles: Float64Array, hull: number): boolean {
    const dx = circles[3 * hull] - this.centreX, dy = circles[3 * hull + 1] - this.centreY;
    const reach = circles[3 * hull + 2] + this.radius + this.slack;
    return dx * dx + dy * dy <= reach * reach;
  }

  /** Whether the light sees the inside of hulls past their holders (Occluded): its exact pixels then take the general program. */
  occluded(): boolean {
    return this.holderPass;
  }

  /** Whether the light lights the inside of hulls from anywhere (Illuminated): its dark tiles with a record in them are then held. */
  illuminated(): boolean {
    return !this.solid && !this.holderPass;
  }

  /** The tiles of tile row `j` whose exact pixels take the general program, by the records added since {@link RecordMarks.begin}. */
  generalMask(j: number): number {
    return this.diskMet ? FULL_ROW : this.holderPass ? this.occupied[j] : 0;
  }

  /** Whether hull `hull`'s box in `bounds` lies wholly in tiles set in `masks` (rows from `from`), inside the grid. */
  boundsWithin(bounds: Float64Array, hull: number, masks: Int32Array, from: number): boolean {
    const tw = this.tileWidth, th = this.tileHeight;
    const first = Math.floor((bounds[4 * hull] - this.slack - this.minX) / tw), last = Math.floor((bounds[4 * hull + 2] + this.slack - this.minX) / tw);
    const firstRow = Math.floor((bounds[4 * hull + 1] - this.slack - this.minY) / th), lastRow = Math.floor((bounds[4 * hull + 3] + this.slack - this.minY) / th);
    if (first < 0 || last >= TILE_COLUMNS || firstRow < 0 || lastRow >= TILE_ROWS) return false;
    const span = (FULL_ROW >>> (TILE_COLUMNS - 1 - last)) & (FULL_ROW << first);
    for (let j = firstRow; j <= lastRow; j++) if ((masks[from + j] & span) !== span) return false;
    return true;
  }

  /** Writes the mask of the tiles of tile row `j` that lie wholly beyond the reach of the filing's centre (none for a light not confined to it) at `outside[at + j]`. */
  writeOutside(outside: Int32Array, at: number, j: number): void {
    const y0 = this.minY + j * this.tileHeight, reach = this.reach + this.slack;
    const dy = Math.max(y0 - this.centreY, 0, this.centreY - y0 - this.tileHeight);
    outside[at + j] = this.confined ? FULL_ROW : 0;
    if (!this.confined || dy > reach) return;
    // Tile i is within reach when it meets [centre − w, centre + w] (its nearest point within the reach).
    const w = Math.sqrt(reach * reach - dy * dy);
    const first = Math.max(0, Math.ceil((this.centreX - w - this.minX) / this.tileWidth - 1));
    const last = Math.min(TILE_COLUMNS - 1, Math.floor((this.centreX + w - this.minX) / this.tileWidth));
    if (first <= last) outside[at + j] = FULL_ROW & ~((FULL_ROW >>> (TILE_COLUMNS - 1 - last)) & (FULL_ROW << first));
  }

  /**
   * Loads the record's distinct corners and the half-planes of its shadow region and umbra; false
   * when the disk meets the record (its shadow region is then every tile, which it marks, and it
   * has no umbra taken, unless it holds the whole disk: then every tile is in its umbra, which it
   * marks, but for an Occluded light, whose pixels inside hulls see past their holders).
   */
  loadRecord(records: Float32Array, record: number): boolean {
    this.loadPoints(records, record);
    this.recordTiles.fill(0, this.recordFirstRow, this.recordLastRow + 1);
    this.recordFirstRow = TILE_ROWS;
    this.recordLastRow = -1;
    this.shadowPlaneCount = 0;
    this.umbraPlaneCount = 0;
    if (this.diskMeetsRecord()) {
      this.shadowed.fill(FULL_ROW);
      this.diskMet = true;
      this.recordsMeetingDisk++;
      if (!this.holderPass && this.recordHoldsDisk()) {
        this.darkened.fill(FULL_ROW);
        this.diskHidden = true;
      }
      return false;
    }
    this.findPlanes();
    return true;
  }

  /** Loads the record's distinct corners into `xs`, `ys` and `pointCount`. */
  private loadPoints(records: Float32Array, record: number): void {
    const xs = this.xs, ys = this.ys;
    let n = 0;
    for (let k = 0; k < RECORD_POINTS; k++) {
      const x = records[record * RECORD_FLOATS + 2 * k], y = records[record * RECORD_FLOATS + 2 * k + 1];
      if (n > 0 && x === xs[n - 1] && y === ys[n - 1]) continue;
      if (k === RECORD_POINTS - 1 && n > 0 && x === xs[0] && y === ys[0]) continue;
      xs[n] = x;
      ys[n] = y;
      n++;
    }
    this.pointCount = n;
  }

  /** Marks in `inside` the tiles wholly inside the record (see {@link LightTiles.markInsideLoaded}). */
  markInside(records: Float32Array, record: number): void {
    this.loadPoints(records, record);
    this.markInsideLoaded();
  }

  /**
   * Marks in `inside` the tiles wholly inside the loaded record, its edges moved in by the slack:
   * an Illuminated light lights a pixel inside a hull fully, whatever hides the disk from it (the
   * shader's walk finds the record holding it). A record too small to hold a tile is passed over.
   */
  markInsideLoaded(): void {
    const xs = this.xs, ys = this.ys, n = this.pointCount, slack = this.slack;
    if (n < 3) return;
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (let k = 0; k < n; k++) {
      minX = Math.min(minX, xs[k]);
      minY = Math.min(minY, ys[k]);
      maxX = Math.max(maxX, xs[k]);
      maxY = Math.max(maxY, ys[k]);
    }
    if (maxX - minX < this.tileWidth + 2 * slack || maxY - minY < this.tileHeight + 2 * slack) return;
    const planes = this.insidePlanes;
    let count = 0;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], ex = xs[(k + 1) % n] - ax, ey = ys[(k + 1) % n] - ay, length = Math.sqrt(ex * ex + ey * ey);
      // The outward normal of a counter-clockwise edge; inside lies a slack within.
      const nx = ey / length, ny = -ex / length;
      planes[3 * count] = nx;
      planes[3 * count + 1] = ny;
      planes[3 * count + 2] = nx * ax + ny * ay - slack;
      count++;
    }
    this.region.clipBox(planes, count);
    this.region.markCovered(this.inside);
  }

  /** Whether the disk, widened by the slack, meets the loaded record: its centre inside, or within a radius of an edge. */
  private diskMeetsRecord(): boolean {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, r = this.radius;
    let inside = n >= 3;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], bx = xs[(k + 1) % n], by = ys[(k + 1) % n];
      const ex = bx - ax, ey = by - ay, length2 = ex * ex + ey * ey;
      const along = length2 > 0 ? Math.min(Math.max(((cx - ax) * ex + (cy - ay) * ey) / length2, 0), 1) : 0;
      const ox = cx - ax - along * ex, oy = cy - ay - along * ey;
      if (ox * ox + oy * oy <= r * r) return true;
      if (ex * (cy - ay) - ey * (cx - ax) < 0) inside = false;
    }
    return inside;
  }

  /** Whether the loaded record holds the disk widened by twice the slack: the centre at least that far inside every edge. */
  private recordHoldsDisk(): boolean {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, inner = this.radius + this.slack;
    if (n < 3) return false;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], ex = xs[(k + 1) % n] - ax, ey = ys[(k + 1) % n] - ay, length = Math.sqrt(ex * ex + ey * ey);
      // The centre's distance inside the counter-clockwise edge.
      if (length > 0 && (ex * (cy - ay) - ey * (cx - ax)) / length < inner) return false;
    }
    return true;
  }

  /**
   * The half-planes of the loaded record (the disk apart from it): per corner, its two tangents to
   * the disk that have the whole record on one side; per edge, its line when it faces the whole disk
   * (shadow region) or some of it (umbra); the line through the point nearest the centre; and for a
   * light that lights the inside of hulls, the chord between the shadow region's two tangent
   * corners (see `addChordPlane`).
   */
  private findPlanes(): void {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, r = this.radius;
    this.tangentCorners = 0;
    for (let k = 0; k < n; k++) {
      const vx = xs[k], vy = ys[k];
      const dx = cx - vx, dy = cy - vy, distance = Math.sqrt(dx * dx + dy * dy);
      const sine = r / distance, cosine = Math.sqrt(Math.max(0, 1 - sine * sine));
      for (let side = -1; side <= 1; side += 2) {
        // The tangent's direction: towards the centre turned by ±asin(r / distance); its normal.
        const ux = (dx * cosine - side * dy * sine) / distance, uy = (dy * cosine + side * dx * sine) / distance;
        const nx = -uy, ny = ux;
        let least = Infinity, most = -Infinity;
        for (let m = 0; m < n; m++) {
          const s = nx * (xs[m] - vx) + ny * (ys[m] - vy);
          if (s < least) least = s;
          if (s > most) most = s;
        }
        const diskSide = nx * dx + ny * dy;
        const eps = this.slack;
        // The record on the + side (sign −1: the plane keeps that side) or the − side; the disk on
        // the same side (the umbra's plane) or the other (the shadow region's).
        const sign = least >= -eps ? -1 : most <= eps ? 1 : 0;
        if (sign === 0) continue;
        const umbra = sign * diskSide < 0, plane = this.plane;
        plane[0] = sign * nx;
        plane[1] = sign * ny;
        plane[2] = sign * (nx * vx + ny * vy) + (umbra ? -eps : eps);
        this.addPlane(umbra);
        if (!umbra) this.noteTangentCorner(k);
      }
    }
    if (!this.solid && !this.holderPass) this.addChordPlane();
    let nearest2 = Infinity, nearestX = 0, nearestY = 0;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], bx = xs[(k + 1) % n], by = ys[(k + 1) % n];
      const ex = bx - ax, ey = by - ay, length = Math.sqrt(ex * ex + ey * ey);
      if (length > 0) {
        // Outward normal of a counter-clockwise edge; the centre's distance outward.
        const nx = ey / length, ny = -ex / length, outward = nx * (cx - ax) + ny * (cy - ay);
        const plane = this.plane;
        plane[0] = nx;
        plane[1] = ny;
        plane[2] = nx * ax + ny * ay + this.slack;
        if (outward > r) this.addPlane(false);
        // The umbra needs every edge some disk point lies outside of.
        plane[2] = nx * ax + ny * ay - this.slack;
        if (outward > -r) this.addPlane(true);
      }
      const along = length > 0 ? Math.min(Math.max(((cx - ax) * ex + (cy - ay) * ey) / (length * length), 0), 1) : 0;
      const px = ax + along * ex, py = ay + along * ey, d2 = (px - cx) * (px - cx) + (py - cy) * (py - cy);
      if (d2 < nearest2) {
        nearest2 = d2;
        nearestX = px;
        nearestY = py;
      }
    }
    const distance = Math.sqrt(nearest2);
    if (distance > 0) {
      const nx = (cx - nearestX) / distance, ny = (cy - nearestY) / distance;
      const plane = this.plane;
      plane[0] = nx;
      plane[1] = ny;
      plane[2] = nx * nearestX + ny * nearestY + this.slack;
      this.addPlane(false);
    }
  }

  /** Notes corner `k` as one a tangent of the shadow region touches (the first two in `tangentX`, `tangentY`). */
  private noteTangentCorner(k: number): void {
    if (this.tangentCorners < 2) {
      this.tangentX[this.tangentCorners] = this.xs[k];
      this.tangentY[this.tangentCorners] = this.ys[k];
    }
    this.tangentCorners++;
  }

  /**
   * For an Illuminated light, whose pixels inside a hull are lit: the record shades only the part
   * of its shadow region outside it, which lies beyond the chord between the two corners t1, t2 the
   * region's tangents touch, when the disk lies wholly on the other side. (A point x outside P
   * whose segment to d in D meets P leaves P through its chain between t1 and t2 away from D, which
   * lies beyond the chord; the segment from d, on the near side, goes on beyond it.) Left out when
   * more than two corners touch a tangent (an edge along one) or the disk meets the chord's line.
   */
  private addChordPlane(): void {
    if (this.tangentCorners !== 2) return;
    const ax = this.tangentX[0], ay = this.tangentY[0], ex = this.tangentX[1] - ax, ey = this.tangentY[1] - ay, length = Math.sqrt(ex * ex + ey * ey);
    if (length === 0) return;
    // The chord's normal towards the side away from the centre.
    let nx = ey / length, ny = -ex / length;
    const centreSide = nx * (this.centreX - ax) + ny * (this.centreY - ay);
    if (Math.abs(centreSide) <= this.radius) return;
    if (centreSide > 0) {
      nx = -nx;
      ny = -ny;
    }
    const plane = this.plane;
    plane[0] = -nx;
    plane[1] = -ny;
    plane[2] = -(nx * ax + ny * ay) + this.slack;
    this.addPlane(false);
  }

  /** Adds `plane` (`a·x + b·y ≤ c`, the slack already in c) to the umbra's half-planes or the shadow region's. */
  private addPlane(umbra: boolean): void {
    const planes = umbra ? this.umbraPlanes : this.shadowPlanes, k = 3 * (umbra ? this.umbraPlaneCount++ : this.shadowPlaneCount++);
    planes[k] = this.plane[0];
    planes[k + 1] = this.plane[1];
    planes[k + 2] = this.plane[2];
  }

  /** Marks in `shadowed` the tiles the loaded record's shadow region touches. */
  markShadowRegion(): void {
    this.region.clipBox(this.shadowPlanes, this.shadowPlaneCount);
    this.region.markTouched(this.shadowed, this.recordTiles);
    this.recordFirstRow = Math.min(this.recordFirstRow, this.region.touchedFirstRow);
    this.recordLastRow = Math.max(this.recordLastRow, this.region.touchedLastRow);
  }

  /** Marks in `darkened` the tiles wholly inside the loaded record's umbra. */
  markUmbra(): void {
    this.region.clipBox(this.umbraPlanes, this.umbraPlaneCount);
    this.region.markCovered(this.darkened);
  }

  /** Marks in `occupied` the tiles the loaded record's bounding box touches. */
  markRecordBox(): void {
    const xs = this.xs, ys = this.ys, box = this.box;
    box[0] = box[1] = Infinity;
    box[2] = box[3] = -Infinity;
    for (let k = 0; k < this.pointCount; k++) {
      box[0] = Math.min(box[0], xs[k]);
      box[1] = Math.min(box[1], ys[k]);
      box[2] = Math.max(box[2], xs[k]);
      box[3] = Math.max(box[3], ys[k]);
    }
    this.markOccupied(true);
  }

  /** Marks in `occupied` the tiles hull `hull`'s box in `bounds` touches. */
  markBox(bounds: Float64Array, hull: number): void {
    for (let k = 0; k < 4; k++) this.box[k] = bounds[4 * hull + k];
    this.markOccupied(false);
  }

  /** Marks in `occupied` (and in `recordTiles` when `ofRecord`) the tiles `box` touches, widened by the slack. */
  private markOccupied(ofRecord: boolean): void {
    const minX = this.box[0], minY = this.box[1], maxX = this.box[2], maxY = this.box[3];
    const first = Math.max(0, Math.floor((minX - this.slack - this.minX) / this.tileWidth));
    const last = Math.min(TILE_COLUMNS - 1, Math.floor((maxX + this.slack - this.minX) / this.tileWidth));
    const firstRow = Math.max(0, Math.floor((minY - this.slack - this.minY) / this.tileHeight));
    const lastRow = Math.min(TILE_ROWS - 1, Math.floor((maxY + this.slack - this.minY) / this.tileHeight));
    if (first > last) return;
    for (let j = firstRow; j <= lastRow; j++) markSpan(this.occupied, j, first, last);
    if (ofRecord) this.markRecordTiles(firstRow, lastRow, first, last);
  }

  /** Adds tiles `first` to `last` of rows `firstRow` to `lastRow` to `recordTiles`. */
  private markRecordTiles(firstRow: number, lastRow: number, first: number, last: number): void {
    for (let j = firstRow; j <= lastRow; j++) markSpan(this.recordTiles, j, first, last);
    this.recordFirstRow = Math.min(this.recordFirstRow, firstRow);
    this.recordLastRow = Math.max(this.recordLastRow, lastRow);
  }
}
