import { describe, expect, it } from 'vitest';
import { Hull, PointLight, Spotlight } from '../../src/index';

/** Expects a RangeError whose message names the property and shows the value. */
function expectRangeError(assign: () => void, property: string, value: string): void {
  expect(assign).toThrow(RangeError);
  try {
    assign();
  } catch (error) {
    expect((error as Error).message).toContain(property);
    expect((error as Error).message).toContain(value);
  }
}

describe('light validation', () => {
  const nonNegative = ['range', 'radius', 'intensity'] as const;
  for (const property of nonNegative) {
    it(`rejects NaN, Infinity and negative ${property}`, () => {
      const light = new PointLight();
      expectRangeError(() => { light[property] = NaN; }, `PointLight.${property}`, 'NaN');
      expectRangeError(() => { light[property] = Infinity; }, `PointLight.${property}`, 'Infinity');
      expectRangeError(() => { light[property] = -2; }, `PointLight.${property}`, '-2');
      expectRangeError(() => new PointLight({ [property]: -3 }), `PointLight.${property}`, '-3');
      light[property] = 0;
      expect(light[property]).toBe(0);
    });
  }

  it('rejects a bad coneDecay and a cone wider than π', () => {
    const spot = new Spotlight();
    expectRangeError(() => { spot.coneDecay = -1; }, 'Spotlight.coneDecay', '-1');
    expectRangeError(() => { spot.coneDecay = NaN; }, 'Spotlight.coneDecay', 'NaN');
    expectRangeError(() => { spot.coneAngle = 4; }, 'Spotlight.coneAngle', '4');
    expectRangeError(() => { spot.coneAngle = -0.5; }, 'Spotlight.coneAngle', '-0.5');
    spot.coneAngle = Math.PI;
    expect(spot.coneAngle).toBe(Math.PI);
  });

  it('rejects non-finite positions and colours, naming the component', () => {
    const light = new PointLight();
    expectRangeError(() => { light.position = [1, NaN]; }, 'PointLight.position[1]', 'NaN');
    expectRangeError(() => { light.color = [1, -1, 0]; }, 'PointLight.color[1]', '-1');
  });

  it('rejects layer masks that are not 32-bit unsigned integers, and shadow strengths outside 0..1', () => {
    const light = new PointLight();
    const hull = new Hull([[0, 0], [1, 0], [0, 1]]);
    expect(light.shadowLayers).toBe(0xffffffff);
    expect(hull.layers).toBe(1);
    expectRangeError(() => { light.shadowLayers = 1.5; }, 'PointLight.shadowLayers', '1.5');
    expectRangeError(() => { light.shadowLayers = -1; }, 'PointLight.shadowLayers', '-1');
    expectRangeError(() => { hull.layers = 2 ** 32; }, 'Hull.layers', '4294967296');
    expect(() => { hull.layers = '2' as unknown as number; }).toThrow(new TypeError('Hull.layers must be an integer from 0 to 0xffffffff (a bit mask), got "2"'));
    expectRangeError(() => { light.shadowStrength = 1.01; }, 'PointLight.shadowStrength', '1.01');
    expectRangeError(() => new PointLight({ shadowStrength: NaN }), 'PointLight.shadowStrength', 'NaN');
    expectRangeError(() => { light.shadowColor = [0, -1, 0]; }, 'PointLight.shadowColor[1]', '-1');
    light.shadowLayers = 0x80000000;
    hull.layers = 0;
    expect([light.shadowLayers, hull.layers]).toEqual([0x80000000, 0]);
  });

  it('rejects numbers that are not finite as float32, what the GPU takes, in every kind of field', () => {
    // The largest float32 is (2 − 2^−23) × 2^127; a double rounds down to it up to half a step above.
    const largest = (2 - 2 ** -23) * 2 ** 127, halfStep = 2 ** 103;
    const light = new PointLight();
    for (const value of [largest, largest + halfStep / 2, -largest]) {
      light.rotation = value;
      light.setPosition(value, -value);
      new Hull([[0, 0], [value, 0], [0, 1]], { scale: value, position: [value, 0] });
    }
    for (const value of [largest + halfStep, 1e39, -1e39, Number.MAX_VALUE]) {
      expectRangeError(() => { light.rotation = value; }, 'PointLight.rotation', String(value));
      expectRangeError(() => light.setPosition(0, value), 'PointLight.position[1]', String(value));
      expectRangeError(() => { light.shadowColor = [0, 0, Math.abs(value)]; }, 'PointLight.shadowColor[2]', String(Math.abs(value)));
      expectRangeError(() => new Hull([[0, 0], [value, 0], [0, 1]]), 'Hull.points[1][0]', String(value));
      expectRangeError(() => new Hull([[0, 0], [1, 0], [0, 1]], { scale: [1, value] }), 'Hull.scale', String(value));
    }
    expect(() => { light.range = 1e39; }).toThrow(new RangeError('PointLight.range must be at most 3.4028234663852886e+38 in size (a float32, as the GPU takes it), got 1e+39'));
  });

  it('keeps the previous value after a rejected assignment', () => {
    const light = new PointLight({ range: 50 });
    expect(() => { light.range = -1; }).toThrow(RangeError);
    expect(light.range).toBe(50);
  });
});
