import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'puppeteer';
import { PROP_POSITION, TILE_SIZE, followPlayer, levelTiles, propImage, type View } from '../../demo/examples/level';
import { FLASHLIGHT, PROP_TRIMMED_WIDTH } from '../../demo/phaser/content';
import { launchChromium } from './chromium';
import { aimAt, brightness, openExample, readAt, type Pixel } from './engineExample';
import { serveDirectory, type StaticServer } from './staticServer';

// The Phaser example's tilemap walls and spinning prop cast shadows through the plugin's
// addTilemapLayer and addSprite. The pixels read are chosen here from geometry: the level's tile
// grid and the prop's alpha, placed as Phaser draws them, seen from the flashlight (at the player).
// A point counts as dark when every ray from a disk larger than the flashlight's crosses an
// occluder shrunk by a margin, and as lit when no such ray comes within the margin of one; the
// margin covers the hulls' tolerance and the pixel grid. Points where the two situations compared
// disagree are the ones read.

/** `propImage()` builds an `ImageData`, which Node lacks; its fields are all the geometry needs. */
if (typeof globalThis.ImageData === 'undefined') {
  (globalThis as { ImageData?: unknown }).ImageData = class {
    constructor(readonly data: Uint8ClampedArray, readonly width: number, readonly height: number) {}
  };
}

type Vec = readonly [number, number];
/** Whether a world point is inside an occluder. */
type Solid = (x: number, y: number) => boolean;

/** The window of the example, as openExample sets it. */
const WINDOW: Vec = [600, 400];
/** The flashlight's radius and a little more: a larger disk only makes "all rays" and "no ray" stricter. */
const LIGHT_RADIUS = FLASHLIGHT.radius! + 0.5;
/** Floor in the flashlight beam, off its axis by up to 20° and up to 150 units away, is brighter than this… */
const LIT = 40;
/** …and floor in its umbra shows the ambient light only (0.08 of the floor's ~150). */
const DARK = 25;

/** A prop placement, as the test hook's setProp takes it. */
interface Prop {
  position: Vec;
  rotation: number;
  scale: number;
  flipX: boolean;
}

const star = propImage();

/**
 * The prop's opaque pixels in the world. Phaser draws a sprite at T(position) · R(rotation) ·
 * S(scale) around its origin, here the default: the centre of the untrimmed frame, which is
 * PROP_TRIMMED_WIDTH × PROP_SIZE with the star's pixels at its left; flipX mirrors the untrimmed
 * frame in place (its origin stays put).
 */
function propSolid({ position, rotation, scale, flipX }: Prop): Solid {
  const cos = Math.cos(rotation), sin = Math.sin(rotation);
  const originX = PROP_TRIMMED_WIDTH / 2, originY = star.height / 2;
  return (x, y) => {
    const dx = x - position[0], dy = y - position[1];
    let u = (cos * dx + sin * dy) / scale + originX;
    const v = (-sin * dx + cos * dy) / scale + originY;
    if (flipX) u = PROP_TRIMMED_WIDTH - u;
    const px = Math.floor(u), py = Math.floor(v);
    return px >= 0 && py >= 0 && px < star.width && py < star.height && star.data[(py * star.width + px) * 4 + 3] >= 128;
  };
}

/** The level's wall tiles in the world, with some tiles changed. */
function tilesSolid(changes: readonly [number, number, boolean][] = []): Solid {
  const grid = levelTiles();
  for (const [x, y, solid] of changes) grid[y][x] = solid ? 1 : 0;
  return (x, y) => grid[Math.floor(y / TILE_SIZE)]?.[Math.floor(x / TILE_SIZE)] === 1;
}

const either = (...solids: Solid[]): Solid => (x, y) => solids.some((solid) => solid(x, y));

const AROUND = Array.from({ length: 8 }, (_, k) => [Math.cos((k * Math.PI) / 4), Math.sin((k * Math.PI) / 4)] as const);

/** Whether every point within `margin` of (x, y) (sampled) is solid. */
function deepInside(solid: Solid, x: number, y: number, margin: number): boolean {
  if (!solid(x, y)) return false;
  for (const r of [margin / 2, margin]) {
    for (const [cx, cy] of AROUND) if (!solid(x + cx * r, y + cy * r)) return false;
  }
  return true;
}

/** Whether no point within `margin` of (x, y) (sampled) is solid. */
function wellOutside(solid: Solid, x: number, y: number, margin: number): boolean {
  if (solid(x, y)) return false;
  for (const r of [margin / 2, margin]) {
    for (const [cx, cy] of AROUND) if (solid(x + cx * r, y + cy * r)) return false;
  }
  return true;
}

/** Points of the light's disk: its centre and its rim. */
function diskPoints(light: Vec): Vec[] {
  return [light, ...Array.from({ length: 16 }, (_, k) => [
    light[0] + LIGHT_RADIUS * Math.cos((k * Math.PI) / 8), light[1] + LIGHT_RADIUS * Math.sin((k * Math.PI) / 8),
  ] as const)];
}

/**
 * Whether `point` is surely `want`: 'dark' when every ray from the light's disk to it crosses an
 * occluder by more than `margin`, 'lit' when none comes within `margin` of one.
 */
function shadeIs(want: 'dark' | 'lit', solid: Solid, light: Vec, point: Vec, margin: number): boolean {
  for (const [sx, sy] of diskPoints(light)) {
    const steps = Math.ceil(Math.hypot(point[0] - sx, point[1] - sy) / 0.5);
    let blocked = false;
    for (let i = 0; i <= steps && !blocked; i++) {
      const x = sx + ((point[0] - sx) * i) / steps, y = sy + ((point[1] - sy) * i) / steps;
      if (want === 'dark') blocked = deepInside(solid, x, y, margin);
      else if (!wellOutside(solid, x, y, margin)) return false;
    }
    if (want === 'dark' && !blocked) return false;
  }
  return true;
}

/** The canvas (CSS pixel) point of a world point, for the camera following the player. */
function toScreen(view: View, [x, y]: Vec): Vec {
  return [(x - view.scroll[0]) * view.zoom, (y - view.scroll[1]) * view.zoom];
}

/** The world point at the centre of a canvas pixel. */
function toWorld(view: View, [x, y]: Vec): Vec {
  return [view.scroll[0] + (Math.floor(x) + 0.5) / view.zoom, view.scroll[1] + (Math.floor(y) + 0.5) / view.zoom];
}

/**
 * Canvas pixels lit by the flashlight aimed from `player` at `aim`, nearest the beam's axis first:
 * floor within 20° of the axis, 35 to 150 units away (clear of the player's own drawing).
 */
function beamPixels(view: View, player: Vec, aim: Vec): Vec[] {
  const axis = Math.atan2(aim[1] - player[1], aim[0] - player[0]);
  const pixels: { pixel: Vec; off: number }[] = [];
  for (let y = 2.5; y < WINDOW[1]; y += 4) {
    for (let x = 2.5; x < WINDOW[0]; x += 4) {
      const [wx, wy] = toWorld(view, [x, y]);
      const distance = Math.hypot(wx - player[0], wy - player[1]);
      const off = Math.abs(Math.atan2(Math.sin(Math.atan2(wy - player[1], wx - player[0]) - axis), Math.cos(Math.atan2(wy - player[1], wx - player[0]) - axis)));
      if (distance >= 35 && distance <= 150 && off <= (20 * Math.PI) / 180) pixels.push({ pixel: [x, y], off });
    }
  }
  return pixels.sort((a, b) => a.off - b.off).map(({ pixel }) => pixel);
}

/** The first pixel of `pixels` on floor (clear of `solids`) whose shade is `want[i]` with occluders `solids[i]`. */
function pick(view: View, light: Vec, pixels: Vec[], solids: Solid[], margins: number[], want: ('dark' | 'lit')[]): Vec {
  const found = pixels.find((pixel) => {
    const world = toWorld(view, pixel);
    return solids.every((solid, i) => wellOutside(solid, world[0], world[1], margins[i] + 1))
      && solids.every((solid, i) => shadeIs(want[i], solid, light, world, margins[i]));
  });
  if (!found) throw new Error(`no pixel in the beam is ${want.join(', then ')}: change the placements compared`);
  return found;
}

/** Margin in world units around an occluder: the hulls' tolerance (1 pixel × scale) and the pixel grids. */
const marginOf = (scale: number) => 1.5 * scale + 1;

describe('Phaser example: occluders from the tilemap and the prop sprite', () => {
  let server: StaticServer;
  let browser: Browser;
  let page: Page;
  let errors: string[];

  beforeAll(async () => {
    server = await serveDirectory('demo-dist');
    browser = await launchChromium();
    ({ page, errors } = await openExample(browser, `${server.url}phaser/`));
  });
  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });

  const setProp = (prop: Prop) => page.evaluate((p) => {
    window.penumbraExample!.setProp(p.position[0], p.position[1], p.rotation, p.scale, p.flipX);
  }, prop);
  const setTiles = (changes: readonly [number, number, boolean][]) => page.evaluate((list) => {
    for (const [x, y, solid] of list) window.penumbraExample!.setTile(x, y, solid);
  }, changes);
  const viewFor = (player: Vec): View => followPlayer(player, WINDOW[0], WINDOW[1], { zoom: 1, scroll: [0, 0] });

  it('lets light through a hole that setTile knocks in a wall, and shadows it again when the tiles are put back', async () => {
    // The player west of the wall at x 400..440 (tile columns 20 and 21), aiming east through it.
    const player: Vec = [370, 300];
    const aim: Vec = [480, 300];
    const view = viewFor(player);
    const parked: Prop = { position: [760, 300], rotation: 0, scale: 1, flipX: false }; // out of the flashlight's range
    await setProp(parked);
    const hole: [number, number, boolean][] = [[20, 14, false], [21, 14, false], [20, 15, false], [21, 15, false]];
    const prop = propSolid(parked);
    const wall = either(tilesSolid(), prop), holed = either(tilesSolid(hole), prop);
    const margin = marginOf(1);
    const pixels = beamPixels(view, player, aim);
    const throughHole = pick(view, player, pixels, [wall, holed], [margin, margin], ['dark', 'lit']);
    const stillWalled = pick(view, player, pixels, [wall, holed], [margin, margin], ['dark', 'dark']);

    await aimAt(page, ...toScreen(view, aim));
    const [before, beside0] = await readAt(page, player, [throughHole, stillWalled]);
    await setTiles(hole);
    const [opened, beside1] = await readAt(page, player, [throughHole, stillWalled]);
    await setTiles(hole.map(([x, y]) => [x, y, true]));
    const [closed, beside2] = await readAt(page, player, [throughHole, stillWalled]);

    expect(brightness(before)).toBeLessThan(DARK);
    expect(brightness(opened)).toBeGreaterThan(LIT);
    expect(brightness(closed)).toBeLessThan(DARK);
    for (const pixel of [beside0, beside1, beside2]) expect(brightness(pixel)).toBeLessThan(DARK);
  });

  describe('the prop sprite\'s shadow', () => {
    // The player west of the prop, in the open floor east of the wall at x 400..440.
    const player: Vec = [455, PROP_POSITION[1]];
    const centre: Vec = [PROP_POSITION[0] + 25, PROP_POSITION[1]];
    const view = viewFor(player);
    const pixels = beamPixels(view, player, centre);

    /** Reads, under placements `a` then `b`, a pixel dark under `a` and lit under `b`, and one the other way round. */
    async function compare(a: Prop, b: Prop): Promise<{ a: Pixel[]; b: Pixel[] }> {
      const walls = tilesSolid();
      const solids = [either(walls, propSolid(a)), either(walls, propSolid(b))];
      const margins = [marginOf(a.scale), marginOf(b.scale)];
      const darkInA = pick(view, player, pixels, solids, margins, ['dark', 'lit']);
      const darkInB = pick(view, player, pixels, solids, margins, ['lit', 'dark']);
      await aimAt(page, ...toScreen(view, centre));
      await setProp(a);
      const inA = await readAt(page, player, [darkInA, darkInB]);
      await setProp(b);
      const inB = await readAt(page, player, [darkInA, darkInB]);
      return { a: inA, b: inB };
    }

    function expectSwapped({ a, b }: { a: Pixel[]; b: Pixel[] }): void {
      expect(brightness(a[0])).toBeLessThan(DARK);
      expect(brightness(a[1])).toBeGreaterThan(LIT);
      expect(brightness(b[0])).toBeGreaterThan(LIT);
      expect(brightness(b[1])).toBeLessThan(DARK);
    }

    it('follows its moves', async () => {
      expectSwapped(await compare(
        { position: centre, rotation: 0, scale: 1, flipX: false },
        { position: [centre[0], centre[1] + 40], rotation: 0, scale: 1, flipX: false },
      ));
    });

    it('follows its rotation (about the frame\'s centre: a half turn takes the star from north to south of it)', async () => {
      expectSwapped(await compare(
        { position: centre, rotation: Math.PI / 2, scale: 1.5, flipX: false },
        { position: centre, rotation: -Math.PI / 2, scale: 1.5, flipX: false },
      ));
    });

    it('follows its scale', async () => {
      // One way only: a larger star covers all the smaller one does.
      const small: Prop = { position: centre, rotation: 0, scale: 1, flipX: false };
      const large: Prop = { position: centre, rotation: 0, scale: 1.6, flipX: false };
      const walls = tilesSolid();
      const solids = [either(walls, propSolid(small)), either(walls, propSolid(large))];
      const margins = [marginOf(small.scale), marginOf(large.scale)];
      const grown = pick(view, player, pixels, solids, margins, ['lit', 'dark']);
      const both = pick(view, player, pixels, solids, margins, ['dark', 'dark']);
      await aimAt(page, ...toScreen(view, centre));
      await setProp(small);
      const [grown0, both0] = await readAt(page, player, [grown, both]);
      await setProp(large);
      const [grown1, both1] = await readAt(page, player, [grown, both]);
      expect(brightness(grown0)).toBeGreaterThan(LIT);
      expect(brightness(grown1)).toBeLessThan(DARK);
      expect(brightness(both0)).toBeLessThan(DARK);
      expect(brightness(both1)).toBeLessThan(DARK);
    });

    it('follows flipX (mirrored within its trimmed frame, so the star moves along its own x axis, here turned to point down)', async () => {
      expectSwapped(await compare(
        { position: centre, rotation: Math.PI / 2, scale: 1, flipX: false },
        { position: centre, rotation: Math.PI / 2, scale: 1, flipX: true },
      ));
    });
  });

  it('places a tilemap layer\'s hulls by its position and scale, rebuilds them when a tile changes, and drops them with the layer', async () => {
    const report = await page.evaluate(() => window.penumbraPhaserOccluders!.tilemap());
    // A ring of 3 × 3 tiles of 20 units is 2 hulls (a hull has no holes); filled, one square.
    expect(report.ringHulls).toBe(2);
    expect(report.ringBounds).toEqual([2000, 3000, 2000 + 3 * 20 * 2, 3000 + 3 * 20 * 2]);
    expect(report.filledHulls).toBe(1);
    expect(report.swappedInRenderer).toBe(true);
    expect(report.movedBounds).toEqual([2100, 3050, 2100 + 3 * 20, 3050 + 3 * 20]);
    expect(report.goneWhenDestroyed).toBe(true);
  });

  it('keeps a sprite\'s hulls with its visibility, display list, frame and container, and drops them with the sprite', async () => {
    const report = await page.evaluate(() => window.penumbraPhaserOccluders!.sprite());
    expect(report.addedToRenderer).toBe(true);
    expect(report.followVisible).toBe(true);
    expect(report.followDisplayList).toBe(true);
    expect(report.replacedOnFrameChange).toBe(true);
    // The container's transform applied to the sprite's: (100, 50) + R(90°) · 2 × (10, 0), turned 90°, scaled 2.
    const [x, y, rotation, scale] = report.inContainer;
    expect([x, y, rotation, scale].map((v) => Math.round(v * 1e6) / 1e6)).toEqual([100, 70, Math.round((Math.PI / 2) * 1e6) / 1e6, 2]);
    expect(report.goneWhenDestroyed).toBe(true);
  });

  it('logs no console errors', () => {
    expect(errors).toEqual([]);
  });
});
