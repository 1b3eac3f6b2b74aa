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
