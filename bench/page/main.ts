import { PenumbraRenderer } from '../../src/index';
import { FillFloor } from '../floor';
import { createScene, SCENES, WORLD_HEIGHT, WORLD_WIDTH, type BenchScene } from '../scenes';
import { createFrameBounds, disposeFrameBounds, type FrameBounds } from './bounds';

/** Times of one frame in ms, each ended by a 1-pixel readPixels so the GPU work is included. */
export interface FrameTimes {
  frame: number;
  floor: number;
  /** With bounds set up: the frame with trivial shadow shading, and with no hulls (see FrameBounds). */
  trivialShading?: number;
  noHulls?: number;
}

/** What the runner calls, one frame per call so that no call outlasts the DevTools protocol timeout. */
export interface BenchPage {
  setup(name: string, lightmapScale: number, withBounds: boolean): void;
  frame(): FrameTimes;
  teardown(): void;
}

const canvas = document.getElementById('canvas') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false })!;
const pixel = new Uint8Array(4);
const floatPixel = new Float32Array(4);
let current: { scene: BenchScene; renderer: PenumbraRenderer; floor: FillFloor; bounds: FrameBounds | null; frame: number } | null = null;

/** One whole frame of `renderer` (scene cleared white, lightmap, composite), in ms. */
function timeFrame(renderer: PenumbraRenderer): number {
  const start = performance.now();
  renderer.beginDraw();
  gl.clearColor(1, 1, 1, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return performance.now() - start;
}

const page: BenchPage = {
  setup(name, lightmapScale, withBounds) {
    const spec = SCENES.find((scene) => scene.name === name);
    if (!spec) throw new Error(`no scene ${name}`);
    const scene = createScene(spec);
    const options = { ambientColor: [0.05, 0.05, 0.05] as const, lightmapScale };
    const renderer = new PenumbraRenderer(gl, options);
    for (const light of scene.lights) renderer.addLight(light);
    for (const hull of scene.hulls) renderer.addHull(hull);
    const bounds = withBounds ? createFrameBounds(gl, options, scene.lights, scene.hulls) : null;
    current = { scene, renderer, floor: new FillFloor(gl, WORLD_WIDTH, WORLD_HEIGHT), bounds, frame: 0 };
  },

  /** The renderer's whole frame, then the fill floor (and the bounds' frames), on the same moving scene. */
  frame() {
    if (!current) throw new Error('setup() first');
    const { scene, renderer, floor, bounds } = current;
    scene.step(current.frame++);
    const frame = timeFrame(renderer);
    const start = performance.now();
    floor.render(scene.lights);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, floatPixel);
    const floorTime = performance.now() - start;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (!bounds) return { frame, floor: floorTime };
    return { frame, floor: floorTime, trivialShading: timeFrame(bounds.trivialShading), noHulls: timeFrame(bounds.noHulls) };
  },

  teardown() {
    current?.renderer.dispose();
    current?.floor.dispose();
    if (current?.bounds) disposeFrameBounds(current.bounds);
    current = null;
  },
};

(window as unknown as { penumbraBench: BenchPage }).penumbraBench = page;
