import { describe, expect, it } from 'vitest';
import { LightTiles } from '../../src/shadow/LightTiles';
import { SHADOW_TYPE_CODES, TILE_CLASS_COUNT, TILE_CLASSES, TILE_COLUMNS, TILE_ROWS } from '../../src/shadow/shadowLayout';
import { ShadowGeometry } from '../../src/shadow/ShadowGeometry';
import { Hull } from '../../src/index';
import { createRandom } from '../reference/randomScenes';
import { box } from '../reference/scenes';
import { check, classify, convexAround, type Case } from './lightTilesSupport';

// Each class against disk sampling (check, in lightTilesSupport.ts) on scenes made for it; the
// same over random scenes is test/accuracy/lightTiles.test.ts.

describe('LightTiles', () => {
  it('classifies a box before a light: lit beside it, dark behind it, exact in its penumbra', () => {
    const c: Case = { hulls: [box(120, 90, 20, 20)], centre: [100, 100], radius: 4, reach: 80, solid: true };
    const { wrong, counts } = check(c);
    expect(wrong).toEqual([]);
    expect(counts[TILE_CLASSES.lit]).toBeGreaterThan(500);
    expect(counts[TILE_CLASSES.dark]).toBeGreaterThan(20);
    expect(counts[TILE_CLASSES.outside]).toBeGreaterThan(150);
    // Its penumbra is lean, its one record listed: no record meets the disk.
    expect(counts[TILE_CLASSES.listed]).toBeGreaterThan(20);
    expect(counts[TILE_CLASSES.lean]).toBe(0);
    expect(counts[TILE_CLASSES.exact]).toBe(0);
  });

  it('draws every exact tile with the general program when a hull meets the disk, and tiles with a hull in them for an Occluded light', () => {
    const wall = box(104, 60, 20, 80);
    const torch = check({ hulls: [wall, box(150, 150, 10, 10)], centre: [100, 100], radius: 6, reach: 80, solid: true });
    expect(torch.wrong).toEqual([]);
    expect(torch.counts[TILE_CLASSES.lean] + torch.counts[TILE_CLASSES.listed]).toBe(0);
    expect(torch.counts[TILE_CLASSES.exact]).toBeGreaterThan(0);
    const crate = box(140, 95, 10, 10);
    const occluded = check({ hulls: [crate], centre: [100, 100], radius: 4, reach: 80, solid: false, occluded: true });
    const illuminated = check({ hulls: [crate], centre: [100, 100], radius: 4, reach: 80, solid: false });
    expect(occluded.wrong).toEqual([]);
    expect(occluded.counts[TILE_CLASSES.exact]).toBeGreaterThan(0);
    expect(occluded.counts[TILE_CLASSES.held]).toBe(0);
    expect(illuminated.counts[TILE_CLASSES.exact]).toBe(0);
    expect(illuminated.counts[TILE_CLASSES.listed]).toBeGreaterThan(0);
  });

  it('draws no exact tile for a disk wholly inside a hull but for an Occluded light: dark, and held where a hull is for an Illuminated one', () => {
    // A torch inside a closed door, a crate before it.
    const hulls = [box(90, 94, 40, 12), box(140, 90, 10, 10)];
    const solid = check({ hulls, centre: [110, 100], radius: 5, reach: 80, solid: true });
    expect(solid.wrong).toEqual([]);
    expect(solid.counts[TILE_CLASSES.dark] + solid.counts[TILE_CLASSES.outside]).toBe(TILE_COLUMNS * TILE_ROWS);
    const illuminated = check({ hulls, centre: [110, 100], radius: 5, reach: 80, solid: false });
    expect(illuminated.wrong).toEqual([]);
    expect(illuminated.counts[TILE_CLASSES.lean] + illuminated.counts[TILE_CLASSES.listed] + illuminated.counts[TILE_CLASSES.exact]).toBe(0);
    expect(illuminated.counts[TILE_CLASSES.held]).toBeGreaterThan(0);
    const occluded = check({ hulls, centre: [110, 100], radius: 5, reach: 80, solid: false, occluded: true });
    expect(occluded.wrong).toEqual([]);
    expect(occluded.counts[TILE_CLASSES.exact]).toBeGreaterThan(0);
    // Reaching out of the door, the disk is seen past it: exact tiles.
    const peeking = check({ hulls, centre: [110, 100], radius: 7, reach: 80, solid: true });
    expect(peeking.wrong).toEqual([]);
    expect(peeking.counts[TILE_CLASSES.exact]).toBeGreaterThan(0);
  });

  it('holds dark tiles with a hull in them for a light that lights the inside of hulls', () => {
    const hulls = [box(120, 80, 10, 40), box(160, 95, 8, 8)];
    const solid = classify({ hulls, centre: [100, 100], radius: 3, reach: 90, solid: true }).classes;
    const lit = classify({ hulls, centre: [100, 100], radius: 3, reach: 90, solid: false }).classes;
    // A tile across the crate's lower edge, behind the wall: dark for a Solid light, held (lit
    // inside the crate) for an Illuminated one (a tile wholly inside the crate is lit).
    const bounds = [10, 10];
    const tile = Math.floor((95.5 - bounds[1]) / (180 / TILE_ROWS)) * TILE_COLUMNS + Math.floor((164 - bounds[0]) / (180 / TILE_COLUMNS));
    expect(solid[tile]).toBe(TILE_CLASSES.dark);
    expect(lit[tile]).toBe(TILE_CLASSES.held);
  });

  it('lights the tiles wholly inside a hull for an Illuminated light, in a wall\'s shadow or in its penumbra', () => {
    // A torch before a wall, a large block behind the wall and one beside its edge.
    const hulls = [box(120, 70, 8, 60), box(150, 80, 40, 40), box(140, 140, 40, 30)];
    const c: Case = { hulls, centre: [100, 100], radius: 4, reach: 100, solid: false };
    const { wrong, counts } = check(c);
    expect(wrong).toEqual([]);
    const { classes, bounds } = classify(c);
    const tw = (bounds[2] - bounds[0]) / TILE_COLUMNS, th = (bounds[3] - bounds[1]) / TILE_ROWS;
    const tileAt = (x: number, y: number) => classes[Math.floor((y - bounds[1]) / th) * TILE_COLUMNS + Math.floor((x - bounds[0]) / tw)];
    // Well inside each block: lit; a Solid light's are dark and exact there.
    expect(tileAt(170, 100)).toBe(TILE_CLASSES.lit);
    expect(tileAt(160, 155)).toBe(TILE_CLASSES.lit);
    const solid = classify({ ...c, solid: true }).classes;
    expect(solid[Math.floor((100 - bounds[1]) / th) * TILE_COLUMNS + Math.floor((170 - bounds[0]) / tw)]).toBe(TILE_CLASSES.dark);
    expect(counts[TILE_CLASSES.lit]).toBeGreaterThan(0);
  });
});

describe('LightTiles rectangles', () => {
  /** The class each tile of `row` is drawn in by the row's rectangles (−1 where none, −2 where several). */
  function drawnClasses(tiles: LightTiles, row: number): Int8Array {
    const drawn = new Int8Array(TILE_COLUMNS * TILE_ROWS).fill(-1);
    const lists = new Int32Array(2 * TILE_CLASS_COUNT);
    tiles.writeLists(row, lists);
    for (let c = 0; c < TILE_CLASS_COUNT; c++) {
      for (let k = lists[2 * c]; k < lists[2 * c] + lists[2 * c + 1]; k += 3) {
        const corners = [0, 1, 2].map((v) => tiles.rectangles[k + v]).map((index) => [index % (TILE_COLUMNS + 1), Math.floor(index / (TILE_COLUMNS + 1))]);
        // Each triangle is half a rectangle: its tiles are those whose centre lies inside it, moved
        // off the diagonals by an irrational step.
        for (let j = 0; j < TILE_ROWS; j++) {
          for (let i = 0; i < TILE_COLUMNS; i++) {
            if (!insideTriangle(corners, i + 0.5, j + 0.5 + 0.01 * Math.SQRT2)) continue;
            const tile = j * TILE_COLUMNS + i;
            drawn[tile] = drawn[tile] === -1 ? c : -2;
          }
        }
      }
    }
    return drawn;
  }

  function insideTriangle(corners: number[][], x: number, y: number): boolean {
    const side = (a: number[], b: number[]) => Math.sign((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]));
    const s = [side(corners[0], corners[1]), side(corners[1], corners[2]), side(corners[2], corners[0])];
    return s.every((v) => v >= 0) || s.every((v) => v <= 0);
  }

  it('draws every tile once in its class, and none outside the reach, as classes change frame to frame', () => {
    const random = createRandom(11);
    const geometry = new ShadowGeometry();
    const hulls = Array.from({ length: 8 }, () => new Hull(convexAround(random, 200 + (random() - 0.5) * 200, 200 + (random() - 0.5) * 200, 4 + random() * 12)));
    geometry.update(hulls);
    const indices = Int32Array.from(hulls.keys());
    for (const i of indices) geometry.prepare(i);
    const tiles = new LightTiles();
    const bounds = Float64Array.of(80, 80, 320, 320);
    for (let row = 0; row < 3; row++) {
      tiles.beginLight(bounds, Float64Array.of(200 + 10 * row, 200, 3 + 4 * row, 120), true, SHADOW_TYPE_CODES.solid);
      tiles.addStillHulls(geometry, indices, 4);
      tiles.endLight(row);
      tiles.beginLight(bounds, Float64Array.of(200 + 10 * row, 200, 3 + 4 * row, 120), true, row === 1 ? SHADOW_TYPE_CODES.occluded : SHADOW_TYPE_CODES.solid);
      tiles.addMovingHulls(row, geometry, indices.subarray(4), 4);
    }
    for (let row = 0; row < 3; row++) {
      const drawn = drawnClasses(tiles, row);
      const wrong: string[] = [];
      for (let tile = 0; tile < TILE_COLUMNS * TILE_ROWS; tile++) {
        const value = tiles.tileClass(row, tile), expected = value === TILE_CLASSES.outside ? -1 : value;
        if (drawn[tile] !== expected) wrong.push(`row ${row} tile ${tile}: class ${value}, drawn ${drawn[tile]}`);
      }
      expect(wrong.slice(0, 5)).toEqual([]);
    }
  });
});
