/**
 * True when `gl` is a WebGL2 context, detected by feature: headless-gl's WebGL2 context is not an
 * `instanceof WebGL2RenderingContext`.
 */
export function isWebGL2(gl: unknown): gl is WebGL2RenderingContext {
  const candidate = gl as Partial<WebGL2RenderingContext> | null;
  return candidate != null
    && typeof candidate.createVertexArray === 'function'
    && typeof candidate.texStorage2D === 'function'
    && typeof candidate.drawElementsInstanced === 'function';
}

/** Whether half-float colour targets can be rendered to and blended. */
export function supportsFloatTargets(gl: WebGL2RenderingContext): boolean {
  return gl.getExtension('EXT_color_buffer_float') != null;
}
