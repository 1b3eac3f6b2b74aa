import { mat4 } from 'gl-matrix';
import { createContext, destroyContext } from '../test/gl/context';
import { readExtraStats, type ExtraStats } from './extraStats';
import { answerVertexArrayLikeBrowsers, probeCalls, stubCalls } from './glProbe';
import type { BenchRenderer, RendererLibrary } from './library';
import { createScene, WORLD_HEIGHT, WORLD_WIDTH, type SceneSpec } from './scenes';
import { summarize, type Summary } from './stats';

/** What the Node run measures for one scene. */
export interface CpuResult {
  /**
   * The renderer's own JavaScript time per frame, ms: `renderLightmap()` with every GL call stubbed
   * out (see `stubCalls`), so neither headless-gl nor its software rasterizer (which blocks in the
   * call that needs a finished mask) is in it; the browser figures account for those.
   */
  js: Summary;
  /** Time inside the real GL calls per frame, ms (headless-gl's JavaScript layer, driver, rasterizer). */
  gl: Summary;
  /** GL calls per frame made by the renderer. */
  glCalls: number;
  /**
   * Heap bytes allocated per frame by `renderLightmap()` in steady state, GL calls stubbed out (see
   * `stubCalls`; null when a GC spoiled every attempt). The WebGL API's own answers are not
   * counted: in a browser `getParameter` returns three fresh arrays per saved host state.
   */
  heapBytesPerFrame: number | null;
  lightsDrawn: number;
  edges: number;
  /** The renderer's optional figures (see bench/extraStats.ts) after the last real-GL frame. */
  extra: ExtraStats;
}

interface CpuOptions {
  warmup: number;
  frames: number;
}

/**
 * Target size divisor: the JavaScript work (culling, geometry, uploads, submission) is the same at
 * any resolution, while the software rasterizer's share (excluded from the figure anyway) would
 * make a 1280×720 run of S4 take hours.
 */
const TARGET_DIVISOR = 8;

/** Frames run before the heap is measured, or as many as fit in the time (S4 gets fewer). */
const HEAP_WARMUP_FRAMES = 6000;
const HEAP_WARMUP_MS = 20_000;

/** Frames run on the real context to count GL calls and time them. */
const PROBED_FRAMES = 10;

/** One renderer on its own headless-gl context with its own copy of the scene. */
interface Contender {
  gl: WebGL2RenderingContext;
  renderer: BenchRenderer;
  /** Advances the scene a frame and lets the rasterizer drain. */
  step(): void;
}

function createContender(spec: SceneSpec, library: RendererLibrary): Contender {
  const width = WORLD_WIDTH / TARGET_DIVISOR, height = WORLD_HEIGHT / TARGET_DIVISOR;
  const gl = createContext(width, height);
  answerVertexArrayLikeBrowsers(gl);
  const renderer = new library.PenumbraRenderer(gl, {
    ambientColor: [0.05, 0.05, 0.05], width, height,
    viewProjection: mat4.ortho(mat4.create(), 0, WORLD_WIDTH, WORLD_HEIGHT, 0, -1, 1),
  });
  const scene = createScene(spec, library);
  for (const light of scene.lights) renderer.addLight(light);
  for (const hull of scene.hulls) renderer.addHull(hull);
  let frame = 0;
  return {
    gl, renderer,
    step() {
      scene.step(frame++);
      // Let the rasterizer drain so a frame does not pay for the previous one.
      gl.finish();
    },
  };
}

/**
 * Runs one scene with each of `libraries`' renderers, each on its own headless-gl WebGL2 context,
 * the world mapped onto small targets. The timed frames run in turns (one frame of each renderer,
 * then the next), so that the machine's drifts in speed, which reach 1.5 × within minutes on these
 * shared machines, fall on every renderer alike and their ratio holds.
 */
export function runCpu(spec: SceneSpec, libraries: readonly RendererLibrary[], options: CpuOptions): CpuResult[] {
  const contenders = libraries.map((library) => createContender(spec, library));
  for (const { renderer, step } of contenders) {
    for (let i = 0; i < options.warmup; i++) {
      step();
      renderer.renderLightmap();
    }
  }
  const unstubs = contenders.map(({ gl }) => stubCalls(gl));
  const heapBytesPerFrame = contenders.map(({ renderer, step }) => measureHeap(renderer, step));
  const js = contenders.map((): number[] => []);
  for (let i = 0; i < options.frames; i++) {
    contenders.forEach(({ renderer, step }, k) => {
      step();
      const start = performance.now();
      renderer.renderLightmap();
      js[k].push(performance.now() - start);
    });
  }
  for (const unstub of unstubs) unstub();
  const probes = contenders.map(({ gl }) => probeCalls(gl));
  const inGL = contenders.map((): number[] => []);
  const calls = contenders.map(() => 0);
  for (let i = 0; i < PROBED_FRAMES; i++) {
    contenders.forEach(({ renderer, step }, k) => {
      step();
      probes[k].reset();
      renderer.renderLightmap();
      inGL[k].push(probes[k].time);
      calls[k] += probes[k].calls;
    });
  }
  return contenders.map(({ gl, renderer }, k) => {
    const result: CpuResult = {
      js: summarize(js[k]), gl: summarize(inGL[k]), glCalls: calls[k] / PROBED_FRAMES, heapBytesPerFrame: heapBytesPerFrame[k],
      lightsDrawn: renderer.stats.lightsDrawn, edges: renderer.stats.edges, extra: readExtraStats(renderer.stats),
    };
    renderer.dispose();
    destroyContext(gl);
    return result;
  });
}

/**
 * Heap growth across `renderLightmap()` calls only (the scene's animation is excluded), over
 * frames during which no garbage collection ran: needs `--expose-gc` and a young generation large
 * enough (`--max-semi-space-size`) to hold the frames' garbage. A GC shows as a negative step.
 */
function measureHeap(renderer: BenchRenderer, step: () => void): number | null {
  const gc = (globalThis as { gc?: () => void }).gc;
  if (!gc) return null;
  const frames = 50;
  // Stubbed frames are cheap: run enough of them for every per-frame function to be optimized.
  // Functions that run once a frame box their doubles until V8 optimizes them, which took
  // between 1,500 and 6,000 frames (V8's sampling heap profiler): those frames are not steady.
  const warmupEnd = performance.now() + HEAP_WARMUP_MS;
  for (let i = 0; i < HEAP_WARMUP_FRAMES && performance.now() < warmupEnd; i++) {
    step();
    renderer.renderLightmap();
  }
  for (let attempt = 0; attempt < 3; attempt++) {
    gc();
    // Reading the heap allocates the answer object: measured with nothing between and subtracted.
    // The first reading after a collection allocates about 1.5 kB more: taken and dropped here, it
    // would fall in the probe and hide as much of the frames' allocation.
    process.memoryUsage();
    let probe = 0;
    for (let i = 0; i < frames; i++) {
      const before = process.memoryUsage().heapUsed;
      probe += process.memoryUsage().heapUsed - before;
    }
    let total = 0;
    let clean = true;
    for (let i = 0; i < frames; i++) {
      step();
      const before = process.memoryUsage().heapUsed;
      renderer.renderLightmap();
      const after = process.memoryUsage().heapUsed;
      if (after < before) clean = false;
      total += after - before;
    }
    if (clean) return Math.max(0, (total - probe) / frames);
  }
  return null;
}
