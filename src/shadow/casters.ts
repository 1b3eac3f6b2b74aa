import type { Hull } from '../scene/Hull';
import type { Light } from '../scene/Light';
import type { ShadowGeometry } from './ShadowGeometry';

/** Whether the hull at `index` shadows `light`: it is in one of the light's shadow layers and not ignored by it. */
export function shadows(light: Light, hulls: readonly Hull[], geometry: ShadowGeometry, index: number): boolean {
  return (geometry.layers[index] & light.shadowLayers) !== 0 && !(light.ignoredHulls.size > 0 && light.ignoredHulls.has(hulls[index]));
}
