import { CURRENT, type BenchHull, type BenchLight, type RendererLibrary } from './library';

/** The benchmark world, in pixels (the renderer's default view maps it 1:1 onto a canvas of this size). */
export const WORLD_WIDTH = 1280;
export const WORLD_HEIGHT = 720;

/** One benchmark scene: how many lights and hulls, and how many extra hulls lie out of every light's range. */
export interface SceneSpec {
  name: string;
  lights: number;
  hulls: number;
  /** Hulls placed beyond the reach of every light (the "sparse" variant). */
  farHulls: number;
  /** Adds a low sun (a `DirectionalLight`) over the whole world: what it costs on top of the lights. */
  sun?: boolean;
  /**
   * Set on a normal-mapped variant: the name of the same scene without normals, which the table
   * compares it to. The renderer is made with `normals: true` and the page's scene writes a normal
   * and a material (specular on) for every pixel (bench/page/surface.ts). Chromium only: headless-gl
   * cannot draw into several attachments.
   */
  normalsOf?: string;
  /** Every light whose index is a multiple of this moves each frame (default 1: all); 0: none. */
  movingLightStride?: number;
  /** Every hull whose index is a multiple of this moves or rotates each frame (default 10: one in ten); 0: none. */
  movingHullStride?: number;
  /** The game-like level instead of random lights and hulls (see `createLevel`; `lights` and `hulls` then say what it holds). */
  level?: boolean;
}

/** `spec` lit through normals: the same lights and hulls, every pixel of the floor normal-mapped. */
function withNormals(spec: SceneSpec): SceneSpec {
  return { ...spec, name: `${spec.name}-normals`, normalsOf: spec.name };
}

/** Wall torches of the level: small disks on the walls' faces, in the rooms. */
const LEVEL_TORCHES = 24;
/** The level's tiles, in pixels: the world is 40 × 22 of them (and a half row). */
const TILE = 32;
const LEVEL_COLUMNS = 40, LEVEL_ROWS = 22;

const S2: SceneSpec = { name: 'S2', lights: 32, hulls: 200, farHulls: 0 };
const S3: SceneSpec = { name: 'S3', lights: 128, hulls: 1000, farHulls: 0 };

export const SCENES: readonly SceneSpec[] = [
  { name: 'level', lights: LEVEL_TORCHES + 1, hulls: 0, farHulls: 0, level: true },
  { name: 'S1', lights: 8, hulls: 40, farHulls: 0 },
  S2,
  S3,
  { name: 'S3-sparse', lights: 128, hulls: 1000, farHulls: 10000 },
  { name: 'S4', lights: 512, hulls: 4000, farHulls: 0 },
  // S4 as a level with wall torches: one light in sixteen moves (the players'), the hulls stand still.
  { name: 'S4-still', lights: 512, hulls: 4000, farHulls: 0, movingLightStride: 16, movingHullStride: 0 },
  { name: 'S2-sun', lights: 32, hulls: 200, farHulls: 0, sun: true },
  { name: 'S3-sun', lights: 128, hulls: 1000, farHulls: 0, sun: true },
  withNormals(S2),
  withNormals(S3),
];

/**
 * Whether `library` can build `spec`: a sun needs its `DirectionalLight`, normals its
 * `SURFACE_GLSL` (a renderer from before normals would take `normals: true` and ignore it).
 */
export function runsOn(spec: SceneSpec, library: RendererLibrary): boolean {
  return (!spec.sun || library.DirectionalLight !== undefined) && (spec.normalsOf === undefined || library.SURFACE_GLSL !== undefined);
}

/** Whether `spec` runs on headless-gl (the Node and GPU modes): not with normals, which need several colour attachments. */
export function runsOnHeadlessGl(spec: SceneSpec): boolean {
  return spec.normalsOf === undefined;
}

/** Every hull whose index is a multiple of this moves or rotates each frame ("one hull in ten"), unless the scene says otherwise. */
const MOVING_HULL_STRIDE = 10;
/** Far hulls start this far right of the world: beyond the longest light range plus its wander. */
const FAR_OFFSET = 1000;
/** How far a light (12 pixels) and a hull (6 pixels) wander from their anchors. */
const WANDER = 12 + 6;
/** Tries at a spot clear of every light before a hull keeps its last one (rare even in S4). */
const PLACEMENT_TRIES = 64;

/** A deterministic scene and its per-frame animation, which allocates nothing. */
export interface BenchScene {
  spec: SceneSpec;
  lights: BenchLight[];
  hulls: BenchHull[];
  /** Moves the scene's moving lights a little and its moving hulls (see `SceneSpec`), for frame number `frame`. */
  step(frame: number): void;
}

/** Mulberry32: a small seeded generator, so every run builds the same scene. */
export function seededRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * Builds `spec` from `seed` with `library`'s classes (each renderer compared gets its own copy of
 * the same scene): lights of range 150–350 and radius 5–25; hulls mostly convex (3–5 points), one
 * in eight concave, placed so that no light centre is ever inside one.
 */
export function createScene(spec: SceneSpec, library: RendererLibrary = CURRENT, seed = 1): BenchScene {
  if (spec.level) return createLevel(spec, library, seed);
  const { Hull, PointLight } = library;
  const random = seededRandom(seed);
  const between = (low: number, high: number) => low + (high - low) * random();
  const lights: BenchLight[] = [];
  const anchors = new Float64Array(spec.lights * 3);
  for (let i = 0; i < spec.lights; i++) {
    const x = between(0, WORLD_WIDTH), y = between(0, WORLD_HEIGHT);
    anchors.set([x, y, between(0, Math.PI * 2)], i * 3);
    lights.push(new PointLight({
      position: [x, y], range: between(150, 350), radius: between(5, 25),
      color: [between(0.3, 1), between(0.3, 1), between(0.3, 1)], intensity: 0.6,
    }));
  }
  if (spec.sun) {
    if (!library.DirectionalLight) throw new Error(`scene ${spec.name} needs a DirectionalLight`);
    // Low and soft (2.9°), so that shadows run long across the world and have wide penumbrae.
    lights.push(new library.DirectionalLight({ rotation: 0.5, angularSize: 0.05, color: [1, 0.9, 0.7], intensity: 0.5 }));
  }
  const hulls: BenchHull[] = [];
  const hullAnchors: number[] = [];
  const total = spec.hulls + spec.farHulls;
  for (let i = 0; i < total; i++) {
    const far = i >= spec.hulls;
    const shape = random() < 1 / 8 ? concaveShape(between) : convexShape(between);
    // Hulls turn around their position: a light anchor this far away never ends up inside one.
    const clearance = reach(shape) + WANDER;
    let x = 0, y = 0;
    for (let attempt = 0; attempt < PLACEMENT_TRIES; attempt++) {
      x = far ? WORLD_WIDTH + FAR_OFFSET + between(0, WORLD_WIDTH * 10) : between(0, WORLD_WIDTH);
      y = between(0, WORLD_HEIGHT);
      if (far || clearOfLights(anchors, x, y, clearance)) break;
    }
    const rotation = between(0, Math.PI * 2);
    hulls.push(new Hull(shape, { position: [x, y], rotation }));
    hullAnchors.push(x, y, rotation);
  }
  const position: [number, number] = [0, 0];
  return {
    spec, lights, hulls,
    step(frame) {
      const lightStride = spec.movingLightStride ?? 1, hullStride = spec.movingHullStride ?? MOVING_HULL_STRIDE;
      for (let i = 0; lightStride > 0 && i < spec.lights; i += lightStride) {
        const phase = anchors[i * 3 + 2] + frame * 0.05;
        lights[i].setPosition(anchors[i * 3] + 12 * Math.cos(phase), anchors[i * 3 + 1] + 12 * Math.sin(phase));
      }
      for (let i = 0; hullStride > 0 && i < hulls.length; i += hullStride) {
        const phase = frame * 0.03 + i;
        position[0] = hullAnchors[i * 3] + 6 * Math.sin(phase);
        position[1] = hullAnchors[i * 3 + 1];
        hulls[i].position = position;
        hulls[i].rotation = hullAnchors[i * 3 + 2] + phase;
      }
    },
  };
}

/** Whether `(x, y)` is at least `clearance` from every light anchor (`[x, y, phase]` triples). */
function clearOfLights(anchors: Float64Array, x: number, y: number, clearance: number): boolean {
  for (let i = 0; i < anchors.length; i += 3) {
    const dx = anchors[i] - x, dy = anchors[i + 1] - y;
    if (dx * dx + dy * dy < clearance * clearance) return false;
  }
  return true;
}

/** Largest distance of a shape's points from its origin. */
function reach(shape: [number, number][]): number {
  let farthest = 0;
  for (const [x, y] of shape) farthest = Math.max(farthest, Math.sqrt(x * x + y * y));
  return farthest;
}

type Between = (low: number, high: number) => number;

/** A convex polygon of 3–5 points around the origin, 6–14 pixels across its radius. */
function convexShape(between: Between): [number, number][] {
  const count = 3 + Math.floor(between(0, 3));
  const radius = between(6, 14);
  const points: [number, number][] = [];
  for (let k = 0; k < count; k++) {
    const angle = (k + between(-0.25, 0.25)) / count * Math.PI * 2;
    points.push([radius * Math.cos(angle), radius * Math.sin(angle)]);
  }
  return points;
}

/** An L-shaped concave polygon of 6 points. */
function concaveShape(between: Between): [number, number][] {
  const w = between(12, 24), h = between(12, 24), t = between(4, 8);
  return [[0, 0], [w, 0], [w, t], [t, t], [t, h], [0, h]];
}

/**
 * A top-down dungeon level like a game's, at 32-px tiles over the world: an outer wall, six rooms
 * between two inner walls across and one along, joined by doorways; the walls as boxes (each run
 * of wall tiles in a row one box), 40 crates of 14–24 px, LEVEL_TORCHES torches of radius 3–6 and
 * range 180–260 six pixels off the walls' faces, a player lamp of radius 10 and range 420 that
 * walks a loop through the rooms, and one door (a box in the middle doorway of the wall across)
 * that slides open and shut every 90 frames. Everything but the lamp and the door stands still.
 */
function createLevel(spec: SceneSpec, library: RendererLibrary, seed: number): BenchScene {
  const { Hull, PointLight } = library;
  const random = seededRandom(seed);
  const between = (low: number, high: number) => low + (high - low) * random();
  const wall = (column: number, row: number): boolean => {
    if (column === 0 || row === 0 || column === LEVEL_COLUMNS - 1 || row === LEVEL_ROWS - 1) return true;
    // Inner walls along columns 13 and 26, with doorways at rows 5–6 and 15–16; across row 11, with doorways.
    if ((column === 13 || column === 26) && !(row >= 5 && row <= 6) && !(row >= 15 && row <= 16)) return true;
    return row === 11 && ![6, 7, 19, 20, 32, 33].includes(column);
  };
  const hulls: BenchHull[] = [];
  const box = (x: number, y: number, w: number, h: number): [number, number][] => [[x, y], [x + w, y], [x + w, y + h], [x, y + h]];
  for (let row = 0; row < LEVEL_ROWS; row++) {
    for (let column = 0; column < LEVEL_COLUMNS; column++) {
      if (!wall(column, row)) continue;
      let end = column;
      while (end + 1 < LEVEL_COLUMNS && wall(end + 1, row)) end++;
      hulls.push(new Hull(box(column * TILE, row * TILE, (end - column + 1) * TILE, TILE)));
      column = end;
    }
  }
  // The lamp's loop: the centres of the rooms, through the doorways.
  const path: [number, number][] = [[208, 176], [416, 192], [624, 176], [832, 192], [1040, 176], [1056, 352], [1040, 528], [832, 512], [624, 528], [416, 512], [208, 528], [224, 352]];
  const nearPath = (x: number, y: number) => path.some(([px, py], k) => {
    const [qx, qy] = path[(k + 1) % path.length];
    const ex = qx - px, ey = qy - py, t = Math.max(0, Math.min(1, ((x - px) * ex + (y - py) * ey) / (ex * ex + ey * ey)));
    return Math.hypot(x - px - t * ex, y - py - t * ey) < 60;
  });
  const lights: BenchLight[] = [];
  for (let i = 0; i < LEVEL_TORCHES; i++) {
    // On the face of a wall tile next to a floor tile, in a room.
    let x = 0, y = 0;
    for (let attempt = 0; attempt < 1000; attempt++) {
      const column = 1 + Math.floor(random() * (LEVEL_COLUMNS - 2)), row = 1 + Math.floor(random() * (LEVEL_ROWS - 2));
      if (wall(column, row)) continue;
      const side = Math.floor(random() * 4), dx = [1, -1, 0, 0][side], dy = [0, 0, 1, -1][side];
      if (!wall(column + dx, row + dy)) continue;
      x = (column + 0.5) * TILE + dx * (TILE / 2 - 6);
      y = (row + 0.5) * TILE + dy * (TILE / 2 - 6);
      break;
    }
    lights.push(new PointLight({ position: [x, y], range: between(180, 260), radius: between(3, 6), color: [1, between(0.55, 0.75), between(0.25, 0.4)], intensity: 0.7 }));
  }
  const lamp = new PointLight({ position: path[0], range: 420, radius: 10, color: [0.9, 0.95, 1], intensity: 0.8 });
  lights.push(lamp);
  for (let placed = 0; placed < 40;) {
    const size = between(14, 24), x = between(TILE, WORLD_WIDTH - TILE - size), y = between(TILE, LEVEL_ROWS * TILE - TILE - size);
    const column0 = Math.floor(x / TILE), column1 = Math.floor((x + size) / TILE), row0 = Math.floor(y / TILE), row1 = Math.floor((y + size) / TILE);
    if (wall(column0, row0) || wall(column1, row0) || wall(column0, row1) || wall(column1, row1) || nearPath(x + size / 2, y + size / 2)) continue;
    if (lights.some((light) => Math.hypot(light.position[0] - x - size / 2, light.position[1] - y - size / 2) < size + 12)) continue;
    hulls.push(new Hull(box(0, 0, size, size), { position: [x, y], rotation: between(-0.3, 0.3) }));
    placed++;
  }
  // The door fills the doorway of row 11, columns 19–20 (off the lamp's loop), and slides left into the wall to open.
  const door = new Hull(box(0, 0, 2 * TILE, 12), { position: [19 * TILE, 11 * TILE + 10] });
  hulls.push(door);
  const doorAt: [number, number] = [0, 0];
  let perimeter = 0;
  const legs = path.map(([px, py], k) => {
    const [qx, qy] = path[(k + 1) % path.length];
    const length = Math.hypot(qx - px, qy - py);
    perimeter += length;
    return length;
  });
  return {
    spec: { ...spec, hulls: hulls.length },
    lights, hulls,
    step(frame) {
      let along = (frame * 3) % perimeter, k = 0;
      while (along > legs[k]) along -= legs[k++];
      const [px, py] = path[k], [qx, qy] = path[(k + 1) % path.length], t = along / legs[k];
      lamp.setPosition(px + t * (qx - px), py + t * (qy - py));
      doorAt[0] = 19 * TILE - (Math.floor(frame / 90) % 2 === 1 ? 2 * TILE - 4 : 0);
      doorAt[1] = 11 * TILE + 10;
      if (door.position[0] !== doorAt[0]) door.position = doorAt;
    },
  };
}
