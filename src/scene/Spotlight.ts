import { Light, LIGHT_OPTION_KEYS, type LightOptions } from './Light';
import { assertNonNegative } from '../util/validate';

/** Options of a {@link Spotlight}. */
export interface SpotlightOptions extends LightOptions {
  /** Full angle of the cone in radians, 0..π. Default `π / 2`. */
  coneAngle?: number;
  /**
   * Falloff across the cone, not negative: the intensity at angle θ off the axis is
   * `(1 − θ / (coneAngle / 2)) ^ coneDecay`. 0 gives a hard-edged cone of even intensity;
   * larger values concentrate the light towards the axis. Default `1`.
   */
  coneDecay?: number;
}

/** The options a spotlight takes; any other key is an error. */
const SPOTLIGHT_OPTION_KEYS: readonly string[] = [
  ...LIGHT_OPTION_KEYS,
  ...Object.keys({ coneAngle: true, coneDecay: true } satisfies Record<Exclude<keyof SpotlightOptions, keyof LightOptions>, true>),
];

/**
 * A cone of light from `position` along `rotation` (0 points along +x), with the point light's
 * distance falloff times a cone falloff set by `coneAngle` and `coneDecay`.
 */
export class Spotlight extends Light {
  get kind(): 'spot' {
    return 'spot';
  }

  private _coneAngle = Math.PI / 2;
  private _coneDecay = 1;

  constructor(options: SpotlightOptions = {}) {
    super(options);
    if (options.coneAngle !== undefined) this.coneAngle = options.coneAngle;
    if (options.coneDecay !== undefined) this.coneDecay = options.coneDecay;
  }

  /** @internal */
  protected override get optionKeys(): readonly string[] {
    return SPOTLIGHT_OPTION_KEYS;
  }

  /** Full angle of the cone in radians (0..π). */
  get coneAngle(): number {
    return this._coneAngle;
  }
  set coneAngle(value: number) {
    assertNonNegative('Spotlight.coneAngle', value);
    if (value > Math.PI) throw new RangeError(`Spotlight.coneAngle must be at most π, got ${value}`);
    this._coneAngle = value;
  }

  /** Falloff exponent across the cone; see {@link SpotlightOptions.coneDecay}. */
  get coneDecay(): number {
    return this._coneDecay;
  }
  set coneDecay(value: number) {
    this._coneDecay = assertNonNegative('Spotlight.coneDecay', value);
  }
}
