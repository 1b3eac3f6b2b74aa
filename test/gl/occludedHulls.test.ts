import { describe, expect, it } from 'vitest';
import { createSceneRenderer } from '../reference/buildScene';
import { compareToReference } from '../reference/compareToReference';
import { limitViolations } from '../reference/limits';
import { computeOccludedReference, OCCLUDED_SCENES, OVERLAPPING_OCCLUDED_SCENES } from '../reference/occludedReference';
import { SceneGeometry } from '../reference/sceneGeometry';
import type { ReferenceScene } from '../reference/scenes';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// Occluded lights (ShadowType.Occluded) against the sampling reference (test/reference/
// occludedReference.ts), held to the limits of every reference scene (test/reference/limits.ts)
// over the whole lightmap, hull insides included; and `illuminationAt` on the hull pixels. The
// Chromium reference test renders the same scenes.
/** Renders an Occluded reference scene, and answers light queries on it. */
function renderOccluded(source: ReferenceScene): { rgb: Float32Array; queried: (x: number, y: number) => number[] } {
  const { width, height } = source;
  const gl = createContext(width, height);
  const renderer = createSceneRenderer(gl, source);
  const { rgb } = renderLightmap(gl, renderer, width, height);
  expect(gl.getError()).toBe(0);
  const queried = (x: number, y: number) => [...renderer.illuminationAt(x, y).color];
  const values = { rgb, queried };
  // The queries run on the CPU: the context can go.
  destroyContext(gl);
  return values;
}

describe('Occluded lights light hulls only where the light reaches them (headless-gl)', () => {
  for (const source of [...OCCLUDED_SCENES, ...OVERLAPPING_OCCLUDED_SCENES]) {
    it(source.name, () => {
      const reference = computeOccludedReference(source);
      const { rgb, queried } = renderOccluded(source);
      const errors = compareToReference(source, rgb, reference);
      console.log(`${source.name.padEnd(100)} mean ${errors.all.mean.toFixed(4)} p99 ${errors.all.p99.toFixed(4)} max ${errors.all.max.toFixed(4)}`);
      expect(limitViolations(errors), JSON.stringify(errors)).toEqual([]);
      // Some hull pixels are lit and some are not, so the scene tests what it is named for.
      const geometry = new SceneGeometry(source.hulls);
      let litInside = 0, darkInside = 0, worstQuery = 0;
      for (let y = 0; y < source.height; y++) {
        for (let x = 0; x < source.width; x++) {
          const pixel = y * source.width + x;
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
      if (!source.name.includes('nothing of itself') && !source.name.includes('torch') && !source.name.includes('hexagons')) expect(darkInside).toBeGreaterThan(20);
    });
  }
});
