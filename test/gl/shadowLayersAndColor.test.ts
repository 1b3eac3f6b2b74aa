import { describe, expect, it } from 'vitest';
import type { PenumbraRenderer } from '../../src/index';
import { createSceneRenderer } from '../reference/buildScene';
import { compareToReference } from '../reference/compareToReference';
import { limitViolations } from '../reference/limits';
import { box, type Point, type ReferenceScene } from '../reference/scenes';
import { computeReference, type ReferenceImage } from '../reference/softShadowReference';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// Layers and shadow colour against the exact reference (test/reference), held to the same limits
// as every reference scene (test/reference/limits.ts). Two boxes, one per layer, and a light that
// sees both; each layer mask must render as the reference scene of the boxes in its layers.
const WIDTH = 160, HEIGHT = 120;
const LOW_WALL = box(70, 30, 10, 25), CRATE = box(70, 70, 12, 12);
const both: ReferenceScene = {
  name: 'two layers', width: WIDTH, height: HEIGHT, lights: [{ position: [35, 58], range: 150, radius: 6 }], hulls: [LOW_WALL, CRATE],
};
const only = (hulls: ReferenceScene['hulls']): ReferenceScene => ({ ...both, hulls });

/** Renders `scene` after `setUp` changes the renderer's lights and hulls (in the scene's order). */
function render(scene: ReferenceScene, setUp: (renderer: PenumbraRenderer) => void): Float32Array {
  const gl = createContext(WIDTH, HEIGHT);
  const renderer = createSceneRenderer(gl, scene);
  setUp(renderer);
  const { rgb } = renderLightmap(gl, renderer, WIDTH, HEIGHT);
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
  return rgb;
}

/** The reference with each light's shadows keeping `kept` of it per channel: full light × (v + (1 − v) × kept). */
function withShadowKept(scene: ReferenceScene, reference: ReferenceImage, kept: readonly number[]): ReferenceImage {
  const light = new Float32Array(reference.light.length);
  const [source] = scene.lights;
  for (let y = 0; y < HEIGHT; y++) {
    for (let x = 0; x < WIDTH; x++) {
      const pixel = y * WIDTH + x;
      const falloff = Math.max(0, 1 - Math.hypot(x + 0.5 - source.position[0], y + 0.5 - source.position[1]) / source.range);
      const visible = reference.visibility[0][pixel];
      for (let c = 0; c < 3; c++) light[pixel * 3 + c] = falloff * (visible + (1 - visible) * kept[c]);
    }
  }
  return { ...reference, light };
}

describe('light and hull layers, on headless-gl', () => {
  const cases = [
    { title: 'a light in layer 1 only is shadowed by the hull in layer 1 only', mask: 0b01, expected: only([LOW_WALL]) },
    { title: 'a light in layer 2 only is shadowed by the hull in layer 2 only', mask: 0b10, expected: only([CRATE]) },
    { title: 'a light in both layers is shadowed by both hulls', mask: 0b11, expected: both },
    { title: 'a light in no layer is shadowed by none', mask: 0, expected: only([]) },
  ];
  for (const { title, mask, expected } of cases) {
    it(title, () => {
      const rendered = render(both, (renderer) => {
        renderer.hulls[0].layers = 0b01;
        renderer.hulls[1].layers = 0b10;
        renderer.lights[0].shadowLayers = mask;
      });
      expect(limitViolations(compareToReference(expected, rendered, computeReference(expected)))).toEqual([]);
    });
  }

  it('draws a light whose centre is inside a hull of a layer it ignores', () => {
    const inside: ReferenceScene = { ...both, lights: [{ position: [75, 75], range: 150, radius: 3 }] };
    const rendered = render(inside, (renderer) => {
      renderer.hulls[1].layers = 0b10;
      renderer.lights[0].shadowLayers = 0b01;
    });
    const expected = { ...inside, hulls: [LOW_WALL] };
    expect(limitViolations(compareToReference(expected, rendered, computeReference(expected)))).toEqual([]);
  });
});

describe('shadow colour and strength, on headless-gl', () => {
  it('keeps 1 − strength × (1 − colour) of the light in full shadow, and mixes by the visible fraction in the penumbra', () => {
    const color = [0.2, 0.5, 0.8] as const, strength = 0.5;
    const kept = color.map((c) => 1 - strength * (1 - c));
    const rendered = render(both, (renderer) => {
      renderer.lights[0].shadowColor = color;
      renderer.lights[0].shadowStrength = strength;
    });
    const expected = withShadowKept(both, computeReference(both), kept);
    const errors = compareToReference(both, rendered, expected);
    expect(errors.umbra.pixels).toBeGreaterThan(500);
    expect(limitViolations(errors)).toEqual([]);
  });

  it('draws today\'s black shadows by default', () => {
    const rendered = render(both, () => {});
    expect(limitViolations(compareToReference(both, rendered, withShadowKept(both, computeReference(both), [0, 0, 0])))).toEqual([]);
  });
});

describe('content layers: lightmaps of the lights that light a layer, on headless-gl', () => {
  // Two lights of the reference scenes' kind, one per content layer: a lightmap built for a layer
  // must be the reference scene of that layer's lights alone.
  const warm = { position: [35, 58] as Point, range: 150, radius: 6, color: [1, 0.5, 0.2] as [number, number, number] };
  const cold = { position: [125, 60] as Point, range: 120, radius: 3, color: [0.2, 0.5, 1] as [number, number, number] };
  const twoLights: ReferenceScene = { ...both, lights: [warm, cold] };
  const cases = [
    { title: 'a lightmap for layer 1 holds the light of layer 1 only', layers: 0b01, lights: [warm] },
    { title: 'a lightmap for layer 2 holds the light of layer 2 only', layers: 0b10, lights: [cold] },
    { title: 'a lightmap for both layers, the default, holds both lights', layers: undefined, lights: [warm, cold] },
  ];
  for (const { title, layers, lights } of cases) {
    it(title, () => {
      const gl = createContext(WIDTH, HEIGHT);
      const renderer = createSceneRenderer(gl, twoLights);
      renderer.lights[0].litLayers = 0b01;
      renderer.lights[1].litLayers = 0b10;
      const { rgb } = renderLightmap(gl, renderer, WIDTH, HEIGHT, layers);
      expect(gl.getError()).toBe(0);
      renderer.dispose();
      destroyContext(gl);
      const expected = { ...twoLights, lights };
      // Errors in units of both lights' full strength, as the scene with both lights would count them.
      expect(limitViolations(compareToReference(twoLights, rgb, computeReference(expected)))).toEqual([]);
    });
  }

  it('names the argument when the layers are not a mask', () => {
    const gl = createContext(WIDTH, HEIGHT);
    const renderer = createSceneRenderer(gl, twoLights);
    expect(() => renderer.drawInPlace(-1)).toThrow('PenumbraRenderer.drawInPlace: layers must be an integer from 0 to 0xffffffff (a bit mask), got -1');
    renderer.dispose();
    destroyContext(gl);
  });
});
