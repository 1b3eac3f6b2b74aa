import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'puppeteer';
import {
  AMBIENT_SQUARE, CHECK_LAYER_A, CHECK_LAYER_B, CHECK_PLAYER, LIGHT_A, LIGHT_B, LIT_SQUARE, SQUARE_COLOR, type GroupCheckBase,
} from '../../demo/examples/groupCheck';
import { AMBIENT_COLOR, PLAYER_START, SIGN, SIGN_COLOR, followPlayer, type Rect } from '../../demo/examples/level';
import { launchChromium } from './chromium';
import { openExample, readAt, type Pixel } from './engineExample';
import { serveDirectory, type StaticServer } from './staticServer';

// The engine examples' lit groups in Chromium, against values computed from the geometry: a square
// drawn in a group of layers A and lit by light A (layers A) and not by light B (layers B), a square
// in a group of layers 0 (the ambient colour only), and the examples' sign, drawn after the lighting
// (unlit). The expected value of a pixel is the square's colour × (ambient + light A's colour ×
// intensity × (1 − d / range)), d from the light to the world point at the pixel's centre: what the
// lightmap holds there (lightmap at full scale, no shadows: the lights cast none).
//
// Tolerance, 1 step of 8 bits per channel: the lightmap is RGBA16F (the sum of ambient and light
// rounded to half floats, a relative error under 2⁻¹⁰, at most 0.25 of a step on these values), then
// the product is rounded once to 8 bits in the group's target (½ step); drawing that target into the
// frame at its own pixels, opaque, copies it exactly.

export type Vec = readonly [number, number];
type Rgb = [number, number, number];

/** A small window: SwiftShader's frames are slow. The last test enlarges it. */
const WINDOW: Vec = [480, 320];
const RESIZED: Vec = [640, 400];
/** Where the player stands after the resize: the camera then shows the lit square beyond the old window's width. */
const RESIZED_PLAYER: Vec = [600, 320];
/** Inset of the points read from the squares' edges, world units: clear of edge pixels at any zoom tried. */
const INSET = 4;
/** How far apart the values read are from another light's, or the square's from the floor's, at least: far beyond the tolerance. */
const APART = 10;

/** The names of the engines' group checks on `window`. */
type GroupCheckName = 'penumbraPixiGroups' | 'penumbraPhaserGroups';

/** The camera the examples put on the player in a window of `size` CSS pixels. */
function viewFor(size: Vec, player: Vec, zoomFactor = 1) {
  return followPlayer(player, size[0], size[1], { zoom: 1, scroll: [0, 0] }, zoomFactor);
}
type View = ReturnType<typeof viewFor>;

/** The canvas pixel (CSS, integer) of a world point, and the world point at that pixel's centre. */
function pixelOf(view: View, [x, y]: Vec): { pixel: Vec; centre: Vec } {
  const pixel: Vec = [Math.floor((x - view.scroll[0]) * view.zoom), Math.floor((y - view.scroll[1]) * view.zoom)];
  return { pixel, centre: [view.scroll[0] + (pixel[0] + 0.5) / view.zoom, view.scroll[1] + (pixel[1] + 0.5) / view.zoom] };
}

function onCanvas(size: Vec, [x, y]: Vec): boolean {
  return x >= 0 && y >= 0 && x < size[0] && y < size[1];
}

/** A 3 × 3 grid of world points inside `rect`, `INSET` from its edges. */
function inside([x, y, w, h]: Rect): Vec[] {
  const points: Vec[] = [];
  for (const fy of [0, 0.5, 1]) {
    for (const fx of [0, 0.5, 1]) points.push([x + INSET + fx * (w - 2 * INSET), y + INSET + fy * (h - 2 * INSET)]);
  }
  return points;
}

/** World points `INSET` outside the middle of each edge of `rect`. */
function outside([x, y, w, h]: Rect): Vec[] {
  return [[x - INSET, y + h / 2], [x + w + INSET, y + h / 2], [x + w / 2, y - INSET], [x + w / 2, y + h + INSET]];
}

function rgb(color: number): Rgb {
  return [(color >> 16) & 0xff, (color >> 8) & 0xff, color & 0xff];
}

/** Light A's (or B's) colour × intensity × linear falloff at world point `p`. */
function lightAt(light: typeof LIGHT_A | typeof LIGHT_B, [x, y]: Vec): Rgb {
  const strength = light.intensity * Math.max(0, 1 - Math.hypot(x - light.position[0], y - light.position[1]) / light.range);
  return [light.color[0] * strength, light.color[1] * strength, light.color[2] * strength];
}

/** The 8-bit value of colour `color` lit by the ambient colour and `lights` at world point `p`, unrounded. */
function litValue(color: number, p: Vec, lights: (typeof LIGHT_A | typeof LIGHT_B)[]): Rgb {
  const light: Rgb = [AMBIENT_COLOR[0], AMBIENT_COLOR[1], AMBIENT_COLOR[2]];
  for (const each of lights) {
    const add = lightAt(each, p);
    for (let k = 0; k < 3; k++) light[k] += add[k];
  }
  return rgb(color).map((c, k) => 255 * Math.min(1, (c / 255) * light[k])) as Rgb;
}

/** The largest difference per channel between what was read and what was expected. */
function worst(read: Pixel[], expected: Rgb[]): number {
  return Math.max(...read.map((pixel, i) => Math.max(...[0, 1, 2].map((k) => Math.abs(pixel[k] - expected[i][k])))));
}

/** Describes every channel read against its expected value, for failure messages. */
function report(read: Pixel[], expected: Rgb[]): string {
  return read.map((pixel, i) => `[${pixel.slice(0, 3).join(',')}] vs [${expected[i].map((v) => v.toFixed(1)).join(',')}]`).join('; ');
}

/** The suite's page and reading, for an engine's own tests. */
interface LitGroupPage {
  page(): Page;
  /** Reads the pixels of world points with the camera on `player`; each with its pixel centre's world point. */
  read(player: Vec, points: Vec[], zoomFactor?: number): Promise<{ read: Pixel[]; centres: Vec[] }>;
  /** Expects the lit square where the camera on `player` puts it: lit by light A inside, not drawn outside. */
  expectLitSquareInView(player: Vec, zoomFactor?: number): Promise<void>;
}

/**
 * The lit-group tests every engine example must pass, then `more` (the engine's life-cycle tests)
 * in the same page.
 */
export function describeLitGroups(title: string, path: string, check: GroupCheckName, more: (context: LitGroupPage) => void): void {
  describe(title, () => {
    let server: StaticServer;
    let browser: Browser;
    let page: Page;
    let errors: string[];
    let size = WINDOW;

    const setLayers = (layers: number) => page.evaluate((name, layers) => (window[name] as GroupCheckBase).setLayers(layers), check, layers);
    const setZoom = (factor: number) => page.evaluate((factor) => window.penumbraExample!.setZoom(factor), factor);

    /** Reads the pixels of world points with the camera on `player` (zoom factor `zoomFactor`); each with its pixel centre's world point. */
    async function read(player: Vec, points: Vec[], zoomFactor = 1): Promise<{ read: Pixel[]; centres: Vec[] }> {
      const view = viewFor(size, player, zoomFactor);
      const placed = points.map((p) => pixelOf(view, p)).filter(({ pixel }) => onCanvas(size, pixel));
      await setZoom(zoomFactor);
      try {
        return { read: await readAt(page, player, placed.map(({ pixel }) => pixel)), centres: placed.map(({ centre }) => centre) };
      } finally {
        await setZoom(1);
      }
    }

    /** Expects the lit square where the camera on `player` puts it: lit by light A inside, not drawn outside. */
    async function expectLitSquareInView(player: Vec, zoomFactor = 1): Promise<void> {
      const within = await read(player, inside(LIT_SQUARE), zoomFactor);
      const expected = within.centres.map((p) => litValue(SQUARE_COLOR, p, [LIGHT_A]));
      expect(within.read.length).toBe(9);
      expect(worst(within.read, expected), report(within.read, expected)).toBeLessThanOrEqual(1);
      const around = await read(player, outside(LIT_SQUARE), zoomFactor);
      expect(around.read.length, 'points around the square on the canvas').toBeGreaterThanOrEqual(3);
      // The floor there, lit by the level's lamps, is far darker than the square would be.
      const squareThere = around.centres.map((p) => litValue(SQUARE_COLOR, p, [LIGHT_A]));
      for (const [i, pixel] of around.read.entries()) expect(Math.abs(pixel[0] - squareThere[i][0]), `around the square: ${pixel}`).toBeGreaterThan(APART);
    }

    beforeAll(async () => {
      server = await serveDirectory('demo-dist');
      browser = await launchChromium();
      ({ page, errors } = await openExample(browser, `${server.url}${path}`));
      await page.setViewport({ width: WINDOW[0], height: WINDOW[1] });
      // The flashlight, which lights the floor only, aimed away from the squares; the engines resize on the next frame.
      await page.mouse.move(2, 2);
      await page.evaluate((name) => (window[name] as GroupCheckBase).setUp(), check);
      await page.evaluate(() => window.penumbraExample!.frames(2));
    }, 300_000);  // loading an example, a few SwiftShader frames at a time, on a shared machine
    afterAll(async () => {
      await browser?.close();
      await server?.close();
    });

    it('lights a group of layers A with light A (layers A) and the ambient colour, not with light B (layers B)', async () => {
      const points = inside(LIT_SQUARE);
      const onlyA = await read(CHECK_PLAYER, points);
      const withA = onlyA.centres.map((p) => litValue(SQUARE_COLOR, p, [LIGHT_A]));
      const withAB = onlyA.centres.map((p) => litValue(SQUARE_COLOR, p, [LIGHT_A, LIGHT_B]));
      // Light B reaches every point read: with it, the blue channel would be well apart.
      for (const [i, value] of withAB.entries()) expect(value[2] - withA[i][2]).toBeGreaterThan(APART);
      expect(onlyA.read.length).toBe(9);
      expect(worst(onlyA.read, withA), report(onlyA.read, withA)).toBeLessThanOrEqual(1);
      // The same group given both layers takes light B too.
      await setLayers(CHECK_LAYER_A | CHECK_LAYER_B);
      try {
        const both = await read(CHECK_PLAYER, points);
        expect(worst(both.read, withAB), report(both.read, withAB)).toBeLessThanOrEqual(1);
      } finally {
        await setLayers(CHECK_LAYER_A);
      }
    });

    it('gives a group of layers 0 the ambient colour only, though lights A and B reach it', async () => {
      const { read: pixels, centres } = await read(CHECK_PLAYER, inside(AMBIENT_SQUARE));
      expect(pixels.length, 'points of the square on the canvas').toBeGreaterThanOrEqual(6);
      const expected = centres.map((p) => litValue(SQUARE_COLOR, p, []));
      for (const [i, p] of centres.entries()) expect(litValue(SQUARE_COLOR, p, [LIGHT_B])[2] - expected[i][2]).toBeGreaterThan(APART);
      expect(worst(pixels, expected), report(pixels, expected)).toBeLessThanOrEqual(1);
    });

    it('keeps the exact colour of the sign drawn after the lighting', async () => {
      const [x, y, w, h] = SIGN;
      // Clear of the rounded corners (radius 4).
      const { read: pixels } = await read(PLAYER_START, inside([x + 2, y + 1, w - 4, h - 2]));
      expect(pixels.length).toBe(9);
      const exact = Array.from({ length: pixels.length }, () => rgb(SIGN_COLOR));
      expect(worst(pixels, exact), report(pixels, exact)).toBeLessThanOrEqual(1);
    });

    it('keeps a group with the world as the camera pans and zooms: the square where the camera puts it, lit as its place says', async () => {
      await expectLitSquareInView(CHECK_PLAYER);
      await expectLitSquareInView([720, 260]);
      await expectLitSquareInView(CHECK_PLAYER, 1.5);
    });

    more({ page: () => page, read, expectLitSquareInView });

    it('keeps a group aligned when the window is resized, also beyond the old size', async () => {
      await page.setViewport({ width: RESIZED[0], height: RESIZED[1] });
      await page.evaluate(() => window.penumbraExample!.frames(3));
      size = RESIZED;
      expect(await page.evaluate(() => window.penumbraExample!.canvasSize().buffer)).toEqual(RESIZED);
      const view = viewFor(size, RESIZED_PLAYER);
      expect(inside(LIT_SQUARE).every((p) => pixelOf(view, p).pixel[0] >= WINDOW[0]), 'the square right of the old width').toBe(true);
      await expectLitSquareInView(RESIZED_PLAYER);
    });

    it('logs no console errors', () => {
      expect(errors).toEqual([]);
    });
  });
}
