import type { Page } from 'puppeteer';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openBuiltPage, type BuiltPage } from './builtPage';
import { ALBEDO, AMBIENT, ELEVATION, FLAT_TEXEL, GROUPED, NORMAL_TEXEL, SPRITES, TILES, TOP_TEXEL, type Engine, type NormalsState } from './engine-normals-page/contract';

// Normal maps in the real PixiJS and Phaser integrations, against the formula of docs/normal-maps.md
// computed here: a sprite of uniform normal (N) lit by a directional light shows
//   255 × albedo × (ambient + max(0, N·L))                       (coverage 1, no highlight)
// with N its map's normal turned by the sprite's rotation and mirroring, L the light's direction;
// a sprite without a normal map (P), and one drawn over a normal-mapped one (E), show
//   255 × albedo × (ambient + 1)                                 (lit as without normals).
//
// Tolerance, 3 steps of 8 bits: the normal target stores the turned normal in 8 bits a channel
// (½ step each, N·L within 0.006), which the albedo (200) turns into at most 1.2 steps; the lightmap
// is half float (a relative error under 2⁻¹⁰, ¼ step here) and the product is rounded once (½ step).
// The expected N uses the map's texel as stored (8 bits), so the map's own quantization is not an error.
// Lit from the other side, the values differ by 100 to 140 steps: far beyond the tolerance.

const TOLERANCE = 3;
const LIT_FLAT = 255 * (ALBEDO / 255) * (AMBIENT + 1);

let built: BuiltPage;
let page: Page;
let errors: string[];

type Vec = readonly [number, number];
const BASE: NormalsState = { rotation: 0, mirrored: false, lightRotation: Math.PI, groupLightRotation: 0, gpuTilemap: false, scroll: [0, 0], zoom: 1 };
/** Light travelling west (from the east), east, south (from the north) and north (from the south). */
const FROM_EAST = Math.PI, FROM_WEST = 0, FROM_NORTH = Math.PI / 2, FROM_SOUTH = -Math.PI / 2;

/** A map's normal in image axes (x right, y down), decoded from its texel as the surface helper does (green up). */
function imageNormal(texel: readonly [number, number, number]): readonly [number, number, number] {
  const [x, y, z] = texel.map((byte) => (byte / 255) * 2 - 1);
  const length = Math.hypot(x, y, z);
  return [x / length, -y / length, z / length] as const;
}
const IMAGE_NORMAL = imageNormal(NORMAL_TEXEL);

/** N·L for `normal` (image axes) on a sprite turned by `rotation`, mirrored left–right or not, lit by a light travelling along `lightRotation`. */
function nDotL(rotation: number, mirrored: boolean, lightRotation: number, normal = IMAGE_NORMAL): number {
  const ix = mirrored ? -normal[0] : normal[0], iy = normal[1];
  const nx = Math.cos(rotation) * ix - Math.sin(rotation) * iy;
  const ny = Math.sin(rotation) * ix + Math.cos(rotation) * iy;
  const l = [-Math.cos(lightRotation) * Math.cos(ELEVATION), -Math.sin(lightRotation) * Math.cos(ELEVATION), Math.sin(ELEVATION)];
  return nx * l[0] + ny * l[1] + normal[2] * l[2];
}

/** The formula for a sprite of uniform `normal` under one directional light along `lightRotation`. */
function litBy(lightRotation: number, { rotation = 0, mirrored = false, normal = IMAGE_NORMAL } = {}): number {
  return 255 * (ALBEDO / 255) * (AMBIENT + Math.max(0, nDotL(rotation, mirrored, lightRotation, normal)));
}

function expectedLit(state: NormalsState): number {
  return litBy(state.lightRotation, state);
}

/** Canvas pixels of a sprite's middle: its centre and 6 world units around it (inside its 24 units). */
function around(state: NormalsState, [x, y]: Vec): [number, number][] {
  return [[0, 0], [-6, -6], [6, -6], [-6, 6], [6, 6]].map(([dx, dy]) => [
    Math.floor((x + dx - state.scroll[0]) * state.zoom), Math.floor((y + dy - state.scroll[1]) * state.zoom),
  ]);
}

/** Reads the three sprites' middles under `state`: the red channel of each point (grey light on grey sprites). */
async function read(engine: Engine, state: NormalsState): Promise<{ normal: number[]; plain: number[]; erased: number[] }> {
  const points = [...around(state, SPRITES.normal), ...around(state, SPRITES.plain), ...around(state, SPRITES.erased)];
  const pixels = await page.evaluate((e, s, p) => window.engineNormals!.read(e, s, p), engine, state, points);
  const red = pixels.map((pixel) => pixel[0]);
  return { normal: red.slice(0, 5), plain: red.slice(5, 10), erased: red.slice(10, 15) };
}

function expectNear(values: number[], expected: number, what: string): void {
  for (const value of values) expect(Math.abs(value - expected), `${what}: ${values.join(', ')} vs ${expected.toFixed(1)}`).toBeLessThanOrEqual(TOLERANCE);
}

beforeAll(async () => {
  built = await openBuiltPage('engine-normals-page', 'engineNormals');
  ({ page, pageErrors: errors } = built);
}, 300_000);

afterAll(async () => {
  await built?.close();
});

for (const engine of ['pixi', 'phaser'] as const) {
  describe(`normal maps in the ${engine === 'pixi' ? 'PixiJS layer' : 'Phaser plugin'}`, () => {
    it('lights a normal-mapped sprite through its normal: brighter from the side it faces, as the formula says', async () => {
      const east = { ...BASE, lightRotation: FROM_EAST }, west = { ...BASE, lightRotation: FROM_WEST };
      const fromEast = await read(engine, east);
      const fromWest = await read(engine, west);
      expectNear(fromEast.normal, expectedLit(east), 'from the east');
      expectNear(fromWest.normal, expectedLit(west), 'from the west');
      // The map faces east: lit from the east it is brighter, in the formula's ratio.
      expect(expectedLit(east) - expectedLit(west)).toBeGreaterThan(100);
      expect(fromEast.normal[0] / fromWest.normal[0]).toBeCloseTo(expectedLit(east) / expectedLit(west), 1);
    });

    it('turns the normal with a rotated sprite', async () => {
      // Turned a quarter clockwise (y down), the map faces south instead of east.
      for (const lightRotation of [FROM_EAST, FROM_SOUTH, FROM_NORTH]) {
        const state = { ...BASE, rotation: Math.PI / 2, lightRotation };
        expectNear((await read(engine, state)).normal, expectedLit(state), `rotated, light ${lightRotation.toFixed(2)}`);
      }
      const south = expectedLit({ ...BASE, rotation: Math.PI / 2, lightRotation: FROM_SOUTH });
      expect(south - expectedLit({ ...BASE, rotation: Math.PI / 2, lightRotation: FROM_NORTH })).toBeGreaterThan(100);
    });

    it('mirrors the normal with a mirrored sprite', async () => {
      // Mirrored, the map faces west.
      for (const lightRotation of [FROM_EAST, FROM_WEST]) {
        const state = { ...BASE, mirrored: true, lightRotation };
        expectNear((await read(engine, state)).normal, expectedLit(state), `mirrored, light ${lightRotation.toFixed(2)}`);
      }
      expect(expectedLit({ ...BASE, mirrored: true, lightRotation: FROM_WEST }) - expectedLit({ ...BASE, mirrored: true, lightRotation: FROM_EAST })).toBeGreaterThan(100);
    });

    it('lights a sprite without a normal map, and one drawn over a normal-mapped sprite, exactly as without normals', async () => {
      const fromEast = await read(engine, { ...BASE, lightRotation: FROM_EAST });
      const fromWest = await read(engine, { ...BASE, lightRotation: FROM_WEST });
      expectNear(fromEast.plain, LIT_FLAT, 'plain');
      // Exactly: the same pixels whichever way the light comes, and the covered sprite's as the plain one's.
      expect(fromWest.plain).toEqual(fromEast.plain);
      expect(fromEast.erased).toEqual(fromEast.plain);
      expect(fromWest.erased).toEqual(fromWest.plain);
    });

    it('keeps the normal pass on the sprites as the camera pans and zooms', async () => {
      for (const view of [{ scroll: [-20, 10] as [number, number], zoom: 1 }, { scroll: [10, 15] as [number, number], zoom: 1.5 }]) {
        for (const lightRotation of [FROM_EAST, FROM_WEST]) {
          const state = { ...BASE, ...view, lightRotation };
          const pixels = await read(engine, state);
          expectNear(pixels.normal, expectedLit(state), `scroll ${view.scroll}, zoom ${view.zoom}`);
          expectNear(pixels.plain, LIT_FLAT, `plain, scroll ${view.scroll}, zoom ${view.zoom}`);
        }
      }
    });

    it('lights a normal-mapped sprite in a lit group through its normal, with the group\'s lights only', async () => {
      // The world's light comes from the other side each time: the group's sprite follows its own light.
      for (const [groupLight, worldLight] of [[FROM_EAST, FROM_WEST], [FROM_WEST, FROM_EAST], [FROM_NORTH, FROM_SOUTH]]) {
        const state = { ...BASE, lightRotation: worldLight, groupLightRotation: groupLight };
        const points = around(state, GROUPED);
        const red = (await page.evaluate((e, s, p) => window.engineNormals!.read(e, s, p), engine, state, points)).map((pixel) => pixel[0]);
        expectNear(red, litBy(groupLight), `grouped, group light ${groupLight.toFixed(2)}`);
      }
      expect(litBy(FROM_EAST) - litBy(FROM_WEST)).toBeGreaterThan(100);
    });

    it('makes no GL object per frame', async () => {
      await read(engine, BASE);
      expect(await page.evaluate((e) => window.engineNormals!.created(e, 4), engine)).toBe(0);
    });

    it('lights a normal-mapped sprite as before after the context is lost and restored, skipping the frames in between', async () => {
      // Lit from the west the normal-mapped sprite is far darker than lit flat: a normal pass that
      // lost its GL objects (no normals read: flat) or threw cannot pass for it.
      const state = { ...BASE, lightRotation: FROM_WEST };
      // The world's sprites, the lit group's sprite and (Phaser) the tiles.
      const points = [...around(state, SPRITES.normal), ...around(state, SPRITES.plain), ...around(state, GROUPED), ...around(state, TILES.mapped)];
      const report = await page.evaluate((e, s, p) => window.engineNormals!.acrossContextLoss(e, s, p), engine, state, points);
      expect(report.lostFrameErrors).toEqual([]);
      const red = (pixels: number[][]) => pixels.map((pixel) => pixel[0]);
      expectNear(red(report.before).slice(0, 5), expectedLit(state), 'before the loss');
      expectNear(red(report.before).slice(10, 15), litBy(state.groupLightRotation), 'grouped, before the loss');
      expect(red(report.after)).toEqual(red(report.before));
      // None of the stale GL objects of the lost context used by the first frame after.
      expect(report.glErrors).toEqual([]);
    });
  });
}

describe('normal maps of Phaser tilemap layers', () => {
  it.each([['TilemapLayer', false], ['TilemapGPULayer', true]])('lights each tile of a %s through its tileset\'s normal map (the texture\'s data source), flipped tiles mirrored, rotated tiles turned', async (_, gpuTilemap) => {
    const flat = imageNormal(FLAT_TEXEL), top = imageNormal(TOP_TEXEL);
    // Unmoved, then panned and zoomed (the tiles Phaser draws are the tiles in sight).
    const views = [{ scroll: [0, 0] as [number, number], zoom: 1 }, { scroll: [40, 40] as [number, number], zoom: 1.25 }];
    for (const [view, lightRotation] of views.flatMap((v) => [FROM_EAST, FROM_WEST, FROM_NORTH].map((l) => [v, l] as const))) {
      const state = { ...BASE, ...view, lightRotation, gpuTilemap };
      const points = [...around(state, TILES.mapped), ...around(state, TILES.flipped), ...around(state, TILES.flat), ...around(state, TILES.rotated)];
      const red = (await page.evaluate((p) => window.engineNormals!.read('phaser', p.state, p.points), { state, points })).map((pixel) => pixel[0]);
      const at = `light ${lightRotation.toFixed(2)}, scroll ${view.scroll}, zoom ${view.zoom}`;
      expectNear(red.slice(0, 5), litBy(lightRotation), `tile, ${at}`);
      expectNear(red.slice(5, 10), litBy(lightRotation, { mirrored: true }), `flipped tile, ${at}`);
      // The second tile: its top two points (6 units up) in its top rows, the centre and the bottom two below them.
      const second = red.slice(10, 15);
      expectNear([second[1], second[2]], litBy(lightRotation, { normal: top }), `second tile's top, ${at}`);
      expectNear([second[0], second[3], second[4]], litBy(lightRotation, { normal: flat }), `second tile, ${at}`);
      expectNear(red.slice(15, 20), litBy(lightRotation, { rotation: gpuTilemap ? 0 : Math.PI / 2 }), `rotated tile, ${at}`);
    }
    // Lit from the two sides, the tile and its flipped copy swap, far beyond the tolerance.
    expect(litBy(FROM_EAST) - litBy(FROM_WEST)).toBeGreaterThan(100);
    expect(Math.abs(litBy(FROM_EAST, { normal: flat }) - (ALBEDO / 255) * 255 * (AMBIENT + 1))).toBeGreaterThan(30);
    // A tile drawn upside down would show its top rows below: lit from the north they differ by far.
    expect(litBy(FROM_NORTH, { normal: top }) - litBy(FROM_NORTH, { normal: flat })).toBeGreaterThan(30);
  });
});

it('logs no console errors', () => {
  expect(errors).toEqual([]);
});
