/** Texture formats a {@link RenderTarget} can use. */
export type TargetFormat = 'rgba8' | 'rgba16f';

/** Options of a {@link RenderTarget}. */
export interface RenderTargetOptions {
  format: TargetFormat;
  /** Attach a depth/stencil renderbuffer (for targets the user draws into). */
  depthStencil?: boolean;
  /** Sample with linear filtering (for targets read at another resolution). */
  linear?: boolean;
}

/** A colour texture with its framebuffer, resizable, owning both GL objects. */
export class RenderTarget {
  texture: WebGLTexture;
  framebuffer: WebGLFramebuffer;
  width = 0;
  height = 0;
  private depthStencil: WebGLRenderbuffer | null = null;

  /** Frees what it made before throwing when the target cannot be completed. */
  constructor(private readonly gl: WebGL2RenderingContext, private readonly options: RenderTargetOptions, width: number, height: number) {
    this.texture = gl.createTexture()!;
    this.framebuffer = gl.createFramebuffer()!;
    if (options.depthStencil) this.depthStencil = gl.createRenderbuffer();
    try {
      this.resize(width, height);
    } catch (error) {
      this.dispose();
      throw error;
    }
  }

  /**
   * Reallocates storage for a new size. Leaves the active unit's texture, the framebuffer and the
   * renderbuffer bindings changed: callers run it inside a saved host state.
   */
  resize(width: number, height: number): void {
    if (width === this.width && height === this.height) return;
    const gl = this.gl;
    this.width = width;
    this.height = height;
    const float = this.options.format === 'rgba16f';
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, float ? gl.RGBA16F : gl.RGBA8, width, height, 0, gl.RGBA, float ? gl.HALF_FLOAT : gl.UNSIGNED_BYTE, null);
    const filter = this.options.linear ? gl.LINEAR : gl.NEAREST;
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.texture, 0);
    if (this.depthStencil) {
      gl.bindRenderbuffer(gl.RENDERBUFFER, this.depthStencil);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH24_STENCIL8, width, height);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_STENCIL_ATTACHMENT, gl.RENDERBUFFER, this.depthStencil);
      gl.bindRenderbuffer(gl.RENDERBUFFER, null);
    }
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    if (status !== gl.FRAMEBUFFER_COMPLETE && !gl.isContextLost()) {
      throw new Error(`penumbra: ${this.options.format} render target ${width}×${height} is incomplete (status 0x${status.toString(16)})`);
    }
  }

  /** Binds the framebuffer and sets the viewport to the whole target. */
  bind(): void {
    this.gl.bindFramebuffer(this.gl.FRAMEBUFFER, this.framebuffer);
    this.gl.viewport(0, 0, this.width, this.height);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteTexture(this.texture);
    gl.deleteFramebuffer(this.framebuffer);
    if (this.depthStencil) gl.deleteRenderbuffer(this.depthStencil);
  }
}
