import { describe, expect, it } from 'vitest';
import { ShadowType } from '../../src/index';
import { createSceneRenderer } from '../reference/buildScene';
import { compareToReference } from '../reference/compareToReference';
import { limitViolations } from '../reference/limits';
import { computeOccludedReference, uShape } from '../reference/occludedReference';
import { SceneGeometry } from '../reference/sceneGeometry';
import { box, type ReferenceScene } from '../reference/scenes';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// Occluded lights (ShadowType.Occluded) against the sampling reference (test/reference/
// occludedReference.ts), held to the limits of every reference scene (test/reference/limits.ts)
// over the whole lightmap, hull insides included; and `illuminationAt` on the hull pixels.
const WIDTH = 160, HEIGHT = 120;
const scene = (name: string, lights: ReferenceScene['lights'], hulls: ReferenceScene['hulls']): ReferenceScene => ({ name, width: WIDTH, height: HEIGHT, lights, hulls });

const SCENES: ReferenceScene[] = [
  scene('a crate behind a wall is dark where the wall\'s shadow falls on it', [{ position: [30, 60], range: 160, radius: 6 }],
    [box(60, 40, 8, 36), box(100, 34, 24, 24), box(100, 84, 16, 16)]),
  scene('a U-shaped building shades its far arm from a light beside it', [{ position: [22, 44], range: 170, radius: 5 }],
    [uShape(56, 30, 70, 56, 14, 32)]),
  scene('a U-shaped building lit into its yard shades nothing of itself from there', [{ position: [91, 40], range: 120, radius: 4 }],
    [uShape(56, 30, 70, 56, 14, 32)]),
  scene('a convex hull never shades itself, and a hard light gives hard edges on the hull behind', [{ position: [20, 100], range: 200, radius: 0 }],
    [[[50, 70], [70, 62], [84, 74], [78, 94], [56, 96]], box(100, 20, 40, 60)]),
  scene('a torch whose disk reaches into an L-shaped hull lights the hull from the part of the disk inside it', [{ position: [66, 47], range: 110, radius: 9 }],
    [[[40, 30], [56, 30], [56, 54], [110, 54], [110, 70], [40, 70]]]),
  scene('two lights on both sides of a row of crates', [{ position: [20, 30], range: 150, radius: 4, color: [1, 0.6, 0.3] }, { position: [140, 100], range: 150, radius: 7, color: [0.3, 0.6, 1] }],
    [box(50, 50, 14, 14), box(72, 56, 14, 14), box(94, 62, 14, 14), uShape(40, 82, 40, 26, 10, 14)]),
];

/** Renders `reference scene` with its lights Occluded. */
function renderOccluded(source: ReferenceScene): { rgb: Float32Array; queried: (x: number, y: number) => number[] } {
  const gl = createContext(WIDTH, HEIGHT);
  const renderer = createSceneRenderer(gl, source);
  for (const light of renderer.lights) light.shadowType = ShadowType.Occluded;
  const { rgb } = renderLightmap(gl, renderer, WIDTH, HEIGHT);
  expect(gl.getError()).toBe(0);
  const queried = (x: number, y: number) => [...renderer.illuminationAt(x, y).color];
  const values = { rgb, queried };
  // The queries run on the CPU: the context can go.
  destroyContext(gl);
  return values;
}

describe('Occluded lights light hulls only where the light reaches them (headless-gl)', () => {
  for (const source of SCENES) {
    it(source.name, () => {
      const reference = computeOccludedReference(source);
      const { rgb, queried } = renderOccluded(source);
      const errors = compareToReference(source, rgb, reference);
      expect(limitViolations(errors), JSON.stringify(errors)).toEqual([]);
      // Some hull pixels are lit and some are not, so the scene tests what it is named for.
      const geometry = new SceneGeometry(source.hulls);
      let litInside = 0, darkInside = 0, worstQuery = 0;
      for (let y = 0; y < HEIGHT; y++) {
        for (let x = 0; x < WIDTH; x++) {
          const pixel = y * WIDTH + x;
          if (!geometry.isInsideHull(x + 0.5, y + 0.5) || reference.ambiguous[pixel]) continue;
          const expected = reference.light[3 * pixel];
          if (expected > 0.05) litInside++;
          else darkInside++;
          if ((x + y) % 3 === 0) worstQuery = Math.max(worstQuery, Math.abs(queried(x + 0.5, y + 0.5)[0] - expected));
        }
      }
      expect(litInside).toBeGreaterThan(20);
      // Sampling error of the reference (≈ 2e-3) plus the half-float lightmap's rounding is not in
      // the query, which is exact: the difference is the reference's.
      expect(worstQuery).toBeLessThan(0.01);
      if (!source.name.includes('nothing of itself') && !source.name.includes('torch')) expect(darkInside).toBeGreaterThan(20);
    });
  }
});
