import type { ReadonlyMat4 } from 'gl-matrix';
import type { Hull } from '../scene/Hull';
import type { Light } from '../scene/lights';
import { HullGrid } from './HullGrid';
import { isInsidePolygon } from './polygon';
import { scissorOf } from './scissor';
import type { ShadowGeometry } from './ShadowGeometry';

/**
 * Point counts up to which a hull's points reach the shadow fragment stages in flat varyings (the
 * vertex stage fetches them once per vertex) instead of a texel fetch per point per fragment. A
 * stage visits as many points as its class holds, so boxes and triangles have a class of their own.
 */
export const VARYING_POINT_COUNTS = [4, 8] as const;
/** One size class per entry of {@link VARYING_POINT_COUNTS}, then this one, for hulls of any size. */
export const ANY_SIZE_CLASS = VARYING_POINT_COUNTS.length;
export const SIZE_CLASS_COUNT = ANY_SIZE_CLASS + 1;

/**
 * How a hull in range casts its shadow: one region (convex or concave), or one quad per edge. A
 * concave hull's region leaves out the inside of the convex hull of its points, where its cavities
 * are: a caster of its own covers that, with the hull's bounding box.
 */
export const CasterKind = { ConvexHull: 0, ConcaveHull: 1, ConcaveCavities: 2, Edges: 3 } as const;
export type CasterKind = (typeof CasterKind)[keyof typeof CasterKind];

/**
 * Each light's casters come in runs, each drawn with a fragment stage of its own (SwiftShader runs
 * both sides of a per-fragment branch): run `kind × SIZE_CLASS_COUNT + sizeClass`, in that order.
 * The regions come first, so that their umbrae are one draw.
 */
export const CASTER_RUN_COUNT = 4 * SIZE_CLASS_COUNT;
const FIRST_CAVITY_RUN = casterRun(CasterKind.ConcaveCavities, 0);
const FIRST_EDGE_RUN = casterRun(CasterKind.Edges, 0);

/** The run of casters of `kind` from hulls of `sizeClass`. */
function casterRun(kind: CasterKind, sizeClass: number): number {
  return kind * SIZE_CLASS_COUNT + sizeClass;
}

/** The kind of the casters in `run`. */
export function kindOfRun(run: number): CasterKind {
  return Math.floor(run / SIZE_CLASS_COUNT) as CasterKind;
}

/** The size class of the hulls whose casters are in `run`. */
export function sizeClassOfRun(run: number): number {
  return run % SIZE_CLASS_COUNT;
}

/** `casters` grows in whole rows of this many entries, so it fills the rows of the texture it is uploaded to. */
export const CASTER_ROW = 1024;

/**
 * The widest a hull's shadow region may open either side of its axis for the hull to be one caster:
 * the shadow-mask vertex stage divides by the cosine of this angle and orders directions by cross
 * products, which needs them all within a half-plane.
 */
const MAX_HALF_ANGLE = (78 / 180) * Math.PI;

/**
 * A hull whose bounding circle lies this many times its radius and the disk's together from the
 * light has a region opening at most asin(1 / 1.1) ≈ 65° either side, below the maximum, without
 * looking at its points.
 */
const CLEARANCE_WITHOUT_POINTS = 1.1;

/** What the passes need to draw one light: its quad, scissor, and the shadow casters and triangles of the hulls in its range. */
export class LightDraw {
  light!: Light;
  /** `[cornerX, cornerY, axisXx, axisXy, axisYx, axisYy]`, see `Light.writeQuad`. */
  readonly quad = new Float32Array(6);
  /** `[minX, minY, maxX, maxY]` of the quad and the light centre, in world units. */
  readonly bounds = new Float64Array(4);
  /** `[x, y, width, height]` in lightmap pixels. */
  readonly scissor = new Int32Array(4);
  /** Offset and count, in the plan's `casters`, of the shadow casters in range (one shadow quad each). */
  casterOffset = 0;
  casterCount = 0;
  /**
   * Where each run of those casters ends (see {@link CASTER_RUN_COUNT}), counted from `casterOffset`: run `r` holds
   * the casters from `runEnds[r - 1]` (0 for the first) up to `runEnds[r]`.
   */
  readonly runEnds = new Uint32Array(CASTER_RUN_COUNT);
  /** Distance from the light's position beyond which it adds nothing (`Light.reach`). */
  reach = 0;
  /** Offset and count, in the plan's `indices`, of the triangles of the hulls in range. */
  triangleIndexOffset = 0;
  triangleIndexCount = 0;
  /** Number of hulls in range that shadow this light. */
  hullCount = 0;

  /** How many casters, first, are regions (which also cast an umbra); cavities and edges follow. */
  get regionCasterCount(): number {
    return this.runEnds[FIRST_CAVITY_RUN - 1];
  }
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
  /**
   * Shadow casters of the hulls in range, per light. A caster is `-1 - firstPoint` for a hull clear
   * of the light disk, whose shadow is one region, or else an edge's number (the number of its start
   * point), for one quad per edge; see shadow-mask.vert.glsl. Floats, uploaded as an R32F texture
   * (headless-gl refuses R32UI uploads): exact while the hulls have fewer than 2^24 points in all.
   */
  casters = new Float32Array(CASTER_ROW);
  casterCount = 0;
  readonly draws: LightDraw[] = [];
  drawCount = 0;
  /** Indices of the hulls in range of the current light: the first `inRangeCount` entries. */
  private hullsInRange = new Int32Array(64);
  /** Per hull in range: the run of its casters. */
  private casterRuns = new Uint8Array(64);
  /** Per run: its caster count, then where its next caster goes. */
  private readonly runCursors = new Uint32Array(CASTER_RUN_COUNT);
  private inRangeCount = 0;
  private readonly grid = new HullGrid();
  /** Box around the bounds of every light placed this frame that casts shadows: the grid files only hulls inside it. */
  private readonly reach = new Float64Array(4);

  build(
    lights: readonly Light[], hulls: readonly Hull[], geometry: ShadowGeometry,
    viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number,
  ): void {
    this.indexCount = 0;
    this.casterCount = 0;
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
      draw.reach = light.reach();
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
    this.inRangeCount = 0;
    if (light.castsShadows && !this.findHullsInRange(draw, hulls, geometry)) return false;
    const count = this.inRangeCount, inRange = this.hullsInRange;
    draw.hullCount = count;
    this.appendCasters(draw, hulls, geometry);
    draw.triangleIndexOffset = this.indexCount;
    for (let i = 0; i < count; i++) this.appendTriangles(geometry, inRange[i]);
    draw.triangleIndexCount = this.indexCount - draw.triangleIndexOffset;
    return true;
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
    this.hullsInRange = ensureCapacity(this.hullsInRange, 0, count);
    const inRange = this.hullsInRange, bounds = geometry.worldBounds;
    for (let i = 0; i < count; i++) {
      const index = grid.found[i];
      if (light.ignoredHulls.size > 0 && light.ignoredHulls.has(hulls[index])) continue;
      geometry.prepare(index);
      const k = 4 * index;
      if (bounds[k] > b[2] || bounds[k + 2] < b[0] || bounds[k + 1] > b[3] || bounds[k + 3] < b[1]) continue;
      if (bounds[k] <= lx && lx <= bounds[k + 2] && bounds[k + 1] <= ly && ly <= bounds[k + 3]
        && isInsidePolygon(hulls[index].worldPoints, light.position)) return false;
      inRange[this.inRangeCount++] = index;
    }
    return true;
  }

  private appendTriangles(geometry: ShadowGeometry, index: number): void {
    const count = geometry.triangleIndexCounts[index];
    this.indices = ensureCapacity(this.indices, this.indexCount, count);
    const source = geometry.triangleIndices;
    const indices = this.indices;
    let k = this.indexCount;
    for (let i = geometry.firstTriangleIndices[index], end = i + count; i < end; i++) indices[k++] = source[i];
    this.indexCount = k;
  }

  /**
   * Appends the casters of the hulls in range, run by run (see {@link CASTER_RUN_COUNT}). Counts first,
   * then writes each caster at its run's cursor, in one pass.
   */
  private appendCasters(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry): void {
    const light = draw.light, inRange = this.hullsInRange, count = this.inRangeCount;
    const runs = this.casterRuns = ensureCapacity(this.casterRuns, 0, count);
    const cursors = this.runCursors.fill(0);
    for (let i = 0; i < count; i++) {
      const run = casterRunOf(geometry, hulls, inRange[i], light);
      runs[i] = run;
      if (run >= FIRST_EDGE_RUN) {
        cursors[run] += geometry.pointCounts[inRange[i]];
      } else {
        cursors[run]++;
        if (kindOfRun(run) === CasterKind.ConcaveHull) cursors[cavityRunOf(run)]++;
      }
    }
    const first = this.casterCount;
    let end = 0;
    for (let run = 0; run < CASTER_RUN_COUNT; run++) {
      const runCount = cursors[run];
      cursors[run] = first + end;
      end += runCount;
      draw.runEnds[run] = end;
    }
    const casters = this.casters = ensureCapacity(this.casters, first, end, CASTER_ROW);
    for (let i = 0; i < count; i++) {
      const run = runs[i], firstPoint = geometry.firstPoints[inRange[i]];
      if (run >= FIRST_EDGE_RUN) {
        for (let e = firstPoint, last = e + geometry.pointCounts[inRange[i]]; e < last; e++) casters[cursors[run]++] = e;
      } else {
        casters[cursors[run]++] = -1 - firstPoint;
        if (kindOfRun(run) === CasterKind.ConcaveHull) casters[cursors[cavityRunOf(run)]++] = -1 - firstPoint;
      }
    }
    this.casterCount = first + end;
    draw.casterOffset = first;
    draw.casterCount = end;
  }
}

/** `array`, or a grown copy of its first `used` entries, with room for `extra` more (and a length a multiple of `granule`). */
function ensureCapacity<T extends Uint8Array<ArrayBuffer> | Int32Array<ArrayBuffer> | Uint32Array<ArrayBuffer> | Float32Array<ArrayBuffer>>(array: T, used: number, extra: number, granule = 1): T {
  if (used + extra <= array.length) return array;
  const grown = new (array.constructor as new (length: number) => T)(Math.ceil(Math.max(used + extra, array.length * 2) / granule) * granule);
  grown.set(array.subarray(0, used));
  return grown;
}

/**
 * The run of the hull at `index`: its kind, one region (convex or concave) while the disk's inner
 * tangents through it open at most {@link MAX_HALF_ANGLE} either side, which its bounds show for
 * most hulls and its points for the rest, else one quad per edge; and its size class.
 */
function casterRunOf(geometry: ShadowGeometry, hulls: readonly Hull[], index: number, light: Light): number {
  const kind = !isClearOfDisk(geometry.worldBounds, index, light) && !hasNarrowShadow(hulls[index], light)
    ? CasterKind.Edges
    : geometry.convex[index] === 1 ? CasterKind.ConvexHull : CasterKind.ConcaveHull;
  return casterRun(kind, sizeClassOf(geometry.pointCounts[index]));
}

/** The cavity run of the same size class as the concave region run `run`. */
function cavityRunOf(run: number): number {
  return casterRun(CasterKind.ConcaveCavities, sizeClassOfRun(run));
}

/** The first size class that holds `pointCount` points. */
export function sizeClassOf(pointCount: number): number {
  let sizeClass = 0;
  while (sizeClass < ANY_SIZE_CLASS && pointCount > VARYING_POINT_COUNTS[sizeClass]) sizeClass++;
  return sizeClass;
}

/**
 * Whether a hull is clear enough of the light disk, by its bounds alone, for its shadow to be one
 * region: its bounding circle lies {@link CLEARANCE_WITHOUT_POINTS} times its radius and the disk's
 * together from the light.
 */
function isClearOfDisk(worldBounds: Float64Array, index: number, light: Light): boolean {
  const k = 4 * index, centre = light.position;
  const halfWidth = (worldBounds[k + 2] - worldBounds[k]) / 2, halfHeight = (worldBounds[k + 3] - worldBounds[k + 1]) / 2;
  const dx = worldBounds[k] + halfWidth - centre[0], dy = worldBounds[k + 1] + halfHeight - centre[1];
  const clearance = CLEARANCE_WITHOUT_POINTS * (Math.sqrt(halfWidth * halfWidth + halfHeight * halfHeight) + light.radius);
  return dx * dx + dy * dy > clearance * clearance;
}

/**
 * The tangents through each point lean asin(r / d) either side of the direction to it; the spread of
 * all of them, measured from the first point's direction, is at least the angle the region opens.
 * A hull that reaches into the disk, or around the light, spreads over 180° and fails.
 */
function hasNarrowShadow(hull: Hull, light: Light): boolean {
  const points = hull.worldPoints, count = hull.edgeCount;
  const cx = light.position[0], cy = light.position[1], radius = light.radius;
  let first = 0, low = 0, high = 0;
  for (let i = 0; i < count; i++) {
    const dx = points[2 * i] - cx, dy = points[2 * i + 1] - cy;
    const distance = Math.sqrt(dx * dx + dy * dy);
    if (distance <= radius) return false;
    const lean = Math.asin(radius / distance);
    let angle = Math.atan2(dy, dx);
    if (i === 0) first = angle;
    angle -= first;
    if (angle > Math.PI) angle -= 2 * Math.PI;
    else if (angle <= -Math.PI) angle += 2 * Math.PI;
    if (angle - lean < low) low = angle - lean;
    if (angle + lean > high) high = angle + lean;
  }
  return high - low <= 2 * MAX_HALF_ANGLE;
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

