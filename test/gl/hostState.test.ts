import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { colorTarget as sharedColorTarget } from './fixtures';
import { setFixedFunctionState } from './hostParameters';
import { readTexture } from './readTexture';

const W = 64, H = 48;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;

beforeEach(() => {
  gl = createContext(W, H);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0.1, 0.1, 0.1] });
  renderer.addLight(new PointLight({ position: [20, 24], range: 50, radius: 3, color: [1.5, 1, 0.5] }));
  renderer.addHull(new Hull([[36, 18], [42, 18], [42, 30], [36, 30]]));
});

afterEach(() => {
  renderer.dispose();
  expect(gl.getError()).toBe(0);
  destroyContext(gl);
});

function colorTarget(): { framebuffer: WebGLFramebuffer; texture: WebGLTexture } {
  return sharedColorTarget(gl, W, H);
}

function hostProgram(): WebGLProgram {
  const shader = (type: number, source: string) => {
    const s = gl.createShader(type)!;
    gl.shaderSource(s, source);
    gl.compileShader(s);
    return s;
  };
  const program = gl.createProgram();
  gl.attachShader(program, shader(gl.VERTEX_SHADER, '#version 300 es\nin vec2 p;\nvoid main() { gl_Position = vec4(p, 0.0, 1.0); }'));
  gl.attachShader(program, shader(gl.FRAGMENT_SHADER, '#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }'));
  gl.linkProgram(program);
  return program;
}

/**
 * Every piece of state the renderer promises to restore, with the host's GL objects replaced by
 * their names (so that a renderer object left bound shows as 'renderer object').
 */
function snapshot(names: Map<unknown, string>): Record<string, unknown> {
  // headless-gl answers VERTEX_ARRAY_BINDING with a raw name, 0 for none (test/gl/context.ts).
  const name = (object: unknown) => (object === null || object === 0 ? null : names.get(object) ?? 'renderer object');
  const active = gl.getParameter(gl.ACTIVE_TEXTURE) as number;
  const textures: unknown[] = [];
  for (let unit = 0; unit < 4; unit++) {
    gl.activeTexture(gl.TEXTURE0 + unit);
    textures.push(name(gl.getParameter(gl.TEXTURE_BINDING_2D)));
  }
  gl.activeTexture(active);
  const parameter = (p: number) => {
    const value = gl.getParameter(p);
    return ArrayBuffer.isView(value) || Array.isArray(value) ? Array.from(value as ArrayLike<unknown>) : value;
  };
  return {
    drawFramebuffer: name(gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING)),
    readFramebuffer: name(gl.getParameter(gl.READ_FRAMEBUFFER_BINDING)),
    viewport: parameter(gl.VIEWPORT),
    scissorTest: gl.isEnabled(gl.SCISSOR_TEST),
    scissorBox: parameter(gl.SCISSOR_BOX),
    blend: gl.isEnabled(gl.BLEND),
    blendEquations: [parameter(gl.BLEND_EQUATION_RGB), parameter(gl.BLEND_EQUATION_ALPHA)],
    blendFactors: [gl.BLEND_SRC_RGB, gl.BLEND_DST_RGB, gl.BLEND_SRC_ALPHA, gl.BLEND_DST_ALPHA].map(parameter),
    blendColor: parameter(gl.BLEND_COLOR),
    colorMask: parameter(gl.COLOR_WRITEMASK),
    clearColor: parameter(gl.COLOR_CLEAR_VALUE),
    depthTest: gl.isEnabled(gl.DEPTH_TEST),
    depthFunc: parameter(gl.DEPTH_FUNC),
    depthMask: parameter(gl.DEPTH_WRITEMASK),
    stencilTest: gl.isEnabled(gl.STENCIL_TEST),
    cullFace: gl.isEnabled(gl.CULL_FACE),
    cullFaceMode: parameter(gl.CULL_FACE_MODE),
    frontFace: parameter(gl.FRONT_FACE),
    program: name(gl.getParameter(gl.CURRENT_PROGRAM)),
    vertexArray: name(gl.getParameter(gl.VERTEX_ARRAY_BINDING)),
    arrayBuffer: name(gl.getParameter(gl.ARRAY_BUFFER_BINDING)),
    elementArrayBuffer: name(gl.getParameter(gl.ELEMENT_ARRAY_BUFFER_BINDING)),
    activeTexture: active,
    textures,
  };
}

/** Sets a host state unlike the renderer's own; returns the names of the host's objects. */
function setDistinctiveState(withVertexArray: boolean): Map<unknown, string> {
  const names = new Map<unknown, string>();
  const target = colorTarget();
  names.set(target.framebuffer, 'host framebuffer').set(target.texture, 'host target texture');
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  setFixedFunctionState(gl);
  const program = hostProgram();
  names.set(program, 'host program');
  gl.useProgram(program);
  if (withVertexArray) {
    const vertexArray = gl.createVertexArray();
    names.set(vertexArray, 'host vertex array');
    gl.bindVertexArray(vertexArray);
    names.set(gl.getParameter(gl.VERTEX_ARRAY_BINDING), 'host vertex array'); // its raw name on headless-gl
  }
  const arrayBuffer = gl.createBuffer();
  const elementBuffer = gl.createBuffer();
  names.set(arrayBuffer, 'host array buffer').set(elementBuffer, 'host element buffer');
  gl.bindBuffer(gl.ARRAY_BUFFER, arrayBuffer);
  gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, elementBuffer);
  for (let unit = 0; unit < 4; unit++) {
    const texture = gl.createTexture();
    names.set(texture, `host texture ${unit}`);
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, texture);
  }
  gl.activeTexture(gl.TEXTURE1);
  return names;
}

describe('host GL state', () => {
  for (const withVertexArray of [true, false]) {
    const variant = withVertexArray ? 'with a host vertex array' : 'on the default vertex array';
    it(`is restored by beginDraw/draw and renderLightmap, ${variant}`, () => {
      const names = setDistinctiveState(withVertexArray);
      const hostVertexArray = gl.getParameter(gl.VERTEX_ARRAY_BINDING);
      const before = snapshot(names);
      renderer.beginDraw();
      // Between the two calls the scene target is bound: the snapshot sees renderer objects.
      expect(snapshot(names).drawFramebuffer).toBe('renderer object');
      renderer.draw();
      rebindOnRawNameContext();
      expect(snapshot(names)).toEqual(before);
      renderer.renderLightmap();
      rebindOnRawNameContext();
      expect(snapshot(names)).toEqual(before);
      expect(gl.getError()).toBe(0);

      /**
       * Where the context answers the vertex-array binding with a raw name (headless-gl) and the
       * host had one bound, HostState promises none bound after a call: checked, then the host
       * rebinds its own (after which everything must be as before).
       */
      function rebindOnRawNameContext(): void {
        if (typeof hostVertexArray !== 'number' || hostVertexArray === 0) return;
        expect(gl.getParameter(gl.VERTEX_ARRAY_BINDING)).toBe(0);
        const [vertexArray] = [...names].find(([object, name]) => name === 'host vertex array' && typeof object === 'object')!;
        gl.bindVertexArray(vertexArray as WebGLVertexArrayObject);
      }
    });
  }

  it('leaves no GL error when the host deleted the program it left current (GL frees it once unbound: none is current after)', () => {
    const program = hostProgram();
    gl.useProgram(program);
    gl.deleteProgram(program);
    expect(gl.getError()).toBe(0);
    const other = new PenumbraRenderer(gl, { ambientColor: [0.1, 0.1, 0.1] });
    expect(gl.getError()).toBe(0);
    other.renderLightmap();
    expect(gl.getError()).toBe(0);
    expect(gl.getParameter(gl.CURRENT_PROGRAM)).toBe(null);
    other.dispose();
  });

  it('on a context that answers VERTEX_ARRAY_BINDING with a raw name, warns once when it cannot restore the host\'s vertex array', () => {
    expect(typeof gl.getParameter(gl.VERTEX_ARRAY_BINDING)).toBe('number'); // headless-gl, unpatched
    const warnings: unknown[] = [];
    const warn = console.warn;
    console.warn = (...args: unknown[]) => { warnings.push(args.join(' ')); };
    try {
      renderer.renderLightmap(); // none bound: exact, no warning
      expect(warnings).toEqual([]);
      const vertexArray = gl.createVertexArray();
      gl.bindVertexArray(vertexArray);
      renderer.renderLightmap();
      expect(gl.getParameter(gl.VERTEX_ARRAY_BINDING)).toBe(0);
      gl.bindVertexArray(vertexArray);
      renderer.renderLightmap();
      expect(warnings).toHaveLength(1);
      expect(String(warnings[0])).toMatch(/VERTEX_ARRAY_BINDING.*rebind yours/);
      gl.bindVertexArray(null);
      gl.deleteVertexArray(vertexArray);
    } finally {
      console.warn = warn;
    }
  });
});

describe('composite', () => {
  /** Draws a scene cleared to `scene` through the renderer into a host target; returns its bytes and the lightmap. */
  function composite(scene: [number, number, number]): { result: Uint8Array; lightmap: Float32Array } {
    const target = colorTarget();
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
    gl.viewport(0, 0, W, H);
    renderer.beginDraw();
    gl.clearColor(scene[0], scene[1], scene[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    renderer.draw();
    expect(gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING)).toBe(target.framebuffer);
    const result = new Uint8Array(W * H * 4);
    gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, result);
    const lightmap = readTexture(gl, renderer.lightmapTexture, W, H);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(target.framebuffer);
    gl.deleteTexture(target.texture);
    return { result, lightmap };
  }

  // The host target is RGBA8: one step is 1/255, and rounding the product adds up to half a step.
  const TOLERANCE = 1.5 / 255;

  it('writes scene × lightmap: a white scene shows the lightmap clamped to 1', () => {
    const { result, lightmap } = composite([1, 1, 1]);
    let above1 = 0;
    for (let i = 0; i < W * H * 4; i += 4) {
      for (let c = 0; c < 3; c++) expect(Math.abs(result[i + c] / 255 - Math.min(1, lightmap[i + c]))).toBeLessThanOrEqual(TOLERANCE);
      if (lightmap[i] > 1) above1++;
    }
    expect(above1).toBeGreaterThan(0); // the red channel (1.5 × falloff) exceeds 1 near the light
  });

  it('multiplies a coloured scene by the lightmap', () => {
    const scene: [number, number, number] = [0.5, 1, 0.25];
    const { result, lightmap } = composite(scene);
    // One more step than for white: the scene texture is RGBA8 too, so 0.5 is stored as 128/255.
    for (let i = 0; i < W * H * 4; i += 4) {
      for (let c = 0; c < 3; c++) {
        expect(Math.abs(result[i + c] / 255 - Math.min(1, scene[c] * lightmap[i + c]))).toBeLessThanOrEqual(TOLERANCE + 1 / 255);
      }
    }
  });
});
