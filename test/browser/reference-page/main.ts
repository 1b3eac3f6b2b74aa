// Renders the reference scenes in the browser for test/browser/reference.test.ts, which compares
// the lightmaps with the exact CPU reference on the Node side, and for
// test/browser/illumination.test.ts, which compares them here with `illuminationAt` run on
// Chromium's JS. Each scene is built with all of its lights and hulls by
// test/reference/buildScene.ts, as on headless-gl. Exposes its entry points on `window`
// (typed in test/browser/referencePage.ts).
import { createDirectionalSceneRenderer, createSceneRenderer, setScene } from '../../reference/buildScene';
import type { DirectionalReferenceScene } from '../../reference/directionalReference';
import type { ReferenceScene } from '../../reference/scenes';
import { readTexture } from '../../gl/readTexture';
import { callsThrowing } from '../../gl/fixtures';
import { checkHostStateAcrossPublicCalls, type HostStateReport } from '../../gl/hostParameters';
import { compareReferenceScene, type IlluminationComparison } from '../../reference/illuminationComparison';
import { PenumbraRenderer, type ShadowType } from '../../../src/index';
import { OUTLINE_SCENE_SIZE, renderOutlineScene } from '../../gl/outlineUpsampling';
import { afterDispatch, nextEvent } from '../pageEvents';
import { compareSurfaceLighting, createSurfaceHost, type SurfaceFigures } from '../../reference/surfaceComparison';
import { SURFACE_AMBIENT, SURFACE_CASES, SURFACE_HEIGHT, SURFACE_WIDTH } from '../../reference/surfaceReference';

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
  return renderWith(scene, createSceneRenderer);
}

function renderDirectionalScene(scene: DirectionalReferenceScene): number[] {
  return renderWith(scene, createDirectionalSceneRenderer);
}

/** Renders the lightmap of `scene` with the renderer `create` sets up for it, read back. */
function renderWith<T extends { name: string; width: number; height: number }>(
  scene: T, create: (gl: WebGL2RenderingContext, scene: T) => PenumbraRenderer,
): number[] {
  const gl = context(scene.width, scene.height);
  const renderer = create(gl, scene);
  renderer.renderLightmap();
  const pixels = readLightmap(gl, renderer.lightmapTexture, scene.width, scene.height);
  const error = gl.getError();
  renderer.dispose();
  if (error !== gl.NO_ERROR) throw new Error(`GL error 0x${error.toString(16)} rendering ${scene.name}`);
  return pixels;
}

/**
 * Renders `scene`, loses and restores the context, renders again: the lightmaps before and after.
 * Calls are made in the window between the loss and its event (the browser queues the event), and
 * after a second loss made by a restored handler that runs before the renderer's: what they threw
 * is `windowErrors`.
 */
async function renderAcrossContextLoss(scene: ReferenceScene): Promise<{ before: number[]; after: number[]; lostFrameError: string | null; windowErrors: string[] }> {
  const gl = context(scene.width, scene.height);
  const loseContext = gl.getExtension('WEBGL_lose_context');
  if (!loseContext) throw new Error('WEBGL_lose_context is not available');
  const windowErrors: string[] = [];
  let renderer: PenumbraRenderer | null = null;
  // Registered before the renderer's own listener, so it runs first.
  canvas.addEventListener('webglcontextrestored', () => {
    loseContext.loseContext();
    windowErrors.push(...callsThrowing(renderer!, scene.width, scene.height).map((error) => `after a second loss: ${error}`));
  }, { once: true });
  renderer = createSceneRenderer(gl, scene);
  renderer.renderLightmap();
  const before = readLightmap(gl, renderer.lightmapTexture, scene.width, scene.height);
  const lost = nextEvent(canvas, 'webglcontextlost');
  loseContext.loseContext();
  windowErrors.push(...callsThrowing(renderer, scene.width, scene.height).map((error) => `before the lost event: ${error}`));
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
  // A promise continuation still runs inside the lost event's dispatch, so wait a task.
  await afterDispatch();
  const lostAgain = nextEvent(canvas, 'webglcontextlost');
  let restored = nextEvent(canvas, 'webglcontextrestored');
  loseContext.restoreContext();
  await restored;
  await lostAgain;
  await afterDispatch();
  restored = nextEvent(canvas, 'webglcontextrestored');
  loseContext.restoreContext();
  await restored;
  renderer.renderLightmap();
  const after = readLightmap(gl, renderer.lightmapTexture, scene.width, scene.height);
  renderer.dispose();
  return { before, after, lostFrameError, windowErrors };
}

/** The host-parameter check of test/gl/hostParameters.ts on a canvas of its own (its state would disturb the scenes). */
function checkHostState(normals = false, lightmapScale = 1): HostStateReport {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) throw new Error('WebGL2 is not available');
  return checkHostStateAcrossPublicCalls(gl, 64, 48, normals, lightmapScale);
}

/** The edge-aware upsampling scene of test/gl/outlineUpsampling.ts, drawn on a canvas of its own. */
function outlineScene(lightmapScale: number, shadowType: ShadowType): number[] {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = OUTLINE_SCENE_SIZE;
  const gl = canvas.getContext('webgl2');
  if (!gl) throw new Error('WebGL2 is not available');
  return Array.from(renderOutlineScene(gl, lightmapScale, shadowType));
}

/** The renderer `compareIllumination` reuses from scene to scene (SwiftShader takes seconds to link a new one's programs). */
let illuminationRenderer: PenumbraRenderer | null = null;

/**
 * Renders `scene`'s lightmap and compares `illuminationAt`, computed here, with it at every
 * unambiguous pixel centre, as test/gl/illumination.test.ts does on headless-gl: both sides run in
 * the browser, so only the figures cross to Node. `floatLightmap`: whether the lightmap is
 * RGBA16F (the read-back as floats needs it).
 */
function compareIllumination(scene: ReferenceScene): IlluminationComparison & { glError: number; floatLightmap: boolean } {
  const gl = context(scene.width, scene.height);
  if (illuminationRenderer) {
    illuminationRenderer.resize(scene.width, scene.height);
    setScene(illuminationRenderer, scene);
  } else {
    illuminationRenderer = createSceneRenderer(gl, scene);
  }
  return { ...compareReferenceScene(gl, illuminationRenderer, scene), floatLightmap: illuminationRenderer.hasFloatLightmap };
}

/** Normal-mapped lighting against its CPU reference (test/reference/surfaceComparison.ts). */
function compareSurfaces(): SurfaceFigures {
  return compareSurfaceLighting(context(SURFACE_WIDTH, SURFACE_HEIGHT));
}

/**
 * A frame of the band scene by a renderer with normals, before a context loss and after the
 * restore (the host rebuilds its program, the renderer itself): how many output bytes differ.
 */
async function surfacesAcrossContextLoss(): Promise<{ differingBytes: number; litBytes: number }> {
  const gl = context(SURFACE_WIDTH, SURFACE_HEIGHT);
  const loseContext = gl.getExtension('WEBGL_lose_context')!;
  const renderer = new PenumbraRenderer(gl, { ambientColor: SURFACE_AMBIENT, normals: true });
  const scene = SURFACE_CASES[0];
  renderer.addLight(scene.light());
  for (const hull of scene.hulls()) renderer.addHull(hull);
  const frame = () => {
    const host = createSurfaceHost(gl);
    renderer.beginDraw();
    host.draw();
    renderer.draw();
    host.dispose();
    const bytes = new Uint8Array(SURFACE_WIDTH * SURFACE_HEIGHT * 4);
    gl.readPixels(0, 0, SURFACE_WIDTH, SURFACE_HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
    return bytes;
  };
  const before = frame();
  const lost = nextEvent(canvas, 'webglcontextlost');
  loseContext.loseContext();
  await lost;
  await afterDispatch();
  const restored = nextEvent(canvas, 'webglcontextrestored');
  loseContext.restoreContext();
  await restored;
  const after = frame();
  renderer.dispose();
  let differingBytes = 0, litBytes = 0;
  for (let i = 0; i < before.length; i++) {
    if (before[i] !== after[i]) differingBytes++;
    if (i % 4 !== 3 && after[i] > 100) litBytes++;
  }
  return { differingBytes, litBytes };
}

/** What a renderer with normals throws for malformed surfaces of `drawInPlace`. */
function surfaceMisuse(): string[] {
  const gl = context(SURFACE_WIDTH, SURFACE_HEIGHT);
  const renderer = new PenumbraRenderer(gl, { normals: true });
  const thrown: string[] = [];
  const attempts: unknown[] = [{ normals: 7 }, { normals: renderer.normalTexture, material: 'stone' }, { normals: renderer.normalTexture, flipY: 1 }, null];
  for (const surfaces of attempts) {
    try {
      renderer.drawInPlace(undefined, surfaces as never);
    } catch (error) {
      thrown.push(`${(error as Error).name}: ${(error as Error).message}`);
    }
  }
  renderer.dispose();
  return thrown;
}

Object.assign(window, { renderScene, renderDirectionalScene, renderAcrossContextLoss, checkHostState, outlineScene, compareIllumination, compareSurfaces, surfaceMisuse, surfacesAcrossContextLoss });
