import { describe, expect, it } from 'vitest';
import { isInsidePolygon, signedArea2 } from '../../src/geometry/polygon';
import type { Hull } from '../../src/scene/Hull';
import { hullsFromTiles, TileHulls } from '../../src/scene/tileHulls';
import { createRandom } from '../reference/randomScenes';

const flat = (hull: Hull) => hull.points.flat();

/**
 * Rasterizes `hulls` back onto the grid, independently of how they were made: each tile centre
 * (world → tile through `tileSize` and `position`) must lie in exactly one hull when the tile is
 * solid and in none when empty; every hull valid; total area = solid tiles × tile area.
 */
function expectCovers(hulls: readonly Hull[], solid: (x: number, y: number) => boolean, width: number, height: number,
  tileSize: [number, number] = [1, 1], position: [number, number] = [0, 0]): void {
  const coords = hulls.map(flat);
  expect(hulls.flatMap((hull, i) => (hull.valid ? [] : [`hull ${i}: ${coords[i].join(',')}`])), 'invalid hulls').toEqual([]);
  let solidCount = 0;
  const wrong: string[] = [];
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const centre = [position[0] + (x + 0.5) * tileSize[0], position[1] + (y + 0.5) * tileSize[1]];
      const inside = coords.filter((c) => isInsidePolygon(c, centre)).length;
      if (inside !== (solid(x, y) ? 1 : 0)) wrong.push(`${solid(x, y) ? 'solid' : 'empty'} tile (${x}, ${y}) in ${inside} hulls`);
      if (solid(x, y)) solidCount++;
    }
  }
  expect(wrong).toEqual([]);
  const area = coords.reduce((sum, c) => sum + Math.abs(signedArea2(c)) / 2, 0);
  expect(area).toBeCloseTo(solidCount * tileSize[0] * tileSize[1], 6);
}

/** The hulls' outlines as sorted strings: equal lists mean the same hulls. */
const shapes = (hulls: readonly Hull[]) => hulls.map((h) => flat(h).join(',')).sort();

function randomRows(width: number, height: number, fill: number, random: () => number): number[][] {
  return Array.from({ length: height }, () => Array.from({ length: width }, () => (random() < fill ? 1 : 0)));
}

describe('hullsFromTiles', () => {
  it('makes a 16-tile wall one 4-point hull, in world units', () => {
    const hulls = hullsFromTiles([Array(16).fill(1)], { tileSize: 32, position: [100, 50] });
    expect(hulls).toHaveLength(1);
    expect(hulls[0].points).toEqual([[100, 50], [612, 50], [612, 82], [100, 82]]);
    expect(hulls[0].position).toEqual([0, 0]);
    expectCovers(hulls, () => true, 16, 1, [32, 32], [100, 50]);
  });

  it('makes a room (a ring of walls) 2 hulls, a room inside a room 4', () => {
    const room = ['########', '#......#', '#......#', '#......#', '########'];
    const hulls = hullsFromTiles(room, { solid: '#' });
    expect(hulls).toHaveLength(2);
    expectCovers(hulls, (x, y) => room[y][x] === '#', 8, 5);
    const nested = ['#########', '#.......#', '#.#####.#', '#.#...#.#', '#.#####.#', '#.......#', '#########'];
    expect(hullsFromTiles(nested, { solid: '#' })).toHaveLength(4);
  });

  it('reads rows of numbers or booleans, a flat array with width, or a function with width and height', () => {
    const rows = [[0, 1, 1], [0, 1, 0], [2, 1, 0]];
    const expected = shapes(hullsFromTiles(rows));
    expect(shapes(hullsFromTiles(rows.map((r) => r.map((v) => v !== 0))))).toEqual(expected);
    expect(shapes(hullsFromTiles(new Uint8Array(rows.flat()), { width: 3 }))).toEqual(expected);
    expect(shapes(hullsFromTiles(rows.flat(), { width: 3, height: 3 }))).toEqual(expected);
    expect(shapes(hullsFromTiles((x, y) => rows[y][x] > 0, { width: 3, height: 3 }))).toEqual(expected);
    expectCovers(hullsFromTiles(rows), (x, y) => rows[y][x] !== 0, 3, 3);
  });

  it('takes which values are solid as a value, a list or a test', () => {
    const rows = [[0, 1, 2], [3, 1, 2]];
    expectCovers(hullsFromTiles(rows, { solid: 2 }), (x) => x === 2, 3, 2);
    expectCovers(hullsFromTiles(rows, { solid: [1, 3] }), (x, y) => [1, 3].includes(rows[y][x]), 3, 2);
    expectCovers(hullsFromTiles(rows, { solid: (v, x, y) => v === 1 || (x === 0 && y === 1) }), (x, y) => rows[y][x] === 1 || (x === 0 && y === 1), 3, 2);
    expect(hullsFromTiles(['#.#'], { solid: (v) => v === '#' })).toHaveLength(2);
  });

  it('scales by [w, h] tiles and makes nothing of an empty grid', () => {
    const rows = [[1, 0], [1, 1]];
    expectCovers(hullsFromTiles(rows, { tileSize: [16, 8], position: [-5, 3] }), (x, y) => rows[y][x] === 1, 2, 2, [16, 8], [-5, 3]);
    expect(hullsFromTiles([])).toEqual([]);
    expect(hullsFromTiles([[0, 0], [0, 0]])).toEqual([]);
    expect(hullsFromTiles([], { width: 4 })).toEqual([]);
  });

  it('cuts a group larger than a chunk along the chunk edges, the pieces meeting at the same points', () => {
    const hulls = hullsFromTiles([Array(16).fill(1), Array(16).fill(1)], { tileSize: 32, position: [100, 50], chunkSize: 5 });
    expect(hulls.map((hull) => hull.points)).toEqual([0, 5, 10, 15].map((x) => {
      const left = 100 + 32 * x, right = 100 + 32 * Math.min(x + 5, 16);
      return [[left, 50], [right, 50], [right, 114], [left, 114]];
    }));
    // A ring of 6 × 6 tiles in chunks of 4: four corners of the ring, each a disk, and no more.
    const ring = ['######', '#....#', '#....#', '#....#', '#....#', '######'];
    const pieces = hullsFromTiles(ring, { solid: '#', chunkSize: 4 });
    expect(pieces).toHaveLength(4);
    expectCovers(pieces, (x, y) => ring[y][x] === '#', 6, 6);
  });

  it('covers random grids exactly with valid hulls (300 grids, seeded)', () => {
    const random = createRandom(2024);
    for (let k = 0; k < 300; k++) {
      const width = 1 + Math.floor(random() * 20), height = 1 + Math.floor(random() * 20);
      const rows = randomRows(width, height, 0.15 + 0.8 * random(), random);
      const size: [number, number] = [1 + Math.floor(random() * 40), 1 + Math.floor(random() * 40)];
      const chunkSize = random() < 0.5 ? undefined : 1 + Math.floor(random() * 6);
      expectCovers(hullsFromTiles(rows, { tileSize: size, position: [7, -3], chunkSize }), (x, y) => rows[y][x] === 1, width, height, size, [7, -3]);
    }
  });

  it('names the field and the value of bad input', () => {
    expect(() => hullsFromTiles(5 as never)).toThrow(new TypeError('hullsFromTiles grid must be an array of rows, a flat array with options.width, or a function (x, y) => value, got 5'));
    expect(() => hullsFromTiles([1, 0, 1] as never)).toThrow(/^hullsFromTiles grid\[0\] must be a row .*got 1$/);
    expect(() => hullsFromTiles([[1, 0], [1]])).toThrow(new RangeError('hullsFromTiles grid[1] must have 2 tiles like grid[0], got 1'));
    expect(() => hullsFromTiles([[1, 'x']])).toThrow(/^hullsFromTiles grid\[0\]\[1\] must be a number or true\/false .*got "x"$/);
    expect(() => hullsFromTiles([1, 0, 1], { width: 2 })).toThrow(RangeError);
    expect(() => hullsFromTiles([1, 0, 1], { width: 1.5 })).toThrow(/options.width must be a non-negative integer, got 1.5/);
    expect(() => hullsFromTiles(() => 1, { width: 2 } as never)).toThrow(/options.width and options.height must be given/);
    expect(() => hullsFromTiles([[1]], { tileSize: 0 })).toThrow(new RangeError('hullsFromTiles options.tileSize must be a positive finite number or [w, h] pair, got 0'));
    expect(() => hullsFromTiles([[1]], { tileSize: 'big' as never })).toThrow(TypeError);
    expect(() => hullsFromTiles([[1]], { position: [0, NaN] })).toThrow(new RangeError('hullsFromTiles options.position[1] must be a finite number, got NaN'));
    expect(() => hullsFromTiles([[1]], { solid: () => 1 as never })).toThrow(/options.solid must return true or false, got 1 for tile \(0, 0\)/);
    expect(() => new TileHulls([[1]], { tileSize: -1 })).toThrow(/^TileHulls options.tileSize/);
    expect(() => hullsFromTiles([[1]], { chunkSize: 0 })).toThrow(new RangeError('hullsFromTiles options.chunkSize must be a positive integer, got 0'));
    expect(() => hullsFromTiles([[1]], { chunkSize: 2.5 })).toThrow(RangeError);
    expect(() => hullsFromTiles([[1]], { chunkSize: '8' as never })).toThrow(new TypeError('hullsFromTiles options.chunkSize must be a positive integer, got "8"'));
    const tiles = new TileHulls([[1, 0]]);
    expect(() => tiles.setTile(2, 0, true)).toThrow(new RangeError('TileHulls.setTile x must be an integer in 0..1, got 2'));
    expect(() => tiles.setTile(0, 0.5, true)).toThrow(RangeError);
    expect(() => tiles.setTile(0, 0, 1 as never)).toThrow(new TypeError('TileHulls.setTile solid must be true or false, got 1'));
  });
});

describe('the size of a grid', () => {
  it('is at most TileHulls.maxTiles tiles, refused before a tile is allocated or read', () => {
    expect(TileHulls.maxTiles).toBe(2 ** 28);
    let reads = 0;
    const tile = () => {
      reads++;
      return 0;
    };
    expect(() => new TileHulls(tile, { width: 1e5, height: 1e5 })).toThrow(new RangeError(
      'TileHulls options.width × options.height must be at most 268435456 tiles (TileHulls.maxTiles), got 100000 × 100000 = 10000000000'));
    expect(() => hullsFromTiles(tile, { width: 2 ** 31, height: 1 })).toThrow(new RangeError('hullsFromTiles options.width must be at most 268435456 (TileHulls.maxTiles), got 2147483648'));
    expect(() => hullsFromTiles(tile, { width: 2 ** 14, height: 2 ** 14 + 1 })).toThrow(RangeError);
    expect(() => hullsFromTiles(tile, { width: 0, height: 2 ** 40 })).toThrow(new RangeError('hullsFromTiles options.height must be at most 268435456 (TileHulls.maxTiles), got 1099511627776'));
    expect(reads).toBe(0);
    expect(() => hullsFromTiles({ length: 2 ** 29 } as ArrayLike<number>, { width: 2 ** 10 })).toThrow(/^hullsFromTiles options.width × height must be at most 268435456 tiles .*got 1024 × 524288 = 536870912$/);
    const row = { length: 2 ** 14 } as ArrayLike<number>;
    expect(() => hullsFromTiles(new Array<ArrayLike<number>>(2 ** 15).fill(row))).toThrow(/^hullsFromTiles grid\[0\].length × grid.length must be at most 268435456 tiles .*got 16384 × 32768 = 536870912$/);
  });
});

describe('TileHulls', () => {
  it('returns the added and removed hulls of a change, leaving the other hulls alone', () => {
    const tiles = new TileHulls(['#####....#', '#...#....#', '#####....#'], { solid: '#' });
    expect(tiles.hulls).toHaveLength(3);
    const [wall] = tiles.hulls.filter((h) => flat(h)[0] === 9);
    // Opening the room's wall: its 2 hulls become 1 (a C); the lone wall on the right stays as it was.
    const open = tiles.setTile(4, 1, false);
    expect(open.removed).toHaveLength(2);
    expect(open.added).toHaveLength(1);
    expect(tiles.hulls).toHaveLength(2);
    expect(tiles.hulls).toContain(wall);
    expect(tiles.isSolid(4, 1)).toBe(false);
    expect(tiles.setTile(4, 1, false)).toEqual({ added: [], removed: [] });
    // A bridge to the wall merges everything into one group.
    const bridge = tiles.setTile(5, 0, true);
    expect(bridge.removed).toHaveLength(1);
    expect(tiles.setTile(6, 0, true).removed).toHaveLength(1);
    const join = tiles.setTile(7, 0, true), last = tiles.setTile(8, 0, true);
    expect(join.added).toHaveLength(1);
    expect(last.removed).toHaveLength(2);
    expect(tiles.hulls).toHaveLength(1);
  });

  it('opens a door in the joined walls of a 1000×1000 map by replacing hulls of its chunk only', () => {
    // Rooms of 25 × 25 tiles: every wall joined to every other, and to the map's outer wall.
    const size = 1000, rows = Array.from({ length: size }, (_, y) => Array.from({ length: size }, (_, x) => (
      x % 25 === 0 || y % 25 === 0 || x === size - 1 || y === size - 1 ? 1 : 0)));
    const tiles = new TileHulls(rows, { tileSize: 32 });
    const before = tiles.hulls, versions = before.map((hull) => hull.version), shapesBefore = shapes(before);
    // The door's chunk (tiles 480..511 × 0..31) holds one piece of the walls: the outer wall's, a
    // room's wall down from it at x = 500 and one across at y = 25. The door cuts tile 511 off it.
    const open = tiles.setTile(510, 0, false);
    rows[0][510] = 0;
    expect(open.removed).toHaveLength(1);
    expect(open.added).toHaveLength(2);
    const inDoorChunk = (hull: Hull) => hull.points.every(([x, y]) => x >= 480 * 32 && x <= 512 * 32 && y >= 0 && y <= 32 * 32);
    expect([...open.added, ...open.removed].every(inDoorChunk)).toBe(true);
    // Every other hull is the same object, unchanged: a renderer sees none of them move.
    const now = new Set(tiles.hulls);
    before.forEach((hull, i) => {
      if (open.removed.includes(hull)) return;
      expect(now.has(hull)).toBe(true);
      expect(hull.version).toBe(versions[i]);
    });
    expect(shapes(tiles.hulls)).toEqual(shapes(hullsFromTiles(rows, { tileSize: 32 })));
    // Closing it again brings back the piece it was.
    const close = tiles.setTile(510, 0, true);
    expect(close.removed).toEqual(open.added);
    expect(close.added).toHaveLength(1);
    expect(shapes(tiles.hulls)).toEqual(shapesBefore);
  });

  it('keeps the hulls a fresh hullsFromTiles makes, through random setTile sequences (200 grids, seeded)', () => {
    const random = createRandom(99);
    for (let k = 0; k < 200; k++) {
      const width = 1 + Math.floor(random() * 14), height = 1 + Math.floor(random() * 14);
      const rows = randomRows(width, height, 0.2 + 0.7 * random(), random);
      const chunkSize = random() < 0.3 ? undefined : 1 + Math.floor(random() * 6);
      const tiles = new TileHulls(rows, { tileSize: 2, position: [1, 1], chunkSize });
      const current = new Set(tiles.hulls);
      for (let step = 0; step < 20; step++) {
        const x = Math.floor(random() * width), y = Math.floor(random() * height), solid = random() < 0.5;
        const { added, removed } = tiles.setTile(x, y, solid);
        rows[y][x] = solid ? 1 : 0;
        for (const hull of removed) expect(current.delete(hull), 'a removed hull was current').toBe(true);
        for (const hull of added) current.add(hull);
        expect(new Set(tiles.hulls)).toEqual(current);
      }
      expect(shapes(tiles.hulls)).toEqual(shapes(hullsFromTiles(rows, { tileSize: 2, position: [1, 1], chunkSize })));
      expectCovers(tiles.hulls, (x, y) => rows[y][x] === 1, width, height, [2, 2], [1, 1]);
    }
  });
});
