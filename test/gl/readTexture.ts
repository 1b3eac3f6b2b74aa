/**
 * Reads an RGBA float-renderable texture back as floats, rows bottom-up as GL stores them.
 * Plain WebGL2: used with headless-gl and in the Chromium reference page alike.
 */
export function readTexture(gl: WebGL2RenderingContext, texture: WebGLTexture, width: number, height: number): Float32Array {
  const framebuffer = gl.createFramebuffer();
  const previous = gl.getParameter(gl.FRAMEBUFFER_BINDING);
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  const pixels = new Float32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, pixels);
  gl.bindFramebuffer(gl.FRAMEBUFFER, previous);
  gl.deleteFramebuffer(framebuffer);
  return pixels;
}
