/**
 * Where the suns' compasses sit. A directional light has no place in the world, so each one is a
 * compass fixed on the view, in a row along the bottom left above the help line: the overlay draws
 * them and the editor picks and turns them, both through these functions.
 */

import { DirectionalLight, type Light } from 'penumbra-gl';

/** Radius of a compass, CSS pixels (also its pick radius). */
export const COMPASS_RADIUS = 24;
/** Gap between the view's left edge and the first compass, and between compasses, CSS pixels. */
const COMPASS_GAP = 14;
/** Height kept free under the compasses for the help line, CSS pixels. */
const HELP_LINE_HEIGHT = 40;

/**
 * The canvas point (CSS pixels) of the centre of compass `index` in a view `viewHeight` pixels
 * tall, written into `out`. Whole pixels, so that a pointer (on whole pixels) can hit an angle exactly.
 */
export function compassCentre(index: number, viewHeight: number, out: [number, number]): [number, number] {
  out[0] = COMPASS_GAP + COMPASS_RADIUS + index * (2 * COMPASS_RADIUS + COMPASS_GAP);
  out[1] = Math.round(viewHeight - HELP_LINE_HEIGHT - COMPASS_RADIUS);
  return out;
}

/** Calls `visit` with every directional light of `lights`, in their order, and the index of its compass. */
export function forEachSun(lights: readonly Light[], visit: (sun: DirectionalLight, index: number) => void): void {
  let index = 0;
  for (const light of lights) if (light instanceof DirectionalLight) visit(light, index++);
}

/** The sun whose compass is under a canvas point (CSS pixels), with the compass's centre; null when none is. */
export function sunUnder(lights: readonly Light[], viewHeight: number, x: number, y: number): { sun: DirectionalLight; centre: [number, number] } | null {
  let found: { sun: DirectionalLight; centre: [number, number] } | null = null;
  forEachSun(lights, (sun, index) => {
    const centre = compassCentre(index, viewHeight, [0, 0]);
    if (!found && Math.hypot(x - centre[0], y - centre[1]) <= COMPASS_RADIUS) found = { sun, centre };
  });
  return found;
}

/** The rotation that points a sun's arrow (where its shadows fall) from its compass's centre towards a canvas point. */
export function rotationTowards(centre: readonly [number, number], x: number, y: number): number {
  return Math.atan2(y - centre[1], x - centre[0]);
}
