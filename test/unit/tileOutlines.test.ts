import { describe, expect, it } from 'vitest';
import { holeFreeRegions, type CellGrid } from '../../src/geometry/gridRegions';
import { traceOutlines } from '../../src/geometry/tileOutlines';
import { isInsidePolygon, isSimplePolygon, signedArea2 } from '../../src/geometry/polygon';
import { randomGrid, textGrid } from './gridSupport';
import { createRandom } from '../reference/randomScenes';

/**
 * Traces every region and checks each outline against the labels it came from: simple, positive
 * area equal to its cell count, no collinear points, every point on the cell lattice, and
 * exactly its own cells' centres inside it.
 */
function checkOutlines(grid: CellGrid): number[][] {
  const { labels, count } = holeFreeRegions(grid);
  const outlines = traceOutlines(labels, grid.width, grid.height, count);
  expect(outlines.length).toBe(count);
  const cells = new Array<number>(count).fill(0);
  for (const label of labels) if (label >= 0) cells[label]++;
  const wrong: string[] = [];
  outlines.forEach((outline, label) => {
    if (!isSimplePolygon(outline)) wrong.push(`region ${label} is not simple: ${outline.join(',')}`);
    if (signedArea2(outline) / 2 !== cells[label]) wrong.push(`region ${label} has area ${signedArea2(outline) / 2}, not ${cells[label]}`);
    const n = outline.length / 2;
    for (let i = 0; i < n; i++) {
      const px = outline[2 * ((i + n - 1) % n)], py = outline[2 * ((i + n - 1) % n) + 1];
      const x = outline[2 * i], y = outline[2 * i + 1];
      const qx = outline[2 * ((i + 1) % n)], qy = outline[2 * ((i + 1) % n) + 1];
      if (!Number.isInteger(x) || !Number.isInteger(y)) wrong.push(`point ${i} of region ${label} is off the lattice`);
      if ((x - px) * (qy - y) - (y - py) * (qx - x) === 0) wrong.push(`point ${i} of region ${label} is no corner`);
    }
  });
  for (let y = 0; y < grid.height; y++) {
    for (let x = 0; x < grid.width; x++) {
      const label = labels[y * grid.width + x];
      outlines.forEach((outline, other) => {
        if (isInsidePolygon(outline, [x + 0.5, y + 0.5]) !== (label === other)) wrong.push(`cell (${x}, ${y}) ${label === other ? 'outside' : 'inside'} region ${other}`);
      });
    }
  }
  expect(wrong, `outlines of ${grid.width} × ${grid.height} cells`).toEqual([]);
  return outlines;
}

describe('traceOutlines', () => {
  it('traces a cell, a wall and an L with one point per corner, counter-clockwise', () => {
    expect(checkOutlines(textGrid(['#']))).toEqual([[0, 0, 1, 0, 1, 1, 0, 1]]);
    expect(checkOutlines(textGrid(['.....', '.....', '..####']))).toEqual([[2, 2, 6, 2, 6, 3, 2, 3]]);
    expect(checkOutlines(textGrid(['#..', '#..', '###']))).toEqual([[0, 0, 1, 0, 1, 2, 3, 2, 3, 3, 0, 3]]);
  });

  it('traces a 16-tile wall as 4 points and a room as 2 simple outlines', () => {
    expect(checkOutlines(textGrid(['################']))[0].length).toBe(8);
    expect(checkOutlines(textGrid(['######', '#....#', '#....#', '#....#', '######']))).toHaveLength(2);
  });

  it('traces regions that share edges and points with their neighbours', () => {
    checkOutlines(textGrid(['#.#', '.#.', '#.#']));
    checkOutlines(textGrid(['##.', '#.#', '###']));
    checkOutlines(textGrid(['#########', '#.......#', '#.#####.#', '#.#...#.#', '#.#####.#', '#.......#', '#########']));
  });

  it('traces random grids (400, seeded): simple outlines covering exactly their cells', () => {
    const random = createRandom(3);
    for (let k = 0; k < 400; k++) {
      const width = 1 + Math.floor(random() * 16), height = 1 + Math.floor(random() * 16);
      checkOutlines(randomGrid(width, height, 0.2 + 0.7 * random(), random));
    }
  });
});
