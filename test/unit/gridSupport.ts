/** Helpers shared by the tile and grid-region tests: independent grid checks. */
import type { CellGrid } from '../../src/geometry/gridRegions';

/** A grid from rows of text: `#` solid, anything else empty. */
export function textGrid(rows: readonly string[]): CellGrid {
  return { width: Math.max(0, ...rows.map((r) => r.length)), height: rows.length, solid: (x, y) => rows[y][x] === '#' };
}

/** A grid of random cells, solid with probability `fill`. */
export function randomGrid(width: number, height: number, fill: number, random: () => number): CellGrid & { cells: Uint8Array } {
  const cells = new Uint8Array(width * height);
  for (let i = 0; i < cells.length; i++) cells[i] = random() < fill ? 1 : 0;
  return { width, height, cells, solid: (x, y) => cells[y * width + x] === 1 };
}

const STEPS = [[1, 0], [-1, 0], [0, 1], [0, -1]] as const;

/**
 * Cells of `inSet` reachable from `seeds` by 4-steps within the rectangle [x0, x1) × [y0, y1);
 * returns a set of `y * W + x` keys (W a stride large enough for the rectangle).
 */
function flood4(seeds: Array<[number, number]>, inSet: (x: number, y: number) => boolean, x0: number, y0: number, x1: number, y1: number): Set<number> {
  const W = x1 - x0 + 1, seen = new Set<number>(), stack = [...seeds];
  while (stack.length > 0) {
    const [x, y] = stack.pop()!;
    if (x < x0 || y < y0 || x >= x1 || y >= y1 || !inSet(x, y)) continue;
    const key = (y - y0) * W + (x - x0);
    if (seen.has(key)) continue;
    seen.add(key);
    for (const [dx, dy] of STEPS) stack.push([x + dx, y + dy]);
  }
  return seen;
}

/** The cells of each label, as [x, y] lists. */
export function cellsByLabel(labels: Int32Array, width: number, count: number): Array<Array<[number, number]>> {
  const out: Array<Array<[number, number]>> = Array.from({ length: count }, () => []);
  for (let i = 0; i < labels.length; i++) if (labels[i] >= 0) out[labels[i]].push([i % width, Math.floor(i / width)]);
  return out;
}

/**
 * Whether a set of cells is a disk: 4-connected, and the cells outside it, within its bounding
 * box grown by one, all 4-connected to the box's corner (no hole, no two cells meeting only at a
 * corner with the outline passing twice there).
 */
export function isDisk(cells: Array<[number, number]>): boolean {
  if (cells.length === 0) return false;
  const key = (x: number, y: number) => `${x},${y}`;
  const set = new Set(cells.map(([x, y]) => key(x, y)));
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of cells) {
    x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
  }
  const inside = flood4([cells[0]], (x, y) => set.has(key(x, y)), x0, y0, x1 + 1, y1 + 1);
  if (inside.size !== cells.length) return false;
  const outside = flood4([[x0 - 1, y0 - 1]], (x, y) => !set.has(key(x, y)), x0 - 1, y0 - 1, x1 + 2, y1 + 2);
  return outside.size === (x1 - x0 + 3) * (y1 - y0 + 3) - cells.length;
}

/** The 4-connected components of the solid cells, as [x, y] lists. */
export function components4(grid: CellGrid): Array<Array<[number, number]>> {
  const seen = new Uint8Array(grid.width * grid.height), out: Array<Array<[number, number]>> = [];
  for (let y = 0; y < grid.height; y++) {
    for (let x = 0; x < grid.width; x++) {
      if (seen[y * grid.width + x] || !grid.solid(x, y)) continue;
      const keys = flood4([[x, y]], grid.solid, 0, 0, grid.width, grid.height);
      const cells: Array<[number, number]> = [];
      for (const k of keys) {
        const cx = k % (grid.width + 1), cy = Math.floor(k / (grid.width + 1));
        seen[cy * grid.width + cx] = 1;
        cells.push([cx, cy]);
      }
      out.push(cells);
    }
  }
  return out;
}
