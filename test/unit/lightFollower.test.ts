import { describe, expect, it } from 'vitest';
import { LightFollower } from '../../src/integrations/LightFollower';
import { PointLight, Spotlight } from '../../src/index';

// The engine-independent part of a light following a display object: the light placed by the
// object → world transform [a, b, c, d, tx, ty]. Expected values are worked out by hand.

const turnedQuarter = (tx: number, ty: number): Float64Array => new Float64Array([0, 1, -1, 0, tx, ty]);

describe('LightFollower', () => {
  it('leaves light.rotation alone with rotation null (the default), turning only the offset', () => {
    const light = new Spotlight({ rotation: 0.3 });
    const follower = new LightFollower({}, light, { offset: [5, 0] }, 'test');
    follower.place(turnedQuarter(100, 50), true);
    expect(light.position).toEqual([100, 55]);
    expect(light.rotation).toBe(0.3);
  });

  it('turns the light with the object when rotation is a number, and keeps the last direction under a zero scale', () => {
    const light = new Spotlight();
    const follower = new LightFollower({}, light, { rotation: 0 }, 'test');
    follower.place(turnedQuarter(0, 0), true);
    expect(light.rotation).toBeCloseTo(Math.PI / 2, 12);
    follower.place(new Float64Array([0, 0, 0, 0, 7, 8]), true);
    expect(light.position).toEqual([7, 8]);
    expect(light.rotation).toBeCloseTo(Math.PI / 2, 12);
  });

  it('writes nothing while the transform stays, and places again after the offset changes', () => {
    const light = new PointLight();
    const follower = new LightFollower({}, light, {}, 'test');
    const m = new Float64Array([2, 0, 0, 2, 10, 10]);
    follower.place(m, true);
    const placed = light.position;
    follower.place(m, true);
    expect(light.position).toBe(placed);
    follower.offset = [1, 2];
    follower.place(m, true);
    expect(light.position).toEqual([12, 14]);
  });

  it('switches the light off while the object is hidden or the follower disabled, and release turns it back on', () => {
    const light = new PointLight();
    const follower = new LightFollower({}, light, {}, 'test');
    const m = new Float64Array([1, 0, 0, 1, 0, 0]);
    follower.place(m, false);
    expect(light.enabled).toBe(false);
    follower.place(m, true);
    expect(light.enabled).toBe(true);
    follower.enabled = false;
    follower.place(m, true);
    expect(light.enabled).toBe(false);
    follower.release();
    expect(light.enabled).toBe(true);
  });

  it('rejects options that do not fit, naming them', () => {
    const light = new PointLight();
    expect(() => new LightFollower({}, light, { ofset: [1, 2] } as never, 'PenumbraLayer.follow'))
      .toThrow('penumbra: PenumbraLayer.follow options.ofset is not an option (did you mean \'offset\'?)');
    expect(() => new LightFollower({}, light, { at: [1, 2] } as never, 'PenumbraLayer.follow'))
      .toThrow('penumbra: PenumbraLayer.follow options.at is not an option (the options are offset, rotation)');
    expect(() => new LightFollower({}, light, { rotation: Number.NaN }, 'PenumbraLayer.follow')).toThrow(RangeError);
    expect(() => new LightFollower({}, light, { offset: 'here' as never }, 'PenumbraLayer.follow')).toThrow(TypeError);
  });
});
