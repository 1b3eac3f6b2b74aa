import type { SceneErrors } from './compareToReference';

/**
 * What every reference scene (fixed or random) is held to, in units of full light (see
 * compareToReference), over every pixel within range that is not ambiguous. A renderer that finds
 * the exact union of what the hulls hide of each disk is left with precision errors only: the
 * shadow mask is RGBA8 (steps of 1/255 ≈ 0.004), the lightmap half float (relative rounding
 * 2^-11 ≈ 0.0005), its shader math float32. Those stay far within the mean and p99 below; the max
 * leaves room for a few pixels of worse rounding where the penumbrae of several hulls meet, and
 * fails any pixel that is plainly wrong (a leak, a missing slice of the disk).
 */
export const MEAN_LIMIT = 0.005;
export const P99_LIMIT = 0.02;
export const MAX_LIMIT = 0.1;
/**
 * Behind a wall of touching tiles, every pixel the reference puts in umbra must be dark to within
 * one step of the RGBA8 shadow mask: light leaking through the seams between tiles shows there.
 */
export const UMBRA_LIMIT = 1 / 255;

/** The limits of the mean, p99 and max that `errors` breaks, as readable lines (empty when within all). */
export function limitViolations(errors: SceneErrors): string[] {
  const violations: string[] = [];
  if (errors.all.mean > MEAN_LIMIT) violations.push(`mean ${errors.all.mean.toFixed(4)} > ${MEAN_LIMIT}`);
  if (errors.all.p99 > P99_LIMIT) violations.push(`p99 ${errors.all.p99.toFixed(4)} > ${P99_LIMIT}`);
  if (errors.all.max > MAX_LIMIT) violations.push(`max ${errors.all.max.toFixed(4)} > ${MAX_LIMIT}`);
  return violations;
}
