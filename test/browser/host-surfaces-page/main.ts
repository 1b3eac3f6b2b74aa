// Host framebuffers that headless-gl cannot make, for test/browser/hostSurfaces.test.ts: one with
// two draw buffers, and the browser's multisampled canvas. One renderer of SIZE² on a canvas of
// (2 × SIZE)² (SwiftShader takes seconds to link a renderer's programs). Each case is compared
// with the same frame drawn into a plain framebuffer of one RGBA8 attachment. Exposes its entry
// points on `window` (typed in test/browser/hostSurfaces.test.ts).
import { Hull, PenumbraRenderer, PointLight, TexturedLight } from '../../../src/index';
import { colorTarget } from '../../gl/fixtures';

const SIZE = 32;
const canvas = document.getElementById('canvas') as HTMLCanvasElement;
canvas.width = canvas.height = 2 * SIZE;
// The default attributes: a multisampled drawing buffer.
const gl = canvas.getContext('webgl2')!;
const renderer = new PenumbraRenderer(gl, { width: SIZE, height: SIZE, ambientColor: [0.1, 0.1, 0.1] });
renderer.addLight(new PointLight({ position: [8, 12], range: 30, radius: 2 }));
renderer.addHull(new Hull([[16, 8], [20, 8], [20, 16], [16, 16]]));

const WHITE = new Float32Array([1, 1, 1, 1]);
/** What the host keeps in its second attachment. */
const BLUE = new Float32Array([0, 0.5, 1, 1]);

/** The bytes of `framebuffer`'s `attachment` in the rectangle at (x, y) of SIZE² (the host's read buffer is left changed). */
function readAttachment(framebuffer: WebGLFramebuffer | null, attachment: number, x = 0, y = 0): Uint8Array {
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, framebuffer);
  gl.readBuffer(attachment);
  const pixels = new Uint8Array(SIZE * SIZE * 4);
  gl.readPixels(x, y, SIZE, SIZE, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

function differingBytes(a: Uint8Array, b: Uint8Array): number {
  let count = 0;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) count++;
  return count;
}

/** The host draws white through beginDraw/draw into the bound framebuffer. */
function whiteFrame(): void {
  renderer.beginDraw();
  gl.clearBufferfv(gl.COLOR, 0, WHITE);
  renderer.draw();
}

/** The frames drawn into a framebuffer of one attachment: with beginDraw/draw, and in place over white. */
function reference(): { drawn: Uint8Array; inPlace: Uint8Array } {
  const target = colorTarget(gl, SIZE, SIZE).framebuffer;
  gl.viewport(0, 0, SIZE, SIZE);
  whiteFrame();
  const drawn = readAttachment(target, gl.COLOR_ATTACHMENT0);
  gl.bindFramebuffer(gl.FRAMEBUFFER, target);
  gl.clearBufferfv(gl.COLOR, 0, WHITE);
  renderer.drawInPlace();
  const inPlace = readAttachment(target, gl.COLOR_ATTACHMENT0);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  return { drawn, inPlace };
}

/** Lit and shadowed pixels of a reference frame (the comparison tests something). */
function contrast(pixels: Uint8Array): { lit: number; dark: number } {
  let lit = 0, dark = 0;
  for (let i = 0; i < pixels.length; i += 4) {
    if (pixels[i] >= 128) lit++;
    else if (pixels[i] < 64) dark++;
  }
  return { lit, dark };
}

export interface MrtFrame {
  glError: number;
  /** Bytes of attachment 0 unlike the frame drawn into a framebuffer of one attachment. */
  attachment0Differs: number;
  /** Bytes of attachment 1 no longer BLUE. */
  attachment1Differs: number;
  /** DRAW_BUFFER0 and DRAW_BUFFER1 after the call, with the host's framebuffer bound. */
  drawBuffers: number[];
  readBuffer: number;
  drawFramebufferKept: boolean;
}

/** A host framebuffer of two RGBA8 attachments with draw buffers for both, its read buffer set to `readBuffer`. */
function twoAttachmentTarget(readBuffer: number): WebGLFramebuffer {
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  for (let i = 0; i < 2; i++) {
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, SIZE, SIZE);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, texture, 0);
  }
  gl.bindTexture(gl.TEXTURE_2D, null);
  gl.drawBuffers([gl.COLOR_ATTACHMENT0, gl.COLOR_ATTACHMENT1]);
  gl.readBuffer(readBuffer);
  gl.clearBufferfv(gl.COLOR, 0, WHITE);
  gl.clearBufferfv(gl.COLOR, 1, BLUE);
  gl.viewport(0, 0, SIZE, SIZE);
  return framebuffer;
}

/** What `frame` left in a framebuffer of two draw buffers, against `expected`. */
function mrtFrame(frame: () => void, expected: Uint8Array): MrtFrame {
  const target = twoAttachmentTarget(gl.COLOR_ATTACHMENT1);
  frame();
  const glError = gl.getError();
  const drawFramebufferKept = gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING) === target && gl.getParameter(gl.READ_FRAMEBUFFER_BINDING) === target;
  const drawBuffers = [gl.getParameter(gl.DRAW_BUFFER0) as number, gl.getParameter(gl.DRAW_BUFFER1) as number];
  const readBuffer = gl.getParameter(gl.READ_BUFFER) as number;
  const blue = new Uint8Array(SIZE * SIZE * 4).map((_, i) => Math.round(BLUE[i % 4] * 255));
  const result = {
    glError, drawBuffers, readBuffer, drawFramebufferKept,
    attachment0Differs: differingBytes(readAttachment(target, gl.COLOR_ATTACHMENT0), expected),
    attachment1Differs: differingBytes(readAttachment(target, gl.COLOR_ATTACHMENT1), blue),
  };
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  return result;
}

/** `draw()` and `drawInPlace()` into a host framebuffer with two draw buffers. */
function mrtFrames(): { draw: MrtFrame; inPlace: MrtFrame; reference: { lit: number; dark: number } } {
  const expected = reference();
  return {
    draw: mrtFrame(whiteFrame, expected.drawn),
    inPlace: mrtFrame(() => renderer.drawInPlace(), expected.inPlace),
    reference: contrast(expected.inPlace),
  };
}

export interface MultisampledFigures {
  samples: number;
  /** The viewport SIZE² at the origin: bytes unlike the frame lit in place in a plain framebuffer, and its GL error. */
  atOrigin: { differs: number; glError: number };
  /** Per viewport that is not the renderer's size at the origin: what drawInPlace threw, its GL error, and whether framebuffer and viewport were kept. */
  refused: { viewport: number[]; thrown: string; glError: number; stateKept: boolean }[];
  /** The viewport at the origin again after the refusals. */
  afterwards: { differs: number; glError: number };
}

/** drawInPlace on the multisampled canvas, over white in a viewport of SIZE² at the origin. */
function inPlaceAtOrigin(expected: Uint8Array): { differs: number; glError: number } {
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.viewport(0, 0, SIZE, SIZE);
  gl.clearBufferfv(gl.COLOR, 0, WHITE);
  renderer.drawInPlace();
  const glError = gl.getError();
  return { differs: differingBytes(readAttachment(null, gl.BACK), expected), glError };
}

/** drawInPlace on the browser's multisampled canvas, in viewports it can and cannot copy. */
function multisampledInPlace(): MultisampledFigures {
  const expected = reference().inPlace;
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  const samples = gl.getParameter(gl.SAMPLES) as number;
  const atOrigin = inPlaceAtOrigin(expected);
  const refused = [[16, 16, SIZE, SIZE], [0, 0, 2 * SIZE, 2 * SIZE], [0, 0, SIZE, SIZE / 2]].map((viewport) => {
    gl.viewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    let thrown = 'nothing';
    try {
      renderer.drawInPlace();
    } catch (error) {
      thrown = String(error);
    }
    const stateKept = gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING) === null && Array.from(gl.getParameter(gl.VIEWPORT) as Int32Array).join() === viewport.join();
    return { viewport, thrown, glError: gl.getError(), stateKept };
  });
  return { samples, atOrigin, refused, afterwards: inPlaceAtOrigin(expected) };
}

/** What TexturedLight and the renderer throw for textures that are not the renderer's context's, and the GL error left. */
function textureMisuse(): { thrown: string[]; glError: number } {
  const thrown: string[] = [];
  const attempt = (run: () => void) => {
    try {
      run();
      thrown.push('nothing');
    } catch (error) {
      thrown.push(String(error));
    }
  };
  attempt(() => new TexturedLight({ texture: {} as WebGLTexture }));
  const cookie = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, cookie);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array([255, 255, 255, 255]));
  gl.bindTexture(gl.TEXTURE_2D, null);
  const light = new TexturedLight({ position: [16, 16], range: 8, texture: cookie });
  attempt(() => { light.texture = gl.createBuffer() as unknown as WebGLTexture; });
  const other = document.createElement('canvas').getContext('webgl2')!;
  const foreign = other.createTexture();
  other.bindTexture(other.TEXTURE_2D, foreign);
  light.texture = foreign;
  attempt(() => renderer.addLight(light));
  light.texture = cookie;
  renderer.addLight(light);
  light.texture = foreign;
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  attempt(() => whiteFrame());
  renderer.removeLight(light);
  return { thrown, glError: gl.getError() };
}

/** drawInPlace on a multisampled opaque canvas (RGB, no alpha): what it throws, and the GL error left. */
function opaqueMultisampledInPlace(): { alphaBits: number; samples: number; thrown: string; glError: number } {
  const opaque = document.createElement('canvas');
  opaque.width = opaque.height = SIZE;
  const context = opaque.getContext('webgl2', { alpha: false, antialias: true })!;
  const lit = new PenumbraRenderer(context, { width: SIZE, height: SIZE });
  lit.addLight(new PointLight({ position: [8, 12], range: 30, radius: 2 }));
  let thrown = 'nothing';
  try {
    lit.drawInPlace();
  } catch (error) {
    thrown = String(error);
  }
  const figures = { alphaBits: context.getParameter(context.ALPHA_BITS) as number, samples: context.getParameter(context.SAMPLES) as number, thrown, glError: context.getError() };
  lit.dispose();
  return figures;
}

Object.assign(window, { mrtFrames, multisampledInPlace, opaqueMultisampledInPlace, textureMisuse });
