import { afterAll, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { Falloff, Hull, PenumbraRenderer, PointLight, ToneMapping } from '../../src/index';
import { falloffAt } from '../../src/scene/falloff';
import { createContext, destroyContext } from './context';
import { readTexture } from './readTexture';

// Numbers reach the GPU as float32: numbers beyond its range are refused up front, and numbers
// within it that overflow a formula (a tone curve's c², the inverse-square core's s², colour ×
// intensity) give finite, sensible texels. Read back from headless-gl: the lightmap (half float)
// and the RGBA8 output.
const WIDTH = 32, HEIGHT = 16;
const FLOAT32_MAX = 3.4028234663852886e38;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;
let light: PointLight;

beforeAll(() => {
  gl = createContext(WIDTH, HEIGHT);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
  light = renderer.addLight(new PointLight({ position: [8, 8], range: 16 }));
});

beforeEach(() => {
  Object.assign(light, { color: [1, 1, 1], intensity: 1, falloff: Falloff.Linear, radius: 0, range: 16 });
  Object.assign(renderer, { exposure: 1, toneMapping: ToneMapping.None });
});

afterAll(() => {
  renderer?.dispose();
  if (gl) destroyContext(gl);
});

/** The lightmap's red channel, rows bottom-up. */
function lightmapReds(): Float32Array {
  renderer.renderLightmap();
  const texels = readTexture(gl, renderer.lightmapTexture, WIDTH, HEIGHT);
  return texels.filter((_, i) => i % 4 === 0);
}

/** A white floor composited with the renderer's look; the red channel of the RGBA8 output, rows bottom-up. */
function outputReds(): Uint8Array {
  renderer.beginDraw();
  gl.clearColor(1, 1, 1, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  const output = new Uint8Array(WIDTH * HEIGHT * 4);
  gl.readPixels(0, 0, WIDTH, HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, output);
  return output.filter((_, i) => i % 4 === 0);
}

describe('values beyond float32 are refused, naming the property', () => {
  it('in every setter that reaches a uniform, through the shared validators', () => {
    const cases: [() => void, string][] = [
      [() => new PointLight({ color: [1e39, 1, 1] }), 'PointLight.color[0] must be at most 3.4028234663852886e+38 in size (a float32, as the GPU takes it), got 1e+39'],
      [() => new PointLight({ intensity: 1e39 }), 'PointLight.intensity must be at most 3.4028234663852886e+38 in size (a float32, as the GPU takes it), got 1e+39'],
      [() => { light.radius = 1e308; }, 'PointLight.radius must be at most'],
      [() => { light.setPosition(0, -1e39); }, 'PointLight.position[1] must be at most'],
      [() => new Hull([[0, 0], [4e38, 0], [0, 1]]), 'Hull.points[1][0] must be at most'],
      [() => { renderer.exposure = 1e39; }, 'PenumbraRenderer.exposure must be at most'],
      [() => { renderer.ambientColor = [0, 0, 5e38]; }, 'PenumbraRenderer.ambientColor[2] must be at most'],
    ];
    for (const [assign, message] of cases) {
      expect(assign).toThrow(RangeError);
      expect(assign).toThrow(message);
    }
    // The largest float32 and a double that rounds down to it are taken.
    expect(new PointLight({ intensity: FLOAT32_MAX }).intensity).toBe(FLOAT32_MAX);
    expect(new PointLight({ intensity: 3.40282356e38 }).intensity).toBe(3.40282356e38);
    expect([light.radius, light.position, renderer.exposure]).toEqual([0, [8, 8], 1]);
  });
});

describe('formulas that overflow float32 for large values give finite, sensible texels', () => {
  it('colour × intensity beyond float32: the lightmap saturates, with no Inf or NaN', () => {
    light.color = [FLOAT32_MAX, 1, 1];
    light.intensity = FLOAT32_MAX;
    const reds = lightmapReds();
    expect(reds.every(Number.isFinite)).toBe(true);
    // Lit inside the range, dark outside it.
    expect(reds[8 * WIDTH + 8]).toBeGreaterThan(1e4);
    expect(reds[8 * WIDTH + 30]).toBe(0);
  });

  for (const curve of [ToneMapping.Aces, ToneMapping.Reinhard, ToneMapping.None]) {
    it(`'${curve}' with an exposure of 1e20 and of the largest float32 writes lit pixels white, unlit ones black`, () => {
      renderer.toneMapping = curve;
      // Overlit (a lightmap near 4), so that the largest exposure takes the lit colour past float32.
      light.intensity = 4;
      for (const exposure of [1e20, FLOAT32_MAX]) {
        renderer.exposure = exposure;
        const reds = outputReds();
        // Near the light (lightmap ≈ 1) and out of its range (lightmap 0, the ambient colour).
        expect([reds[8 * WIDTH + 8], reds[8 * WIDTH + 30]], `${curve} ${exposure}`).toEqual([255, 0]);
      }
    });
  }

  it('the inverse-square falloff with a radius of up to the largest float32, and with a range of it, matches its CPU curve', () => {
    light.falloff = Falloff.InverseSquare;
    for (const [radius, range] of [[1e30, 16], [FLOAT32_MAX, 16], [1, FLOAT32_MAX / 4], [0, 1e20]]) {
      light.radius = radius;
      light.range = range;
      const reds = lightmapReds();
      expect(reds.every(Number.isFinite), `radius ${radius}, range ${range}`).toBe(true);
      // At a pixel centre 4.5 px right of the light: the curve at t = 4.5 / range (on rows bottom-up, row 8 is y 7.5).
      const t = Math.hypot(12.5 - 8, 8.5 - 8) / range;
      const expected = falloffAt(Falloff.InverseSquare, t, light.inverseSquareCore());
      expect(reds[7 * WIDTH + 12], `radius ${radius}, range ${range}`).toBeCloseTo(expected, 2);
    }
  });
});
