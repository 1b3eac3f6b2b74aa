import { describe, expect, it } from 'vitest';
import { HullGrid } from '../../src/geometry/HullGrid';
import { Hull } from '../../src/index';

/** A small deterministic generator (LCG), so failures reproduce. */
function seededRandom(seed: number): () => number {
  let state = seed;
  return () => (state = (state * 1664525 + 1013904223) >>> 0) / 4294967296;
}

function square(x: number, y: number, size: number): Hull {
  const hull = new Hull([[0, 0], [size, 0], [size, size], [0, size]], { position: [x, y] });
  hull.updateCoarseBounds();
  return hull;
}

/** Builds `grid` over the coarse bounds of the enabled, valid hulls, as the shadow cache does. */
function build(grid: HullGrid, hulls: readonly Hull[], clip = [-Infinity, -Infinity, Infinity, Infinity]): void {
  const bounds = new Float64Array(4 * hulls.length);
  hulls.forEach((hull, i) => bounds.set(hull.coarseBounds, 4 * i));
  grid.build(bounds, Uint8Array.from(hulls, (hull) => (hull.enabled && hull.valid ? 1 : 0)), hulls.length, clip);
}

function bruteForce(hulls: readonly Hull[], box: number[]): number[] {
  const found: number[] = [];
  hulls.forEach((hull, i) => {
    const h = hull.coarseBounds;
    if (hull.enabled && hull.valid && !(h[0] > box[2] || h[2] < box[0] || h[1] > box[3] || h[3] < box[1])) found.push(i);
  });
  return found;
}

describe('HullGrid', () => {
  it('finds exactly the hulls whose bounds overlap a box, each once', () => {
    const random = seededRandom(7);
    const hulls = Array.from({ length: 500 }, () => square(random() * 2000 - 500, random() * 1000, 2 + random() * 120));
    hulls[3].enabled = false;
    const grid = new HullGrid();
    build(grid, hulls);
    for (let q = 0; q < 200; q++) {
      const x = random() * 2400 - 700, y = random() * 1400 - 200, w = random() * 700, h = random() * 700;
      const box = [x, y, x + w, y + h];
      const count = grid.search(box);
      const found = Array.from(grid.found.subarray(0, count)).sort((a, b) => a - b);
      expect(found).toEqual(bruteForce(hulls, box));
    }
  });

  it('finds nothing without hulls, and follows hulls that moved after a rebuild', () => {
    const grid = new HullGrid();
    build(grid, []);
    expect(grid.search([0, 0, 100, 100])).toBe(0);
    const hull = square(0, 0, 10);
    build(grid, [hull]);
    expect(grid.search([0, 0, 5, 5])).toBe(1);
    hull.setPosition(500, 500);
    hull.updateCoarseBounds();
    build(grid, [hull]);
    expect(grid.search([0, 0, 5, 5])).toBe(0);
    expect(grid.search([505, 505, 506, 506])).toBe(1);
    build(grid, [hull], [0, 0, 400, 400]);
    expect(grid.search([505, 505, 506, 506])).toBe(0);
  });
});
