/**
 * The look of the final image as public option values: tone-mapping curves, dithering and the range
 * of the lightmap blur. The composite and blur passes turn them into shader codes and loop bounds.
 */

/** The widest lightmap blur, in lightmap pixels either side: the blur shader's loop bound and weight array (a define). */
export const MAX_BLUR_RADIUS = 32;

/**
 * The narrowest lightmap blur, in pixels: a narrower one is off. The blur's Gaussian has σ =
 * radius / 2, so its taps at ±1 weigh exp(−2 / radius²) of the centre's: below 1/8 that is under
 * exp(−128), less than the smallest float32 (2^−149), so the weights the shader gets are the single
 * tap 1 and the blur is the identity. Far below it (about 3e−162) σ² underflows to 0 and the
 * centre's weight exp(−0 / 0) is NaN: every lightmap value would be NaN.
 */
export const MIN_BLUR_RADIUS = 1 / 8;

/** Curves that map the lit colour (scene × lightmap × exposure, unbounded) into the output's 0..1. */
export const ToneMapping = {
  /** None: the colour as it is, clipped at 1 by the output (the default; overlapping lights blow out). */
  None: 'none',
  /** Reinhard, per channel: c / (1 + c). Never clips; halves a colour of 1 (raise the exposure to compensate). */
  Reinhard: 'reinhard',
  /** The ACES filmic curve as fitted by Narkowicz (2015), per channel: contrast in the mid tones, a soft shoulder above. */
  Aces: 'aces',
} as const;
/** One of the {@link ToneMapping} values. */
export type ToneMapping = (typeof ToneMapping)[keyof typeof ToneMapping];

/** Noise added to the output before it is stored, against banding in dark gradients of 8-bit output. */
export const Dithering = {
  /** No dithering (the default). */
  None: 'none',
  /** A 4 × 4 Bayer matrix: a fine regular pattern. */
  Ordered: 'ordered',
  /** Interleaved gradient noise (Jimenez 2014): no visible pattern, close to blue noise. */
  Noise: 'noise',
} as const;
/** One of the {@link Dithering} values. */
export type Dithering = (typeof Dithering)[keyof typeof Dithering];
