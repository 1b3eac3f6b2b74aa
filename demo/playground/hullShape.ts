import type { Hull } from 'penumbra-gl';

/**
 * World-space point `index` of a hull, placed as `Hull` documents it: around `origin`, scaled,
 * rotated, then moved to `position`. Written into `out` (no allocation: used every frame).
 */
export function hullWorldPoint(hull: Hull, index: number, out: [number, number]): [number, number] {
  const [lx, ly] = hull.points[index];
  return hullLocalToWorld(hull, lx, ly, out);
}

/** Any local-space point (lx, ly) placed as the hull's points are: a sprite's corner that follows the hull. */
export function hullLocalToWorld(hull: Hull, lx: number, ly: number, out: [number, number]): [number, number] {
  const x = (lx - hull.origin[0]) * hull.scale[0];
  const y = (ly - hull.origin[1]) * hull.scale[1];
  const cos = Math.cos(hull.rotation), sin = Math.sin(hull.rotation);
  out[0] = hull.position[0] + x * cos - y * sin;
  out[1] = hull.position[1] + x * sin + y * cos;
  return out;
}

const scratch: [number, number] = [0, 0];
const previous: [number, number] = [0, 0];

/**
 * Whether world point (x, y) picks the hull: inside a closed one (which is drawn filled), within
 * `reach` world units of an open one's line (which is drawn as a line, with no inside to click).
 */
export function hullHit(hull: Hull, x: number, y: number, reach: number): boolean {
  return hull.closed ? hullContains(hull, x, y) : polylineDistance(hull, x, y) <= reach;
}

/** Distance from world point (x, y) to the nearest segment of a hull's points taken as an open polyline (∞ with no points). */
function polylineDistance(hull: Hull, x: number, y: number): number {
  const n = hull.points.length;
  if (n === 0) return Infinity;
  hullWorldPoint(hull, 0, previous);
  // A single point is a segment of length 0.
  let nearest = Math.hypot(x - previous[0], y - previous[1]);
  for (let i = 1; i < n; i++) {
    const [bx, by] = hullWorldPoint(hull, i, scratch);
    nearest = Math.min(nearest, segmentDistance(x, y, previous[0], previous[1], bx, by));
    previous[0] = bx;
    previous[1] = by;
  }
  return nearest;
}

/** Distance from (x, y) to the segment from (ax, ay) to (bx, by). */
function segmentDistance(x: number, y: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax, dy = by - ay;
  const lengthSquared = dx * dx + dy * dy;
  // The segment's point nearest (x, y), as a fraction of the way from a to b, kept on the segment.
  const t = lengthSquared === 0 ? 0 : Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / lengthSquared));
  return Math.hypot(x - ax - t * dx, y - ay - t * dy);
}

/** Whether world point (x, y) lies inside the hull's polygon (even-odd rule, so also for invalid hulls). */
export function hullContains(hull: Hull, x: number, y: number): boolean {
  const n = hull.points.length;
  if (n < 3) return false;
  let inside = false;
  hullWorldPoint(hull, n - 1, previous);
  for (let i = 0; i < n; i++) {
    const [ax, ay] = hullWorldPoint(hull, i, scratch);
    const [bx, by] = previous;
    if ((ay > y) !== (by > y) && x < ((bx - ax) * (y - ay)) / (by - ay) + ax) inside = !inside;
    previous[0] = ax;
    previous[1] = ay;
  }
  return inside;
}
