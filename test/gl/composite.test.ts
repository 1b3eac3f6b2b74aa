import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Dithering, PenumbraRenderer, PointLight, ToneMapping } from '../../src/index';
import { createContext, destroyContext } from './context';
import { readTexture } from './readTexture';

// The composite's exposure, tone mapping and dithering against CPU versions of the same formulas,
// applied to the lightmap the frame read back. The output is the context's RGBA8 framebuffer: one
// 8-bit step (1/255) is the tolerance, for the GPU's rounding of a float to 8 bits.
const WIDTH = 128, HEIGHT = 32;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;

beforeAll(() => {
  gl = createContext(WIDTH, HEIGHT);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
  // A light at the left edge: its falloff is a gradient across the image, up to 1.6 (overlit).
  renderer.addLight(new PointLight({ position: [0, HEIGHT / 2], range: WIDTH, intensity: 1.6 }));
});

afterAll(() => {
  if (gl) destroyContext(gl);
});

/** Renders a floor of `floor` colour with the renderer's look; returns the output bytes and the lightmap (both rows bottom-up). */
function frame(floor: readonly [number, number, number]): { output: Uint8Array; lightmap: Float32Array } {
  renderer.beginDraw();
  gl.clearColor(floor[0], floor[1], floor[2], 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  const output = new Uint8Array(WIDTH * HEIGHT * 4);
  gl.readPixels(0, 0, WIDTH, HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, output);
  return { output, lightmap: readTexture(gl, renderer.lightmapTexture, WIDTH, HEIGHT) };
}

const CURVES: Record<ToneMapping, (c: number) => number> = {
  none: (c) => c,
  reinhard: (c) => c / (1 + c),
  aces: (c) => Math.min(1, Math.max(0, (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14))),
};

/** The exact output value (in 8-bit steps, unrounded) of every channel: curve(floor × light × exposure) × 255. */
function expected(lightmap: Float32Array, floor: readonly number[], exposure: number, curve: ToneMapping): Float64Array {
  const values = new Float64Array(WIDTH * HEIGHT * 3);
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    for (let c = 0; c < 3; c++) values[p * 3 + c] = Math.min(1, CURVES[curve](floor[c] * lightmap[p * 4 + c] * exposure)) * 255;
  }
  return values;
}

function largestDifference(output: Uint8Array, values: Float64Array): number {
  let largest = 0;
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    for (let c = 0; c < 3; c++) largest = Math.max(largest, Math.abs(output[p * 4 + c] - values[p * 3 + c]));
  }
  return largest;
}

describe('the composite: exposure and tone mapping', () => {
  // Exact in the scene's RGBA8 target: 204, 153 and 102 / 255.
  const floor = [0.8, 0.6, 0.4] as const;
  const cases: [ToneMapping, number][] = [['none', 1], ['none', 0.5], ['reinhard', 2], ['aces', 1.5]];
  for (const [curve, exposure] of cases) {
    it(`writes ${curve}(scene × lightmap × ${exposure}) to within one 8-bit step`, () => {
      renderer.toneMapping = curve;
      renderer.exposure = exposure;
      renderer.dithering = Dithering.None;
      const { output, lightmap } = frame(floor);
      // Rounding to 8 bits: within half a step of the exact value, and a little float error.
      expect(largestDifference(output, expected(lightmap, floor, exposure, curve))).toBeLessThanOrEqual(0.5 + 0.02);
    });
  }

  it('names the property and the value of a bad exposure, curve or dithering', () => {
    expect(() => { renderer.exposure = -1; }).toThrow(new RangeError('PenumbraRenderer.exposure must not be negative, got -1'));
    expect(() => { renderer.toneMapping = 'filmic' as ToneMapping; })
      .toThrow(new RangeError('PenumbraRenderer.toneMapping must be one of "none", "reinhard", "aces", got "filmic"'));
    expect(() => new PenumbraRenderer(gl, { dithering: 'blue' as Dithering }))
      .toThrow(new RangeError('PenumbraRenderer.dithering must be one of "none", "ordered", "noise", got "blue"'));
  });
});

describe('the composite: dithering', () => {
  // A dark floor (13/255, exact in the RGBA8 scene target) under a far light: the lit gradient is
  // shallow, about 2 8-bit levels over 128 pixels, in wide bands.
  const floor = [13 / 255, 13 / 255, 13 / 255] as const;

  /** Mean over each 4 × 4 block of the red channel, minus the exact value's mean there: how far the blocks are off. */
  function blockErrors(output: Uint8Array, values: Float64Array): number[] {
    const errors: number[] = [];
    for (let by = 0; by < HEIGHT; by += 4) {
      for (let bx = 0; bx < WIDTH; bx += 4) {
        let sum = 0;
        for (let y = by; y < by + 4; y++) for (let x = bx; x < bx + 4; x++) sum += output[(y * WIDTH + x) * 4] - values[(y * WIDTH + x) * 3];
        errors.push(Math.abs(sum / 16));
      }
    }
    return errors;
  }
  const mean = (values: number[]) => values.reduce((a, b) => a + b, 0) / values.length;

  for (const dithering of [Dithering.Ordered, Dithering.Noise]) {
    it(`${dithering}: moves no value by more than one step, and brings 4 × 4 block means close to the exact gradient`, () => {
      renderer.toneMapping = ToneMapping.None;
      renderer.exposure = 1;
      renderer.dithering = Dithering.None;
      renderer.lights[0].setPosition(-400, HEIGHT / 2);
      renderer.lights[0].range = 1200;
      const plain = frame(floor);
      renderer.dithering = dithering;
      const dithered = frame(floor);
      let moved = 0;
      for (let i = 0; i < plain.output.length; i++) moved = Math.max(moved, Math.abs(dithered.output[i] - plain.output[i]));
      expect(moved).toBeLessThanOrEqual(1);
      const values = expected(plain.lightmap, floor, 1, 'none');
      const bandedError = mean(blockErrors(plain.output, values));
      const ditheredError = mean(blockErrors(dithered.output, values));
      console.log(`${dithering}: mean error of 4×4 block means, in 8-bit steps: ${bandedError.toFixed(3)} without dithering, ${ditheredError.toFixed(3)} with`);
      // Rounding leaves a block of a shallow gradient up to half a step off (a quarter on average);
      // dithering spreads each block over the two levels around it in the right proportion.
      expect(bandedError).toBeGreaterThan(0.15);
      expect(ditheredError).toBeLessThan(bandedError / 3);
    });
  }
});
