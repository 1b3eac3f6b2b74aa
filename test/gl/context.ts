import createGL from 'gl';

/**
 * A plain headless-gl WebGL2 context (needs an X display; run the tests through
 * scripts/with-display.mjs). Not patched: the renderer copes with headless-gl 9.0.0-rc.10 as a user's
 * Node script gets it (see HostState). Two of its answers differ from a browser's, which tests
 * that read state back must allow for: `getParameter` gives the WebGL2-only bindings
 * (VERTEX_ARRAY_BINDING, SAMPLER_BINDING, PIXEL_UNPACK_BUFFER_BINDING) as raw GL names (0 for none),
 * and `blendEquation` rejects MIN/MAX unless the driver lists EXT_blend_minmax.
 */
export function createContext(width: number, height: number): WebGL2RenderingContext {
  const gl = createGL(width, height, { createWebGL2Context: true, preserveDrawingBuffer: true }) as unknown as WebGL2RenderingContext | null;
  if (!gl || typeof gl.createVertexArray !== 'function') {
    throw new Error('headless-gl could not create a WebGL2 context: is gl@9.0.0-rc.10 installed and an X display (Xvfb) running?');
  }
  return gl;
}

/** Frees a headless-gl context. */
export function destroyContext(gl: WebGL2RenderingContext): void {
  (gl.getExtension('STACKGL_destroy_context') as { destroy(): void } | null)?.destroy();
}
