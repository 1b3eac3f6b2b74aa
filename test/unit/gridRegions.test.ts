import { describe, expect, it } from 'vitest';
import { holeFreeRegions, type CellGrid } from '../../src/geometry/gridRegions';
import { cellsByLabel, components4, isDisk, randomGrid, textGrid } from './gridSupport';
import { createRandom } from '../reference/randomScenes';

/**
 * Checks every promise of holeFreeRegions against independent floods: each solid cell labelled
 * and no empty one, every label used, each region a disk (4-connected, its complement
 * 4-connected to the outside), and a 4-connected group that is already a disk left whole.
 */
function checkRegions(grid: CellGrid): { count: number; labels: Int32Array } {
  const { labels, count } = holeFreeRegions(grid);
  expect(labels.length).toBe(grid.width * grid.height);
  const wrong: string[] = [];
  for (let y = 0; y < grid.height; y++) {
    for (let x = 0; x < grid.width; x++) {
      const label = labels[y * grid.width + x];
      if (grid.solid(x, y) ? !(label >= 0 && label < count) : label !== -1) wrong.push(`${grid.solid(x, y) ? 'solid' : 'empty'} cell (${x}, ${y}) labelled ${label}`);
    }
  }
  const regions = cellsByLabel(labels, grid.width, count);
  regions.forEach((cells, i) => {
    if (!isDisk(cells)) wrong.push(`region ${i} is no disk: ${JSON.stringify(cells.slice(0, 8))}`);
  });
  for (const component of components4(grid)) {
    if (!isDisk(component)) continue;
    const label = labels[component[0][1] * grid.width + component[0][0]];
    if (!component.every(([x, y]) => labels[y * grid.width + x] === label) || regions[label].length !== component.length) {
      wrong.push(`the disk at (${component[0].join(', ')}) is not one region`);
    }
  }
  expect(wrong, `regions of ${grid.width} × ${grid.height} cells`).toEqual([]);
  return { count, labels };
}

describe('holeFreeRegions', () => {
  it('leaves an empty grid, and a grid of no size, without regions', () => {
    expect(checkRegions(textGrid(['...', '...'])).count).toBe(0);
    expect(holeFreeRegions({ width: 0, height: 0, solid: () => true }).count).toBe(0);
    expect(holeFreeRegions({ width: 5, height: 0, solid: () => true }).count).toBe(0);
  });

  it('keeps a wall, a block, a comb and a spiral (all without holes) as one region each', () => {
    expect(checkRegions(textGrid(['################'])).count).toBe(1);
    expect(checkRegions(textGrid(['####', '####', '####'])).count).toBe(1);
    expect(checkRegions(textGrid(['#.#.#.#', '#.#.#.#', '#######', '.#.#.#.', '.#.#.#.'])).count).toBe(1);
    expect(checkRegions(textGrid([
      '#########',
      '#.......#',
      '#.#####.#',
      '#.#...#.#',
      '#.#.#.#.#',
      '#.#.###.#',
      '#.#.....#',
      '#.#######',
    ])).count).toBe(1);
  });

  it('cuts a ring (a room) into 2 regions, and each of two nested rings into 2', () => {
    expect(checkRegions(textGrid(['#####', '#...#', '#...#', '#####'])).count).toBe(2);
    expect(checkRegions(textGrid(['###', '#.#', '###'])).count).toBe(2);
    expect(checkRegions(textGrid([
      '#########',
      '#.......#',
      '#.#####.#',
      '#.#...#.#',
      '#.#####.#',
      '#.......#',
      '#########',
    ])).count).toBe(4);
  });

  it('cuts a block with holes side by side into 2 regions, one per band of holes after that', () => {
    expect(checkRegions(textGrid(['#########', '#.#.#.#.#', '#########'])).count).toBe(2);
    expect(checkRegions(textGrid(['##########', '#..###.###', '#..#.#.#.#', '######.###', '##########'])).count).toBe(2);
    // Holes stacked: one cut below each.
    expect(checkRegions(textGrid(['###', '#.#', '###', '#.#', '###', '#.#', '###'])).count).toBe(4);
  });

  it('separates cells of one 4-connected group that meet only at a corner', () => {
    // (1, 0) and (2, 1) meet at a corner around the empty (1, 1): the outline would pass there twice.
    const { count, labels } = checkRegions(textGrid(['##.', '#.#', '###']));
    expect(count).toBe(2);
    expect(labels[1]).not.toBe(labels[5]);
    // Corner contacts between separate groups are left alone: each stays one region.
    expect(checkRegions(textGrid(['#.#', '.#.', '#.#'])).count).toBe(5);
    expect(checkRegions(textGrid(['##..', '##..', '..##', '..##'])).count).toBe(2);
  });

  it('splits random grids into disks, never cutting a group that is one (600 grids, seeded)', () => {
    const random = createRandom(16);
    for (let k = 0; k < 600; k++) {
      const width = 1 + Math.floor(random() * 24), height = 1 + Math.floor(random() * 24);
      checkRegions(randomGrid(width, height, 0.2 + 0.7 * random(), random));
    }
  });

  it('cuts few times: a random grid has at most one region per group plus one per enclosed empty pocket', () => {
    const random = createRandom(7);
    for (let k = 0; k < 50; k++) {
      const grid = randomGrid(40, 40, 0.6, random);
      const { count } = holeFreeRegions(grid);
      const groups = components4(grid).length;
      // A pocket: empty cells 4-connected to each other but not to the border (a hole, or a corner's pocket).
      expect(count).toBeLessThanOrEqual(groups + emptyPockets(grid));
    }
  });
});

/** Empty 4-components that do not touch the border. */
function emptyPockets(grid: CellGrid): number {
  const seen = new Uint8Array(grid.width * grid.height);
  let holes = 0;
  for (let y = 0; y < grid.height; y++) {
    for (let x = 0; x < grid.width; x++) {
      if (seen[y * grid.width + x] || grid.solid(x, y)) continue;
      let border = false;
      const stack: Array<[number, number]> = [[x, y]];
      seen[y * grid.width + x] = 1;
      while (stack.length > 0) {
        const [cx, cy] = stack.pop()!;
        if (cx === 0 || cy === 0 || cx === grid.width - 1 || cy === grid.height - 1) border = true;
        for (const [dx, dy] of [[1, 0], [-1, 0], [0, 1], [0, -1]]) {
          const nx = cx + dx, ny = cy + dy;
          if (nx < 0 || ny < 0 || nx >= grid.width || ny >= grid.height) continue;
          if (seen[ny * grid.width + nx] || grid.solid(nx, ny)) continue;
          seen[ny * grid.width + nx] = 1;
          stack.push([nx, ny]);
        }
      }
      if (!border) holes++;
    }
  }
  return holes;
}
