import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Browser, Page } from 'puppeteer';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { SceneDocument } from '../../src/index';
import { collectPageErrors, launchChromium } from './chromium';
import { serveDirectory, type StaticServer } from './staticServer';

// The page is 800 × 400 CSS pixels and the test scenes put the camera so that world units equal
// CSS pixels (centre [400, 200], zoom 1). Everything happens left of x = 520: the panel is on the right.
const WIDTH = 800, HEIGHT = 400;

/** One light at `light` (no source radius, so the umbra is exact) and one 40 × 120 box at (220, 200). */
function testScene(light: [number, number], range = 300): SceneDocument {
  return {
    format: 'penumbra-scene', version: 1, ambient: [0.02, 0.02, 0.02], camera: { center: [400, 200], zoom: 1 },
    hulls: [{ points: [[-20, -60], [20, -60], [20, 60], [-20, 60]], position: [220, 200], origin: [0, 0], rotation: 0, scale: [1, 1], enabled: true }],
    lights: [{
      kind: 'point', position: light, range, radius: 0, color: [1, 1, 1], intensity: 1, rotation: 0, origin: [0.5, 0.5],
      shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [],
    }],
  };
}

const brightness = ([r, g, b]: [number, number, number]) => r + g + b;

describe('playground page in Chromium', () => {
  let server: StaticServer;
  let browser: Browser;
  let page: Page;
  let errors: string[];

  const readPixel = (x: number, y: number) => page.evaluate((px, py) => window.playground.readPixel(px, py), x, y);
  const load = (scene: SceneDocument | string) =>
    page.evaluate((text) => window.playground.loadScene(text), typeof scene === 'string' ? scene : JSON.stringify(scene));

  beforeAll(async () => {
    server = await serveDirectory('demo-dist');
    browser = await launchChromium();
    page = await browser.newPage();
    await page.setViewport({ width: WIDTH, height: HEIGHT });
    errors = collectPageErrors(page);
    await page.goto(server.url);
    await page.waitForFunction(() => window.playground !== undefined);
    await page.evaluate(() => window.playground.setAnimation(false));
  });

  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });

  it('opens on the default level with no console or GL errors', async () => {
    const stats = await page.evaluate(() => window.playground.rendererStats());
    expect(stats.lights).toBeGreaterThanOrEqual(4);
    expect(stats.hulls).toBeGreaterThanOrEqual(4);
    // The overlay shows the renderer's CPU time, so the playground turns its timing on.
    expect(stats.cpuTime).toBeGreaterThan(0);
    expect(await page.evaluate(() => window.playground.glError())).toBe(0);
    expect(errors).toEqual([]);
  });

  it('lights a pixel near the light and leaves the umbra behind the hull dark', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    const lit = await readPixel(160, 200);
    const umbra = await readPixel(300, 200);
    const beside = await readPixel(300, 60);
    expect(brightness(lit)).toBeGreaterThan(150);
    expect(brightness(umbra)).toBeLessThan(30);
    // Same distance from the light as the umbra pixel, but not behind the hull: lit.
    expect(brightness(beside)).toBeGreaterThan(3 * brightness(umbra) + 30);
  });

  it('moves the bright region when a light is dragged with the mouse', async () => {
    expect(await load(testScene([100, 200], 120))).toBe(true);
    const oldSpot = await readPixel(100, 230), newSpot = await readPixel(420, 90);
    expect(brightness(oldSpot)).toBeGreaterThan(brightness(newSpot) + 100);

    const [x, y] = await page.evaluate(() => window.playground.worldToScreen(100, 200));
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(260, 140, { steps: 5 });
    await page.mouse.move(420, 60, { steps: 5 });
    await page.mouse.up();

    const scene = JSON.parse(await page.evaluate(() => window.playground.sceneText())) as SceneDocument;
    expect(scene.lights[0].position).toEqual([420, 60]);
    const oldAfter = await readPixel(100, 230), newAfter = await readPixel(420, 90);
    expect(brightness(newAfter)).toBeGreaterThan(brightness(oldAfter) + 100);
  });

  it('shows the path of a bad field and keeps the scene when a file is bad', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    const before = await page.evaluate(() => window.playground.sceneText());
    const bad = testScene([300, 100]) as unknown as { hulls: { points: unknown[] }[] };
    bad.hulls[0].points[1] = [1, 'two'];
    expect(await load(JSON.stringify(bad))).toBe(false);
    const shown = await page.$eval('#message', (element) => ({ text: element.textContent, hidden: (element as HTMLElement).hidden }));
    expect(shown.hidden).toBe(false);
    expect(shown.text).toContain('hulls[0].points[1]: expected two finite numbers');
    expect(await page.evaluate(() => window.playground.sceneText())).toBe(before);

    expect(await load('{"format": "penumbra-scene", "version": 9}')).toBe(false);
    expect(await page.evaluate(() => window.playground.errorMessage())).toContain('version: unsupported version 9');
    expect(await page.evaluate(() => window.playground.sceneText())).toBe(before);
  });

  it('loads a saved scene through the file picker back to the same scene', async () => {
    await page.evaluate(() => window.playground.selectPreset('Stage'));
    const saved = await page.evaluate(() => window.playground.sceneText());
    const file = join(mkdtempSync(join(tmpdir(), 'penumbra-playground-')), 'scene.penumbra.json');
    writeFileSync(file, saved);
    expect(await load(testScene([100, 200]))).toBe(true);

    const [chooser] = await Promise.all([
      page.waitForFileChooser(),
      page.evaluate(() => [...document.querySelectorAll('.lil-gui button')].find((b) => b.textContent?.startsWith('load scene'))!
        .dispatchEvent(new MouseEvent('click', { bubbles: true }))),
    ]);
    await chooser.accept([file]);
    await page.waitForFunction((text) => window.playground.sceneText() === text, { timeout: 10_000 }, saved);
    expect(await page.evaluate(() => window.playground.errorMessage())).toBeNull();
  });

  it('switches presets and keeps the scene across a reload', async () => {
    for (const name of ['Penumbra lab', 'Dungeon']) {
      await page.evaluate((preset) => window.playground.selectPreset(preset), name);
      expect(await page.evaluate(() => window.playground.glError())).toBe(0);
    }
    await page.evaluate(() => window.playground.selectPreset('Penumbra lab'));
    const stats = await page.evaluate(() => window.playground.rendererStats());
    expect(stats).toMatchObject({ lights: 3, hulls: 6 });
    expect(await page.$eval('.lil-gui select', (select) => (select as HTMLSelectElement).selectedOptions[0].textContent)).toBe('Penumbra lab');

    const before = await page.evaluate(() => window.playground.sceneText());
    await page.reload();
    await page.waitForFunction(() => window.playground !== undefined);
    expect(await page.evaluate(() => window.playground.sceneText())).toBe(before);
    expect(errors).toEqual([]);
  });
});
