// The cases of `node bench/tiles.mjs`: tile grids → hulls (hullsFromTiles, TileHulls.setTile).
// Each case builds its grid outside the timing and times only the library call.
import { holeFreeRegions } from '../src/geometry/gridRegions';
import { traceOutlines } from '../src/geometry/tileOutlines';
import { hullsFromTiles, TileHulls } from '../src/scene/tileHulls';
import { createRandom } from '../test/reference/randomScenes';

/** A perfect maze (depth-first, seeded) on (2n+1)² tiles: 1 = wall. Its walls are one group around one hole. */
function maze(n: number): number[][] {
  const size = 2 * n + 1, random = createRandom(1);
  const rows = Array.from({ length: size }, () => new Array<number>(size).fill(1));
  const stack: Array<[number, number]> = [[0, 0]];
  rows[1][1] = 0;
  while (stack.length > 0) {
    const [x, y] = stack[stack.length - 1];
    const next = ([[1, 0], [-1, 0], [0, 1], [0, -1]] as const)
      .map(([dx, dy]) => [x + dx, y + dy] as const)
      .filter(([nx, ny]) => nx >= 0 && ny >= 0 && nx < n && ny < n && rows[2 * ny + 1][2 * nx + 1] === 1);
    if (next.length === 0) {
      stack.pop();
      continue;
    }
    const [nx, ny] = next[Math.floor(random() * next.length)];
    rows[y + ny + 1][x + nx + 1] = 0;
    rows[2 * ny + 1][2 * nx + 1] = 0;
    stack.push([nx, ny]);
  }
  return rows;
}

function randomMap(size: number, fill: number): number[][] {
  const random = createRandom(2);
  return Array.from({ length: size }, () => Array.from({ length: size }, () => (random() < fill ? 1 : 0)));
}

/** A size² map of rooms: walls one tile thick every `room` tiles and around the edge, all joined into one group. */
function rooms(size: number, room: number): number[][] {
  return Array.from({ length: size }, (_, y) => Array.from({ length: size }, (_, x) => (
    x % room === 0 || y % room === 0 || x === size - 1 || y === size - 1 ? 1 : 0)));
}

const count = (rows: number[][]) => rows.reduce((sum, row) => sum + row.reduce((a, b) => a + b, 0), 0);

interface Case {
  /** What the table says about the grid. */
  describe(): string;
  /** Runs the call once and returns milliseconds. */
  run(): number;
}

function build(rows: number[][]): Case {
  return {
    describe: () => {
      const hulls = hullsFromTiles(rows, { tileSize: 32 });
      return `${rows[0].length}×${rows.length}, ${count(rows)} solid, ${hulls.length} hulls, ${hulls.reduce((s, h) => s + h.edgeCount, 0)} points`;
    },
    run: () => {
      const start = performance.now();
      const hulls = hullsFromTiles(rows, { tileSize: 32 });
      const ms = performance.now() - start;
      if (!hulls.every((h) => h.valid)) throw new Error('an invalid hull');
      return ms;
    },
  };
}

/** The regions and their outlines alone, without making hulls of them. */
function outlines(rows: number[][]): Case {
  const width = rows[0].length, height = rows.length;
  const grid = { width, height, solid: (x: number, y: number) => rows[y][x] === 1 };
  return {
    describe: () => `${width}×${height}, ${count(rows)} solid, ${holeFreeRegions(grid).count} regions`,
    run: () => {
      const start = performance.now();
      const { labels, count: regions } = holeFreeRegions(grid);
      traceOutlines(labels, width, height, regions);
      return performance.now() - start;
    },
  };
}

/** One setTile per run, on a random tile; every other run undoes the previous one, so the map stays near its start. */
function edit(rows: number[][]): Case {
  const tiles = new TileHulls(rows, { tileSize: 32 });
  const random = createRandom(3);
  let undo: [number, number, boolean] | null = null;
  return {
    describe: () => `${rows[0].length}×${rows.length}, ${count(rows)} solid, ${tiles.hulls.length} hulls`,
    run: () => {
      let x: number, y: number, solid: boolean;
      if (undo) [x, y, solid] = undo;
      else {
        x = Math.floor(random() * rows[0].length);
        y = Math.floor(random() * rows.length);
        solid = !tiles.isSolid(x, y);
      }
      undo = undo ? null : [x, y, !solid];
      const start = performance.now();
      tiles.setTile(x, y, solid);
      return performance.now() - start;
    },
  };
}

/**
 * One door per run, in a random wall between two rooms of {@link rooms} (never at a crossing): every
 * other run closes the door the previous one opened, so the map stays as it started.
 */
function door(rows: number[][], room: number): Case {
  const tiles = new TileHulls(rows, { tileSize: 32 });
  const random = createRandom(4), walls = Math.floor((rows.length - 1) / room);
  let open: [number, number] | null = null;
  return {
    describe: () => `${rows[0].length}×${rows.length}, ${count(rows)} solid, ${tiles.hulls.length} hulls`,
    run: () => {
      let x: number, y: number;
      if (open) [x, y] = open;
      else {
        let along: number;
        do along = 1 + Math.floor(random() * (rows.length - 2)); while (along % room === 0);
        const across = room * Math.floor(random() * walls);
        [x, y] = random() < 0.5 ? [along, across] : [across, along];
      }
      const start = performance.now();
      tiles.setTile(x, y, open !== null);
      const ms = performance.now() - start;
      open = open ? null : [x, y];
      return ms;
    },
  };
}

export const CASES: Record<string, () => Case> = {
  'hullsFromTiles: 100×100 all solid': () => build(randomMap(100, 1)),
  'hullsFromTiles: maze': () => build(maze(70)),
  'hullsFromTiles: 256×256, 30% random walls': () => build(randomMap(256, 0.3)),
  'holeFreeRegions + traceOutlines only: 256×256, 30% random walls': () => outlines(randomMap(256, 0.3)),
  'setTile: 256×256, 30% random walls': () => edit(randomMap(256, 0.3)),
  'setTile: maze': () => edit(maze(70)),
  'setTile: a door in a 1000×1000 map of 25×25 rooms': () => door(rooms(1000, 25), 25),
};
