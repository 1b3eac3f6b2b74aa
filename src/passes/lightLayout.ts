import type { Falloff } from '../scene/lights';

/**
 * The light passes' codes for a light's distance falloff (see `Falloff`), which
 * shaders/chunks/light-common.glsl compares its varying with, reaching it as defines
 * ({@link LIGHT_DEFINES}).
 */
export const FALLOFF_CODES = { linear: 0, smooth: 1, inverseSquare: 2 } as const satisfies Record<Falloff, number>;

/** The falloff codes as `#define`s. */
export const LIGHT_DEFINES: Readonly<Record<string, number>> = {
  FALLOFF_LINEAR: FALLOFF_CODES.linear, FALLOFF_SMOOTH: FALLOFF_CODES.smooth, FALLOFF_INVERSE_SQUARE: FALLOFF_CODES.inverseSquare,
};
