// Small scenes and host objects shared by the GL tests and the Chromium page (plain WebGL2).
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { readTexture } from './readTexture';

/** A host colour target of `width × height` (an RGBA8 texture), left bound as the framebuffer. */
export function colorTarget(gl: WebGL2RenderingContext, width: number, height: number): { framebuffer: WebGLFramebuffer; texture: WebGLTexture } {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, width, height);
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return { framebuffer, texture };
}

/** A renderer with one light and one hull casting a shadow, for a scene about 32 × 24. */
export function sceneRenderer(gl: WebGL2RenderingContext): PenumbraRenderer {
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0.1, 0.1, 0.1] });
  renderer.addLight(new PointLight({ position: [8, 12], range: 30, radius: 2 }));
  renderer.addHull(new Hull([[16, 8], [20, 8], [20, 16], [16, 16]]));
  return renderer;
}

/** Builds the lightmap and reads it back (`width × height`, floats). */
export function lightmapOf(gl: WebGL2RenderingContext, renderer: PenumbraRenderer, width: number, height: number): Float32Array {
  renderer.renderLightmap();
  return readTexture(gl, renderer.lightmapTexture, width, height);
}

/** Every public call that reaches GL, as a frame would make them; returns what each threw. */
export function callsThrowing(renderer: PenumbraRenderer, width: number, height: number): string[] {
  const thrown: string[] = [];
  const calls: [string, () => void][] = [
    ['frame', () => { renderer.beginDraw(); renderer.draw(); }],
    ['beginDraw twice', () => { renderer.beginDraw(); renderer.beginDraw(); }],
    ['drawInPlace', () => renderer.drawInPlace()],
    ['renderLightmap', () => renderer.renderLightmap()],
    ['resize', () => { renderer.resize(width + 1, height); renderer.resize(width, height); }],
  ];
  for (const [name, call] of calls) {
    try {
      call();
    } catch (error) {
      thrown.push(`${name}: ${String(error)}`);
    }
  }
  return thrown;
}
