import { afterAll, describe, expect, it } from 'vitest';
import { createSceneRenderer } from '../reference/buildScene';
import { compareToReference, formatErrorTable, type SceneErrors } from '../reference/compareToReference';
import { MAX_LIMIT, MEAN_LIMIT, P99_LIMIT, UMBRA_LIMIT } from '../reference/limits';
import { REFERENCE_SCENES, type ReferenceScene } from '../reference/scenes';
import { computeReference } from '../reference/softShadowReference';
import { createContext, destroyContext } from './context';
import { renderLightmap, type Lightmap } from './lightmap';

// Every scene is held to the limits of test/reference/limits.ts over every pixel within range
// (lit, umbra and penumbra alike), in units of full light: mean ≤ 0.005, p99 ≤ 0.02, max ≤ 0.1,
// against the exact CPU reference (test/reference/softShadowReference.ts, itself held to disk
// sampling in test/unit/reference.test.ts, test/unit/illumination.test.ts and test/accuracy/).

function renderScene(scene: ReferenceScene): Lightmap {
  const gl = createContext(scene.width, scene.height);
  const renderer = createSceneRenderer(gl, scene);
  const lightmap = renderLightmap(gl, renderer, scene.width, scene.height);
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
  return lightmap;
}

const figures: { scene: string; errors: SceneErrors }[] = [];

describe('reference scenes on headless-gl', () => {
  afterAll(() => {
    console.log(formatErrorTable('headless-gl lightmap vs exact CPU reference (error in units of full light)', figures));
  });

  for (const scene of REFERENCE_SCENES) {
    it(`matches the exact reference: ${scene.name}`, () => {
      const errors = compareToReference(scene, renderScene(scene).rgb, computeReference(scene));
      figures.push({ scene: scene.name, errors });
      expect(errors.all.mean).toBeLessThanOrEqual(MEAN_LIMIT);
      expect(errors.all.p99).toBeLessThanOrEqual(P99_LIMIT);
      expect(errors.all.max).toBeLessThanOrEqual(MAX_LIMIT);
      // Behind a tile wall no light may leak through the seams: dark to one step of the mask.
      if (scene.darkUmbra) {
        expect(errors.umbra.pixels).toBeGreaterThan(1000);
        expect(errors.umbra.max).toBeLessThanOrEqual(UMBRA_LIMIT);
      }
    });
  }

  it('falls monotonically from lit to umbra across a penumbra', () => {
    const scene = REFERENCE_SCENES.find((s) => s.name.startsWith('convex rotated'))!;
    const lightmap = renderScene(scene);
    const [light] = scene.lights;
    const [lx, ly] = light.position;
    // Down column x = 145 from the top edge to the row where the ray from the light through the
    // hull's middle crosses it: lit, then the upper penumbra, then umbra.
    const x = 145;
    const visibility: number[] = [];
    for (let y = 0; y <= 53; y++) {
      const falloff = 1 - Math.hypot(x + 0.5 - lx, y + 0.5 - ly) / light.range;
      visibility.push(lightmap.at(x, y)[0] / falloff);
    }
    expect(visibility[0]).toBeGreaterThan(0.99);
    expect(visibility[visibility.length - 1]).toBeLessThan(0.01);
    expect(visibility.filter((v) => v > 0.05 && v < 0.95).length).toBeGreaterThanOrEqual(5);
    // Allowed rise between neighbours: the mask is RGBA8 (steps of 1/255) and the lightmap half
    // float (relative rounding 2^-11), so equal true values may read back up to ~0.005 apart.
    for (let i = 1; i < visibility.length; i++) expect(visibility[i]).toBeLessThanOrEqual(visibility[i - 1] + 0.005);
  });
});
