import { describe, expect, it } from 'vitest';
import { DirectionalLight, Hull, PenumbraRenderer, ShadowType } from '../../src/index';
import { compareToReference } from '../reference/compareToReference';
import { computeDirectionalReference, type DirectionalReferenceScene } from '../reference/directionalReference';
import { limitViolations, UMBRA_LIMIT } from '../reference/limits';
import { box, type Point, type ReferenceScene } from '../reference/scenes';
import { UMBRA } from '../reference/softShadowReference';
import { uShape } from '../reference/occludedReference';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// The directional light against the reference that samples its disk at infinity
// (test/reference/directionalReference.ts), held to the limits of every reference scene
// (test/reference/limits.ts) over the whole view.
const WIDTH = 160, HEIGHT = 120;
const tiles = (x: number, y: number, count: number, size: number): Point[][] => Array.from({ length: count }, (_, i) => box(x, y + i * size, size, size));

type Scene = DirectionalReferenceScene & { tileWall?: boolean };
const scene = (name: string, light: Scene['light'], hulls: Point[][], extra: Partial<Scene> = {}): Scene => ({
  name, width: WIDTH, height: HEIGHT, light, shadowType: 'solid', hulls, ...extra,
});

const SCENES: Scene[] = [
  scene('a wall under a low sun', { rotation: 0.3, angularSize: 0.1 }, [box(40, 30, 10, 40)]),
  scene('a row of posts under a hard noon sun', { rotation: Math.PI / 2, angularSize: 0 }, [box(30, 20, 6, 6), box(60, 24, 6, 6), box(90, 20, 6, 6), box(120, 28, 6, 6)]),
  scene('crates under an overcast sky', { rotation: 2.2, angularSize: 0.6, color: [0.6, 0.7, 1] }, [box(50, 40, 20, 20), box(95, 60, 16, 24), [[120, 30], [140, 36], [128, 50]]]),
  scene('a hull far upstream, out of view, shadows into it', { rotation: 0.05, angularSize: 0.03 }, [box(-400, 40, 20, 30)]),
  scene('a wall of touching tiles lets no light through', { rotation: -0.2, angularSize: 0.08 }, tiles(60, 10, 12, 8), { tileWall: true }),
  scene('a concave building under the sun with Occluded hulls', { rotation: 0.4, angularSize: 0.12 }, [uShape(30, 30, 70, 56, 14, 32), box(120, 20, 14, 14)], { shadowType: 'occluded' }),
  scene('Illuminated hulls are lit and cast shadows', { rotation: -2.5, angularSize: 0.2 }, [box(70, 50, 24, 16), [[30, 80], [50, 70], [44, 100]]], { shadowType: 'illuminated' }),
  scene('fences and posts across a slanted sun', { rotation: 0.9, angularSize: 0.05 }, [box(100, 80, 8, 8)], { polylines: [[[20, 40], [60, 30], [80, 50]], [[110, 20], [140, 25]]] }),
];

const SHADOW_TYPES = { solid: ShadowType.Solid, illuminated: ShadowType.Illuminated, occluded: ShadowType.Occluded } as const;

function render(source: Scene): Float32Array {
  const gl = createContext(WIDTH, HEIGHT);
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], width: WIDTH, height: HEIGHT });
  // Each hull placed at its centre, so its coarse bounds (around its position) are as tight as its
  // points': the search for hulls upstream, not a loose box, must find the far ones.
  for (const points of source.hulls) renderer.addHull(centredHull(points));
  for (const points of source.polylines ?? []) renderer.addHull(new Hull(points, { closed: false }));
  const { rotation, angularSize, color, intensity } = source.light;
  renderer.addLight(new DirectionalLight({ rotation, angularSize, color, intensity, shadowType: SHADOW_TYPES[source.shadowType] }));
  const { rgb } = renderLightmap(gl, renderer, WIDTH, HEIGHT);
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
  return rgb;
}

function centredHull(points: Point[]): Hull {
  const cx = points.reduce((sum, p) => sum + p[0], 0) / points.length, cy = points.reduce((sum, p) => sum + p[1], 0) / points.length;
  return new Hull(points.map(([x, y]): Point => [x - cx, y - cy]), { position: [cx, cy] });
}

/** The scene as compareToReference counts full light: one light of the sun's colour × intensity. */
function asReferenceScene(source: Scene): ReferenceScene {
  const { color, intensity } = source.light;
  return { name: source.name, width: WIDTH, height: HEIGHT, hulls: source.hulls, lights: [{ position: [0, 0], range: 1, radius: 0, color, intensity }] };
}

describe('a directional light matches the reference that samples its disk at infinity (headless-gl)', () => {
  for (const source of SCENES) {
    it(source.name, () => {
      const reference = computeDirectionalReference(source);
      const rendered = render(source);
      const errors = compareToReference(asReferenceScene(source), rendered, reference);
      console.log(`${source.name.padEnd(58)} mean ${errors.all.mean.toFixed(4)} p99 ${errors.all.p99.toFixed(4)} max ${errors.all.max.toFixed(4)}`);
      expect(limitViolations(errors), JSON.stringify(errors)).toEqual([]);
      // Each scene has shadow to test: penumbra or umbra pixels the reference is sure of.
      expect(errors.penumbra.pixels + errors.umbra.pixels).toBeGreaterThan(200);
      if (source.tileWall) {
        let leak = 0;
        for (let pixel = 0; pixel < WIDTH * HEIGHT; pixel++) {
          if (reference.shade[pixel] === UMBRA && !reference.ambiguous[pixel]) leak = Math.max(leak, rendered[3 * pixel]);
        }
        expect(leak).toBeLessThanOrEqual(UMBRA_LIMIT);
      }
    });
  }
});
