import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { SurfaceFigures } from '../reference/surfaceComparison';
import { openReferencePage, type ReferencePage, type ReferencePageApi } from './referencePage';

// Normal-mapped lighting (docs/normal-maps.md) in Chromium against the CPU version of its equation
// (test/reference/surfaceComparison.ts; headless-gl cannot draw into several attachments). Float
// targets: the lightmap is half-float (relative error 2⁻¹¹ of values up to 2), so 0.002 of full
// light; 8-bit output and stored normals: half a step for the rounding and a little float error.
const FLOAT_TOLERANCE = 0.002;
const BYTE_TOLERANCE = 0.55;

let referencePage: ReferencePage;
let figures: SurfaceFigures;

beforeAll(async () => {
  referencePage = await openReferencePage();
  figures = await referencePage.page.evaluate(() => (window as unknown as ReferencePageApi).compareSurfaces());
  console.log(`Normal-mapped lighting in Chromium vs the CPU equation: stored normals ${figures.normalStorage.toFixed(3)} steps, ` +
    `composite ${figures.composite.toFixed(3)} steps, emissive ${figures.emissiveUnlit.toFixed(3)} steps\n` +
    figures.cases.map((c) => `  ${c.name}: diffuse ${c.diffuse.toFixed(5)}, highlight ${c.highlight.toFixed(5)} ` +
      `(${c.darkenedPixels} pixels darkened by the relief, ${c.highlightPixels} with highlights)`).join('\n'));
});

afterAll(async () => {
  await referencePage?.close();
});

describe('normal-mapped lighting in Chromium', () => {
  it('stores the world normal of mirrored, turned and scaled sprites through the GLSL helpers', () => {
    expect(figures.glError).toBe(0);
    expect(figures.normalStorage).toBeLessThanOrEqual(BYTE_TOLERANCE);
  });

  it('weights each light by N·L and adds Blinn-Phong highlights, as the CPU equation', () => {
    for (const scene of figures.cases) {
      expect(scene.diffuse, scene.name).toBeLessThanOrEqual(FLOAT_TOLERANCE);
      expect(scene.highlight, scene.name).toBeLessThanOrEqual(FLOAT_TOLERANCE);
      // The scene tests something: the relief darkens pixels and the shiny bands catch highlights.
      expect(scene.darkenedPixels, scene.name).toBeGreaterThan(100);
      expect(scene.highlightPixels, scene.name).toBeGreaterThan(20);
    }
  });

  it('composites albedo × (lightmap + emissive) + highlights', () => {
    expect(figures.composite).toBeLessThanOrEqual(BYTE_TOLERANCE);
  });

  it('keeps emissive pixels glowing with every light off', () => {
    expect(figures.emissiveUnlit).toBeLessThanOrEqual(BYTE_TOLERANCE);
  });

  it('lights pixels without a normal exactly as a renderer without normals', () => {
    expect(figures.bandWithoutNormalDiffers).toBe(0);
  });

  it('draws what a host that writes no normal draws without normals, bit for bit', () => {
    expect(figures.colorOnlyDiffers).toBe(0);
  });

  it('leaves every host parameter as the host set it after each public call of a renderer with normals', async () => {
    const report = await referencePage.page.evaluate(() => (window as unknown as ReferencePageApi).checkHostState(true));
    expect(report.calls).toContain('drawInPlace with surfaces');
    expect(report.failures).toEqual([]);
  });

  it('draws the same frame after the context is lost and restored', async () => {
    const { differingBytes, litBytes } = await referencePage.page.evaluate(() => (window as unknown as ReferencePageApi).surfacesAcrossContextLoss());
    expect(litBytes).toBeGreaterThan(1000);
    expect(differingBytes).toBe(0);
  });

  it('names the field and the value of malformed drawInPlace surfaces', async () => {
    const thrown = await referencePage.page.evaluate(() => (window as unknown as ReferencePageApi).surfaceMisuse());
    expect(thrown).toEqual([
      'TypeError: PenumbraRenderer.drawInPlace: surfaces.normals must be a WebGLTexture, got 7',
      'TypeError: PenumbraRenderer.drawInPlace: surfaces.material must be a WebGLTexture, got "stone"',
      'TypeError: PenumbraRenderer.drawInPlace: surfaces.flipY must be true or false, got 1',
      'TypeError: PenumbraRenderer.drawInPlace: surfaces must be an object, got null',
    ]);
    expect(referencePage.pageErrors).toEqual([]);
  });
});
