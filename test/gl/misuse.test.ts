import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { PenumbraRenderer } from '../../src/index';
import { createContext, destroyContext } from './context';
import { colorTarget, lightmapOf, sceneRenderer } from './fixtures';
import { countGLObjects } from './glObjects';
import { differences, HostObjects, snapshot } from './hostParameters';

const W = 32, H = 24;

let gl: WebGL2RenderingContext;

beforeEach(() => {
  gl = createContext(W, H);
});

afterEach(() => {
  destroyContext(gl);
});

function lightmap(renderer: PenumbraRenderer): Float32Array {
  return lightmapOf(gl, renderer, W, H);
}

/** A host framebuffer bound, and its bytes after a frame drawn through the renderer with a white scene. */
function frame(renderer: PenumbraRenderer, target: WebGLFramebuffer): Uint8Array {
  gl.bindFramebuffer(gl.FRAMEBUFFER, target);
  renderer.beginDraw();
  gl.clearColor(1, 1, 1, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  const pixels = new Uint8Array(W * H * 4);
  gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

function hostTarget(): WebGLFramebuffer {
  return colorTarget(gl, W, H).framebuffer;
}

describe('call order', () => {
  const insideFrame: [string, (renderer: PenumbraRenderer) => void, RegExp][] = [
    ['beginDraw()', (renderer) => renderer.beginDraw(), /beginDraw\(\) called twice: call draw\(\) to end the frame/],
    ['drawInPlace()', (renderer) => renderer.drawInPlace(), /drawInPlace\(\) called between beginDraw\(\) and draw\(\)/],
  ];
  for (const [call, run, message] of insideFrame) {
    it(`${call} inside a frame throws an Error naming the order and changes nothing; the frame then ends as usual`, () => {
      const renderer = sceneRenderer(gl);
      const target = hostTarget();
      const expected = frame(renderer, target);
      renderer.beginDraw();
      const objects = new HostObjects();
      const before = snapshot(gl, objects);
      expect(() => run(renderer)).toThrow(message);
      expect(differences(before, snapshot(gl, objects))).toEqual([]);
      gl.clearColor(1, 1, 1, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      renderer.draw();
      expect(gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING)).toBe(target);
      expect(frame(renderer, target)).toEqual(expected);
      renderer.dispose();
      expect(gl.getError()).toBe(0);
    });
  }
});

describe('sizes beyond the context', () => {
  const max = () => Math.min(gl.getParameter(gl.MAX_TEXTURE_SIZE), gl.getParameter(gl.MAX_RENDERBUFFER_SIZE)) as number;

  it('resize() beyond MAX_TEXTURE_SIZE: a RangeError naming the size and the limit; the renderer keeps its size and works', () => {
    const renderer = sceneRenderer(gl);
    const before = lightmap(renderer);
    const limit = max();
    expect(() => renderer.resize(limit + 1, H)).toThrow(RangeError);
    expect(() => renderer.resize(W, limit + 1)).toThrow(new RegExp(`height ${limit + 1} exceeds .*largest texture size ${limit}`));
    expect(gl.getError()).toBe(0);
    expect(lightmap(renderer)).toEqual(before);
    renderer.dispose();
  });

  it('resize() out of memory: a RangeError naming OUT_OF_MEMORY; the renderer keeps its size and works', () => {
    const renderer = sceneRenderer(gl);
    const before = lightmap(renderer);
    const getError = gl.getError.bind(gl);
    let outOfMemory = true;
    // headless-gl cannot be driven out of memory: the first error read after the allocation says it was.
    gl.getError = () => (outOfMemory ? ((outOfMemory = false), gl.OUT_OF_MEMORY) : getError());
    expect(() => renderer.resize(W * 4, H * 4)).toThrow(new RegExp(`resize\\(${W * 4}, ${H * 4}\\) failed: .*OUT_OF_MEMORY.*keeps its size ${W}×${H}`));
    expect(outOfMemory).toBe(false);
    expect(getError()).toBe(0);
    expect(lightmap(renderer)).toEqual(before);
    renderer.dispose();
  });

  it('the constructor beyond MAX_TEXTURE_SIZE: a RangeError naming width or height; no GL object made, no GL error', () => {
    const objects = countGLObjects(gl);
    const limit = max();
    expect(() => new PenumbraRenderer(gl, { width: limit + 1, height: 4 })).toThrow(new RegExp(`PenumbraRenderer.width ${limit + 1} exceeds`));
    expect(() => new PenumbraRenderer(gl, { width: 4, height: limit + 1 })).toThrow(new RegExp(`PenumbraRenderer.height ${limit + 1} exceeds`));
    expect(objects.byKind()).toEqual({});
    expect(gl.getError()).toBe(0);
  });
});

describe('a constructor that fails part-way', () => {
  it('frees every GL object it made and leaves no GL error, wherever it fails', () => {
    const objects = countGLObjects(gl);
    const createShader = gl.createShader.bind(gl);
    let shadersAsked = 0;
    let shadersLeft = Infinity;
    // A lost or exhausted context answers null: with `shadersLeft` = k the (k+1)-th shader fails.
    gl.createShader = (type: number) => {
      shadersAsked++;
      return shadersLeft-- > 0 ? createShader(type) : null;
    };
    new PenumbraRenderer(gl).dispose();
    const shaders = shadersAsked;
    expect(shaders).toBeGreaterThan(10);
    const failures: string[] = [];
    for (let failAt = 0; failAt < shaders; failAt++) {
      shadersLeft = failAt;
      expect(() => new PenumbraRenderer(gl)).toThrow(/could not create a shader/);
      if (objects.live() > 0) failures.push(`shader ${failAt + 1} failing left ${JSON.stringify(objects.byKind())}`);
      const error = gl.getError();
      if (error !== 0) failures.push(`shader ${failAt + 1} failing left GL error 0x${error.toString(16)}`);
    }
    expect(failures).toEqual([]);
  });
});
