import { describe, expect, it } from 'vitest';
import { compareToReference } from '../reference/compareToReference';
import { createDirectionalSceneRenderer } from '../reference/buildScene';
import { asLitScene, computeDirectionalReference, DIRECTIONAL_SCENES, type DirectionalScene } from '../reference/directionalReference';
import { limitViolations, UMBRA_LIMIT } from '../reference/limits';
import { UMBRA } from '../reference/softShadowReference';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// The directional light against the reference that samples its disk at infinity
// (test/reference/directionalReference.ts), held to the limits of every reference scene
// (test/reference/limits.ts) over the whole view. The Chromium reference test renders the same scenes.
function render(source: DirectionalScene): Float32Array {
  const gl = createContext(source.width, source.height);
  const renderer = createDirectionalSceneRenderer(gl, source);
  const { rgb } = renderLightmap(gl, renderer, source.width, source.height);
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
  return rgb;
}

describe('a directional light matches the reference that samples its disk at infinity (headless-gl)', () => {
  for (const source of DIRECTIONAL_SCENES) {
    it(source.name, () => {
      const reference = computeDirectionalReference(source);
      const rendered = render(source);
      const errors = compareToReference(asLitScene(source), rendered, reference);
      console.log(`${source.name.padEnd(58)} mean ${errors.all.mean.toFixed(4)} p99 ${errors.all.p99.toFixed(4)} max ${errors.all.max.toFixed(4)}`);
      expect(limitViolations(errors), JSON.stringify(errors)).toEqual([]);
      // Each scene has shadow to test: penumbra or umbra pixels the reference is sure of.
      expect(errors.penumbra.pixels + errors.umbra.pixels).toBeGreaterThan(200);
      if (source.tileWall) {
        let leak = 0;
        for (let pixel = 0; pixel < source.width * source.height; pixel++) {
          if (reference.shade[pixel] === UMBRA && !reference.ambiguous[pixel]) leak = Math.max(leak, rendered[3 * pixel]);
        }
        expect(leak).toBeLessThanOrEqual(UMBRA_LIMIT);
      }
    });
  }
});
