/**
 * How a point light's or a spotlight's strength falls with the distance d from its position, t =
 * d / range: every curve is 1 at the centre and 0 from the range on.
 */
export const Falloff = {
  /** `max(0, 1 − t)`: the default. */
  Linear: 'linear',
  /** `max(0, 1 − t²)²`: flat near the centre, a soft edge at the range. */
  Smooth: 'smooth',
  /**
   * `s² / (s² + t²) × max(0, 1 − t⁴)²`, s = max(radius, 1) / range: the light of a uniformly
   * emitting disk of the light's radius seen face-on (inverse square beyond it), windowed to reach
   * zero at the range. Physically based and bright only near a small light: raise the intensity.
   * s is taken within [2^−60, 2^16], so that s² stays a normal float32 on the GPU: above 2^16 the
   * curve is its window to float32 precision, and below 2^−60 (a range over 2^60 times the radius,
   * where float32 cannot tell the distances near the light apart anyway) it is that of 2^−60.
   */
  InverseSquare: 'inverseSquare',
} as const;
/** One of the {@link Falloff} values. */
export type Falloff = (typeof Falloff)[keyof typeof Falloff];

/**
 * The light's strength at distance t (in ranges) from its position by `falloff` (see
 * {@link Falloff}); `core` is s, the inverse-square core in ranges. The same curves as
 * `distanceFalloff` in shaders/chunks/light-common.glsl.
 * @internal
 */
export function falloffAt(falloff: Falloff, t: number, core: number): number {
  if (falloff === Falloff.Smooth) {
    const window = Math.max(0, 1 - t * t);
    return window * window;
  }
  if (falloff === Falloff.InverseSquare) {
    const t2 = t * t, window = Math.max(0, 1 - t2 * t2), core2 = core * core;
    return (window * window * core2) / (core2 + t2);
  }
  return Math.max(0, 1 - t);
}
