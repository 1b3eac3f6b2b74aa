// The cases of `node bench/illumination.mjs`: what `renderer.illuminationAt` and `isLit` cost on the
// CPU, as a game would call them: a few hundred points a frame in an animated scene. Each frame
// moves every light and one hull in ten (bench/scenes.ts), so the first query of a frame rebuilds
// the hull grid; then every query reads each hull's version once. The query object is the one the
// renderer forwards to (src/scene/illumination.ts), driven without a GL context.
import type { Hull } from '../src/scene/Hull';
import { IlluminationQuery, type Illumination, type IlluminationOptions } from '../src/scene/illumination';
import type { Light } from '../src/scene/Light';
import { createScene, seededRandom, WORLD_HEIGHT, WORLD_WIDTH, type SceneSpec } from './scenes';

/** Queries per frame. */
export const POINTS_PER_FRAME = 300;

interface IlluminationCase {
  /** The scene's lights and hulls, for the table. */
  describe(): string;
  /** Runs one frame (moves the scene, then the queries) and returns the milliseconds of the queries. */
  frame(): number;
  /** Share of the last frame's points that some light lit (isLit: above the threshold). */
  reached(): number;
}

const AMBIENT = Object.freeze([0.1, 0.1, 0.15] as const);
const AMBIENT_LUMINANCE = 0.2126 * AMBIENT[0] + 0.7152 * AMBIENT[1] + 0.0722 * AMBIENT[2];

type Mode = 'sum' | 'perLight' | 'isLit' | 'still';

function illuminationCase(spec: SceneSpec, mode: Mode): IlluminationCase {
  const scene = createScene(spec);
  // The bench's scene types are the public API's subset; these are the library's own objects.
  const lights = scene.lights as unknown as Light[], hulls = scene.hulls as unknown as Hull[];
  const query = new IlluminationQuery();
  const random = seededRandom(7);
  const points = new Float64Array(2 * POINTS_PER_FRAME);
  const out: Illumination = { color: [0, 0, 0], luminance: 0, lights: [] };
  const options: IlluminationOptions = { perLight: mode === 'perLight' };
  let frameNumber = 0, reached = 0;
  return {
    describe: () => `${spec.lights} lights, ${spec.hulls + spec.farHulls} hulls${spec.farHulls > 0 ? ` (${spec.farHulls} out of every light's range)` : ''}`,
    frame: () => {
      if (mode !== 'still' || frameNumber === 0) scene.step(frameNumber);
      frameNumber++;
      for (let i = 0; i < points.length; i += 2) {
        points[i] = random() * WORLD_WIDTH;
        points[i + 1] = random() * WORLD_HEIGHT;
      }
      reached = 0;
      const start = performance.now();
      if (mode === 'isLit') {
        for (let i = 0; i < points.length; i += 2) if (query.isLit(lights, hulls, points[i], points[i + 1], 0.1, null)) reached++;
      } else {
        for (let i = 0; i < points.length; i += 2) {
          if (query.at(lights, hulls, AMBIENT, points[i], points[i + 1], options, out).luminance > AMBIENT_LUMINANCE + 1e-9) reached++;
        }
      }
      return performance.now() - start;
    },
    reached: () => reached / POINTS_PER_FRAME,
  };
}

const PLAYGROUND: SceneSpec = { name: 'playground-like', lights: 10, hulls: 50, farHulls: 0 };
const S2: SceneSpec = { name: 'S2', lights: 32, hulls: 200, farHulls: 0 };
const S2_SUN: SceneSpec = { ...S2, name: 'S2-sun', sun: true };
const S3: SceneSpec = { name: 'S3', lights: 128, hulls: 1000, farHulls: 0 };
const S3_SPARSE: SceneSpec = { name: 'S3-sparse', lights: 128, hulls: 1000, farHulls: 10000 };

/** Each case: a scene and how it is asked (see the table's legend in bench/illumination.mjs). */
export const CASES: Record<string, () => IlluminationCase> = {
  'playground-like: illuminationAt, sum only': () => illuminationCase(PLAYGROUND, 'sum'),
  'playground-like: illuminationAt, per light': () => illuminationCase(PLAYGROUND, 'perLight'),
  'playground-like: isLit(0.1)': () => illuminationCase(PLAYGROUND, 'isLit'),
  'playground-like: illuminationAt, scene still': () => illuminationCase(PLAYGROUND, 'still'),
  'S2: illuminationAt, sum only': () => illuminationCase(S2, 'sum'),
  'S2 with a sun: illuminationAt, sum only': () => illuminationCase(S2_SUN, 'sum'),
  'S2 with a sun: isLit(0.1)': () => illuminationCase(S2_SUN, 'isLit'),
  'S3 (stress): illuminationAt, sum only': () => illuminationCase(S3, 'sum'),
  'S3 (stress): isLit(0.1)': () => illuminationCase(S3, 'isLit'),
  'S3-sparse (stress): illuminationAt, sum only': () => illuminationCase(S3_SPARSE, 'sum'),
  'S3-sparse (stress): illuminationAt, scene still': () => illuminationCase(S3_SPARSE, 'still'),
};
