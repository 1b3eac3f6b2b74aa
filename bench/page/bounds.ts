import { shaderSources } from '../../src/passes/shaders';
import { CURRENT, type BenchHull, type BenchLight, type BenchRenderer, type BenchRendererOptions } from '../library';

/**
 * The renderer's frame with part of its work taken away, to show what is left to win: a bound on
 * what any faster shadow shading could give.
 * - `trivialShading`: every shadow-mask shading stage (region, edge and cavity fragments) writes a
 *   constant instead of the hidden part of the disk. The shadow quads, their vertex work, the umbra
 *   prepass, depth tests, blending and every other pass are the real ones.
 * - `noHulls`: the same lights and no hulls: the light pass and composite alone.
 */
export interface FrameBounds {
  /** Null when the renderer has no separate shadow shading stages (see SHADING_STAGES). */
  trivialShading: BenchRenderer | null;
  noHulls: BenchRenderer;
}

/**
 * The shadow-mask shading stages: every source (or variant) under a `shadow…Fragment` key of
 * `shaderSources`, each writing `o_mask` (the core of 8d3feef). A core without such stages (the
 * shadow core v2 shades shadows in the light pass) gets no trivial-shading bound: '–'.
 */
const SHADING_STAGES: ReadonlySet<string> = new Set(
  Object.entries(shaderSources as Record<string, unknown>)
    .filter(([key]) => /^shadow\w*Fragment$/.test(key))
    .flatMap(([, value]) => (typeof value === 'string' ? [value] : value && typeof value === 'object' ? Object.values(value) : []))
    .filter((source): source is string => typeof source === 'string' && source.includes('o_mask')),
);

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

/** Bounds for the working tree's renderer (they reach into its shader sources); `lights` and `hulls` made with CURRENT. */
export function createFrameBounds(gl: WebGL2RenderingContext, options: BenchRendererOptions, lights: readonly BenchLight[], hulls: readonly BenchHull[]): FrameBounds {
  let trivialShading: BenchRenderer | null = null;
  if (SHADING_STAGES.size > 0) {
    const swapped = new Set<string>();
    trivialShading = new CURRENT.PenumbraRenderer(withTrivialShading(gl, swapped), options);
    // The renderer links its programs when it is built; a stage it no longer uses would make this bound the full frame.
    if (swapped.size !== SHADING_STAGES.size) throw new Error(`bench bounds: ${swapped.size} of the ${SHADING_STAGES.size} shadow shading stages were compiled`);
    for (const light of lights) trivialShading.addLight(light);
    for (const hull of hulls) trivialShading.addHull(hull);
  }
  const noHulls = new CURRENT.PenumbraRenderer(gl, options);
  for (const light of lights) noHulls.addLight(light);
  return { trivialShading, noHulls };
}

export function disposeFrameBounds(bounds: FrameBounds): void {
  bounds.trivialShading?.dispose();
  bounds.noHulls.dispose();
}
