import { describe, expect, it } from 'vitest';
import { LightTiles } from '../../src/shadow/LightTiles';
import { SHADOW_TYPE_CODES, TILE_CLASS_COUNT, TILE_CLASSES, TILE_COLUMNS, TILE_ROWS } from '../../src/shadow/shadowLayout';
import { ShadowGeometry } from '../../src/shadow/ShadowGeometry';
import { Hull } from '../../src/index';
import { createRandom } from '../reference/randomScenes';
import { diskSamples, shareOfSamplesSeen } from '../reference/softShadowReference';
import { box, type Point } from '../reference/scenes';

/**
 * The tile classes against disk sampling, independent of the classification's geometry: every
 * point of a lit tile (corners, edges and middles, 3×3 per tile) sees every disk sample, every point
 * of a dark tile outside the hulls sees none, and from every point of a lean tile outside the hulls
 * each hull that hides a sample hides every sample in its wedge (the disk lies wholly beyond it
 * there, what the lean program takes for granted). Samples: 512 per disk plus 256 on its rim (the
 * tangent points a lit tile's corner may graze); for the lean tiles 128 and 64.
 */
const SAMPLES_PER_SIDE = 3;

interface Case {
  hulls: Point[][];
  centre: Point;
  radius: number;
  reach: number;
  solid: boolean;
  /** An Occluded light (else Solid or Illuminated, by `solid`). */
  occluded?: boolean;
}

function classify({ hulls, centre, radius, reach, solid, occluded }: Case): { classes: Uint8Array; bounds: Float64Array } {
  const geometry = new ShadowGeometry();
  const made = hulls.map((points) => new Hull(points));
  geometry.update(made);
  const indices = Int32Array.from(made.keys());
  for (const i of indices) geometry.prepare(i);
  const tiles = new LightTiles();
  const bounds = Float64Array.of(centre[0] - reach, centre[1] - reach, centre[0] + reach, centre[1] + reach);
  const shadowType = occluded ? SHADOW_TYPE_CODES.occluded : solid ? SHADOW_TYPE_CODES.solid : SHADOW_TYPE_CODES.illuminated;
  tiles.beginLight(bounds, Float64Array.of(centre[0], centre[1], radius, reach), true, shadowType);
  tiles.addStillHulls(geometry, indices, indices.length);
  tiles.endLight(0);
  return { classes: Uint8Array.from({ length: TILE_COLUMNS * TILE_ROWS }, (_, tile) => tiles.tileClass(0, tile)), bounds };
}

function samplesWithRim(centre: Point, radius: number, inner = 512, onRim = 256): Float64Array {
  const inside = diskSamples(centre[0], centre[1], radius, inner);
  const rim = new Float64Array(2 * onRim);
  for (let k = 0; k < onRim; k++) {
    rim[2 * k] = centre[0] + radius * Math.cos((2 * Math.PI * k) / onRim);
    rim[2 * k + 1] = centre[1] + radius * Math.sin((2 * Math.PI * k) / onRim);
  }
  const all = new Float64Array(inside.length + rim.length);
  all.set(inside);
  all.set(rim, inside.length);
  return all;
}

function edgesOf(hulls: Point[][]): Float64Array {
  const edges: number[] = [];
  for (const points of hulls) {
    for (let k = 0; k < points.length; k++) edges.push(...points[k], ...points[(k + 1) % points.length]);
  }
  return Float64Array.from(edges);
}

function insideAny(hulls: Point[][], x: number, y: number): boolean {
  return hulls.some((points) => {
    let inside = false;
    for (let i = 0, j = points.length - 1; i < points.length; j = i++) {
      const [xi, yi] = points[i], [xj, yj] = points[j];
      if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  });
}

/**
 * Whether some hull of `hulls` (convex, as here) hides a sample from (x, y) but not every sample in
 * its wedge: one whose ray from (x, y) meets the hull, its segment not (the sample before the hull).
 */
function seenPastFrom(hulls: Point[][], x: number, y: number, samples: Float64Array): boolean {
  return hulls.some((points) => {
    const edges = edgesOf([points]);
    if (shareOfSamplesSeen(x, y, samples, edges, edges.length) === 1) return false;
    for (let s = 0; s < samples.length; s += 2) {
      const dx = samples[s] - x, dy = samples[s + 1] - y, far = 1e6 / Math.hypot(dx, dy);
      const ray = Float64Array.of(x + dx * far, y + dy * far);
      if (shareOfSamplesSeen(x, y, ray, edges, edges.length) === 0 && shareOfSamplesSeen(x, y, samples.subarray(s, s + 2), edges, edges.length) === 1) return true;
    }
    return false;
  });
}

/** Wrong tiles of `c`'s classification, and how many tiles of each class it has. */
function check(c: Case): { wrong: string[]; counts: number[] } {
  const { classes, bounds } = classify(c);
  const samples = samplesWithRim(c.centre, Math.max(c.radius, 1e-3));
  const fewSamples = samplesWithRim(c.centre, Math.max(c.radius, 1e-3), 128, 64);
  const edges = edgesOf(c.hulls);
  const tw = (bounds[2] - bounds[0]) / TILE_COLUMNS, th = (bounds[3] - bounds[1]) / TILE_ROWS;
  const wrong: string[] = [];
  const counts = new Array<number>(TILE_CLASS_COUNT).fill(0);
  for (let j = 0; j < TILE_ROWS; j++) {
    for (let i = 0; i < TILE_COLUMNS; i++) {
      const value = classes[j * TILE_COLUMNS + i];
      counts[value]++;
      if (value === TILE_CLASSES.outside || value === TILE_CLASSES.exact) continue;
      for (let a = 0; a < SAMPLES_PER_SIDE; a++) {
        for (let b = 0; b < SAMPLES_PER_SIDE; b++) {
          const x = bounds[0] + (i + a / (SAMPLES_PER_SIDE - 1)) * tw, y = bounds[1] + (j + b / (SAMPLES_PER_SIDE - 1)) * th;
          if (value === TILE_CLASSES.lean) {
            if (c.occluded && insideAny(c.hulls, x, y)) wrong.push(`lean tile (${i}, ${j}) of an Occluded light holds (${x.toFixed(2)}, ${y.toFixed(2)}) inside a hull`);
            else if (seenPastFrom(c.hulls, x, y, fewSamples)) wrong.push(`lean tile (${i}, ${j}) at (${x.toFixed(2)}, ${y.toFixed(2)}) sees past a hull`);
            continue;
          }
          // Inside a hull a Solid light's pixel is dark, another's lit (the dark tiles' rule below),
          // and a held tile's is lit.
          const inside = insideAny(c.hulls, x, y);
          if (value === TILE_CLASSES.held && (c.solid || c.occluded)) wrong.push(`held tile (${i}, ${j}) of a light that is not Illuminated`);
          if (inside && (value === TILE_CLASSES.dark || value === TILE_CLASSES.held || !c.solid)) continue;
          const seen = shareOfSamplesSeen(x, y, samples, edges, edges.length);
          if (value === TILE_CLASSES.lit && seen < 1) wrong.push(`lit tile (${i}, ${j}) at (${x.toFixed(2)}, ${y.toFixed(2)}) sees ${seen}`);
          if ((value === TILE_CLASSES.dark || value === TILE_CLASSES.held) && seen > 0) wrong.push(`dark or held tile (${i}, ${j}) at (${x.toFixed(2)}, ${y.toFixed(2)}) sees ${seen}`);
        }
      }
    }
  }
  return { wrong, counts };
}

/** A convex polygon of 3–6 corners around (x, y), counter-clockwise in x-right, y-up axes. */
function convexAround(random: () => number, x: number, y: number, size: number): Point[] {
  const count = 3 + Math.floor(random() * 4);
  const points: Point[] = [];
  for (let k = 0; k < count; k++) {
    const angle = ((k + (random() - 0.5) * 0.5) / count) * 2 * Math.PI;
    points.push([x + size * Math.cos(angle), y + size * Math.sin(angle)]);
  }
  return points;
}

describe('LightTiles', () => {
  it('classifies a box before a light: lit beside it, dark behind it, exact in its penumbra', () => {
    const c: Case = { hulls: [box(120, 90, 20, 20)], centre: [100, 100], radius: 4, reach: 80, solid: true };
    const { wrong, counts } = check(c);
    expect(wrong).toEqual([]);
    expect(counts[TILE_CLASSES.lit]).toBeGreaterThan(500);
    expect(counts[TILE_CLASSES.dark]).toBeGreaterThan(20);
    expect(counts[TILE_CLASSES.outside]).toBeGreaterThan(150);
    // Its penumbra is lean: no record meets the disk.
    expect(counts[TILE_CLASSES.lean]).toBeGreaterThan(20);
    expect(counts[TILE_CLASSES.exact]).toBe(0);
  });

  it('draws every exact tile with the general program when a hull meets the disk, and tiles with a hull in them for an Occluded light', () => {
    const wall = box(104, 60, 20, 80);
    const torch = check({ hulls: [wall, box(150, 150, 10, 10)], centre: [100, 100], radius: 6, reach: 80, solid: true });
    expect(torch.wrong).toEqual([]);
    expect(torch.counts[TILE_CLASSES.lean]).toBe(0);
    expect(torch.counts[TILE_CLASSES.exact]).toBeGreaterThan(0);
    const crate = box(140, 95, 10, 10);
    const occluded = check({ hulls: [crate], centre: [100, 100], radius: 4, reach: 80, solid: false, occluded: true });
    const illuminated = check({ hulls: [crate], centre: [100, 100], radius: 4, reach: 80, solid: false });
    expect(occluded.wrong).toEqual([]);
    expect(occluded.counts[TILE_CLASSES.exact]).toBeGreaterThan(0);
    expect(occluded.counts[TILE_CLASSES.held]).toBe(0);
    expect(illuminated.counts[TILE_CLASSES.exact]).toBe(0);
    expect(illuminated.counts[TILE_CLASSES.lean]).toBeGreaterThan(0);
  });

  it('never calls a tile lit, dark, held or lean wrongly in random scenes (disks of radius 0 to 30, walls, posts, overlapping disks)', () => {
    const random = createRandom(7);
    let lit = 0, dark = 0, lean = 0, held = 0;
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
      lean += counts[TILE_CLASSES.lean];
      held += counts[TILE_CLASSES.held];
    }
    // Not everything exact: the classification must decide most of the light's area.
    expect(lit).toBeGreaterThan(30 * 300);
    expect(dark).toBeGreaterThan(30 * 5);
    expect(lean).toBeGreaterThan(30 * 20);
    expect(held).toBeGreaterThan(0);
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
