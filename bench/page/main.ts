import { library as baselineLibrary } from 'virtual:penumbra-baseline';
import { readExtraStats, type ExtraStats } from '../extraStats';
import { FillFloor } from '../floor';
import { CURRENT, type BenchRenderer, type RendererLibrary } from '../library';
import { createScene, runsOn, SCENES, WORLD_HEIGHT, WORLD_WIDTH, type BenchScene } from '../scenes';
import { createFrameBounds, disposeFrameBounds, type FrameBounds } from './bounds';
import { measureMicroRow, type MicroRow } from './micro';
import { measureShadowStatistics } from './statistics';

/** Times of one frame in ms, each ended by a 1-pixel readPixels so the GPU work is included. */
export interface FrameTimes {
  frame: number;
  /** The baseline renderer's frame on the same scene (absent without a baseline). */
  baseline?: number;
  floor: number;
  /** With bounds set up: the frame with trivial shadow shading, and with no hulls (see FrameBounds). */
  trivialShading?: number;
  noHulls?: number;
}

/** What the runner calls, one frame per call so that no call outlasts the DevTools protocol timeout. */
export interface BenchPage {
  setup(name: string, lightmapScale: number, withBounds: boolean): void;
  frame(): FrameTimes;
  /** The working tree renderer's shadow-loop figures (bench/extraStats.ts) on the scene as it is now. */
  extraStats(): ExtraStats;
  /** One configuration of the inner loop's micro-benchmark (see micro.ts). */
  micro(index: number, frames: number): MicroRow;
  teardown(): void;
}

/** One renderer with its own copy of the scene (lights and hulls are its version's classes). */
interface Contender {
  scene: BenchScene;
  renderer: BenchRenderer;
}

const canvas = document.getElementById('canvas') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false })!;
const pixel = new Uint8Array(4);
const floatPixel = new Float32Array(4);
let current: { now: Contender; old: Contender | null; floor: FillFloor; bounds: FrameBounds | null; frame: number } | null = null;

/** One whole frame of `renderer` (scene cleared white, lightmap, composite), in ms. */
function timeFrame(renderer: BenchRenderer): number {
  const start = performance.now();
  renderer.beginDraw();
  gl.clearColor(1, 1, 1, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return performance.now() - start;
}

function contender(library: RendererLibrary, name: string, lightmapScale: number): Contender {
  const spec = SCENES.find((scene) => scene.name === name);
  if (!spec) throw new Error(`no scene ${name}`);
  const scene = createScene(spec, library);
  const renderer = new library.PenumbraRenderer(gl, { ambientColor: [0.05, 0.05, 0.05], lightmapScale });
  for (const light of scene.lights) renderer.addLight(light);
  for (const hull of scene.hulls) renderer.addHull(hull);
  return { scene, renderer };
}

const page: BenchPage = {
  setup(name, lightmapScale, withBounds) {
    const now = contender(CURRENT, name, lightmapScale);
    const old = baselineLibrary && runsOn(SCENES.find((scene) => scene.name === name)!, baselineLibrary) ? contender(baselineLibrary, name, lightmapScale) : null;
    const bounds = withBounds ? createFrameBounds(gl, { ambientColor: [0.05, 0.05, 0.05], lightmapScale }, now.scene.lights, now.scene.hulls) : null;
    current = { now, old, floor: new FillFloor(gl, WORLD_WIDTH, WORLD_HEIGHT), bounds, frame: 0 };
  },

  /**
   * Both renderers' whole frames on the same moving scene (which goes first alternates from frame
   * to frame), then the fill floor (and the bounds' frames).
   */
  frame() {
    if (!current) throw new Error('setup() first');
    const { now, old, floor, bounds } = current;
    const number = current.frame++;
    now.scene.step(number);
    old?.scene.step(number);
    let frame: number, baseline: number | undefined;
    if (old && number % 2 === 1) {
      baseline = timeFrame(old.renderer);
      frame = timeFrame(now.renderer);
    } else {
      frame = timeFrame(now.renderer);
      baseline = old ? timeFrame(old.renderer) : undefined;
    }
    const start = performance.now();
    floor.render(now.scene.lights);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, floatPixel);
    const floorTime = performance.now() - start;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const times: FrameTimes = { frame, baseline, floor: floorTime };
    if (bounds) {
      times.trivialShading = bounds.trivialShading ? timeFrame(bounds.trivialShading) : undefined;
      times.noHulls = timeFrame(bounds.noHulls);
    }
    return times;
  },

  extraStats() {
    if (!current) return {};
    const { now } = current;
    const statistics = measureShadowStatistics(gl, {}, now.scene.lights, now.scene.hulls);
    return readExtraStats({
      shadowVisitsPerPixel: statistics.visits / statistics.pixels,
      shadowSkipShare: statistics.decidedWithoutLoop / statistics.pixels,
      shadowQuadratureShare: statistics.swept / statistics.pixels,
    });
  },

  micro: (index, frames) => measureMicroRow(gl, index, frames),

  teardown() {
    current?.now.renderer.dispose();
    current?.old?.renderer.dispose();
    current?.floor.dispose();
    if (current?.bounds) disposeFrameBounds(current.bounds);
    current = null;
  },
};

(window as unknown as { penumbraBench: BenchPage }).penumbraBench = page;
