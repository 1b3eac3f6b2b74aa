import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { PenumbraRenderer, TexturedLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { callsThrowing, lightmapOf, sceneRenderer } from './fixtures';
import { countGLObjects } from './glObjects';
import { losableContext, type LosableContext } from './losableContext';

// The same in Chromium with a real loss: test/browser/reference.test.ts.
const W = 32, H = 24;

let real: WebGL2RenderingContext;
let context: LosableContext;

beforeEach(() => {
  real = createContext(W, H);
  context = losableContext(real);
});

afterEach(() => {
  destroyContext(real);
  vi.restoreAllMocks();
});

function lightmap(renderer: PenumbraRenderer): Float32Array {
  return lightmapOf(real, renderer, W, H);
}

function everyCall(renderer: PenumbraRenderer): string[] {
  return callsThrowing(renderer, W, H);
}

describe('context loss', () => {
  it('skips every call between the loss and its event, and draws the same after the restore', () => {
    const renderer = sceneRenderer(context.gl);
    const before = lightmap(renderer);
    renderer.beginDraw();
    context.lose();
    expect(everyCall(renderer)).toEqual([]);
    context.dispatchLost();
    expect(everyCall(renderer)).toEqual([]);
    context.restore();
    expect(lightmap(renderer)).toEqual(before);
    renderer.dispose();
    expect(real.getError()).toBe(0);
  });

  for (const handlerFirst of [true, false]) {
    it(`skips every call after a second loss inside a restored handler that runs ${handlerFirst ? 'before' : 'after'} the renderer’s`, () => {
      const thrown: string[] = [];
      let renderer: PenumbraRenderer | null = null;
      const loseAgainAndDraw = () => {
        context.lose();
        thrown.push(...everyCall(renderer!));
      };
      // Listeners run in the order they were added: the renderer adds its own when it is made.
      if (handlerFirst) context.canvas.addEventListener('webglcontextrestored', loseAgainAndDraw, { once: true });
      renderer = sceneRenderer(context.gl);
      if (!handlerFirst) context.canvas.addEventListener('webglcontextrestored', loseAgainAndDraw, { once: true });
      const before = lightmap(renderer);
      context.lose();
      context.dispatchLost();
      context.restore();
      expect(thrown).toEqual([]);
      expect(everyCall(renderer)).toEqual([]);
      context.dispatchLost();
      context.restore();
      expect(lightmap(renderer)).toEqual(before);
      renderer.dispose();
    });
  }

  it('builds in the loss window without throwing, and draws once restored', () => {
    const reference = sceneRenderer(context.gl);
    const before = lightmap(reference);
    reference.dispose();
    context.lose();
    const renderer = sceneRenderer(context.gl);
    expect(everyCall(renderer)).toEqual([]);
    context.dispatchLost();
    context.restore();
    expect(lightmap(renderer)).toEqual(before);
    renderer.dispose();
  });

  it('made in the loss window without a size, waits quietly and takes the restored drawing buffer’s size', () => {
    const reference = sceneRenderer(real);
    const before = lightmap(reference);
    const view = Array.from(reference.viewProjection);
    reference.dispose();
    context.lose();
    // The lost context reports a drawing buffer of 0 × 0, as browsers do.
    expect(context.gl.drawingBufferWidth).toBe(0);
    const renderer = new PenumbraRenderer(context.gl, { ambientColor: [0.1, 0.1, 0.1] });
    const scene = sceneRenderer(real);
    for (const light of scene.lights) renderer.addLight(light);
    for (const hull of scene.hulls) renderer.addHull(hull);
    scene.dispose();
    expect(everyCall(renderer)).toEqual([]);
    context.dispatchLost();
    context.restore();
    expect(lightmap(renderer)).toEqual(before);
    // The default view follows the restored size, as a renderer made on the live context.
    expect(Array.from(renderer.viewProjection)).toEqual(view);
    renderer.dispose();
    expect(real.getError()).toBe(0);
  });

  it('ignores a restored event without a loss before it: no GL object is made', () => {
    const renderer = sceneRenderer(context.gl);
    const before = lightmap(renderer);
    const objects = countGLObjects(real);
    context.restore();
    expect(objects.byKind()).toEqual({});
    expect(lightmap(renderer)).toEqual(before);
    renderer.dispose();
  });

  it('calls onContextRestored, where a textured light gets a new cookie; warns naming a light left with an old one', () => {
    const cookie = () => {
      const texture = real.createTexture();
      real.bindTexture(real.TEXTURE_2D, texture);
      real.texImage2D(real.TEXTURE_2D, 0, real.RGBA8, 1, 1, 0, real.RGBA, real.UNSIGNED_BYTE, new Uint8Array([255, 255, 255, 255]));
      real.bindTexture(real.TEXTURE_2D, null);
      return texture;
    };
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const renderer = sceneRenderer(context.gl);
    const resupplied = renderer.addLight(new TexturedLight({ position: [4, 4], range: 10, texture: cookie() }));
    renderer.addLight(new TexturedLight({ position: [24, 4], range: 10, texture: cookie() }));
    const restoredWith: PenumbraRenderer[] = [];
    renderer.onContextRestored = (restored) => {
      restoredWith.push(restored);
      resupplied.texture = cookie();
    };
    context.lose();
    context.dispatchLost();
    // In a browser every texture of the lost context is gone; here they live on, so the test deletes them.
    for (const light of renderer.lights) if (light instanceof TexturedLight) real.deleteTexture(light.texture);
    context.restore();
    expect(restoredWith).toEqual([renderer]);
    expect(warn.mock.calls.map((call) => String(call[0]))).toEqual([
      expect.stringMatching(/lights\[2\] \(TexturedLight\).*before the context loss.*onContextRestored/),
    ]);
    renderer.dispose();
  });
});
