import { isInsidePolygon } from '../geometry/polygon';
import type { Hull } from '../scene/Hull';
import type { Light } from '../scene/lights';
import type { ShadowGeometry } from './ShadowGeometry';

/** Whether the hull at `index` shadows `light`: it is in one of the light's shadow layers and not ignored by it. */
export function shadows(light: Light, hulls: readonly Hull[], geometry: ShadowGeometry, index: number): boolean {
  return (geometry.layers[index] & light.shadowLayers) !== 0 && !(light.ignoredHulls.size > 0 && light.ignoredHulls.has(hulls[index]));
}

/**
 * Whether `point` is inside the closed hull at `index` (prepared): its exact bounds first, then its
 * outline. The point comes in an array: V8 boxes a double passed to a function it does not inline.
 */
export function isInsideHull(hulls: readonly Hull[], geometry: ShadowGeometry, index: number, point: Float64Array): boolean {
  const bounds = geometry.worldBounds, k = 4 * index, x = point[0], y = point[1];
  if (bounds[k] > x || x > bounds[k + 2] || bounds[k + 1] > y || y > bounds[k + 3] || !hulls[index].closed) return false;
  return isInsidePolygon(hulls[index].worldPoints, point);
}
