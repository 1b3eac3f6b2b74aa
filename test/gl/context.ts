import createGL from 'gl';

/** A headless-gl WebGL2 context (needs an X display; run the tests through scripts/with-display.mjs). */
export function createContext(width: number, height: number): WebGL2RenderingContext {
  fixWebGL2Validation();
  const gl = createGL(width, height, { createWebGL2Context: true, preserveDrawingBuffer: true }) as unknown as WebGL2RenderingContext | null;
  if (!gl || typeof gl.createVertexArray !== 'function') {
    throw new Error('headless-gl could not create a WebGL2 context: is gl@9.0.0-rc.10 installed and an X display (Xvfb) running?');
  }
  return gl;
}

/**
 * Works around two gaps in headless-gl 9.0.0-rc.10's JavaScript validation layer (its native
 * context is OpenGL ES 3 and does the right thing), so that the renderer runs as in a browser:
 * - `getParameter` answers the WebGL2-only bindings (VAO, sampler, pixel-unpack buffer) with raw GL
 *   names instead of objects; the VAO is answered from headless-gl's own tracking, the sampler as
 *   its raw name (what `createSampler` returns there) or null, and the pixel-unpack binding (which
 *   headless-gl's `bindBuffer` rejects) as null.
 * - `blendEquation` accepts MIN/MAX only when the native driver lists EXT_blend_minmax, though they
 *   are core in WebGL2.
 * Neither changes what is drawn. Remove once headless-gl fixes them.
 */
function fixWebGL2Validation(): void {
  const proto = (createGL as unknown as { WebGL2RenderingContext: { prototype: HeadlessContext } }).WebGL2RenderingContext.prototype;
  if (proto.__penumbraPatched) return;
  proto.__penumbraPatched = true;
  const getParameter = proto.getParameter;
  proto.getParameter = function (this: HeadlessContext, name: number) {
    if (name === this.VERTEX_ARRAY_BINDING) return this._activeVertexArrayObject;
    if (name === this.SAMPLER_BINDING) return getParameter.call(this, name) || null;
    if (name === this.PIXEL_UNPACK_BUFFER_BINDING) return null;
    return getParameter.call(this, name);
  };
  const validBlendMode = proto._validBlendMode;
  proto._validBlendMode = function (this: HeadlessContext, mode: number) {
    return mode === this.MIN || mode === this.MAX || validBlendMode.call(this, mode);
  };
}

interface HeadlessContext {
  __penumbraPatched?: boolean;
  _activeVertexArrayObject: unknown;
  VERTEX_ARRAY_BINDING: number;
  SAMPLER_BINDING: number;
  PIXEL_UNPACK_BUFFER_BINDING: number;
  MIN: number;
  MAX: number;
  getParameter(name: number): unknown;
  _validBlendMode(mode: number): boolean;
}

/** Frees a headless-gl context. */
export function destroyContext(gl: WebGL2RenderingContext): void {
  (gl.getExtension('STACKGL_destroy_context') as { destroy(): void } | null)?.destroy();
}
