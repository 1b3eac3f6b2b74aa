import { LightTiles } from '../../src/shadow/LightTiles';
import { LISTED_RECORDS, RECORD_FLOATS, RECORD_POINTS, SHADOW_TYPE_CODES, TILE_CLASS_COUNT, TILE_CLASSES, TILE_COLUMNS, TILE_ROWS } from '../../src/shadow/shadowLayout';
import { ShadowGeometry } from '../../src/shadow/ShadowGeometry';
import { Hull } from '../../src/index';
import { diskSamples, shareOfSamplesSeen } from '../reference/softShadowReference';
import type { Point } from '../reference/scenes';

/**
 * The tile classes against disk sampling, independent of the classification's geometry: every
 * point of a lit tile (corners, edges and middles, 3×3 per tile) sees every disk sample, every point
 * of a dark tile outside the hulls sees none, and from every point of a lean tile outside the hulls
 * each hull that hides a sample hides every sample in its wedge (the disk lies wholly beyond it
 * there, what the lean program takes for granted), and a listed tile lists every record that hides a
 * sample from one of its points or holds it (what the listed program walks). Samples: 512 per disk plus 256 on its rim (the
 * tangent points a lit tile's corner may graze); for the lean tiles 128 and 64.
 */
const SAMPLES_PER_SIDE = 3;

/** A light and its hulls, to classify. */
export interface Case {
  hulls: Point[][];
  centre: Point;
  radius: number;
  reach: number;
  solid: boolean;
  /** An Occluded light (else Solid or Illuminated, by `solid`). */
  occluded?: boolean;
}

/** What `classify` found: the tiles' classes, the filed bounds, and per listed tile the listed records' corners. */
interface Classified {
  classes: Uint8Array;
  bounds: Float64Array;
  /** Per tile, the corners of the records its mask lists (see TileRecordLists). */
  listedOf: (tile: number) => Point[][];
}

/** LightTiles' classes of `c`'s tiles, and the light's filed bounds. */
export function classify({ hulls, centre, radius, reach, solid, occluded }: Case): Classified {
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
  const classes = Uint8Array.from({ length: TILE_COLUMNS * TILE_ROWS }, (_, tile) => tiles.tileClass(0, tile));
  const recordCorners = (record: number): Point[] => Array.from({ length: RECORD_POINTS }, (_, k) => [geometry.records[record * RECORD_FLOATS + 2 * k], geometry.records[record * RECORD_FLOATS + 2 * k + 1]]);
  const listedOf = (tile: number): Point[][] => {
    const listed: Point[][] = [];
    for (let k = 0; k < LISTED_RECORDS; k++) if (((tiles.lists.masks[tile] >>> k) & 1) === 1) listed.push(recordCorners(tiles.lists.records[k]));
    return listed;
  };
  return { classes, bounds, listedOf };
}

/** All records of `hulls` as `classify` made them, each as its corners. */
function recordsOf(hulls: Point[][]): Point[][] {
  const geometry = new ShadowGeometry();
  const made = hulls.map((points) => new Hull(points));
  geometry.update(made);
  const all: Point[][] = [];
  for (let i = 0; i < made.length; i++) {
    geometry.prepare(i);
    for (let r = geometry.firstRecords[i]; r < geometry.firstRecords[i] + geometry.recordCounts[i]; r++) {
      all.push(Array.from({ length: RECORD_POINTS }, (_, k) => [geometry.records[r * RECORD_FLOATS + 2 * k], geometry.records[r * RECORD_FLOATS + 2 * k + 1]]));
    }
  }
  return all;
}

/** Whether the two records have the same corners. */
function sameRecord(a: Point[], b: Point[]): boolean {
  return a.every(([x, y], k) => x === b[k][0] && y === b[k][1]);
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
export function check(c: Case): { wrong: string[]; counts: number[] } {
  const { classes, bounds, listedOf } = classify(c);
  const records = recordsOf(c.hulls);
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
          if (value === TILE_CLASSES.listed) {
            const hides = (record: Point[]) => {
              const recordEdges = edgesOf([record]);
              return insideAny([record], x, y) || shareOfSamplesSeen(x, y, fewSamples, recordEdges, recordEdges.length) < 1;
            };
            // The point's tile and, on a side, the tile across it, whose mask a pixel there may read.
            for (const [ti, tj] of [[i, j], [i + a - 1, j], [i, j + b - 1], [i + a - 1, j + b - 1]]) {
              if (ti < 0 || tj < 0 || ti >= TILE_COLUMNS || tj >= TILE_ROWS) continue;
              const listed = listedOf(tj * TILE_COLUMNS + ti);
              const missing = records.find((record) => !listed.some((other) => sameRecord(record, other)) && hides(record));
              if (missing) wrong.push(`tile (${ti}, ${tj}) beside listed tile (${i}, ${j}) leaves out a record hiding part of the disk from (${x.toFixed(2)}, ${y.toFixed(2)}) or holding it`);
            }
          }
          if (value === TILE_CLASSES.lean || value === TILE_CLASSES.listed) {
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
export function convexAround(random: () => number, x: number, y: number, size: number): Point[] {
  const count = 3 + Math.floor(random() * 4);
  const points: Point[] = [];
  for (let k = 0; k < count; k++) {
    const angle = ((k + (random() - 0.5) * 0.5) / count) * 2 * Math.PI;
    points.push([x + size * Math.cos(angle), y + size * Math.sin(angle)]);
  }
  return points;
}
