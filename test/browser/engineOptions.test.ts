import type { Page } from 'puppeteer';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openBuiltPage, type BuiltPage } from './builtPage';
import type { PenumbraPluginOptions } from '../../src/integrations/phaser/PenumbraPlugin';
import { CANVAS, type PhaserRoute, type RendererReport } from './engine-options-page/contract';

// Renderer options given to the real PixiJS and Phaser integrations reach the renderer: the
// lightmap texture's size on the GL context (lightmapScale), stats.cpuTime (measureCpuTime) and
// the rest read back from the renderer each engine built.

let built: BuiltPage;
let page: Page;
let errors: string[];

const OPTIONS: PenumbraPluginOptions = {
  lightmapScale: 0.5, measureCpuTime: true, ambientColor: [0.25, 0.5, 0.75], debug: true,
  exposure: 1.5, toneMapping: 'aces', dithering: 'ordered', lightmapBlur: 2,
};
const HALF: [number, number] = [CANVAS[0] / 2, CANVAS[1] / 2];

beforeAll(async () => {
  built = await openBuiltPage('engine-options-page', 'engineOptions');
  ({ page, pageErrors: errors } = built);
}, 300_000);  // a Vite build and Chromium on a shared machine

afterAll(async () => {
  await built?.close();
});

function pixi(options: PenumbraPluginOptions): Promise<RendererReport> {
  return page.evaluate((o) => window.engineOptions!.pixi(o), options);
}
function phaser(route: PhaserRoute, options: PenumbraPluginOptions): Promise<RendererReport> {
  return page.evaluate((r, o) => window.engineOptions!.phaser(r, o), route, options);
}

/** What every route must show for {@link OPTIONS}. */
function expectOptionsTaken(report: RendererReport): void {
  expect(report.lightmapSize).toEqual(HALF);
  expect(report.measureCpuTime).toBe(true);
  // performance.now() is coarse (0.1 ms without cross-origin isolation): some frames may read 0.
  expect(Math.max(...report.cpuTimes)).toBeGreaterThan(0);
  expect(report.ambientColor).toEqual([0.25, 0.5, 0.75]);
  expect(report.debug).toBe(true);
  expect(report.look).toEqual([1.5, 'aces', 'ordered', 2]);
  expect(report.restoredHandlerKept).toBe(true);
  expectSceneDrawn(report);
}

/** The page's 3 lights and 4 hulls are in the renderer that drew the last frame, the lights drawn. */
function expectSceneDrawn(report: RendererReport): void {
  expect([report.lights, report.lightsDrawn, report.hulls]).toEqual([3, 3, 4]);
}

describe('engine options', () => {
  it('PenumbraLayer (PixiJS) gives the renderer its defaults: a lightmap the size of the canvas, no CPU timing', async () => {
    const report = await pixi({});
    expect(report.lightmapSize).toEqual([...CANVAS]);
    expect(report.measureCpuTime).toBe(false);
    expect(report.cpuTimes.every((t) => t === 0)).toBe(true);
    expectSceneDrawn(report);
  });

  it('PenumbraLayer (PixiJS) forwards lightmapScale, measureCpuTime, ambientColor, debug, the look and onContextRestored', async () => {
    expectOptionsTaken(await pixi(OPTIONS));
  });

  it('PenumbraPlugin (Phaser) gives the renderer its defaults without data', async () => {
    const report = await phaser('data', {});
    expect(report.lightmapSize).toEqual([...CANVAS]);
    expect(report.measureCpuTime).toBe(false);
    expectSceneDrawn(report);
  });

  it('PenumbraPlugin (Phaser) takes the renderer options from its plugin entry\'s data', async () => {
    expectOptionsTaken(await phaser('data', OPTIONS));
  });

  it('PenumbraPlugin (Phaser) takes them from configure() in the scene\'s create, keeping the lights and hulls added before', async () => {
    expectOptionsTaken(await phaser('configure', OPTIONS));
  });

  it('logs no console errors', () => {
    expect(errors).toEqual([]);
  });
});
