import { describe, expect, it } from 'vitest';
import { DirectionalLight, PointLight, Spotlight } from '../../src/index';

describe('light height and sun elevation (normal-mapped lighting)', () => {
  it('follows a quarter of the range until set, and again after null', () => {
    const light = new PointLight({ range: 200 });
    expect(light.height).toBe(50);
    light.range = 80;
    expect(light.height).toBe(20);
    light.height = 7;
    light.range = 400;
    expect([light.height, light.givenHeight]).toEqual([7, 7]);
    light.height = null;
    expect([light.height, light.givenHeight]).toEqual([100, null]);
    expect(new Spotlight({ range: 40, height: 0 }).height).toBe(0);
  });

  it('names the light and the value of a bad height or elevation', () => {
    expect(() => new PointLight({ height: -1 })).toThrow(new RangeError('PointLight.height must not be negative, got -1'));
    expect(() => new Spotlight({ height: NaN })).toThrow(new RangeError('Spotlight.height must be a finite number, got NaN'));
    expect(new DirectionalLight().elevation).toBe(Math.PI / 4);
    expect(new DirectionalLight({ elevation: Math.PI / 2 }).elevation).toBe(Math.PI / 2);
    expect(() => new DirectionalLight({ elevation: 0 })).toThrow(new RangeError('DirectionalLight.elevation must be in (0, π/2], got 0'));
    expect(() => new DirectionalLight({ elevation: 2 })).toThrow(new RangeError('DirectionalLight.elevation must be in (0, π/2], got 2'));
    expect(() => new DirectionalLight({ elevation: '1' as unknown as number })).toThrow(new TypeError('DirectionalLight.elevation must be a finite number, got "1"'));
  });
});
