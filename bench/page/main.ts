import { PenumbraRenderer } from '../../src/index';
import { FillFloor } from '../floor';
import { createScene, SCENES, WORLD_HEIGHT, WORLD_WIDTH, type BenchScene } from '../scenes';

/** Times of one frame in ms, each ended by a 1-pixel readPixels so the GPU work is included. */
export interface FrameTimes {
  frame: number;
  floor: number;
}

/** What the runner calls, one frame per call so that no call outlasts the DevTools protocol timeout. */
export interface BenchPage {
  setup(name: string, lightmapScale: number): void;
  frame(): FrameTimes;
  teardown(): void;
}

const canvas = document.getElementById('canvas') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false })!;
const pixel = new Uint8Array(4);
const floatPixel = new Float32Array(4);
let current: { scene: BenchScene; renderer: PenumbraRenderer; floor: FillFloor; frame: number } | null = null;

const page: BenchPage = {
  setup(name, lightmapScale) {
    const spec = SCENES.find((scene) => scene.name === name);
    if (!spec) throw new Error(`no scene ${name}`);
    const scene = createScene(spec);
    const renderer = new PenumbraRenderer(gl, { ambientColor: [0.05, 0.05, 0.05], lightmapScale });
    for (const light of scene.lights) renderer.addLight(light);
    for (const hull of scene.hulls) renderer.addHull(hull);
    current = { scene, renderer, floor: new FillFloor(gl, WORLD_WIDTH, WORLD_HEIGHT), frame: 0 };
  },

  /** The renderer's whole frame (scene cleared white, lightmap, composite), then the fill floor, on the same moving scene. */
  frame() {
    if (!current) throw new Error('setup() first');
    const { scene, renderer, floor } = current;
    scene.step(current.frame++);
    let start = performance.now();
    renderer.beginDraw();
    gl.clearColor(1, 1, 1, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    renderer.draw();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    const frame = performance.now() - start;
    start = performance.now();
    floor.render(scene.lights);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, floatPixel);
    const floorTime = performance.now() - start;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return { frame, floor: floorTime };
  },

  teardown() {
    current?.renderer.dispose();
    current?.floor.dispose();
    current = null;
  },
};

(window as unknown as { penumbraBench: BenchPage }).penumbraBench = page;
