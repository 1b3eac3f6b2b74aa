import { Light } from './Light';

/** An isotropic light: full at its centre, falling to zero at `range` along its `falloff` curve (see {@link Falloff}). */
export class PointLight extends Light {
  get kind(): 'point' {
    return 'point';
  }
}
