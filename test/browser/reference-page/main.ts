// Renders the reference scenes in the browser for test/browser/reference.test.ts, which compares
// the lightmaps with the exact CPU reference on the Node side. Each scene is built with all of its
// lights and hulls by test/reference/buildScene.ts, as on headless-gl. Exposes its entry points on `window`.
import { createSceneRenderer } from '../../reference/buildScene';
import type { ReferenceScene } from '../../reference/scenes';
import { readTexture } from '../../gl/readTexture';

const canvas = document.getElementById('canvas') as HTMLCanvasElement;

function context(width: number, height: number): WebGL2RenderingContext {
  canvas.width = width;
  canvas.height = height;
  const gl = canvas.getContext('webgl2');
  if (!gl) throw new Error('WebGL2 is not available');
  return gl;
}

/** The renderer's lightmap as plain numbers (puppeteer serialises arrays), RGBA rows bottom-up. */
function readLightmap(gl: WebGL2RenderingContext, texture: WebGLTexture, width: number, height: number): number[] {
  return Array.from(readTexture(gl, texture, width, height));
}

function renderScene(scene: ReferenceScene): number[] {
  const gl = context(scene.width, scene.height);
  const renderer = createSceneRenderer(gl, scene);
  renderer.renderLightmap();
  const pixels = readLightmap(gl, renderer.lightmapTexture, scene.width, scene.height);
  const error = gl.getError();
  renderer.dispose();
  if (error !== gl.NO_ERROR) throw new Error(`GL error 0x${error.toString(16)} rendering ${scene.name}`);
  return pixels;
}

/** Resolves on the canvas' next `type` event; rejects after 10 s so a missing event fails clearly. */
function nextEvent(type: string): Promise<void> {
  return new Promise((done, fail) => {
    const timer = setTimeout(() => fail(new Error(`no ${type} event within 10 s`)), 10_000);
    canvas.addEventListener(type, () => {
      clearTimeout(timer);
      done();
    }, { once: true });
  });
}

/** Renders `scene`, loses and restores the context, renders again: the lightmaps before and after. */
async function renderAcrossContextLoss(scene: ReferenceScene): Promise<{ before: number[]; after: number[]; lostFrameError: string | null }> {
  const gl = context(scene.width, scene.height);
  const renderer = createSceneRenderer(gl, scene);
  renderer.renderLightmap();
  const before = readLightmap(gl, renderer.lightmapTexture, scene.width, scene.height);
  const loseContext = gl.getExtension('WEBGL_lose_context');
  if (!loseContext) throw new Error('WEBGL_lose_context is not available');
  const lost = nextEvent('webglcontextlost');
  loseContext.loseContext();
  await lost;
  // While lost, frames are skipped quietly rather than throwing.
  let lostFrameError: string | null = null;
  try {
    renderer.renderLightmap();
    renderer.beginDraw();
    renderer.draw();
  } catch (error) {
    lostFrameError = String(error);
  }
  // Chromium allows restoring only once the lost event's dispatch has finished (it reads
  // defaultPrevented afterwards); a promise continuation still runs inside it, so wait a task.
  await new Promise((done) => setTimeout(done, 0));
  const restored = nextEvent('webglcontextrestored');
  loseContext.restoreContext();
  await restored;
  renderer.renderLightmap();
  const after = readLightmap(gl, renderer.lightmapTexture, scene.width, scene.height);
  renderer.dispose();
  return { before, after, lostFrameError };
}

Object.assign(window, { renderScene, renderAcrossContextLoss });
