import { Light, LIGHT_OPTION_KEYS, type LightOptions } from './Light';
import { assertFinite, assertNonNegative } from '../util/validate';

/** Options of a {@link DirectionalLight}: those of every light but the ones about a position and a range. */
export interface DirectionalLightOptions extends Omit<LightOptions, 'position' | 'range' | 'radius' | 'origin' | 'falloff' | 'height'> {
  /**
   * Angle of the light above the plane in radians, in (0, π/2], for normal-mapped lighting
   * (`PenumbraRenderer` option `normals`): π/2 is straight above, small values graze the relief.
   * Shadows do not depend on it. Default `π/4`.
   */
  elevation?: number;
  /**
   * Apparent diameter of the light's disk in radians, 0..π/2: the sun's is about 0.0093 (0.53°);
   * wider gives the soft shadows of an overcast sky, 0 hard shadows. Default `0.0093`.
   */
  angularSize?: number;
}

/** The options about a position and a range, which a directional light has not. */
const POSITIONAL_OPTION_KEYS: readonly string[] = Object.keys({
  position: true, range: true, radius: true, origin: true, falloff: true, height: true,
} satisfies Record<Exclude<keyof LightOptions, keyof DirectionalLightOptions>, true>);

/** The options a directional light takes; any other key is an error. */
const DIRECTIONAL_LIGHT_OPTION_KEYS: readonly string[] = [
  ...LIGHT_OPTION_KEYS.filter((key) => !POSITIONAL_OPTION_KEYS.includes(key)),
  ...Object.keys({ angularSize: true, elevation: true } satisfies Record<Exclude<keyof DirectionalLightOptions, keyof LightOptions>, true>),
];

/** The sun's apparent diameter seen from the Earth, in radians (0.53°). */
const SUN_ANGULAR_SIZE = 0.0093;

/**
 * Light from far away — the sun or the moon — travelling along `rotation` (0: towards +x, so
 * shadows fall towards +x) and covering the whole view with the same colour × intensity: no
 * position, no range, no falloff. Its disk has an apparent diameter `angularSize`, so shadows are
 * soft: exact for a uniformly emitting disk at infinity, hard at the hull and widening with the
 * distance from it (by `2 × tan(angularSize / 2)` per unit). Hulls anywhere upstream of the view
 * shadow it, not only those in view.
 *
 * `position`, `range`, `radius`, `origin`, `falloff` and `height` mean nothing for it: as options
 * they are errors, as the properties it inherits they are ignored.
 */
export class DirectionalLight extends Light {
  private _angularSize = SUN_ANGULAR_SIZE;
  private _elevation = Math.PI / 4;

  constructor(options: DirectionalLightOptions = {}) {
    super(options);
    if (options.angularSize !== undefined) this.angularSize = options.angularSize;
    if (options.elevation !== undefined) this.elevation = options.elevation;
  }

  get kind(): 'directional' {
    return 'directional';
  }

  /** @internal */
  protected override get optionKeys(): readonly string[] {
    return DIRECTIONAL_LIGHT_OPTION_KEYS;
  }

  /** Apparent diameter of the light's disk in radians (0..π/2); see {@link DirectionalLightOptions.angularSize}. */
  get angularSize(): number {
    return this._angularSize;
  }
  set angularSize(value: number) {
    assertNonNegative('DirectionalLight.angularSize', value);
    if (value > Math.PI / 2) throw new RangeError(`DirectionalLight.angularSize must be at most π/2, got ${value}`);
    this._angularSize = value;
  }

  /** Angle above the plane in radians, (0, π/2]; see {@link DirectionalLightOptions.elevation}. */
  get elevation(): number {
    return this._elevation;
  }
  set elevation(value: number) {
    assertFinite('DirectionalLight.elevation', value);
    if (!(value > 0 && value <= Math.PI / 2)) throw new RangeError(`DirectionalLight.elevation must be in (0, π/2], got ${value}`);
    this._elevation = value;
  }

  /** Unbounded: it lights the whole view. @internal */
  override reach(): number {
    return Infinity;
  }

  /** It covers the view, not a disk. @internal */
  override isConfinedToRangeDisk(): boolean {
    return false;
  }
}
