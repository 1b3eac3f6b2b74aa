import { describe, expect, it } from 'vitest';
import { hullsFromTiles, TileHulls, type Hull } from '../../src/index';
import { compareToReference } from '../reference/compareToReference';
import { MAX_LIMIT, MEAN_LIMIT, P99_LIMIT, UMBRA_LIMIT } from '../reference/limits';
import type { Point, ReferenceScene } from '../reference/scenes';
import { computeReference } from '../reference/softShadowReference';
import { createSceneRenderer } from '../reference/buildScene';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// A room of 8×8 tiles as a game's tile map has it: walls one tile thick around a floor, with a
// pillar of four tiles inside, lit by a lamp in the room. hullsFromTiles makes the hulls; the
// renderer must let no light out of the room (its walls' outside is dark to one step of the
// shadow mask) and match the exact reference inside, as every reference scene does.
const TILE = 8;
const ROOM = [
  '....................',
  '.##########.........',
  '.#........#.........',
  '.#........#.........',
  '.#...##...#.........',
  '.#...##...#.........',
  '.#........#.........',
  '.#........#.........',
  '.##########.........',
  '....................',
  '....................',
  '....................',
  '....................',
  '....................',
  '....................',
];
const WIDTH = ROOM[0].length * TILE, HEIGHT = ROOM.length * TILE;

/** The hull's outline in world points (hullsFromTiles gives its hulls world points at position [0, 0]). */
const outline = (hull: Hull): Point[] => hull.points.map(([x, y]) => [x, y]);

/** Whether world point (x, y) lies on or inside the room's outer wall. */
const inRoom = (x: number, y: number) => x >= TILE && x <= 11 * TILE && y >= TILE && y <= 9 * TILE;

describe('a tile-map room made by hullsFromTiles, on headless-gl', () => {
  const hulls = hullsFromTiles(ROOM.map((row) => [...row].map((cell) => cell === '#')), { tileSize: TILE });
  const scene: ReferenceScene = {
    name: 'tile room', width: WIDTH, height: HEIGHT, darkUmbra: true,
    lights: [{ position: [30, 30], range: 140, radius: 6 }],
    hulls: hulls.map(outline),
  };

  it('is a few hulls, not one per tile', () => {
    // The ring of walls is cut into two pieces (a hull cannot have a hole), the pillar is one.
    expect(hulls.length).toBe(3);
    expect(hulls.every((hull) => hull.valid)).toBe(true);
  });

  it('lets no light out through its walls and matches the exact reference inside', () => {
    const gl = createContext(WIDTH, HEIGHT);
    const renderer = createSceneRenderer(gl, scene);
    const lightmap = renderLightmap(gl, renderer, WIDTH, HEIGHT);
    expect(gl.getError()).toBe(0);
    renderer.dispose();
    destroyContext(gl);

    let outside = 0, brightestOutside = 0;
    for (let y = 0; y < HEIGHT; y++) {
      for (let x = 0; x < WIDTH; x++) {
        if (inRoom(x + 0.5, y + 0.5) || Math.hypot(x + 0.5 - 30, y + 0.5 - 30) >= 140) continue;
        outside++;
        brightestOutside = Math.max(brightestOutside, lightmap.at(x, y)[0]);
      }
    }
    expect(outside).toBeGreaterThan(10_000);
    expect(brightestOutside).toBeLessThanOrEqual(UMBRA_LIMIT);

    const errors = compareToReference(scene, lightmap.rgb, computeReference(scene));
    expect(errors.all.mean).toBeLessThanOrEqual(MEAN_LIMIT);
    expect(errors.all.p99).toBeLessThanOrEqual(P99_LIMIT);
    expect(errors.all.max).toBeLessThanOrEqual(MAX_LIMIT);
    expect(errors.umbra.max).toBeLessThanOrEqual(UMBRA_LIMIT);
  });
});

// Walls two tiles thick crossing the seams of chunks of 8 tiles (every 16 pixels), so TileHulls
// cuts them into hulls that meet along those seams, and lights standing on the seams' lines,
// looking through them: a gap between two hulls would let a thin beam out there. The reference
// sees the walls as the uncut groups of tiles, so the cuts must change nothing it can see.
describe('walls cut at chunk seams, on headless-gl', () => {
  const size = 2, chunkSize = 8, columns = 48, rows = 40;
  const solid = (x: number, y: number) => (y >= 15 && y <= 16 && x >= 4 && x <= 43) // across x = 16, 32, 48, 64 and 80; along y = 32
    || (x >= 6 && x <= 9 && y >= 20 && y <= 37) // along x = 16; across y = 48 and 64
    || (x >= 34 && x <= 43 && y >= 21 && y <= 34 && !(x >= 36 && x <= 41 && y >= 23 && y <= 32)); // a room across x = 80, y = 48 and 64
  const cut = new TileHulls(solid, { width: columns, height: rows, tileSize: size, chunkSize });
  const whole = hullsFromTiles(solid, { width: columns, height: rows, tileSize: size, chunkSize: columns });
  const width = columns * size, height = rows * size;
  const lights: ReferenceScene['lights'] = [
    { position: [48, 10], range: 110, radius: 3 }, // above the wall, on the seam x = 48
    { position: [5, 48], range: 110, radius: 2 }, // left of the wall below, on the seam y = 48
    { position: [80, 48], range: 60, radius: 1.5 }, // in the room, on the seams x = 80 and y = 48
  ];

  it('is cut into more hulls than the uncut groups, meeting along the seams', () => {
    expect(whole.length).toBe(4);
    expect(cut.hulls.length).toBeGreaterThan(10);
    expect(cut.hulls.filter((hull) => hull.points.some(([x, y]) => x === 48 && y === 30))).toHaveLength(2);
  });

  it('lets no light through the seams and matches the exact reference of the uncut walls', () => {
    const gl = createContext(width, height);
    const renderer = createSceneRenderer(gl, { name: 'chunk seams', width, height, lights, hulls: [] });
    for (const hull of cut.hulls) renderer.addHull(hull);
    const lightmap = renderLightmap(gl, renderer, width, height);
    expect(gl.getError()).toBe(0);
    renderer.dispose();
    destroyContext(gl);

    const scene: ReferenceScene = { name: 'chunk seams', width, height, darkUmbra: true, lights, hulls: whole.map(outline) };
    const errors = compareToReference(scene, lightmap.rgb, computeReference(scene));
    expect(errors.umbra.pixels).toBeGreaterThan(1000);
    expect(errors.umbra.max).toBeLessThanOrEqual(UMBRA_LIMIT);
    expect(errors.all.mean).toBeLessThanOrEqual(MEAN_LIMIT);
    expect(errors.all.p99).toBeLessThanOrEqual(P99_LIMIT);
    expect(errors.all.max).toBeLessThanOrEqual(MAX_LIMIT);
  });
});
