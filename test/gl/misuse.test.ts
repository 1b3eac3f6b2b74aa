import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { Hull, PenumbraRenderer, PointLight, TexturedLight } from '../../src/index';
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
  vi.restoreAllMocks();
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

/** The host's framebuffer bound with a viewport unlike the renderer's, and the host state as it reads then. */
function hostFrameState(target: WebGLFramebuffer, objects: HostObjects): ReturnType<typeof snapshot> {
  objects.add('host framebuffer', target);
  gl.bindFramebuffer(gl.FRAMEBUFFER, target);
  gl.viewport(0, 0, W, H);
  return snapshot(gl, objects);
}

describe('a frame that throws', () => {
  it('draw() with a bad layer mask throws naming it, after binding the host framebuffer and viewport again; the next frame draws as usual', () => {
    const renderer = sceneRenderer(gl);
    const target = hostTarget();
    const expected = frame(renderer, target);
    const objects = new HostObjects();
    const before = hostFrameState(target, objects);
    renderer.beginDraw();
    expect(() => renderer.draw(~0)).toThrow(/PenumbraRenderer\.draw: layers must be an integer from 0 to 0xffffffff .*got -1/);
    expect(differences(before, snapshot(gl, objects))).toEqual([]);
    expect(() => renderer.draw()).toThrow(/draw\(\) called without beginDraw\(\)/);
    expect(frame(renderer, target)).toEqual(expected);
    renderer.dispose();
    expect(gl.getError()).toBe(0);
  });

  it('a frame the host abandoned (its code threw before draw()) is closed by the next beginDraw(), with one warning; that frame draws as usual', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const renderer = sceneRenderer(gl);
    const target = hostTarget();
    const expected = frame(renderer, target);
    const objects = new HostObjects();
    for (let attempt = 0; attempt < 2; attempt++) {
      const before = hostFrameState(target, objects);
      renderer.beginDraw();
      // The host's drawing throws here: draw() is never called. The next frame starts with the scene target still bound.
      renderer.beginDraw();
      gl.clearColor(1, 1, 1, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      renderer.draw();
      expect(differences(before, snapshot(gl, objects), ['COLOR_CLEAR_VALUE'])).toEqual([]);
      expect(frame(renderer, target)).toEqual(expected);
    }
    expect(warn.mock.calls.map((call) => String(call[0]))).toEqual([expect.stringMatching(/previous one was still open.*abandoned.*Warned once/)]);
    renderer.dispose();
    expect(gl.getError()).toBe(0);
  });

  it('a framebuffer the host bound after abandoning a frame is the next frame\'s target', () => {
    vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const renderer = sceneRenderer(gl);
    const abandoned = hostTarget();
    const target = hostTarget();
    const expected = frame(renderer, target);
    gl.bindFramebuffer(gl.FRAMEBUFFER, abandoned);
    renderer.beginDraw();
    expect(frame(renderer, target)).toEqual(expected);
    expect(gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING)).toBe(target);
    renderer.dispose();
    expect(gl.getError()).toBe(0);
  });

  it('drawInPlace() on an abandoned frame closes it likewise and lights the host framebuffer', () => {
    vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const renderer = sceneRenderer(gl);
    const target = hostTarget();
    const lightInPlace = () => {
      gl.clearColor(1, 1, 1, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      renderer.drawInPlace();
      const pixels = new Uint8Array(W * H * 4);
      gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      return pixels;
    };
    const objects = new HostObjects();
    hostFrameState(target, objects);
    const expected = lightInPlace();
    const before = snapshot(gl, objects);
    renderer.beginDraw();
    // The scene target is bound: drawInPlace lights the framebuffer of the abandoned frame's beginDraw.
    renderer.drawInPlace();
    expect(differences(before, snapshot(gl, objects))).toEqual([]);
    expect(lightInPlace()).toEqual(expected);
    renderer.dispose();
    expect(gl.getError()).toBe(0);
  });

  it('dispose() inside a frame binds the host framebuffer and viewport again', () => {
    const renderer = sceneRenderer(gl);
    const objects = new HostObjects();
    const before = hostFrameState(hostTarget(), objects);
    renderer.beginDraw();
    renderer.dispose();
    expect(differences(before, snapshot(gl, objects))).toEqual([]);
    expect(gl.getError()).toBe(0);
  });
});

describe('a disposed renderer', () => {
  it('refuses addLight and addHull with an Error naming the call; removing still answers false', () => {
    const renderer = sceneRenderer(gl);
    renderer.dispose();
    const light = new PointLight({ position: [4, 4], range: 10 });
    const hull = new Hull([[0, 0], [1, 0], [0, 1]]);
    expect(() => renderer.addLight(light)).toThrow(/PenumbraRenderer\.addLight: the renderer was disposed/);
    expect(() => renderer.addHull(hull)).toThrow(/PenumbraRenderer\.addHull: the renderer was disposed/);
    expect(renderer.lights).toEqual([]);
    expect(renderer.hulls).toEqual([]);
    expect(renderer.removeLight(light)).toBe(false);
  });
});

describe('a TexturedLight whose texture is not one of the context\'s', () => {
  /** A 1 × 1 white cookie of `context`. */
  function cookie(context: WebGL2RenderingContext): WebGLTexture {
    const texture = context.createTexture();
    context.bindTexture(context.TEXTURE_2D, texture);
    context.texImage2D(context.TEXTURE_2D, 0, context.RGBA8, 1, 1, 0, context.RGBA, context.UNSIGNED_BYTE, new Uint8Array([255, 255, 255, 255]));
    context.bindTexture(context.TEXTURE_2D, null);
    return texture;
  }

  /** Not a texture of `gl`: a plain object (headless-gl has no WebGLTexture class to check against), a buffer, another context's texture, a deleted one. */
  function foreignTextures(other: WebGL2RenderingContext): [string, WebGLTexture, RegExp][] {
    const deleted = cookie(gl);
    gl.deleteTexture(deleted);
    return [
      ['a plain object', {} as WebGLTexture, /got \{\}/],
      ['a buffer', gl.createBuffer() as WebGLTexture, /got a WebGLBuffer/],
      ['another context\'s texture', cookie(other), /got a WebGLTexture/],
      ['a deleted texture', deleted, /got a WebGLTexture/],
    ];
  }

  it('addLight throws a TypeError naming the texture; nothing is added and no GL error is left', () => {
    const other = createContext(4, 4);
    const renderer = sceneRenderer(gl);
    for (const [name, texture, got] of foreignTextures(other)) {
      const light = new TexturedLight({ position: [8, 8], range: 10, texture });
      expect(() => renderer.addLight(light), name).toThrow(TypeError);
      expect(() => renderer.addLight(light), name).toThrow(/PenumbraRenderer\.addLight: the TexturedLight's texture must be a texture of the renderer's WebGL context/);
      expect(() => renderer.addLight(light), name).toThrow(got);
      expect(renderer.lights.length, name).toBe(1);
    }
    expect(gl.getError()).toBe(0);
    renderer.dispose();
    destroyContext(other);
  });

  it('assigned after addLight, it is refused by the next frame before anything is bound: the host state is as it was; a good texture draws again', () => {
    const other = createContext(4, 4);
    const renderer = sceneRenderer(gl);
    const light = renderer.addLight(new TexturedLight({ position: [8, 8], range: 10, texture: cookie(gl) }));
    const good = light.texture;
    const target = hostTarget();
    const expected = frame(renderer, target);
    const objects = new HostObjects();
    const calls: [string, () => void][] = [
      ['beginDraw', () => renderer.beginDraw()],
      ['draw', () => renderer.draw()],
      ['drawInPlace', () => renderer.drawInPlace()],
      ['renderLightmap', () => renderer.renderLightmap()],
    ];
    for (const [name, texture] of foreignTextures(other)) {
      for (const [call, run] of calls) {
        light.texture = good;
        const before = hostFrameState(target, objects);
        if (call === 'draw') renderer.beginDraw();
        light.texture = texture;
        expect(run, `${call} with ${name}`).toThrow(/PenumbraRenderer\.lights\[1\] \(TexturedLight\)\.texture must be a texture of the renderer's WebGL context/);
        expect(differences(before, snapshot(gl, objects)), `${call} with ${name}`).toEqual([]);
        expect(gl.getError(), `${call} with ${name}`).toBe(0);
      }
    }
    light.texture = good;
    expect(frame(renderer, target)).toEqual(expected);
    renderer.dispose();
    destroyContext(other);
  });
});

describe('sizes beyond the context', () => {
  const max = () => Math.min(gl.getParameter(gl.MAX_TEXTURE_SIZE), gl.getParameter(gl.MAX_RENDERBUFFER_SIZE));

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

describe('a constructor, or the first light of a kind, that fails part-way', () => {
  /** Counts the shaders `gl` is asked for; with `failAfter(k)` the (k+1)-th fails, as a lost or exhausted context answers null. */
  function failingShaders(): { asked: () => number; failAfter: (k: number) => void } {
    const createShader = gl.createShader.bind(gl);
    let asked = 0;
    let left = Infinity;
    gl.createShader = (type: number) => {
      asked++;
      return left-- > 0 ? createShader(type) : null;
    };
    return { asked: () => asked, failAfter: (k) => { left = k; } };
  }

  it('frees every GL object the constructor made and leaves no GL error, wherever it fails', () => {
    const objects = countGLObjects(gl);
    const shaders = failingShaders();
    new PenumbraRenderer(gl).dispose();
    const count = shaders.asked();
    expect(count).toBeGreaterThan(4);
    const failures: string[] = [];
    for (let failAt = 0; failAt < count; failAt++) {
      shaders.failAfter(failAt);
      expect(() => new PenumbraRenderer(gl)).toThrow(/could not create a shader/);
      if (objects.live() > 0) failures.push(`shader ${failAt + 1} failing left ${JSON.stringify(objects.byKind())}`);
      const error = gl.getError();
      if (error !== 0) failures.push(`shader ${failAt + 1} failing left GL error 0x${error.toString(16)}`);
    }
    expect(failures).toEqual([]);
  });

  it('frees every program the first light of a kind made, adds no light, and draws on, wherever it fails', () => {
    const objects = countGLObjects(gl);
    const shaders = failingShaders();
    const renderer = new PenumbraRenderer(gl);
    const made = objects.live(), before = shaders.asked();
    renderer.addLight(new PointLight({ position: [8, 8], range: 10 }));
    const count = shaders.asked() - before;
    expect(count).toBeGreaterThan(10);
    renderer.dispose();
    const failures: string[] = [];
    for (let failAt = 0; failAt < count; failAt++) {
      const failing = new PenumbraRenderer(gl);
      shaders.failAfter(failAt);
      expect(() => failing.addLight(new PointLight({ position: [8, 8], range: 10 }))).toThrow(/could not create a shader/);
      if (objects.live() !== made) failures.push(`shader ${failAt + 1} failing left ${JSON.stringify(objects.byKind())}`);
      if (failing.lights.length !== 0) failures.push(`shader ${failAt + 1} failing added the light`);
      shaders.failAfter(Infinity);
      failing.addLight(new PointLight({ position: [8, 8], range: 10 }));
      failing.renderLightmap();
      const error = gl.getError();
      if (error !== 0) failures.push(`shader ${failAt + 1} failing left GL error 0x${error.toString(16)}`);
      failing.dispose();
    }
    expect(failures).toEqual([]);
    expect(objects.live()).toBe(0);
  });
});
