import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { TILE_COLUMNS, TILE_ROWS } from '../../src/shadow/shadowLayout';
import { createContext, destroyContext } from './context';
import { renderLightmap, type Lightmap } from './lightmap';

/**
 * The classification budget (PenumbraRendererOptions.classificationBudget): a light whose hulls do
 * not fit it is drawn wholly with the exact program, one whose moving hulls do not fit has its lit
 * tiles drawn exact, and either way the lightmap is the one an unlimited budget gives.
 */
const W = 96, H = 64;

let gl: WebGL2RenderingContext;
const renderers: PenumbraRenderer[] = [];

beforeEach(() => {
  gl = createContext(W, H);
});

afterEach(() => {
  expect(gl.getError()).toBe(0);
  for (const renderer of renderers.splice(0)) renderer.dispose();
  destroyContext(gl);
});

function create(classificationBudget: number): PenumbraRenderer {
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], classificationBudget });
  renderers.push(renderer);
  return renderer;
}

function maxDifference(a: Lightmap, b: Lightmap): number {
  let max = 0;
  for (let i = 0; i < a.rgb.length; i++) max = Math.max(max, Math.abs(a.rgb[i] - b.rgb[i]));
  return max;
}

/** 2 × 2 posts (one record each) in rows of 10, 9 apart across and `down` apart down, `count` of them from (x, y). */
function posts(renderer: PenumbraRenderer, count: number, x: number, y: number, down: number): void {
  for (let k = 0; k < count; k++) {
    renderer.addHull(new Hull([[-1, -1], [1, -1], [1, 1], [-1, 1]], { position: [x + 9 * (k % 10), y + down * Math.floor(k / 10)] }));
  }
}

describe('classification budget', () => {
  it('draws the lights it leaves unclassified wholly exact, classifies them in later frames, and lights as without a budget', () => {
    const build = (renderer: PenumbraRenderer) => {
      posts(renderer, 30, 6, 10, 20);
      // Every post in range of every light.
      renderer.addLight(new PointLight({ position: [20, 20], range: 100, radius: 3 }));
      renderer.addLight(new PointLight({ position: [70, 40], range: 100, radius: 2 }));
      renderer.addLight(new PointLight({ position: [45, 55], range: 100, radius: 4 }));
    };
    const unlimited = create(Infinity), none = create(0), small = create(31);
    for (const renderer of [unlimited, none, small]) build(renderer);
    const reference = renderLightmap(gl, unlimited, W, H);
    expect(unlimited.stats.lightsUnclassified).toBe(0);
    expect(unlimited.stats.tilesLit).toBeGreaterThan(0);
    // Every tile of the three lights in one class, the posts' penumbrae lean.
    const { tilesLit, tilesDark, tilesExact, tilesOutside, tilesLean } = unlimited.stats;
    expect(tilesLit + tilesDark + tilesExact + tilesOutside).toBe(3 * TILE_COLUMNS * TILE_ROWS);
    expect(tilesLean).toBeGreaterThan(0);
    // Nothing fits a budget of 0: every tile within reach is exact.
    const exact = renderLightmap(gl, none, W, H);
    expect(none.stats.lightsUnclassified).toBe(3);
    expect(none.stats.tilesLit + none.stats.tilesDark).toBe(0);
    expect(maxDifference(exact, reference)).toBeLessThan(1e-3);
    // Each light has all 30 posts in range: one light a frame fits 31.
    const unclassified: number[] = [];
    for (let frame = 0; frame < 4; frame++) {
      const lightmap = renderLightmap(gl, small, W, H);
      unclassified.push(small.stats.lightsUnclassified);
      expect(maxDifference(lightmap, reference), `frame ${frame}`).toBeLessThan(1e-3);
    }
    expect(unclassified).toEqual([2, 1, 0, 0]);
    expect(small.stats.tilesLit).toBe(unlimited.stats.tilesLit);
  });

  it('draws the lit tiles of a light whose moving hulls do not fit exact, and lights as without a budget', () => {
    // A light crossing the room, all 20 posts in range, is filed anew every frame and spends most of
    // the budget: the crates moving past it and past the second light do not fit.
    const runner = (renderer: PenumbraRenderer) => renderer.addLight(new PointLight({ position: [10, 20], range: 100, radius: 2 }));
    const build = (renderer: PenumbraRenderer) => {
      posts(renderer, 20, 4, 4, 8);
      renderer.addLight(new PointLight({ position: [70, 50], range: 30, radius: 2 }));
      return [0, 1, 2, 3].map((i) => renderer.addHull(new Hull([[-2, -2], [2, -2], [2, 2], [-2, 2]], { position: [56 + 8 * i, 40] })));
    };
    const limited = create(22), unlimited = create(Infinity);
    const lights = [runner(limited), runner(unlimited)];
    const crates = [build(limited), build(unlimited)];
    let fewerLit = 0;
    for (let frame = 0; frame < 12; frame++) {
      for (const light of lights) light.setPosition(10 + 7 * frame, 20);
      // Edges off the pixel centres: a pixel centre on a hull's edge is inside it or not by rounding,
      // which differs between draws of different rectangles.
      for (const set of crates) set.forEach((crate, i) => (crate.position = [56 + 8 * i, 40.2 + 0.5 * frame]));
      const kept = renderLightmap(gl, limited, W, H), reference = renderLightmap(gl, unlimited, W, H);
      if (limited.stats.tilesLit < unlimited.stats.tilesLit) fewerLit++;
      expect(maxDifference(kept, reference), `frame ${frame}`).toBeLessThan(1e-3);
    }
    expect(fewerLit).toBeGreaterThan(5);
  });

  it('draws an unclassified light\'s tiles lean unless a hull, still or moving, may reach into its disk, and lights as without a budget', () => {
    // Two lights among posts, apart from them; a crate that walks into the second light's disk and
    // out again. With no budget both stay unclassified.
    const build = (renderer: PenumbraRenderer) => {
      posts(renderer, 20, 6, 8, 16);
      renderer.addLight(new PointLight({ position: [20, 20], range: 100, radius: 3 }));
      renderer.addLight(new PointLight({ position: [70, 44], range: 100, radius: 4 }));
      return renderer.addHull(new Hull([[-2, -2], [2, -2], [2, 2], [-2, 2]], { position: [84, 44.3] }));
    };
    const none = create(0), unlimited = create(Infinity);
    const crates = [build(none), build(unlimited)];
    const leanShares: number[] = [];
    for (let frame = 0; frame < 8; frame++) {
      // Frames 2–5: the crate's corner within the disk (radius 4 around x = 70): x from 84 down to 73.
      const x = [84, 80, 74, 73, 73, 74, 80, 84][frame];
      for (const crate of crates) crate.position = [x, 44.3];
      const lightmap = renderLightmap(gl, none, W, H), reference = renderLightmap(gl, unlimited, W, H);
      expect(none.stats.lightsUnclassified).toBe(2);
      leanShares.push(none.stats.tilesLean / none.stats.tilesExact);
      expect(maxDifference(lightmap, reference), `frame ${frame}`).toBeLessThan(1e-3);
    }
    // Both lights lean but while the crate reaches into the second one's disk (general there).
    expect(leanShares.map((share) => share === 1)).toEqual([true, true, false, false, false, false, true, true]);
    // Hulls still in the disk keep its light's tiles general: one box (the closed program), two
    // boxes (the general one, as each may be seen past).
    for (const inDisk of [[[73, 44.3]], [[73, 44.3], [66.7, 43.1]]]) {
      const [still, stillReference] = [create(0), create(Infinity)];
      for (const renderer of [still, stillReference]) {
        posts(renderer, 20, 6, 8, 16);
        for (const position of inDisk) renderer.addHull(new Hull([[-2, -2], [2, -2], [2, 2], [-2, 2]], { position: position as [number, number] }));
        renderer.addLight(new PointLight({ position: [70, 44], range: 100, radius: 4 }));
      }
      const lightmap = renderLightmap(gl, still, W, H);
      expect(still.stats.tilesLean).toBe(0);
      expect(maxDifference(lightmap, renderLightmap(gl, stillReference, W, H)), `${inDisk.length} in the disk`).toBeLessThan(1e-3);
    }
  });

  it('rejects a budget that is not a non-negative integer, naming it', () => {
    for (const bad of [-1, 0.5, Number.NaN, '8' as unknown as number]) {
      expect(() => new PenumbraRenderer(gl, { classificationBudget: bad })).toThrow(/classificationBudget must be a non-negative integer or Infinity, got/);
    }
  });
});
