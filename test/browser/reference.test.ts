import type { Page } from 'puppeteer';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { lightmapToWorldRows } from '../reference/buildScene';
import { compareToReference, formatErrorTable, type SceneErrors } from '../reference/compareToReference';
import { limitViolations, MAX_LIMIT, MEAN_LIMIT, P99_LIMIT, UMBRA_LIMIT } from '../reference/limits';
import { computeOccludedReference, OCCLUDED_SCENES } from '../reference/occludedReference';
import { asLitScene, computeDirectionalReference, DIRECTIONAL_SCENES } from '../reference/directionalReference';
import { REFERENCE_SCENES } from '../reference/scenes';
import { computeReference } from '../reference/softShadowReference';
import { openReferencePage, type ReferencePage, type ReferencePageApi } from './referencePage';
import { outlineErrors, outlinePixel } from '../gl/outlineUpsampling';
import { ShadowType } from '../../src/index';

// The same limits as on headless-gl (test/gl/reference.test.ts, test/reference/limits.ts), in
// units of full light, against the same exact CPU reference.

let referencePage: ReferencePage;
let page: Page;
let pageErrors: string[];
const figures: { scene: string; errors: SceneErrors }[] = [];

beforeAll(async () => {
  referencePage = await openReferencePage();
  ({ page, pageErrors } = referencePage);
});

afterAll(async () => {
  console.log(formatErrorTable('Chromium (SwiftShader) lightmap vs exact CPU reference (error in units of full light)', figures));
  await referencePage?.close();
});

describe('reference scenes in Chromium', () => {
  for (const scene of REFERENCE_SCENES) {
    it(`matches the exact reference: ${scene.name}`, async () => {
      const texels = await page.evaluate((s) => (window as unknown as ReferencePageApi).renderScene(s), scene);
      const errors = compareToReference(scene, lightmapToWorldRows(texels, scene.width, scene.height), computeReference(scene));
      figures.push({ scene: scene.name, errors });
      expect(pageErrors).toEqual([]);
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

  for (const scene of OCCLUDED_SCENES) {
    it(`matches the Occluded reference: ${scene.name}`, async () => {
      const texels = await page.evaluate((s) => (window as unknown as ReferencePageApi).renderScene(s), scene);
      const errors = compareToReference(scene, lightmapToWorldRows(texels, scene.width, scene.height), computeOccludedReference(scene));
      figures.push({ scene: scene.name, errors });
      expect(pageErrors).toEqual([]);
      expect(limitViolations(errors)).toEqual([]);
    });
  }

  for (const scene of DIRECTIONAL_SCENES) {
    it(`matches the directional reference: ${scene.name}`, async () => {
      const texels = await page.evaluate((s) => (window as unknown as ReferencePageApi).renderDirectionalScene(s), scene);
      const errors = compareToReference(asLitScene(scene), lightmapToWorldRows(texels, scene.width, scene.height), computeDirectionalReference(scene));
      figures.push({ scene: scene.name, errors });
      expect(pageErrors).toEqual([]);
      expect(limitViolations(errors)).toEqual([]);
    });
  }

  it('draws the same light again after the context is lost and restored, keeping lights and hulls', async () => {
    const scene = REFERENCE_SCENES.find((s) => s.name.startsWith('two hulls'))!;
    const { before, after, lostFrameError, windowErrors } = await page.evaluate(
      (s) => (window as unknown as ReferencePageApi).renderAcrossContextLoss(s), scene);
    expect(lostFrameError).toBeNull();
    // Calls before the lost event arrives, and after a second loss inside a restored handler, are skipped.
    expect(windowErrors).toEqual([]);
    expect(pageErrors).toEqual([]);
    const reference = computeReference(scene);
    const restored = compareToReference(scene, lightmapToWorldRows(after, scene.width, scene.height), reference);
    expect(restored.all.mean).toBeLessThanOrEqual(MEAN_LIMIT);
    expect(restored.all.p99).toBeLessThanOrEqual(P99_LIMIT);
    expect(restored.all.max).toBeLessThanOrEqual(MAX_LIMIT);
    // Same scene on rebuilt resources: the same pixels.
    let largest = 0;
    for (let i = 0; i < before.length; i++) largest = Math.max(largest, Math.abs(before[i] - after[i]));
    expect(largest).toBeLessThan(1e-6);
    expect(restored.umbra.pixels).toBeGreaterThan(0);
  });
});

describe('lightmap scale in Chromium', () => {
  for (const shadowType of [ShadowType.Solid, ShadowType.Illuminated]) {
    it(`at half scale, keeps the light on each side of a ${shadowType} hull's outline (as on headless-gl: test/gl/lightmapScale.test.ts)`, async () => {
      const render = (scale: number) => page.evaluate((s, type) => (window as unknown as ReferencePageApi).outlineScene(s, type), scale, shadowType);
      const full = await render(1), half = await render(0.5);
      expect(outlineErrors(full, half)).toEqual([]);
      expect(outlinePixel(full, 29, 32)).toBeGreaterThan(150);
      expect(outlinePixel(full, 42, 32)).toBe(0);
      expect(pageErrors).toEqual([]);
    });
  }
});

describe('host state in Chromium', () => {
  it('every host parameter is as the host set it after each public call (as on headless-gl: test/gl/hostParameters.test.ts)', async () => {
    const report = await page.evaluate(() => (window as unknown as ReferencePageApi).checkHostState());
    console.log(`Chromium: ${report.compared} parameters compared after each of ${report.calls.length} public calls; rejected setup steps: ${report.unsupported.join(', ') || 'none'}`);
    expect(report.failures).toEqual([]);
    expect(report.unsupported).toEqual([]);
    expect(pageErrors).toEqual([]);
  });

  it('and with a half-scale lightmap (the hull masks and the edge-aware composite)', async () => {
    const report = await page.evaluate(() => (window as unknown as ReferencePageApi).checkHostState(false, 0.5));
    expect(report.failures).toEqual([]);
    expect(pageErrors).toEqual([]);
  });
});
