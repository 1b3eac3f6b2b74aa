import { library as baselineLibrary } from 'virtual:penumbra-baseline';
import { readExtraStats, type ExtraStats } from '../extraStats';
import { FillFloor } from '../floor';
import { CURRENT, type BenchRenderer, type RendererLibrary } from '../library';
import { createScene, runsOn, SCENES, WORLD_HEIGHT, WORLD_WIDTH, type BenchScene } from '../scenes';
import { createFrameBounds, disposeFrameBounds, type FrameBounds } from './bounds';
import { measureMicroRow, type MicroRow } from './micro';
import { measureShadowStatistics } from './statistics';
import { SurfaceFloor } from './surface';

/** Times of one frame in ms, each ended by a 1-pixel readPixels so the GPU work is included. */
interface FrameTimes {
  frame: number;
  /** The baseline renderer's frame on the same scene (absent without a baseline). */
  baseline?: number;
  /** In a normal-mapped scene: the working tree renderer's frame on the same scene without normals (see BenchPage.frame). */
  withoutNormals?: number;
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

/**
 * One renderer with its own copy of the scene (lights and hulls are its version's classes), and in
 * a normal-mapped scene the floor it draws (through its version's SURFACE_GLSL).
 */
interface Contender {
  scene: BenchScene;
  renderer: BenchRenderer;
  surface: SurfaceFloor | null;
}

const canvas = document.getElementById('canvas') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false })!;
const pixel = new Uint8Array(4);
const floatPixel = new Float32Array(4);
let current: {
  now: Contender;
  old: Contender | null;
  /** In a normal-mapped scene: the working tree's renderer on the same scene without normals. */
  plain: Contender | null;
  floor: FillFloor;
  bounds: FrameBounds | null;
  frame: number;
} | null = null;

/**
 * One whole frame of `renderer` (scene cleared white, lightmap, composite), in ms. With `surface`
 * (a renderer with normals) the scene is that normal-mapped floor, drawn white, instead of the clear.
 */
function timeFrame(renderer: BenchRenderer, surface: SurfaceFloor | null = null): number {
  const start = performance.now();
  renderer.beginDraw();
  if (surface) {
    surface.render();
  } else {
    gl.clearColor(1, 1, 1, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
  }
  renderer.draw();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return performance.now() - start;
}

function contender(library: RendererLibrary, name: string, lightmapScale: number): Contender {
  const spec = SCENES.find((scene) => scene.name === name);
  if (!spec) throw new Error(`no scene ${name}`);
  if (spec.normalsOf !== undefined && !library.SURFACE_GLSL) throw new Error(`scene ${name} needs a renderer with normals`);
  const scene = createScene(spec, library);
  const normals = spec.normalsOf !== undefined;
  const renderer = new library.PenumbraRenderer(gl, { ambientColor: [0.05, 0.05, 0.05], lightmapScale, ...(normals ? { normals } : {}) });
  for (const light of scene.lights) renderer.addLight(light);
  for (const hull of scene.hulls) renderer.addHull(hull);
  return { scene, renderer, surface: normals ? new SurfaceFloor(gl, library.SURFACE_GLSL!) : null };
}

const page: BenchPage = {
  setup(name, lightmapScale, withBounds) {
    const now = contender(CURRENT, name, lightmapScale);
    const spec = SCENES.find((scene) => scene.name === name)!;
    const old = baselineLibrary && runsOn(spec, baselineLibrary) ? contender(baselineLibrary, name, lightmapScale) : null;
    const plain = spec.normalsOf !== undefined ? contender(CURRENT, spec.normalsOf, lightmapScale) : null;
    // The bounds' renderers light the same surface as the frame's (drawn by now.surface).
    const options = { ambientColor: [0.05, 0.05, 0.05] as const, lightmapScale, ...(now.surface ? { normals: true } : {}) };
    const bounds = withBounds ? createFrameBounds(gl, options, now.scene.lights, now.scene.hulls) : null;
    current = { now, old, plain, floor: new FillFloor(gl, WORLD_WIDTH, WORLD_HEIGHT), bounds, frame: 0 };
  },

  /**
   * Both renderers' whole frames on the same moving scene (which goes first alternates from frame
   * to frame), then the fill floor (and the bounds' frames). A normal-mapped scene also times the
   * same scene without normals in the same turns, so that their ratio shares the machine's load.
   */
  frame() {
    if (!current) throw new Error('setup() first');
    const { now, old, plain, floor, bounds } = current;
    const number = current.frame++;
    const turns = [now, old, plain].filter((entry): entry is Contender => entry !== null);
    for (const entry of turns) entry.scene.step(number);
    // Which renderer goes first turns round from frame to frame.
    const times = new Map<Contender, number>();
    for (let k = 0; k < turns.length; k++) {
      const entry = turns[(number + k) % turns.length];
      times.set(entry, timeFrame(entry.renderer, entry.surface));
    }
    const frame = times.get(now)!;
    const baseline = old ? times.get(old) : undefined;
    const start = performance.now();
    floor.render(now.scene.lights);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, floatPixel);
    const floorTime = performance.now() - start;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const result: FrameTimes = { frame, baseline, floor: floorTime };
    if (plain) result.withoutNormals = times.get(plain);
    if (bounds) {
      result.trivialShading = bounds.trivialShading ? timeFrame(bounds.trivialShading, now.surface) : undefined;
      result.noHulls = timeFrame(bounds.noHulls, now.surface);
    }
    return result;
  },

  extraStats() {
    if (!current) return {};
    const { now } = current;
    const statistics = measureShadowStatistics(gl, {}, now.scene.lights, now.scene.hulls);
    // Every light pixel: the same lights with no hull, each drawn whole by its plain program.
    const lightPixels = measureShadowStatistics(gl, {}, now.scene.lights, []).pixels;
    const { pixels, held, lean, general } = statistics;
    return readExtraStats({
      pixelsLitShare: (pixels - held - lean - general) / lightPixels,
      pixelsHeldShare: held / lightPixels,
      pixelsLeanShare: lean / lightPixels,
      pixelsGeneralShare: general / lightPixels,
      pixelsNotDrawnShare: (lightPixels - pixels) / lightPixels,
      exactVisitsPerPixel: lean + general > 0 ? statistics.visits / (lean + general) : undefined,
      shadowVisitsPerPixel: statistics.visits / statistics.pixels,
      shadowSkipShare: statistics.decidedWithoutLoop / statistics.pixels,
      shadowQuadratureShare: statistics.swept / statistics.pixels,
    });
  },

  micro: (index, frames) => measureMicroRow(gl, index, frames),

  teardown() {
    current?.now.renderer.dispose();
    current?.now.surface?.dispose();
    current?.old?.renderer.dispose();
    current?.old?.surface?.dispose();
    current?.plain?.renderer.dispose();
    current?.floor.dispose();
    if (current?.bounds) disposeFrameBounds(current.bounds);
    current = null;
  },
};

(window as unknown as { penumbraBench: BenchPage }).penumbraBench = page;
