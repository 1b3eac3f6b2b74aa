import { PenumbraRenderer } from '../../src/index';
import { FillFloor } from '../floor';
import { createScene, SCENES, WORLD_HEIGHT, WORLD_WIDTH } from '../scenes';

/** Whole-frame times in ms, each ended by a 1-pixel readPixels so the GPU work is included. */
export interface BrowserTimes {
  frame: number[];
  floor: number[];
}

const canvas = document.getElementById('canvas') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false })!;
const pixel = new Uint8Array(4);
const floatPixel = new Float32Array(4);

/** Times `frames` frames of the renderer and of the fill-rate floor on the same moving scene, after `warmup` frames of each. */
function run(name: string, warmup: number, frames: number): BrowserTimes {
  const spec = SCENES.find((scene) => scene.name === name);
  if (!spec) throw new Error(`no scene ${name}`);
  const scene = createScene(spec);
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0.05, 0.05, 0.05] });
  for (const light of scene.lights) renderer.addLight(light);
  for (const hull of scene.hulls) renderer.addHull(hull);
  const floor = new FillFloor(gl, WORLD_WIDTH, WORLD_HEIGHT);
  const times: BrowserTimes = { frame: [], floor: [] };
  let frameNumber = 0;
  for (let i = 0; i < warmup + frames; i++) {
    scene.step(frameNumber++);
    let start = performance.now();
    renderer.beginDraw();
    gl.clearColor(1, 1, 1, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    renderer.draw();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    const frameTime = performance.now() - start;
    start = performance.now();
    floor.render(scene.lights);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, floatPixel);
    const floorTime = performance.now() - start;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (i < warmup) continue;
    times.frame.push(frameTime);
    times.floor.push(floorTime);
  }
  renderer.dispose();
  floor.dispose();
  return times;
}

(window as unknown as { penumbraBench: unknown }).penumbraBench = { run };
