import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { PenumbraRenderer } from '../../src/index';
import { createSceneRenderer, setScene } from '../reference/buildScene';
import { compareToReference, type SceneErrors } from '../reference/compareToReference';
import { limitViolations } from '../reference/limits';
import { randomScene } from '../reference/randomScenes';
import type { ReferenceScene } from '../reference/scenes';
import { computeReference } from '../reference/softShadowReference';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

/**
 * Property test: random scenes (convex and concave hulls of any size and rotation, rows of touching
 * tiles, overlapping hulls, open polylines; 1–3 lights of radius 0–30 anywhere outside the hulls, their disks free
 * to overlap them) rendered on headless-gl, each held to the same limits as the fixed reference
 * scenes (test/reference/limits.ts) against the exact CPU reference.
 *
 * Scene i is built from seed PENUMBRA_SEED + i (PENUMBRA_SEED defaults to BASE_SEED; PENUMBRA_SCENES
 * sets how many). A failure names its seed: `PENUMBRA_SEED=<seed> PENUMBRA_SCENES=1` renders that
 * scene alone, on a fresh renderer.
 *
 * Small images keep the reference fast: 120 scenes of 80×60 take seconds. One context and renderer
 * render every scene in turn (a context and its programs cost far more than a scene); each scene
 * replaces every light and hull with new objects, and the last test checks that a scene renders
 * the same on a fresh renderer as after all the others.
 */
const BASE_SEED = 0x5eed;
const SEED = Number(process.env.PENUMBRA_SEED ?? BASE_SEED) >>> 0;
const COUNT = Number(process.env.PENUMBRA_SCENES ?? 120);
const WIDTH = 80, HEIGHT = 60;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;
const results: { seed: number; errors: SceneErrors; violations: string[] }[] = [];

beforeAll(() => {
  gl = createContext(WIDTH, HEIGHT);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], width: WIDTH, height: HEIGHT });
});

afterAll(() => {
  renderer?.dispose();
  if (gl) destroyContext(gl);
  const failed = results.filter((r) => r.violations.length > 0);
  const worst = [...results].sort((a, b) => b.errors.all.max - a.errors.all.max).slice(0, 5);
  console.log([
    `random scenes: ${failed.length} of ${results.length} outside the limits (seeds ${SEED}…${SEED + COUNT - 1})`,
    'worst by max error (seed: mean / p99 / max):',
    ...worst.map((r) => `  ${r.seed}: ${r.errors.all.mean.toFixed(4)} / ${r.errors.all.p99.toFixed(4)} / ${r.errors.all.max.toFixed(4)}`),
  ].join('\n'));
});

function render(scene: ReferenceScene): Float32Array {
  setScene(renderer, scene);
  const lightmap = renderLightmap(gl, renderer, WIDTH, HEIGHT);
  expect(gl.getError()).toBe(0);
  return lightmap.rgb;
}

describe('random scenes on headless-gl', () => {
  for (let i = 0; i < COUNT; i++) {
    const seed = (SEED + i) >>> 0;
    it(`matches the exact reference: seed ${seed}`, () => {
      const scene = randomScene(seed, WIDTH, HEIGHT);
      const errors = compareToReference(scene, render(scene), computeReference(scene));
      const violations = limitViolations(errors);
      results.push({ seed, errors, violations });
      if (violations.length > 0) {
        throw new Error(`seed ${seed}: ${violations.join(', ')}\n`
          + `reproduce alone: PENUMBRA_SEED=${seed} PENUMBRA_SCENES=1 node scripts/with-display.mjs npx vitest run test/gl/randomScenes.test.ts\n`
          + `scene: ${JSON.stringify(scene)}`);
      }
    });
  }

  it('renders a scene the same on a fresh renderer as after the other scenes', () => {
    // Each scene above reuses the renderer that drew the previous ones: its result must not depend on them.
    const scene = randomScene((SEED + COUNT - 1) >>> 0, WIDTH, HEIGHT);
    const reused = render(scene);
    const freshContext = createContext(WIDTH, HEIGHT);
    const fresh = createSceneRenderer(freshContext, scene);
    const alone = renderLightmap(freshContext, fresh, WIDTH, HEIGHT).rgb;
    fresh.dispose();
    destroyContext(freshContext);
    let largest = 0;
    for (let i = 0; i < alone.length; i++) largest = Math.max(largest, Math.abs(alone[i] - reused[i]));
    expect(largest).toBeLessThan(1e-6);
  });
});
