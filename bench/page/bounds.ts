import { PenumbraRenderer, type Hull, type Light, type PenumbraRendererOptions } from '../../src/index';
import { shaderSources } from '../../src/passes/shaders';

/**
 * The renderer's frame with part of its work taken away, to show what is left to win: a bound on
 * what any faster shadow shading could give.
 * - `trivialShading`: every shadow-mask shading stage (region, edge and cavity fragments) writes a
 *   constant instead of the hidden part of the disk. The shadow quads, their vertex work, the umbra
 *   prepass, depth tests, blending and every other pass are the real ones.
 * - `noHulls`: the same lights and no hulls: the light pass and composite alone.
 */
export interface FrameBounds {
  trivialShading: PenumbraRenderer;
  noHulls: PenumbraRenderer;
}

const SHADING_STAGES: ReadonlySet<string> = new Set([
  ...shaderSources.shadowHullFragment,
  ...shaderSources.shadowConcaveFragment,
  ...shaderSources.shadowEdgesFragment,
  ...shaderSources.shadowCavityFragment,
]);

/** A shading stage that keeps its declarations (so the program links as before) and writes a mask constant. */
function withConstantMask(source: string): string {
  const main = source.lastIndexOf('void main()');
  if (main < 0) throw new Error('bench bounds: a shadow shading stage has no main()');
  return `${source.slice(0, main)}void main() {\n  o_mask = vec4(0.5, 0.0, 0.0, 0.0);\n}\n`;
}

/**
 * `gl` as a renderer built on it sees it: the same context, except that the shadow shading stages'
 * sources are swapped for constant ones when they are compiled (and added to `swapped`).
 */
function withTrivialShading(gl: WebGL2RenderingContext, swapped: Set<string>): WebGL2RenderingContext {
  const methods = new Map<PropertyKey, unknown>();
  const shaderSource = (shader: WebGLShader, source: string) => {
    const isShading = SHADING_STAGES.has(source);
    if (isShading) swapped.add(source);
    gl.shaderSource(shader, isShading ? withConstantMask(source) : source);
  };
  return new Proxy(gl, {
    get(target, key) {
      if (key === 'shaderSource') return shaderSource;
      const value: unknown = Reflect.get(target, key);
      if (typeof value !== 'function') return value;
      // Bound once: the frame makes thousands of calls.
      if (!methods.has(key)) methods.set(key, value.bind(target));
      return methods.get(key);
    },
  });
}

export function createFrameBounds(gl: WebGL2RenderingContext, options: PenumbraRendererOptions, lights: readonly Light[], hulls: readonly Hull[]): FrameBounds {
  const swapped = new Set<string>();
  const trivialShading = new PenumbraRenderer(withTrivialShading(gl, swapped), options);
  // The renderer links its programs when it is built; a stage it no longer uses would make this bound the full frame.
  if (swapped.size !== SHADING_STAGES.size) throw new Error(`bench bounds: ${swapped.size} of the ${SHADING_STAGES.size} shadow shading stages were compiled`);
  const noHulls = new PenumbraRenderer(gl, options);
  for (const light of lights) {
    trivialShading.addLight(light);
    noHulls.addLight(light);
  }
  for (const hull of hulls) trivialShading.addHull(hull);
  return { trivialShading, noHulls };
}

export function disposeFrameBounds(bounds: FrameBounds): void {
  bounds.trivialShading.dispose();
  bounds.noHulls.dispose();
}
