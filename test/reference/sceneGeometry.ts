import type { Point } from './scenes';

/**
 * The hulls and open polylines of a scene as the CPU references use them: every edge, every point
 * where two edges cross (overlapping hulls), and point-in-hull tests (polylines have no inside).
 * Plain double-precision geometry, none of the renderer's code.
 */
export class SceneGeometry {
  /** Every hull edge, `[ax, ay, bx, by, …]`. */
  readonly edges: Float64Array;
  /** Points where two edges cross inside both (hulls that overlap), `[x, y, …]`. */
  readonly crossings: Float64Array;
  /** Every hull point, `[x, y, …]`. */
  readonly vertices: Float64Array;
  private readonly hulls: readonly Float64Array[];

  constructor(hulls: readonly (readonly Point[])[], polylines: readonly (readonly Point[])[] = []) {
    this.hulls = hulls.map((hull) => Float64Array.from(hull.flat()));
    const edges: number[] = [];
    const addEdges = (points: readonly Point[], closed: boolean): void => {
      for (let i = 0; i < points.length - (closed ? 0 : 1); i++) {
        const a = points[i], b = points[(i + 1) % points.length];
        edges.push(a[0], a[1], b[0], b[1]);
      }
    };
    for (const hull of hulls) addEdges(hull, true);
    for (const polyline of polylines) addEdges(polyline, false);
    this.edges = Float64Array.from(edges);
    this.vertices = Float64Array.from([...hulls, ...polylines].flat(2));
    this.crossings = findCrossings(this.edges);
  }

  /** Whether (x, y) lies inside some hull (even-odd rule per hull; on an outline counts either way). */
  isInsideHull(x: number, y: number): boolean {
    return this.hullHolding(x, y) >= 0;
  }

  /** The index of the first hull (in the order given) that (x, y) lies inside, or −1. */
  hullHolding(x: number, y: number): number {
    return this.hulls.findIndex((points) => {
      let inside = false;
      const count = points.length / 2;
      for (let i = 0, j = count - 1; i < count; j = i++) {
        const ax = points[2 * i], ay = points[2 * i + 1], bx = points[2 * j], by = points[2 * j + 1];
        if ((ay > y) !== (by > y) && x < ax + ((y - ay) * (bx - ax)) / (by - ay)) inside = !inside;
      }
      return inside;
    });
  }

  /** Whether (x, y) lies closer than `distance` to a hull edge. */
  isNearOutline(x: number, y: number, distance: number): boolean {
    const e = this.edges;
    for (let i = 0; i < e.length; i += 4) {
      if (pointSegmentDistanceSquared(x, y, e[i], e[i + 1], e[i + 2], e[i + 3]) < distance * distance) return true;
    }
    return false;
  }
}

/** Squared distance from point (px, py) to segment a→b. */
function pointSegmentDistanceSquared(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax, ey = by - ay;
  const lengthSquared = ex * ex + ey * ey;
  const t = lengthSquared > 0 ? Math.min(1, Math.max(0, ((px - ax) * ex + (py - ay) * ey) / lengthSquared)) : 0;
  const dx = px - ax - t * ex, dy = py - ay - t * ey;
  return dx * dx + dy * dy;
}

/** True when segment p→s crosses segment a→b, ends included (parallel segments count as not crossing: zero measure). */
export function segmentsCross(px: number, py: number, sx: number, sy: number, ax: number, ay: number, bx: number, by: number): boolean {
  const dx = sx - px, dy = sy - py, ex = bx - ax, ey = by - ay;
  const denominator = dx * ey - dy * ex;
  if (denominator === 0) return false;
  const qx = ax - px, qy = ay - py;
  const t = (qx * ey - qy * ex) / denominator;
  const u = (qx * dy - qy * dx) / denominator;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

/** Points where two edges cross strictly inside both. */
function findCrossings(edges: Float64Array): Float64Array {
  const points: number[] = [];
  for (let i = 0; i < edges.length; i += 4) {
    for (let j = i + 4; j < edges.length; j += 4) {
      const ax = edges[i], ay = edges[i + 1], dx = edges[i + 2] - ax, dy = edges[i + 3] - ay;
      const bx = edges[j], by = edges[j + 1], ex = edges[j + 2] - bx, ey = edges[j + 3] - by;
      const denominator = dx * ey - dy * ex;
      if (denominator === 0) continue;
      const qx = bx - ax, qy = by - ay;
      const t = (qx * ey - qy * ex) / denominator;
      const u = (qx * dy - qy * dx) / denominator;
      if (t > 0 && t < 1 && u > 0 && u < 1) points.push(ax + t * dx, ay + t * dy);
    }
  }
  return Float64Array.from(points);
}
