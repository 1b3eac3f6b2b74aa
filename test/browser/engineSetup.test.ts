import type { Page } from 'puppeteer';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openBuiltPage, type BuiltPage } from './builtPage';
import { WORLD_ORIGIN, type CarrierChange, type FollowFrame, type FollowOptions, type Pixel } from './engine-setup-page/contract';

// Real PixiJS 8 and Phaser 4 in Chromium: each engine's default context against the integrations
// (a WebGL1 context is refused with a message that says what to do), Phaser through
// penumbraGameConfig, and a spotlight following a display object. Expected light placements are
// worked out here by hand from the object's transform; the pixels check that the renderer drew the
// light there: the floor is white, the ambient light none, the beam 14 units long and a quarter
// turn wide.

let built: BuiltPage;
let page: Page;
let errors: string[];

beforeAll(async () => {
  built = await openBuiltPage('engine-setup-page', 'engineSetup');
  ({ page, pageErrors: errors } = built);
}, 300_000);  // a Vite build and Chromium on a shared machine

afterAll(async () => {
  await built?.close();
});

/** Floor the beam reaches, 4 units from the light… */
const LIT = 120;
/** …and floor it does not (no ambient light). */
const DARK = 30;
const brightness = ([r, g, b]: Pixel): number => (r + g + b) / 3;
/** A world point on the canvas. */
const onCanvas = ([x, y]: readonly [number, number]): [number, number] => [x + WORLD_ORIGIN[0], y + WORLD_ORIGIN[1]];

/** Canvas points 4 units ahead of and behind a light at world `at`, along `angle`. */
function aheadAndBehind(at: readonly [number, number], angle: number): [number, number][] {
  const dx = 4 * Math.cos(angle), dy = 4 * Math.sin(angle);
  return [onCanvas([at[0] + dx, at[1] + dy]), onCanvas([at[0] - dx, at[1] - dy])];
}

const PHASER_FIX = 'Phaser 4 makes a WebGL1 context unless its game config gives one; '
  + 'make the game with new Phaser.Game(penumbraGameConfig({ … })), penumbraGameConfig from \'penumbra-gl/phaser\'';
const PIXI_FIX = 'Pixi made a WebGL1 context (preferWebGLVersion: 1, or no WebGL2 in this browser); '
  + 'init the Application with preference: \'webgl\' and preferWebGLVersion: 2 (the default) in a browser with WebGL2';

describe('engine contexts', () => {
  it('Phaser\'s default config: the plugin refuses its WebGL1 context, naming the cause and the one-line fix', async () => {
    const report = await page.evaluate(() => window.engineSetup!.phaserDefaultConfig());
    expect(report.webgl2).toBe(false);
    const message = `penumbra: PenumbraPlugin needs a WebGL2 rendering context, got a WebGL1 context (WebGLRenderingContext): ${PHASER_FIX}`;
    expect(report.error).toBe(message);
    // Uncaught, as Phaser boots the plugin in its own callbacks: the page's only error.
    expect(errors).toEqual([expect.stringContaining(message)]);
    errors.length = 0;
  });

  it('penumbraGameConfig gives Phaser a WebGL2 context: the scene is lit on an opaque canvas, the config\'s own preBoot still runs', async () => {
    const light: [number, number] = [60, 50];
    const points = [onCanvas(light), onCanvas([light[0] + 30, light[1]])];
    const report = await page.evaluate((l, p) => window.engineSetup!.phaserGameConfig(l, p), light, points);
    expect(report.error).toBeNull();
    expect(report.webgl2).toBe(true);
    expect(report.ownPreBoot).toBe(true);
    expect(brightness(report.pixels[0])).toBeGreaterThan(LIT);
    expect(brightness(report.pixels[1])).toBeLessThan(DARK);
    // Phaser's default antialiasGL: the canvas has an alpha channel, which Phaser clears opaque.
    expect(report.pixels.map((pixel) => pixel[3])).toEqual([255, 255]);
  });

  it('an antialiased opaque canvas, which the lighting cannot copy, is refused with the fix', async () => {
    const report = await page.evaluate(() => window.engineSetup!.antialiasedOpaque());
    expect(report.pixi).toBe('penumbra: PenumbraLayer cannot light Pixi\'s canvas: it is antialiased and opaque (antialias: true with an opaque '
      + 'background), and the lighting copies a multisampled canvas only into its own RGBA format; init the Application with antialias: false');
    const phaser = 'penumbra: PenumbraPlugin cannot light Phaser\'s canvas: its context is antialiased and opaque (antialias: true, '
      + 'alpha: false), and the lighting copies a multisampled canvas only into its own RGBA format; make the game with '
      + 'penumbraGameConfig, or make the context with antialias: false or alpha: true';
    expect(report.phaser).toBe(phaser);
    expect(errors).toEqual([expect.stringContaining(phaser)]);
    errors.length = 0;
  });

  it('PenumbraLayer refuses a WebGL1 Pixi renderer, naming it and what to pass', async () => {
    const report = await page.evaluate(() => window.engineSetup!.pixiWebGL1());
    expect(report.webgl2).toBe(false);
    expect(report.error).toBe(`penumbra: PenumbraLayer needs a WebGL2 rendering context, got a WebGL1 context (WebGLRenderingContext): ${PIXI_FIX}`);
  });
});

/** Per engine: how the carrier is mirrored, and where the light's offset lands then. */
interface Engine {
  name: 'pixi' | 'phaser';
  mirror: CarrierChange;
  unmirror: CarrierChange;
  /** The light's world position with the carrier at (40, 50), unturned, unscaled, mirrored; offset [6, 0]. */
  mirrored: [number, number];
}

const ENGINES: Engine[] = [
  // A negative scale mirrors about the container's position.
  { name: 'pixi', mirror: { scaleX: -1 }, unmirror: { scaleX: 1 }, mirrored: [34, 50] },
  // flipX mirrors the 20-unit frame in place, drawn from its top-left corner: local x → 20 − x.
  { name: 'phaser', mirror: { flipX: true }, unmirror: { flipX: false }, mirrored: [54, 50] },
];

describe.each(ENGINES)('a light following a display object: $name', ({ name, mirror, unmirror, mirrored }) => {
  function frame(change: CarrierChange, points: readonly [number, number][] = []): Promise<FollowFrame> {
    return page.evaluate((n, c, p) => window.engineSetup![n].frame(c, p), name, change, points);
  }
  function follow(options: FollowOptions): Promise<void> {
    return page.evaluate((n, o) => window.engineSetup![n].follow(o), name, options);
  }

  beforeAll(async () => {
    await page.evaluate((n) => window.engineSetup![n].start({ x: 40, y: 50 }), name);
    await follow({ offset: [6, 0], rotation: 0 });
  }, 120_000);

  afterAll(async () => {
    await page.evaluate((n) => window.engineSetup![n].close(), name);
  });

  it('sits at its offset on the object, its beam along the object\'s +x', async () => {
    const result = await frame({}, aheadAndBehind([46, 50], 0));
    expect(result.position).toEqual([46, 50]);
    expect(result.rotation).toBe(0);
    expect([result.inRenderer, result.enabled, result.followers]).toEqual([true, true, 1]);
    expect(brightness(result.pixels[0])).toBeGreaterThan(LIT);
    expect(brightness(result.pixels[1])).toBeLessThan(DARK);
  });

  it('moves, turns and scales with the object, and writes nothing while it stands still', async () => {
    // Offset (6, 0) turned a quarter turn and doubled: (0, 12) from the object at (40, 50).
    const moved = await frame({ rotation: Math.PI / 2, scaleX: 2, scaleY: 2 }, aheadAndBehind([40, 62], Math.PI / 2));
    expect(moved.position[0]).toBeCloseTo(40, 9);
    expect(moved.position[1]).toBeCloseTo(62, 9);
    expect(moved.rotation).toBeCloseTo(Math.PI / 2, 12);
    expect(brightness(moved.pixels[0])).toBeGreaterThan(LIT);
    expect(brightness(moved.pixels[1])).toBeLessThan(DARK);
    const still = await frame({});
    expect(still.positionKept).toBe(true);
    expect(still.position).toEqual(moved.position);
  });

  it('mirrors with the object: its offset and its beam', async () => {
    const result = await frame({ rotation: 0, scaleX: 1, scaleY: 1, ...mirror }, aheadAndBehind(mirrored, Math.PI));
    expect(result.position[0]).toBeCloseTo(mirrored[0], 9);
    expect(result.position[1]).toBeCloseTo(mirrored[1], 9);
    expect(Math.abs(result.rotation)).toBeCloseTo(Math.PI, 12);
    expect(brightness(result.pixels[0])).toBeGreaterThan(LIT);
    expect(brightness(result.pixels[1])).toBeLessThan(DARK);
    await frame(unmirror);
  });

  it('goes out while the object is hidden, and back on when it is shown', async () => {
    const spot = aheadAndBehind([46, 50], 0).slice(0, 1);
    const hidden = await frame({ visible: false }, spot);
    expect(hidden.enabled).toBe(false);
    expect(brightness(hidden.pixels[0])).toBeLessThan(DARK);
    const shown = await frame({ visible: true }, spot);
    expect(shown.enabled).toBe(true);
    expect(brightness(shown.pixels[0])).toBeGreaterThan(LIT);
  });

  it('unfollow leaves the light where it is, lit; following again picks the object up', async () => {
    expect(await page.evaluate((n) => window.engineSetup![n].unfollow(), name)).toBe(true);
    const left = await frame({ x: 100 });
    expect(left.position).toEqual([46, 50]);
    expect([left.inRenderer, left.enabled, left.followers]).toEqual([true, true, 0]);
    await follow({ offset: [6, 0], rotation: 0 });
    const again = await frame({});
    expect(again.position).toEqual([106, 50]);
    expect(again.followers).toBe(1);
  });

  it('is removed with the object when the object is destroyed', async () => {
    const result = await page.evaluate((n) => window.engineSetup![n].destroyCarrier(), name);
    expect([result.inRenderer, result.followers]).toEqual([false, 0]);
  });
});

describe('the page', () => {
  it('logs no other console errors', () => {
    expect(errors).toEqual([]);
  });
});
