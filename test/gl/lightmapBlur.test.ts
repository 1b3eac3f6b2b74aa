import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { lightmapOf } from './fixtures';
import { readTexture } from './readTexture';

// The lightmap blur against a CPU version of the same filter applied to the unblurred lightmap:
// per axis, Σ_k w_k × texel(x + k), k = −⌈R⌉..⌈R⌉, w_k ∝ exp(−k² / (2 (R/2)²)) normalised, taps past
// the edge reading the edge texel. The lightmap is half float: 2^-11 relative per stored value,
// twice (the scratch pass and the result), so 0.002 of the brightest value is the tolerance.
const WIDTH = 64, HEIGHT = 48;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;

beforeAll(() => {
  gl = createContext(WIDTH, HEIGHT);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0.05, 0.1, 0.15] });
  renderer.addLight(new PointLight({ position: [14, 24], range: 60, radius: 0, color: [1, 0.8, 0.6], intensity: 1.5 }));
  renderer.addHull(new Hull([[30, 16], [36, 16], [36, 32], [30, 32]]));
});

afterAll(() => {
  renderer?.dispose();
  if (gl) destroyContext(gl);
});

/** The CPU blur of RGBA rows (`width × height × 4`) by `radius` texels, one axis then the other. */
function blurred(texels: Float32Array, radius: number): Float64Array {
  const taps = Math.ceil(radius), sigma = radius / 2;
  const weights = Array.from({ length: 2 * taps + 1 }, (_, i) => Math.exp(-((i - taps) ** 2) / (2 * sigma * sigma)));
  const total = weights.reduce((a, b) => a + b, 0);
  const clamp = (v: number, max: number) => Math.min(max - 1, Math.max(0, v));
  const pass = (source: ArrayLike<number>, dx: number, dy: number) => {
    const out = new Float64Array(source.length);
    for (let y = 0; y < HEIGHT; y++) {
      for (let x = 0; x < WIDTH; x++) {
        for (let c = 0; c < 4; c++) {
          let sum = 0;
          for (let k = -taps; k <= taps; k++) sum += weights[k + taps] * source[(clamp(y + k * dy, HEIGHT) * WIDTH + clamp(x + k * dx, WIDTH)) * 4 + c];
          out[(y * WIDTH + x) * 4 + c] = sum / total;
        }
      }
    }
    return out;
  };
  return pass(pass(texels, 1, 0), 0, 1);
}

describe('lightmap blur, on headless-gl', () => {
  for (const radius of [1.5, 4, 11]) {
    it(`blurs the lightmap by a Gaussian of radius ${radius}, as the CPU filter does`, () => {
      renderer.lightmapBlur = 0;
      const sharp = lightmapOf(gl, renderer, WIDTH, HEIGHT);
      renderer.lightmapBlur = radius;
      const soft = lightmapOf(gl, renderer, WIDTH, HEIGHT);
      const expected = blurred(sharp, radius);
      let largest = 0, changed = 0;
      for (let i = 0; i < soft.length; i++) {
        largest = Math.max(largest, Math.abs(soft[i] - expected[i]));
        changed = Math.max(changed, Math.abs(soft[i] - sharp[i]));
      }
      const brightest = Math.max(...sharp);
      expect(largest).toBeLessThanOrEqual(0.002 * brightest);
      // And the blur did something: the shadow's edge moved by far more than the tolerance.
      expect(changed).toBeGreaterThan(0.05);
      expect(gl.getError()).toBe(0);
    });
  }

  it('treats a radius too small to move any value as off: no NaN from an underflowing Gaussian', () => {
    renderer.lightmapBlur = 0;
    const sharp = lightmapOf(gl, renderer, WIDTH, HEIGHT);
    // Down to the smallest double: σ² underflows to 0 below about 3e-162 (exp(−0 / 0) is NaN).
    for (const radius of [0.12, 1e-10, 3e-162, 1e-200, 1e-320, Number.MIN_VALUE]) {
      renderer.lightmapBlur = radius;
      expect(renderer.lightmapBlur).toBe(0);
      expect(lightmapOf(gl, renderer, WIDTH, HEIGHT)).toEqual(sharp);
    }
    // 1/8 is on: its weights are the single tap (the passes' sampling may still round).
    renderer.lightmapBlur = 0.125;
    expect(renderer.lightmapBlur).toBe(0.125);
    const barely = lightmapOf(gl, renderer, WIDTH, HEIGHT);
    expect(Math.max(...barely.map((value, i) => Math.abs(value - sharp[i])))).toBeLessThanOrEqual(0.002 * Math.max(...sharp));
    expect(gl.getError()).toBe(0);
  });

  it('leaves the lightmap as it is where lightmapScale brings the radius below 1/8 of a lightmap texel', () => {
    const scaled = new PenumbraRenderer(gl, { lightmapScale: 0.5, lightmapBlur: 0.2 });
    scaled.addLight(new PointLight({ position: [14, 24], range: 60 }));
    scaled.renderLightmap();
    const blurred = readTexture(gl, scaled.lightmapTexture, WIDTH / 2, HEIGHT / 2);
    scaled.lightmapBlur = 0;
    scaled.renderLightmap();
    expect(blurred).toEqual(readTexture(gl, scaled.lightmapTexture, WIDTH / 2, HEIGHT / 2));
    expect(blurred.every(Number.isFinite)).toBe(true);
    scaled.dispose();
  });

  it('names the property and the value of a bad radius', () => {
    expect(() => { renderer.lightmapBlur = -1; }).toThrow(new RangeError('PenumbraRenderer.lightmapBlur must not be negative, got -1'));
    expect(() => { renderer.lightmapBlur = 40; }).toThrow(new RangeError('PenumbraRenderer.lightmapBlur must be at most 32, got 40'));
  });
});
