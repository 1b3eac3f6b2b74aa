import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import type { Browser, Page } from 'puppeteer';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import type { SceneDirectionalLight, SceneDocument, SceneLight, ScenePointLight } from '../../src/index';
import { Dithering, ToneMapping } from '../../src/scene/look';
import { Falloff, falloffAt } from '../../src/scene/falloff';
import { ShadowType } from '../../src/scene/Light';
import { collectPageErrors, launchChromium } from './chromium';
import { serveDirectory, type StaticServer } from './staticServer';

// The page is 800 × 400 CSS pixels; the panel covers about 260 on the right and the camera centres
// the test scenes in the rest (centre [300, 200], zoom 1: world x from about 30 to 570 shows).
// Pixels are read and the pointer moved at world points, through the page's worldToScreen.
const WIDTH = 800, HEIGHT = 400;
/** The page is ready after its first frames, which SwiftShader compiles and draws slowly on a busy machine (170 s seen at load 10). */
const PAGE_READY_MS = 240_000;
/** The showcase's frames take seconds each in SwiftShader (14 s seen at load 8), and its tests read several. */
const SHOWCASE_TEST_MS = 400_000;

/** A scene of these tests, built or saved: they have no directional light, so every light has a position, range and radius. */
interface TestScene extends Omit<SceneDocument, 'lights'> {
  lights: Exclude<SceneLight, SceneDirectionalLight>[];
}

/** One light at `light` (no source radius, so the umbra is exact) and one 40 × 120 box at (220, 200). */
function testScene(light: [number, number], range = 300): TestScene {
  return {
    format: 'penumbra-scene', version: 3, ambient: [0.02, 0.02, 0.02], camera: { center: [300, 200], zoom: 1 },
    hulls: [{ points: [[-20, -60], [20, -60], [20, 60], [-20, 60]], position: [220, 200], origin: [0, 0], rotation: 0, scale: [1, 1], enabled: true, closed: true, layers: 1 }],
    lights: [{
      kind: 'point', position: light, range, radius: 0, color: [1, 1, 1], intensity: 1, rotation: 0, origin: [0.5, 0.5],
      shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [],
      shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, falloff: 'linear', height: null,
    }],
    look: { exposure: 1, toneMapping: 'none', dithering: 'none', lightmapBlur: 0 },
    app: {},
  };
}

/** The test scene without its box: painted and traced hulls are then the only ones. */
function emptyScene(light: [number, number], range = 300): TestScene {
  return { ...testScene(light, range), hulls: [] };
}

/** The test scene's box with no light: what a sun added to it alone lights. */
function darkScene(): TestScene {
  return { ...testScene([100, 200]), lights: [] };
}

const brightness = ([r, g, b]: [number, number, number]) => r + g + b;

/** How many bytes two base64-encoded frames of the same size differ in. */
function differingBytes(a: string, b: string): number {
  const [x, y] = [Buffer.from(a, 'base64'), Buffer.from(b, 'base64')];
  expect(x.length).toBe(y.length);
  return x.reduce((count, byte, i) => count + (byte === y[i] ? 0 : 1), 0);
}

/** Each channel of `scaled` is `factor` × that of `colour`, within 8-bit rounding. */
function brightnessNear(scaled: [number, number, number], colour: [number, number, number], factor: number): void {
  scaled.forEach((channel, i) => expect(Math.abs(channel - colour[i] * factor)).toBeLessThanOrEqual(1.5));
}

/** Area (shoelace, either winding) and bounds `[minX, minY, maxX, maxY]` of a polygon. */
function shape(points: [number, number][]): { area: number; bounds: [number, number, number, number] } {
  let twice = 0;
  const bounds: [number, number, number, number] = [Infinity, Infinity, -Infinity, -Infinity];
  points.forEach(([x, y], i) => {
    const [nx, ny] = points[(i + 1) % points.length];
    twice += x * ny - nx * y;
    bounds[0] = Math.min(bounds[0], x);
    bounds[1] = Math.min(bounds[1], y);
    bounds[2] = Math.max(bounds[2], x);
    bounds[3] = Math.max(bounds[3], y);
  });
  return { area: Math.abs(twice) / 2, bounds };
}

/** The union of bounds. */
function unionBounds(all: [number, number, number, number][]): [number, number, number, number] {
  return all.reduce((a, b) => [Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])]);
}

describe('playground page in Chromium', () => {
  let server: StaticServer;
  let browser: Browser;
  let page: Page;
  let errors: string[];

  /** The canvas colour at a world point. */
  const readPixel = (x: number, y: number) => page.evaluate((wx, wy) => window.playground.readPixel(...window.playground.worldToScreen(wx, wy)), x, y);
  const toScreen = (x: number, y: number) => page.evaluate((wx, wy) => window.playground.worldToScreen(wx, wy), x, y);
  const sceneDocument = async () => JSON.parse(await page.evaluate(() => window.playground.sceneText())) as TestScene;
  /** Clicks the panel button whose label starts with `label`. */
  const clickButton = (label: string) => page.evaluate((text) => [...document.querySelectorAll('.lil-gui button')]
    .find((b) => b.textContent?.startsWith(text))!.dispatchEvent(new MouseEvent('click', { bubbles: true })), label);
  /** What the panel shows for the field named `name`: its input's text, or the option menu's. */
  const fieldText = (name: string) => page.evaluate((label) => {
    const row = [...document.querySelectorAll('.lil-gui .lil-controller')].find((c) => c.querySelector('.lil-name')?.textContent === label)!;
    return row.querySelector('input')?.value ?? row.querySelector('.lil-display')?.textContent ?? null;
  }, name);
  const load = (scene: SceneDocument | string) =>
    page.evaluate((text) => window.playground.loadScene(text), typeof scene === 'string' ? scene : JSON.stringify(scene));
  /** Each hull's area and world bounds, in the renderer's order. */
  const hullShapes = async () => (await page.evaluate(() => window.playground.hullOutlines())).map(shape);
  /** Picks option `value` of the panel's menu named `name`, as a user would. */
  const choose = (name: string, value: string) => page.evaluate((label, option) => {
    const row = [...document.querySelectorAll('.lil-gui .lil-controller')].find((c) => c.querySelector('.lil-name')?.textContent === label)!;
    const select = row.querySelector('select')!;
    select.selectedIndex = [...select.options].findIndex((o) => o.textContent === option);
    select.dispatchEvent(new Event('change'));
  }, name, value);
  /** The input (or, with `selector`, another element) of the panel's field named `name`. */
  const fieldElement = (name: string, selector = 'input') => page.evaluateHandle((label, element) =>
    [...document.querySelectorAll('.lil-gui .lil-controller')].find((c) => c.querySelector('.lil-name')?.textContent === label)!
      .querySelector<HTMLInputElement>(element)!, name, selector);
  /** Enters `text` into the field named `name` (a number, a slider's number or a colour as `#rrggbb`), as typing or picking does. */
  const enter = async (name: string, text: string) => (await fieldElement(name)).evaluate((input, value) => {
    input.value = value;
    input.dispatchEvent(new Event('input'));
    input.dispatchEvent(new Event('blur'));
  }, text);
  /** Ticks or clears the checkbox named `name` (folded folders included), as a click does. */
  const tick = async (name: string, on: boolean) => (await fieldElement(name)).evaluate((input, value) => {
    if (input.checked !== value) input.click();
  }, on);
  const isTicked = async (name: string) => (await fieldElement(name)).evaluate((input) => input.checked);
  /** Ticks or clears the checkbox named `name` in the folder whose title starts with `folder` (layer folders share their checkboxes' names). */
  const tickIn = (folder: string, name: string, on: boolean) => page.evaluate((title, label, value) => {
    const gui = [...document.querySelectorAll('.lil-gui')].find((g) => g.querySelector(':scope > .lil-title')?.textContent?.startsWith(title))!;
    const input = [...gui.querySelectorAll('.lil-controller')].find((c) => c.querySelector('.lil-name')?.textContent === label)!.querySelector('input')!;
    if (input.checked !== value) input.click();
  }, folder, name, on);
  /** Whether the panel has a field named `name`. */
  const hasField = (name: string) => page.evaluate((label) =>
    [...document.querySelectorAll('.lil-gui .lil-controller')].some((c) => c.querySelector('.lil-name')?.textContent === label), name);
  /** The saved scene with any light, directional ones included. */
  const savedLights = async () => (JSON.parse(await page.evaluate(() => window.playground.sceneText())) as SceneDocument).lights;
  /** Drags with the mouse from one canvas point (CSS pixels) to another. */
  const dragOnCanvas = async (from: [number, number], to: [number, number]) => {
    await page.mouse.move(...from);
    await page.mouse.down();
    await page.mouse.move(...to, { steps: 4 });
    await page.mouse.up();
  };
  /** The labels of the menu named `name`, in order. */
  const menuLabels = async (name: string) => (await fieldElement(name, 'select')).evaluate((select) =>
    [...(select as unknown as HTMLSelectElement).options].map((option) => option.textContent));
  const folderTitles = () => page.$$eval('.lil-gui .lil-title', (titles) => titles.map((title) => title.textContent));
  /** What the Look folder shows: exposure, tone mapping, dithering and lightmap blur. */
  const lookShown = async () => [await fieldText('exposure'), await fieldText('tone mapping'), await fieldText('dithering'), await fieldText('lightmap blur')];
  /** Clicks "save scene" and returns the text of the file it downloads. */
  const saveThroughPanel = async () => {
    const folder = mkdtempSync(join(tmpdir(), 'penumbra-playground-save-'));
    const session = await page.createCDPSession();
    await session.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: folder });
    await clickButton('save scene');
    const file = join(folder, 'scene.penumbra.json');
    await vi.waitFor(() => expect(existsSync(file)).toBe(true), { timeout: 10_000 });
    await session.detach();
    return readFileSync(file, 'utf8');
  };
  /** Turns tile mode on or off through its panel button (whatever an earlier test left it in). */
  const tileMode = async (on: boolean) => {
    if (await page.evaluate(() => window.playground.tileMode().painting) !== on) await clickButton(on ? 'paint tiles' : 'stop painting');
  };
  /** A mouse stroke through world points, with the left button or (`right`) the right one. */
  const stroke = async (points: [number, number][], button: 'left' | 'right' = 'left') => {
    await page.mouse.move(...await toScreen(...points[0]));
    await page.mouse.down({ button });
    for (const point of points.slice(1)) await page.mouse.move(...await toScreen(...point), { steps: 4 });
    await page.mouse.up({ button });
  };
  /**
   * Drops a generated PNG on the view at a world point, as a file dragged from the desktop would
   * land: a disc of radius `outer` with a hole of radius `inner` (0: none) in a `size` square,
   * `color` filled; and waits until the page has traced it (or given up on it).
   */
  const dropDisc = async (name: string, at: [number, number], size: number, outer: number, inner: number, color: string) => {
    const [x, y] = await toScreen(...at);
    await page.evaluate(async (fileName, side, r0, r1, fill, cx, cy) => {
      const canvas = new OffscreenCanvas(side, side);
      const g = canvas.getContext('2d')!;
      g.fillStyle = fill;
      g.beginPath();
      if (r0 > 0) g.arc(side / 2, side / 2, r0, 0, Math.PI * 2);
      if (r1 > 0) g.arc(side / 2, side / 2, r1, 0, Math.PI * 2);
      g.fill('evenodd');
      const file = new File([await canvas.convertToBlob({ type: 'image/png' })], fileName, { type: 'image/png' });
      dropFile(file, cx, cy);

      function dropFile(dropped: File, clientX: number, clientY: number) {
        const data = new DataTransfer();
        data.items.add(dropped);
        document.getElementById('gizmos')!.dispatchEvent(new DragEvent('drop', { dataTransfer: data, clientX, clientY, bubbles: true, cancelable: true }));
      }
    }, name, size, outer, inner, color, x, y);
    await page.waitForFunction((fileName) => window.playground.traceStatus().startsWith(`${fileName}:`), { timeout: 20_000 }, name);
  };

  beforeAll(async () => {
    server = await serveDirectory('demo-dist');
    browser = await launchChromium();
    page = await browser.newPage();
    await page.setViewport({ width: WIDTH, height: HEIGHT });
    errors = collectPageErrors(page);
    await page.goto(server.url);
    await page.waitForFunction(() => window.playground !== undefined, { timeout: PAGE_READY_MS });
    await page.evaluate(() => window.playground.setAnimation(false));
  }, PAGE_READY_MS + 60_000);

  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });

  it('opens on the showcase level with no console or GL errors', async () => {
    expect(await page.evaluate(() => window.playground.showcase())).toEqual({ active: true, daylight: 0 });
    expect(await fieldText('preset')).toBe('Showcase');
    const stats = await page.evaluate(() => window.playground.rendererStats());
    expect(stats.lights).toBeGreaterThanOrEqual(4);
    expect(stats.hulls).toBeGreaterThanOrEqual(4);
    // The overlay shows the renderer's CPU time, so the playground turns its timing on.
    expect(stats.cpuTime).toBeGreaterThan(0);
    expect(await page.evaluate(() => window.playground.glError())).toBe(0);
    expect(errors).toEqual([]);
  }, SHOWCASE_TEST_MS);

  describe('showcase', () => {
    /** Light indices of the showcase level (its document's order). */
    const SKY = 0, TORCH = 1, LANTERN = 6, LIGHTS = 7;
    /** Loads the showcase with every light off but those in `on`. */
    const showcaseWith = async (on: number[]) => {
      await page.evaluate(() => window.playground.selectPreset('Showcase'));
      for (let i = 0; i < LIGHTS; i++) await page.evaluate((index, enabled) => window.playground.setLight(index, { enabled }), i, on.includes(i));
    };
    const setCamera = (x: number, y: number, zoom: number) => page.evaluate((cx, cy, z) => window.playground.setCamera(cx, cy, z), x, y, zoom);

    it('lights a pillar through its normal map: its side facing the torch is brighter than with the torch as far on the other side', async () => {
      // The pillar at (270, 300) has a domed top: 20 units west of its centre the normal leans west.
      // A torch 90 units west or east of that point, 70 up, is as far in both places and nothing
      // else shadows it, so only N·L changes: about 0.84 west, 0.33 east (a slope of ~0.34).
      await showcaseWith([TORCH]);
      await setCamera(270, 300, 1.5);
      const at: [number, number] = [250, 300];
      await page.evaluate((torch, p) => window.playground.setLight(torch, { position: [p[0] - 90, p[1]], intensity: 1 }), TORCH, at);
      const facing = await readPixel(...at);
      await page.evaluate((torch, p) => window.playground.setLight(torch, { position: [p[0] + 90, p[1]], intensity: 1 }), TORCH, at);
      const away = await readPixel(...at);
      expect(brightness(facing)).toBeGreaterThan(1.6 * brightness(away) + 10);
      // The same on the pillar's east side with the torch swapped (the relief, not the place, decides).
      const east: [number, number] = [290, 300];
      const eastFacing = await readPixel(...east);
      await page.evaluate((torch, p) => window.playground.setLight(torch, { position: [p[0] - 90, p[1]] }), TORCH, east);
      const eastAway = await readPixel(...east);
      expect(brightness(eastFacing)).toBeGreaterThan(1.6 * brightness(eastAway) + 10);
    }, SHOWCASE_TEST_MS);

    it('keeps emissive pixels bright with every light off and no ambient', async () => {
      await showcaseWith([]);
      await enter('ambient', '#000000');
      await setCamera(170, 396, 1.5);
      // A pane of the lantern's glass (8 units right of and below its centre, clear of its frame
      // and cross bars) glows; the floor beside the table is black.
      const glass = await readPixel(178, 404);
      const floor = await readPixel(260, 396);
      expect(brightness(glass)).toBeGreaterThan(300);
      expect(brightness(floor)).toBeLessThan(6);
      expect(await page.evaluate(() => window.playground.rendererStats().lightsDrawn)).toBe(0);
    }, SHOWCASE_TEST_MS);

    it('brightens the level by day with its daylight slider, and scales the picture with exposure', async () => {
      await showcaseWith([SKY, LANTERN]);
      await choose('tone mapping', 'None');
      await enter('exposure', '1');
      await setCamera(1000, 560, 1);
      // The storeroom's floor, out of the windows' light: the ambient lights it.
      const night = await readPixel(1000, 560);
      await enter('daylight', '1');
      expect(await page.evaluate(() => window.playground.showcase().daylight)).toBe(1);
      expect(await fieldText('daylight')).toBe('1');
      const day = await readPixel(1000, 560);
      // The ambient goes from 0.045–0.08 to 0.30–0.34 a channel: several times brighter.
      expect(brightness(day)).toBeGreaterThan(3 * brightness(night) + 20);
      const { ambient, lights } = await sceneDocument();
      expect(ambient[0]).toBeGreaterThan(0.3);
      expect((lights[SKY] as unknown as { intensity: number }).intensity).toBeGreaterThan(1.5);

      await enter('exposure', '0.5');
      expect(await fieldText('exposure')).toBe('0.5');
      const half = await readPixel(1000, 560);
      // No tone mapping: the colour halves (within 8-bit rounding).
      brightnessNear(half, day, 0.5);
    }, SHOWCASE_TEST_MS);

    it('outlines no hull the level\'s art draws (a rim of light along every wall), but a hull drawn in the editor and the selected one', async () => {
      await page.evaluate(() => window.playground.selectPreset('Showcase'));
      // The west side of the wall between the hall and the storeroom (world x = 768, y 384–704).
      const edge: [number, number] = [768, 459];
      await setCamera(...edge, 1);
      const outlineAt = async (x: number, y: number) => page.evaluate((p) => window.playground.overlayAlpha(...p), await toScreen(x, y));
      expect(await outlineAt(...edge)).toBe(0);
      await page.mouse.click(...await toScreen(800, 459));
      expect(await outlineAt(...edge)).toBeGreaterThan(100);
      await page.keyboard.press('Escape');
      expect(await outlineAt(...edge)).toBe(0);
      await clickButton('draw hull');
      for (const point of [[700, 420], [740, 420], [740, 500]] as [number, number][]) await page.mouse.click(...await toScreen(...point));
      await page.keyboard.press('Enter');
      await page.keyboard.press('Escape');
      expect(await outlineAt(720, 420)).toBeGreaterThan(30);
    }, SHOWCASE_TEST_MS);

    it('saves the showcase with its art, look, daylight and flicker, and the saved file loads back to the same pixels', async () => {
      await page.evaluate(() => window.playground.selectPreset('Showcase'));
      // Take out the second torch: the lights after it move up the file, and keep their art.
      const [torchX, torchY] = ((await savedLights())[TORCH + 1] as ScenePointLight).position;
      await setCamera(torchX, torchY, 1);
      await page.mouse.click(...await toScreen(torchX, torchY));
      await page.keyboard.press('Delete');
      expect(await savedLights()).toHaveLength(LIGHTS - 1);
      await enter('daylight', '0.6');
      await enter('exposure', '1.1');
      await setCamera(600, 450, 0.8);
      const before = await page.evaluate(() => window.playground.readFrame());
      const saved = await saveThroughPanel();
      const state = JSON.parse(saved).app['penumbra-gl/playground'];
      expect(state).toMatchObject({ version: 1, art: 'showcase', showcase: { daylight: 0.6 } });
      expect(state.showcase.lightRoles).toEqual([0, 1, 3, 4, 5, 6]);

      await page.evaluate(() => window.playground.selectPreset('Stage'));
      expect(await page.evaluate(() => window.playground.showcase().active)).toBe(false);
      const file = join(mkdtempSync(join(tmpdir(), 'penumbra-playground-')), 'showcase.penumbra.json');
      writeFileSync(file, saved);
      const [chooser] = await Promise.all([page.waitForFileChooser(), clickButton('load scene')]);
      await chooser.accept([file]);
      await page.waitForFunction((text) => window.playground.sceneText() === text, { timeout: 10_000 }, saved);
      expect(await page.evaluate(() => window.playground.showcase())).toEqual({ active: true, daylight: 0.6 });
      expect(await lookShown()).toEqual(['1.1', 'Aces', 'None', '0']);
      expect(await fieldText('daylight')).toBe('0.6');
      const after = await page.evaluate(() => window.playground.readFrame());
      expect(differingBytes(before, after)).toBe(0);
    }, SHOWCASE_TEST_MS);
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

    await page.mouse.move(...await toScreen(100, 200));
    await page.mouse.down();
    await page.mouse.move(...await toScreen(260, 140), { steps: 5 });
    await page.mouse.move(...await toScreen(420, 60), { steps: 5 });
    await page.mouse.up();

    const [x, y] = (await sceneDocument()).lights[0].position;
    // Pointer events land on whole CSS pixels.
    expect(Math.abs(x - 420)).toBeLessThanOrEqual(1);
    expect(Math.abs(y - 60)).toBeLessThanOrEqual(1);
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

    const [chooser] = await Promise.all([page.waitForFileChooser(), clickButton('load scene')]);
    await chooser.accept([file]);
    await page.waitForFunction((text) => window.playground.sceneText() === text, { timeout: 10_000 }, saved);
    expect(await page.evaluate(() => window.playground.errorMessage())).toBeNull();
    // The menu no longer names the preset the file replaced.
    expect(await fieldText('preset')).toBe('file: scene.penumbra.json');
  });

  it('adds new lights in view, clear of each other', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    for (let i = 0; i < 4; i++) await clickButton('add point light');
    const added = (await sceneDocument()).lights.slice(1).map((light) => light.position);
    expect(added).toHaveLength(4);
    const panelLeft = await page.$eval('.lil-gui.lil-root', (element) => element.getBoundingClientRect().left);
    for (const [i, [x, y]] of added.entries()) {
      const [sx, sy] = await toScreen(x, y);
      expect(sx).toBeGreaterThan(0);
      expect(sx).toBeLessThan(panelLeft);
      expect(sy).toBeGreaterThan(0);
      expect(sy).toBeLessThan(HEIGHT);
      for (const [ox, oy] of added.slice(0, i)) expect(Math.hypot(ox - x, oy - y)).toBeGreaterThanOrEqual(40);
    }
  });

  it('picks a light\'s ignored hulls by clicking them, and the light then passes through', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    expect(brightness(await readPixel(300, 200))).toBeLessThan(30);
    await page.mouse.click(...await toScreen(100, 200));
    expect(await fieldText('ignored hulls')).toBe('0 hulls');
    await clickButton('pick ignored hulls');
    await page.mouse.click(...await toScreen(220, 200));
    expect((await sceneDocument()).lights[0].ignoredHulls).toEqual([0]);
    expect(await fieldText('ignored hulls')).toBe('1 hull');
    expect(brightness(await readPixel(300, 200))).toBeGreaterThan(150);
    // A second click takes it out again; Escape ends picking, after which a click selects the hull.
    await page.mouse.click(...await toScreen(220, 200));
    expect((await sceneDocument()).lights[0].ignoredHulls).toEqual([]);
    await page.keyboard.press('Escape');
    await page.mouse.click(...await toScreen(220, 200));
    expect(await page.$$eval('.lil-gui .lil-title', (titles) => titles.map((t) => t.textContent))).toContain('Selected hull');
  });

  it('shows numbers rounded and refuses an out-of-range entry with a message instead of clamping it', async () => {
    const scene = testScene([100.123456, 200]);
    scene.lights[0].radius = 10;
    expect(await load(scene)).toBe(true);
    await page.mouse.click(...await toScreen(100.123456, 200));
    expect(await fieldText('x')).toBe('100.1');
    const radius = await page.evaluateHandle(() => [...document.querySelectorAll('.lil-gui .lil-controller')]
      .find((c) => c.querySelector('.lil-name')?.textContent === 'radius')!.querySelector('input')!);
    await radius.click({ count: 3 });
    await radius.type('-5');
    await page.keyboard.press('Enter');
    expect(await page.evaluate(() => window.playground.errorMessage())).toMatch(/radius must not be negative, got -5/);
    expect((await sceneDocument()).lights[0].radius).toBe(10);
    await radius.click({ count: 3 });
    await radius.type('250');
    await page.keyboard.press('Enter');
    // Above the old slider's end (100) is a valid radius, kept as typed.
    expect((await sceneDocument()).lights[0].radius).toBe(250);
  });

  it('centres the view beside the open panel, and in the whole page once the panel is collapsed', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    const panel = await page.$eval('.lil-gui.lil-root', (element) => { const r = element.getBoundingClientRect(); return { left: r.left, bottom: r.bottom }; });
    expect(panel.bottom).toBeLessThanOrEqual(HEIGHT);
    expect((await toScreen(300, 200))[0]).toBeCloseTo(panel.left / 2, -1);
    await page.click('.lil-gui .lil-title');
    expect((await toScreen(300, 200))[0]).toBeCloseTo(WIDTH / 2, 5);
    await page.click('.lil-gui .lil-title');
    expect((await toScreen(300, 200))[0]).toBeCloseTo(panel.left / 2, -1);
  });

  it('ends tile painting, hull drawing and picking with Escape while a panel button has the focus, and says how a drawn hull closes', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    /**
     * Clicks the panel button whose label starts with `label` with the mouse (opening its folder
     * first), which leaves the focus on it: the panel stops keys there from bubbling.
     */
    const clickWithMouse = async (label: string) => {
      const button = await page.evaluateHandle((text) => {
        const found = [...document.querySelectorAll<HTMLButtonElement>('.lil-gui button')].find((b) => b.textContent?.startsWith(text))!;
        for (let folder = found.closest('.lil-gui.lil-closed'); folder; folder = folder.parentElement!.closest('.lil-gui.lil-closed')) {
          folder.querySelector<HTMLElement>(':scope > .lil-title')!.click();
        }
        return found;
      }, label);
      await page.waitForFunction((b) => b.getBoundingClientRect().height > 0 && !b.closest('.lil-transition'), {}, button);
      await button.click();
      expect(await button.evaluate((b) => document.activeElement === b)).toBe(true);
    };
    const buttonLabels = () => page.$$eval('.lil-gui button', (buttons) => buttons.map((b) => b.textContent));
    await tileMode(false);
    await clickWithMouse('paint tiles');
    expect(await page.evaluate(() => window.playground.tileMode().painting)).toBe(true);
    await page.keyboard.press('Escape');
    expect(await page.evaluate(() => window.playground.tileMode().painting)).toBe(false);

    await clickWithMouse('draw hull');
    expect(await buttonLabels()).toContain('cancel hull (Enter closes)');
    await page.keyboard.press('Escape');
    expect(await buttonLabels()).toContain('draw hull (click points)');

    await page.mouse.click(...await toScreen(100, 200));
    await clickWithMouse('pick ignored hulls');
    expect(await buttonLabels()).toContain('done picking (Esc)');
    await page.keyboard.press('Escape');
    expect(await buttonLabels()).toContain('pick ignored hulls (click hulls)');
    // Picking has ended, the light is still selected: a click on the hull selects it, not ignores it.
    await page.mouse.click(...await toScreen(220, 200));
    expect((await sceneDocument()).lights[0].ignoredHulls).toEqual([]);

    const help = await page.$eval('#help', (element) => element.textContent);
    expect(help).toContain('a drawn hull closes on a click on its first point, a double-click or Enter');
  });

  it('paints a line of wall tiles into one hull covering exactly those tiles, over a faint grid, and it casts a shadow', async () => {
    expect(await load(emptyScene([100, 200]))).toBe(true);
    await tileMode(false);
    expect(brightness(await readPixel(300, 200))).toBeGreaterThan(150);
    await choose('tile size', '32');
    await clickButton('paint tiles');
    expect(await page.evaluate(() => window.playground.tileMode())).toEqual({ painting: true, tileSize: 32 });
    expect(await page.evaluate(() => window.playground.debugWireframe())).toBe(true);
    // Grid lines at every multiple of 32 world units: one at x = 256, none halfway to the next.
    const [lineX, lineY] = (await toScreen(256, 40)).map(Math.round);
    expect(await page.evaluate((x, y) => window.playground.overlayAlpha(x, y), lineX, lineY)).toBeGreaterThan(10);
    expect(await page.evaluate((x, y) => window.playground.overlayAlpha(x, y), lineX + 16, lineY)).toBe(0);

    // Down the column of tiles x = 6 (192–224), from row 3 (96–128) to row 9 (288–320).
    await stroke([[208, 112], [208, 200], [208, 304]]);
    const shapes = await hullShapes();
    expect(shapes).toHaveLength(1);
    expect(shapes[0].bounds).toEqual([192, 96, 224, 320]);
    expect(shapes[0].area).toBe(32 * 32 * 7);
    // Saved like any other hull.
    expect((await sceneDocument()).hulls).toHaveLength(1);

    await page.keyboard.press('Escape');
    expect(await page.evaluate(() => window.playground.tileMode().painting)).toBe(false);
    expect(await page.evaluate(() => window.playground.debugWireframe())).toBe(false);
    expect(await page.evaluate((x, y) => window.playground.overlayAlpha(x, y), lineX, lineY)).toBe(0);
    expect(brightness(await readPixel(160, 200))).toBeGreaterThan(150);
    expect(brightness(await readPixel(300, 200))).toBeLessThan(30);
  });

  it('erases tiles with a right-drag or Shift, changing only the hulls they touch, and adopts them at another tile size', async () => {
    expect(await load(emptyScene([100, 200]))).toBe(true);
    await choose('tile size', '32');
    await tileMode(true);
    await stroke([[208, 112], [208, 304]]);
    await stroke([[400, 112], [400, 176]]);  // a second wall: tiles (12, 3–5)
    const [wall, other] = await page.evaluate(() => window.playground.hullIds());

    await stroke([[208, 208], [210, 210]], 'right');  // tile (6, 6): the wall splits in two
    let shapes = await hullShapes();
    expect(shapes).toHaveLength(3);
    const ids = await page.evaluate(() => window.playground.hullIds());
    expect(ids).toContain(other);
    expect(ids).not.toContain(wall);
    const pieces = shapes.filter((_, i) => ids[i] !== other).map((s) => s.bounds).sort((a, b) => a[1] - b[1]);
    expect(pieces).toEqual([[192, 96, 224, 192], [192, 224, 224, 320]]);
    expect(shapes[ids.indexOf(other)].bounds).toEqual([384, 96, 416, 192]);

    await page.keyboard.down('Shift');
    await stroke([[208, 112], [209, 113]]);  // tile (6, 3), erased with Shift
    await page.keyboard.up('Shift');
    shapes = await hullShapes();
    expect(shapes.map((s) => s.bounds).sort((a, b) => a[0] - b[0] || a[1] - b[1]))
      .toEqual([[192, 128, 224, 192], [192, 224, 224, 320], [384, 96, 416, 192]]);
    expect(shapes.reduce((sum, s) => sum + s.area, 0)).toBe(32 * 32 * 8);

    await page.keyboard.press('Escape');
    expect(brightness(await readPixel(300, 208))).toBeGreaterThan(150);  // through the gap
    expect(brightness(await readPixel(300, 150))).toBeLessThan(30);

    // At 16 units the 32-unit walls are adopted: a 16-unit tile under the upper piece joins it.
    await tileMode(true);
    await choose('tile size', '16');
    await stroke([[200, 200], [201, 201]]);  // tile (12, 12) at 16: 192–208 × 192–208
    shapes = await hullShapes();
    expect(shapes).toHaveLength(3);
    const upper = shapes.find((s) => s.bounds[1] === 128)!;
    expect(upper.bounds).toEqual([192, 128, 224, 208]);
    expect(upper.area).toBe(32 * 64 + 16 * 16);
    await page.keyboard.press('Escape');
  });

  it('traces a dropped PNG into hulls at the drop point with the disc\'s area, drawn under them', async () => {
    expect(await load(emptyScene([100, 200], 500))).toBe(true);
    await tileMode(false);
    // Off the view's centre, so that the hulls show where it was dropped.
    const [cx, cy] = [250, 180];
    const floor = await readPixel(cx + 35, cy);
    // A red disc of radius 50 with a hole of radius 20, 128 pixels square: traced at its own size.
    await dropDisc('ring.png', [cx, cy], 128, 50, 20, '#ff0000');
    expect(await page.evaluate(() => window.playground.errorMessage())).toBeNull();
    expect(await page.evaluate(() => window.playground.traceStatus())).toMatch(/^ring\.png: \d+ hulls/);
    const shapes = await hullShapes();
    // A ring is no simple polygon: it is cut into pieces that meet exactly.
    expect(shapes.length).toBeGreaterThanOrEqual(2);
    const area = shapes.reduce((sum, s) => sum + s.area, 0);
    const ring = Math.PI * (50 ** 2 - 20 ** 2);
    // Within the tolerance (1 pixel) of the outline, on both rims.
    expect(Math.abs(area - ring)).toBeLessThan(0.5 * 2 * Math.PI * (50 + 20));
    expect(Math.abs(area - ring) / ring).toBeLessThan(0.03);
    const [x0, y0, x1, y1] = unionBounds(shapes.map((s) => s.bounds));
    expect((x0 + x1) / 2).toBeCloseTo(cx, 0);
    expect((y0 + y1) / 2).toBeCloseTo(cy, 0);
    expect(x1 - x0).toBeGreaterThan(98);
    expect(x1 - x0).toBeLessThan(102);
    expect(await page.evaluate(() => window.playground.debugWireframe())).toBe(true);
    // The image under the hulls: red where the floor was grey (the wireframe off, so no line crosses it).
    await page.evaluate(() => [...document.querySelectorAll('.lil-gui .lil-controller')]
      .find((c) => c.querySelector('.lil-name')?.textContent === 'debug wireframe')!.querySelector('input')!.click());
    const [r, g] = await readPixel(cx + 35, cy);
    expect(r).toBeGreaterThan(2 * g + 20);
    expect(Math.abs(floor[0] - floor[1])).toBeLessThan(30);
    // A file keeps the traced hulls, not the picture: the save says so.
    expect(JSON.parse(await saveThroughPanel()).hulls).toHaveLength(shapes.length);
    expect(await page.evaluate(() => window.playground.errorMessage())).toBe('Saved. The file keeps the hulls traced from images, not the images drawn under them.');
    expect(errors).toEqual([]);
  });

  it('traces an image from the file picker, and reports an unreadable or empty image without throwing', async () => {
    expect(await load(emptyScene([100, 200]))).toBe(true);
    const png = new PNG({ width: 80, height: 40 });
    png.data.fill(255);  // opaque white
    const file = join(mkdtempSync(join(tmpdir(), 'penumbra-playground-')), 'block.png');
    writeFileSync(file, PNG.sync.write(png));
    const [chooser] = await Promise.all([page.waitForFileChooser(), clickButton('trace image')]);
    await chooser.accept([file]);
    await page.waitForFunction(() => window.playground.traceStatus().startsWith('block.png:'), { timeout: 20_000 });
    let shapes = await hullShapes();
    expect(shapes).toHaveLength(1);
    // Centred in the view at one world unit per pixel: the outline runs along the pixel edges,
    // corners cut by half a pixel and then simplified within the tolerance (1 pixel).
    shapes[0].bounds.forEach((value, i) => expect(Math.abs(value - [260, 180, 340, 220][i])).toBeLessThanOrEqual(1));
    expect(Math.abs(shapes[0].area - 80 * 40)).toBeLessThan(80 + 40);

    await page.evaluate(() => {
      const data = new DataTransfer();
      data.items.add(new File(['not a picture'], 'notes.png', { type: 'image/png' }));
      document.getElementById('gizmos')!.dispatchEvent(new DragEvent('drop', { dataTransfer: data, clientX: 200, clientY: 200, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction(() => window.playground.traceStatus().startsWith('notes.png:'), { timeout: 20_000 });
    expect(await page.evaluate(() => window.playground.errorMessage())).toMatch(/Could not trace notes\.png: it is not an image/);
    await dropDisc('empty.png', [300, 200], 64, 0, 0, '#ff0000');
    expect(await page.evaluate(() => window.playground.errorMessage())).toMatch(/Could not trace empty\.png: it has no opaque pixels/);
    expect(await page.evaluate(() => window.playground.traceStatus())).toBe('empty.png: not traced');
    shapes = await hullShapes();
    expect(shapes).toHaveLength(1);
    expect(errors).toEqual([]);
  });

  it('tints a light\'s shadow with its shadow colour, and at shadow strength 0 lights the pixel behind a hull as without it', async () => {
    expect(await load(emptyScene([100, 200]))).toBe(true);
    const unshadowed = await readPixel(300, 200);
    expect(await load(testScene([100, 200]))).toBe(true);
    await page.mouse.click(...await toScreen(100, 200));
    expect(brightness(await readPixel(300, 200))).toBeLessThan(30);

    // A red shadow colour lets the red channel through in full.
    await enter('shadowColor', '#ff0000');
    expect((await sceneDocument()).lights[0].shadowColor).toEqual([1, 0, 0]);
    const [r, g, b] = await readPixel(300, 200);
    expect(Math.abs(r - unshadowed[0])).toBeLessThanOrEqual(2);
    expect(g + b).toBeLessThan(10);

    await enter('shadowStrength', '0');
    expect((await sceneDocument()).lights[0].shadowStrength).toBe(0);
    (await readPixel(300, 200)).forEach((channel, i) => expect(Math.abs(channel - unshadowed[i])).toBeLessThanOrEqual(2));
  });

  it('offers every shadow type, tone mapping and dithering the library has, and sets the one picked', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    await page.mouse.click(...await toScreen(100, 200));
    expect(await menuLabels('shadowType')).toEqual(Object.keys(ShadowType));
    expect(await menuLabels('tone mapping')).toEqual(Object.keys(ToneMapping));
    expect(await menuLabels('dithering')).toEqual(Object.keys(Dithering));
    await choose('shadowType', 'Solid');
    expect((await sceneDocument()).lights[0].shadowType).toBe('solid');
  });

  it('removes a hull\'s shadow when its layers share none with the light\'s shadow layers, and brings it back when they do', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    await page.mouse.click(...await toScreen(100, 200));
    expect(await folderTitles()).toContain('shadow layers: all');
    await tick('layer 0', false);
    expect((await sceneDocument()).lights[0].shadowLayers).toBe(0xfffffffe);
    expect(await folderTitles()).toContain('shadow layers: 1–31');
    // The hull is in layer 0 only.
    expect(brightness(await readPixel(300, 200))).toBeGreaterThan(150);

    await page.mouse.click(...await toScreen(220, 200));
    expect(await folderTitles()).toContain('layers: 0');
    await tick('layer 2', true);
    expect((await sceneDocument()).hulls[0].layers).toBe(0b101);
    expect(await folderTitles()).toContain('layers: 0 2');
    expect(brightness(await readPixel(300, 200))).toBeLessThan(30);
    await tick('layer 2', false);
    expect((await sceneDocument()).hulls[0].layers).toBe(1);
    expect(brightness(await readPixel(300, 200))).toBeGreaterThan(150);
  });

  it('rebuilds a hull as an open polyline and back with its other settings, keeping it selected and ignored', async () => {
    const scene = testScene([100, 200]);
    Object.assign(scene.hulls[0], { origin: [5, 0], rotation: 0.3, scale: [1.5, 1], layers: 5 });
    scene.lights[0].ignoredHulls = [0];
    expect(await load(scene)).toBe(true);
    const [original] = await page.evaluate(() => window.playground.hullIds());
    await page.mouse.click(...await toScreen(220, 200));
    expect(await isTicked('closed')).toBe(true);

    await tick('closed', false);
    let saved = await sceneDocument();
    expect(saved.hulls).toEqual([{ ...scene.hulls[0], closed: false }]);
    expect(saved.lights[0].ignoredHulls).toEqual([0]);
    expect(await page.evaluate(() => window.playground.hullIds())).not.toEqual([original]);
    // The panel shows the rebuilt hull, and its fields edit it.
    expect(await isTicked('closed')).toBe(false);
    await enter('x', '260');
    expect((await sceneDocument()).hulls[0].position).toEqual([260, 200]);

    await tick('closed', true);
    saved = await sceneDocument();
    expect(saved.hulls).toEqual([{ ...scene.hulls[0], position: [260, 200] }]);
    expect(saved.lights[0].ignoredHulls).toEqual([0]);
    expect(errors).toEqual([]);
  });

  it('keeps a traced hull rebuilt as open in its image\'s group: the hulls still move together', async () => {
    expect(await load(emptyScene([100, 200], 500))).toBe(true);
    await tileMode(false);
    await dropDisc('pieces.png', [250, 180], 128, 50, 20, '#ff0000');
    const before = unionBounds((await hullShapes()).map((s) => s.bounds));
    // A point of the ring, off the axes its pieces may be cut along.
    const onRing: [number, number] = [250 + 35 * Math.cos(0.6), 180 + 35 * Math.sin(0.6)];
    await page.mouse.click(...await toScreen(...onRing));
    await tick('closed', false);
    expect((await sceneDocument()).hulls.filter((hull) => !hull.closed)).toHaveLength(1);

    await stroke([onRing, [onRing[0] + 20, onRing[1] + 30]]);
    const after = unionBounds((await hullShapes()).map((s) => s.bounds));
    // Pointer events land on whole CSS pixels.
    after.forEach((value, i) => expect(Math.abs(value - before[i] - [20, 30][i % 2])).toBeLessThanOrEqual(1));
  });

  it('applies the look set in the panel, saves it, and a saved file loaded through the picker brings it back to the renderer and the panel', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    const lit = await readPixel(160, 200);
    await enter('exposure', '0.5');
    (await readPixel(160, 200)).forEach((channel, i) => expect(Math.abs(channel - lit[i] / 2)).toBeLessThanOrEqual(2));
    await choose('tone mapping', 'Aces');
    await choose('dithering', 'Ordered');
    await enter('lightmap blur', '7');
    const look = { exposure: 0.5, toneMapping: 'aces', dithering: 'ordered', lightmapBlur: 7 };
    const saved = await saveThroughPanel();
    expect(JSON.parse(saved).look).toEqual(look);

    expect(await load(testScene([100, 200]))).toBe(true);
    expect(await fieldText('exposure')).toBe('1');
    const file = join(mkdtempSync(join(tmpdir(), 'penumbra-playground-')), 'look.penumbra.json');
    writeFileSync(file, saved);
    const [chooser] = await Promise.all([page.waitForFileChooser(), clickButton('load scene')]);
    await chooser.accept([file]);
    await page.waitForFunction((text) => window.playground.sceneText() === text, { timeout: 10_000 }, saved);
    expect((await sceneDocument()).look).toEqual(look);
    expect(await lookShown()).toEqual(['0.5', 'Aces', 'Ordered', '7']);
  });

  it('shows the look of a scene dropped on the page in the panel, and a preset\'s look after it', async () => {
    const scene = { ...testScene([100, 200]), look: { exposure: 2.25, toneMapping: 'reinhard', dithering: 'noise', lightmapBlur: 12 } } as const;
    await page.evaluate((text) => {
      const data = new DataTransfer();
      data.items.add(new File([text], 'look.json', { type: 'application/json' }));
      document.getElementById('gizmos')!.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    }, JSON.stringify(scene));
    await page.waitForFunction(() => JSON.parse(window.playground.sceneText()).look.exposure === 2.25, { timeout: 10_000 });
    expect((await sceneDocument()).look).toEqual(scene.look);
    expect(await lookShown()).toEqual(['2.25', 'Reinhard', 'Noise', '12']);

    await page.evaluate(() => window.playground.selectPreset('Stage'));
    expect(await lookShown()).toEqual(['1', 'None', 'None', '0']);
  });

  it('adds a sun whose shadow falls along its rotation, turned by its compass and softened by its angular size', async () => {
    expect(await load(darkScene())).toBe(true);
    const unlit = brightness(await readPixel(150, 200));
    await clickButton('add sun');
    expect(await folderTitles()).toContain('Selected directional light');
    // A sun has no position, range, radius or origin, and no falloff.
    for (const name of ['x', 'y', 'range', 'radius', 'originX', 'originY', 'falloff']) expect(await hasField(name)).toBe(false);

    // Travelling along +x: the box (x 200–240, y 140–260) shadows its right.
    await enter('rotation°', '0');
    let upstream = brightness(await readPixel(150, 200)), downstream = brightness(await readPixel(300, 200));
    expect(upstream).toBeGreaterThan(unlit + 100);
    expect(upstream).toBeGreaterThan(3 * downstream + 30);

    // Its compass's arrow follows a drag: pointing down, the shadow falls below the box instead.
    const centre = await page.evaluate(() => window.playground.sunCompass(0));
    await dragOnCanvas(centre, [centre[0], centre[1] + 20]);
    const [sun] = await savedLights();
    expect(sun.kind).toBe('directional');
    expect(sun.rotation).toBeCloseTo(Math.PI / 2, 6);
    expect(Number(await fieldText('rotation°'))).toBe(90);
    upstream = brightness(await readPixel(220, 100));
    downstream = brightness(await readPixel(220, 320));
    expect(upstream).toBeGreaterThan(3 * downstream + 30);
    expect(brightness(await readPixel(300, 200))).toBeGreaterThan(3 * downstream + 30);

    // 4 units inside the shadow's edge and 120–240 below the box: in the umbra of the sun's
    // 0.0093 radians, in a wide penumbra at 0.6 (rays up to 0.3 off the axis clear the box's corner).
    const nearEdge = brightness(await readPixel(236, 380));
    expect(nearEdge).toBeLessThan(downstream + 10);
    await enter('angularSize', '0.6');
    expect((await savedLights())[0]).toMatchObject({ kind: 'directional', angularSize: 0.6 });
    expect(brightness(await readPixel(236, 380))).toBeGreaterThan(nearEdge + 60);
    expect(errors).toEqual([]);
  });

  it('saves a sun with its rotation and angular size, and a saved file loaded through the picker brings it back', async () => {
    expect(await load(darkScene())).toBe(true);
    await clickButton('add sun');
    await enter('rotation°', '30');
    await enter('angularSize', '0.25');
    const saved = await saveThroughPanel();
    const [sun] = (JSON.parse(saved) as SceneDocument).lights;
    expect(sun).toMatchObject({ kind: 'directional', angularSize: 0.25 });
    expect(sun.rotation).toBeCloseTo(Math.PI / 6, 12);
    expect(sun).not.toHaveProperty('position');
    const lit = await readPixel(150, 200);

    expect(await load(darkScene())).toBe(true);
    expect(await savedLights()).toEqual([]);
    const file = join(mkdtempSync(join(tmpdir(), 'penumbra-playground-')), 'sun.penumbra.json');
    writeFileSync(file, saved);
    const [chooser] = await Promise.all([page.waitForFileChooser(), clickButton('load scene')]);
    await chooser.accept([file]);
    await page.waitForFunction((text) => window.playground.sceneText() === text, { timeout: 10_000 }, saved);
    expect(await savedLights()).toEqual([sun]);
    expect(await readPixel(150, 200)).toEqual(lit);
    // Its compass is back, and selects it.
    await page.mouse.click(...await page.evaluate(() => window.playground.sunCompass(0)));
    expect(await folderTitles()).toContain('Selected directional light');
    expect(Number(await fieldText('angularSize'))).toBe(0.25);
  });

  it('offers every falloff the library has for a point light, and the light at a point then follows the curve picked', async () => {
    // No ambient light, so that a pixel's colour is the floor's times the light's falloff alone.
    const scene = { ...emptyScene([100, 200]), ambient: [0, 0, 0] as [number, number, number] };
    scene.lights[0].radius = 60;  // the inverse-square curve's core: 60 / 300 = 0.2 ranges
    expect(await load(scene)).toBe(true);
    await page.mouse.click(...await toScreen(100, 200));
    expect(await menuLabels('falloff')).toEqual(Object.keys(Falloff));
    expect(await fieldText('falloff')).toBe('Linear');
    // 0.3 and 0.6 ranges from the light; the same pixels under each curve, so the floor's colour divides out.
    const distances = [0.3, 0.6];
    const read = () => Promise.all(distances.map(async (t) => brightness(await readPixel(100 + 300 * t, 200))));
    const linear = await read();
    for (const [label, falloff] of [['Smooth', Falloff.Smooth], ['InverseSquare', Falloff.InverseSquare]] as const) {
      await choose('falloff', label);
      expect((await savedLights())[0]).toMatchObject({ falloff });
      const curved = await read();
      distances.forEach((t, i) => {
        const expected = falloffAt(falloff, t, 0.2) / falloffAt(Falloff.Linear, t, 0.2);
        expect(Math.abs(curved[i] / linear[i] - expected)).toBeLessThan(0.06 * expected + 0.02);
      });
    }
  });

  it('sets a light\'s lit layers with their checkboxes, apart from its shadow layers, and saves them', async () => {
    expect(await load(testScene([100, 200]))).toBe(true);
    await page.mouse.click(...await toScreen(100, 200));
    expect(await folderTitles()).toEqual(expect.arrayContaining(['shadow layers: all', 'lit layers: all']));
    await tickIn('lit layers', 'layer 0', false);
    await tickIn('lit layers', 'layer 3', false);
    expect((await sceneDocument()).lights[0]).toMatchObject({ litLayers: 0xfffffff6, shadowLayers: 0xffffffff });
    expect(await folderTitles()).toEqual(expect.arrayContaining(['shadow layers: all', 'lit layers: 1–2 4–31']));
    await tickIn('lit layers', 'layer 0', true);
    expect((await sceneDocument()).lights[0].litLayers).toBe(0xfffffff7);
  });

  it('selects an open hull by a click near its line, not by one inside its outline', async () => {
    const scene = testScene([100, 200]);
    // Open: three sides of the box, (200, 140) → (240, 140) → (240, 260) → (200, 260).
    scene.hulls[0].closed = false;
    expect(await load(scene)).toBe(true);
    await page.mouse.click(...await toScreen(220, 200));  // 20 units from the nearest side
    expect(await folderTitles()).not.toContain('Selected hull');
    await page.mouse.click(...await toScreen(243, 200));  // 3 units right of the right side
    expect(await folderTitles()).toContain('Selected hull');
    await page.keyboard.press('Escape');
    await page.mouse.click(...await toScreen(220, 136));  // 4 units above the top side
    expect(await folderTitles()).toContain('Selected hull');
  });

  it('switches presets and keeps the scene across a reload', async () => {
    for (const name of ['Penumbra lab', 'Dungeon']) {
      await page.evaluate((preset) => window.playground.selectPreset(preset), name);
      expect(await page.evaluate(() => window.playground.glError())).toBe(0);
    }
    await page.evaluate(() => window.playground.selectPreset('Penumbra lab'));
    const stats = await page.evaluate(() => window.playground.rendererStats());
    expect(stats).toMatchObject({ lights: 3, hulls: 6 });
    expect(await page.$eval('.lil-gui select', (select) => select.selectedOptions[0].textContent)).toBe('Penumbra lab');

    const before = await page.evaluate(() => window.playground.sceneText());
    await page.reload();
    await page.waitForFunction(() => window.playground !== undefined, { timeout: PAGE_READY_MS });
    expect(await page.evaluate(() => window.playground.sceneText())).toBe(before);
    expect(errors).toEqual([]);
  });
});
