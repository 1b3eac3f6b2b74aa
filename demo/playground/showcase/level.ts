/**
 * The showcase level: a torch-lit hall and a storeroom behind a stone wall with barred windows
 * onto a courtyard, laid out on a grid of {@link TILE} world units. It yields the scene document
 * (hulls and lights, as any preset) and what each hull and light is, so the art can follow them.
 */
import type { SceneDocument, SceneHull, SceneLight, SceneLightBase } from 'penumbra-gl';

/** World units per map cell. */
const TILE = 64;

/**
 * The map: `#` wall, `w` a barred window in a wall, `.` floor; the first row is the courtyard
 * outside (grass, no hulls).
 */
const MAP = [
  '                    ',
  '##ww#######ww#ww####',
  '#...........#......#',
  '#...........#......#',
  '#..................#',
  '#..................#',
  '#...........#......#',
  '#...........#......#',
  '#...........#......#',
  '#...........#......#',
  '#...........#......#',
  '####################',
];

/** The level's extent in world units: the map's columns and rows. */
export const LEVEL_WIDTH = MAP[0].length * TILE;
export const LEVEL_HEIGHT = MAP.length * TILE;
/** Where the floor starts: below the courtyard row. */
export const FLOOR_TOP = TILE;

/** What a hull of the level is, for the art. */
export type HullRole = 'wall' | 'bar' | 'pillar' | 'crate' | 'barrel' | 'table';

/** What a light of the level is. Torches' `facing` is the angle their bracket points (towards the wall). */
export type LightRole =
  | { kind: 'sky' }
  | { kind: 'torch'; facing: number }
  | { kind: 'brazier' }
  | { kind: 'runes' }
  | { kind: 'lantern' };

/** Decoration drawn flat on the floor or on props, with no hull. */
export interface Decor {
  kind: 'rug' | 'books';
  x: number;
  y: number;
  rotation: number;
}

interface Level {
  document: SceneDocument;
  /** One role per hull of the document, in its order. */
  hullRoles: HullRole[];
  /** One role per light of the document, in its order. */
  lightRoles: LightRole[];
  decor: Decor[];
}

type Point = [number, number];

function hull(points: Point[], position: Point, rotation = 0): SceneHull {
  return { points, position, origin: [0, 0], rotation, scale: [1, 1], enabled: true, closed: true, layers: 1 };
}

function box(x: number, y: number, w: number, h: number, rotation = 0): SceneHull {
  return hull([[-w / 2, -h / 2], [w / 2, -h / 2], [w / 2, h / 2], [-w / 2, h / 2]], [x, y], rotation);
}

function round(x: number, y: number, radius: number, sides: number): SceneHull {
  const points: Point[] = [];
  for (let i = 0; i < sides; i++) points.push([Math.cos((i / sides) * Math.PI * 2) * radius, Math.sin((i / sides) * Math.PI * 2) * radius]);
  return hull(points, [x, y]);
}

function light(position: Point, fields: Partial<SceneLightBase>): SceneLightBase {
  return {
    position, range: 300, radius: 8, color: [1, 1, 1], intensity: 1, rotation: 0, origin: [0.5, 0.5],
    shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [],
    shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, falloff: 'smooth', height: null, ...fields,
  };
}

/**
 * Walls as few rectangles: each row's runs of `#`, merged with the run below while it spans the
 * same columns.
 */
function wallRects(): [number, number, number, number][] {
  const open: Map<string, [number, number, number, number]> = new Map();
  const done: [number, number, number, number][] = [];
  MAP.forEach((line, row) => {
    const runs = new Map<string, [number, number, number, number]>();
    for (let col = 0; col < line.length;) {
      if (line[col] !== '#') {
        col++;
        continue;
      }
      const start = col;
      while (col < line.length && line[col] === '#') col++;
      const key = `${start}:${col}`;
      const above = open.get(key);
      if (above) {
        above[3] = row + 1;
        runs.set(key, above);
        open.delete(key);
      } else runs.set(key, [start, row, col, row + 1]);
    }
    done.push(...open.values());
    open.clear();
    for (const [key, rect] of runs) open.set(key, rect);
  });
  done.push(...open.values());
  return done;
}

/** Columns of the windows (first column of each `ww`). */
function windowColumns(): number[] {
  const columns: number[] = [];
  MAP.forEach((line, row) => {
    for (let col = 0; col < line.length; col++) if (line[col] === 'w' && line[col - 1] !== 'w') columns.push(row * 1000 + col);
  });
  return columns;
}

/** Day (1) or night (0): the values {@link Showcase} blends for the ambient and the sky. */
export const NIGHT = { ambient: [0.045, 0.05, 0.08], sky: [0.55, 0.7, 1], skyIntensity: 0.55, elevation: 0.55 } as const;
export const DAY = { ambient: [0.34, 0.32, 0.3], sky: [1, 0.92, 0.78], skyIntensity: 2, elevation: 0.9 } as const;

/** Where the showcase's lights stand. */
const TORCHES: { at: Point; facing: number }[] = [
  { at: [420, 128 + 14], facing: -Math.PI / 2 },
  { at: [150, 704 - 14], facing: Math.PI / 2 },
  { at: [1216 - 14, 360], facing: 0 },
];
const BRAZIER: Point = [430, 430];
const RUNES: Point = [1050, 440];
const LANTERN: Point = [170, 396];

/** Builds the level. */
export function buildLevel(): Level {
  const hulls: SceneHull[] = [];
  const hullRoles: HullRole[] = [];
  const add = (h: SceneHull, role: HullRole) => {
    hulls.push(h);
    hullRoles.push(role);
    return hulls.length - 1;
  };
  for (const [c0, r0, c1, r1] of wallRects()) {
    add(box(((c0 + c1) / 2) * TILE, ((r0 + r1) / 2) * TILE, (c1 - c0) * TILE, (r1 - r0) * TILE), 'wall');
  }
  // Three iron bars across each two-cell window, in the middle of the wall's thickness.
  for (const code of windowColumns()) {
    const row = Math.floor(code / 1000), col = code % 1000;
    for (let i = 1; i <= 3; i++) add(box(col * TILE + i * 32, (row + 0.5) * TILE, 8, 16), 'bar');
  }
  for (const [x, y] of [[270, 300], [600, 300], [270, 570], [600, 570]] as Point[]) add(round(x, y, 36, 12), 'pillar');
  const table = add(box(LANTERN[0], 440, 96, 192), 'table');
  for (const [x, y, r] of [[1160, 186, 0.05], [1096, 178, -0.12], [1164, 250, 0.2], [940, 650, 0.3], [1004, 662, -0.1]] as [number, number, number][]) {
    add(box(x, y, 60, 60, r), 'crate');
  }
  for (const [x, y] of [[1160, 650], [1150, 590], [1096, 660], [730, 190], [780, 200]] as Point[]) add(round(x, y, 28, 12), 'barrel');

  const lights: SceneLight[] = [];
  const lightRoles: LightRole[] = [];
  lights.push({
    kind: 'directional', color: [...NIGHT.sky], intensity: NIGHT.skyIntensity, rotation: Math.PI / 2 + 0.38, angularSize: 0.03, elevation: NIGHT.elevation,
    shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [],
    shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff,
  });
  lightRoles.push({ kind: 'sky' });
  for (const { at, facing } of TORCHES) {
    lights.push({ kind: 'point', ...light(at, { range: 380, radius: 7, color: [1, 0.62, 0.3], intensity: 1.5, height: 70 }) });
    lightRoles.push({ kind: 'torch', facing });
  }
  lights.push({ kind: 'point', ...light(BRAZIER, { range: 460, radius: 20, color: [1, 0.5, 0.2], intensity: 12, falloff: 'inverseSquare', height: 46 }) });
  lightRoles.push({ kind: 'brazier' });
  lights.push({ kind: 'point', ...light(RUNES, { range: 240, radius: 30, color: [0.3, 0.75, 1], intensity: 0.9, height: 16 }) });
  lightRoles.push({ kind: 'runes' });
  lights.push({ kind: 'point', ...light(LANTERN, { range: 200, radius: 4, color: [1, 0.8, 0.45], intensity: 1, ignoredHulls: [table], height: 40 }) });
  lightRoles.push({ kind: 'lantern' });

  const document: SceneDocument = {
    format: 'penumbra-scene', version: 3, ambient: [...NIGHT.ambient], camera: { center: [LEVEL_WIDTH / 2, LEVEL_HEIGHT / 2], zoom: 0.8 },
    hulls, lights, look: { exposure: 1.3, toneMapping: 'aces', dithering: 'none', lightmapBlur: 0 }, app: {},
  };
  const decor: Decor[] = [
    { kind: 'rug', x: 435, y: 610, rotation: Math.PI / 2 },
    { kind: 'books', x: LANTERN[0], y: 480, rotation: Math.PI / 2 },
  ];
  return { document, hullRoles, lightRoles, decor };
}
