import { describe, expect, it } from 'vitest';
import { TILE_CLASSES } from '../../src/shadow/shadowLayout';
import { createRandom } from '../reference/randomScenes';
import { box, type Point } from '../reference/scenes';
import { check, convexAround } from '../unit/lightTilesSupport';

// The tile classes against disk sampling (check, in test/unit/lightTilesSupport.ts) over random
// scenes; the scenes made for each class are test/unit/lightTiles.test.ts.

describe('LightTiles', () => {
  it('never calls a tile lit, dark, held, lean or listed wrongly in random scenes (disks of radius 0 to 30, walls, posts, overlapping disks)', () => {
    const random = createRandom(7);
    let lit = 0, dark = 0, lean = 0, held = 0, listed = 0;
    for (let scene = 0; scene < 30; scene++) {
      const centre: Point = [200, 200];
      const radius = scene % 5 === 0 ? 0 : random() * 30;
      const hulls: Point[][] = [];
      for (let k = 0, n = 1 + Math.floor(random() * 6); k < n; k++) {
        const x = 200 + (random() - 0.5) * 240, y = 200 + (random() - 0.5) * 240;
        if (k % 3 === 2) hulls.push(box(x, y, 2 + random() * 4, 30 + random() * 60)); // a thin wall
        else hulls.push(convexAround(random, x, y, 3 + random() * 20));
      }
      const { wrong, counts } = check({ hulls, centre, radius, reach: 150, solid: scene % 2 === 0, occluded: scene % 4 === 1 });
      expect(wrong.slice(0, 3), `scene ${scene}`).toEqual([]);
      lit += counts[TILE_CLASSES.lit];
      dark += counts[TILE_CLASSES.dark];
      lean += counts[TILE_CLASSES.lean] + counts[TILE_CLASSES.listed];
      listed += counts[TILE_CLASSES.listed];
      held += counts[TILE_CLASSES.held];
    }
    // Not everything exact: the classification must decide most of the light's area.
    expect(lit).toBeGreaterThan(30 * 300);
    expect(dark).toBeGreaterThan(30 * 5);
    expect(lean).toBeGreaterThan(30 * 20);
    expect(listed).toBeGreaterThan(lean / 2);
    expect(held).toBeGreaterThan(0);
  });
});
