/**
 * The look's GPU interface: the codes the composite shader (shaders/composite.frag.glsl) compares
 * its tone-mapping and dithering uniforms with, which reach it as defines ({@link COMPOSITE_DEFINES}).
 * The public values and the blur's bounds are in scene/look.ts.
 */
import type { Dithering, ToneMapping } from '../scene/look';

/** The shader's code of each curve and dithering. */
export const TONE_MAPPING_CODES: Readonly<Record<ToneMapping, number>> = { none: 0, reinhard: 1, aces: 2 };
export const DITHERING_CODES: Readonly<Record<Dithering, number>> = { none: 0, ordered: 1, noise: 2 };

/** The codes as `#define`s. */
export const COMPOSITE_DEFINES: Readonly<Record<string, number>> = {
  TONE_REINHARD: TONE_MAPPING_CODES.reinhard,
  TONE_ACES: TONE_MAPPING_CODES.aces,
  DITHER_ORDERED: DITHERING_CODES.ordered,
  DITHER_NOISE: DITHERING_CODES.noise,
};
