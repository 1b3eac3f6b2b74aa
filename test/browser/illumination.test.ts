import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { MAX_DIFFERENCE, type IlluminationComparison } from '../reference/illuminationComparison';
import { REFERENCE_SCENES } from '../reference/scenes';
import { openReferencePage, type ReferencePage, type ReferencePageApi } from './referencePage';

/**
 * `renderer.illuminationAt` against the lightmap the same renderer renders, both in Chromium: the
 * library's CPU query on Chromium's JS engine against its WebGL2 (SwiftShader here), as
 * test/gl/illumination.test.ts does on Node and headless-gl, with the same code
 * (test/reference/illuminationComparison.ts) run inside the reference page. Every pixel centre of
 * each reference scene is compared but those within 1/16 pixel of a hull outline or a hard shadow's
 * edge, where the rasterizer's snapping decides; penumbrae and umbrae included (over 18,000 points
 * some light reaches per scene). Limit {@link MAX_DIFFERENCE} of full light in any channel, as on
 * headless-gl; the largest differences here are SwiftShader's lightmap's own, at a few penumbra pixels.
 */

let referencePage: ReferencePage;
const figures: { scene: string; result: IlluminationComparison }[] = [];

beforeAll(async () => {
  referencePage = await openReferencePage();
});

afterAll(async () => {
  console.log(formatFigures());
  await referencePage?.close();
});

/** The per-scene figures as a table, with the largest difference over all scenes first. */
function formatFigures(): string {
  const max = Math.max(0, ...figures.map(({ result }) => result.max));
  const points = figures.reduce((sum, { result }) => sum + result.points, 0);
  return [
    `illuminationAt vs the rendered lightmap (Chromium, SwiftShader): max difference ${max.toFixed(4)} over ${points} points (limit ${MAX_DIFFERENCE})`,
    '| scene | points | max difference | p99 | where |',
    '|---|---|---|---|---|',
    ...figures.map(({ scene, result }) => `| ${scene} | ${result.points} | ${result.max.toFixed(4)} | ${result.p99.toFixed(4)} | ${result.worst} |`),
  ].join('\n');
}

describe('illuminationAt matches the lightmap in Chromium: reference scenes', () => {
  for (const scene of REFERENCE_SCENES) {
    it(scene.name, async () => {
      const { page, pageErrors } = referencePage;
      const { glError, floatLightmap, ...result } = await page.evaluate(
        (s) => (window as unknown as ReferencePageApi).compareIllumination(s), scene);
      figures.push({ scene: scene.name, result });
      expect(pageErrors).toEqual([]);
      // An RGBA8 lightmap could not be read back as floats (and would clamp light sums at 1).
      expect(floatLightmap).toBe(true);
      expect(glError).toBe(0);
      expect(result.points).toBeGreaterThan(1000);
      expect(result.max, result.worst).toBeLessThanOrEqual(MAX_DIFFERENCE);
    });
  }
});
