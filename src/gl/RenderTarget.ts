/** Texture formats a {@link RenderTarget} can use. */
export type TargetFormat = 'rgba8' | 'rgba16f' | 'r8';

/** Options of a {@link RenderTarget}. */
interface RenderTargetOptions {
  format: TargetFormat;
  /** Attach a depth/stencil renderbuffer (for targets the user draws into). */
  depthStencil?: boolean;
  /** Sample with linear filtering (for targets read at another resolution). */
  linear?: boolean;
  /** Colour attachments, all of `format`, at locations 0, 1, …. Default `1`. */
  colorAttachments?: number;
}

/**
 * Colour textures with their framebuffer, resizable, owning the GL objects. A target of several
 * colour attachments draws into all of them after {@link RenderTarget.bind}, into the first only
 * after {@link RenderTarget.bindFirst}; a target of one never sets draw buffers.
 */
export class RenderTarget {
  /** The colour attachments, location by location. */
  readonly textures: readonly WebGLTexture[];
  framebuffer: WebGLFramebuffer;
  width = 0;
  height = 0;
  private depthStencil: WebGLRenderbuffer | null = null;
  /** The draw buffers of {@link RenderTarget.bind} and {@link RenderTarget.bindFirst}, made once. */
  private readonly allBuffers: readonly number[];
  private readonly firstBuffer: readonly number[];

  /** Frees what it made before throwing when the target cannot be completed. */
  constructor(private readonly gl: WebGL2RenderingContext, private readonly options: RenderTargetOptions, width: number, height: number) {
    const count = options.colorAttachments ?? 1;
    this.textures = Array.from({ length: count }, () => gl.createTexture());
    this.allBuffers = this.textures.map((_, i) => gl.COLOR_ATTACHMENT0 + i);
    this.firstBuffer = [gl.COLOR_ATTACHMENT0];
    this.framebuffer = gl.createFramebuffer()!;
    if (options.depthStencil) this.depthStencil = gl.createRenderbuffer();
    try {
      this.resize(width, height);
      if (count > 1) this.checkDrawBuffers();
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
    const filter = this.options.linear ? gl.LINEAR : gl.NEAREST;
    const [internalFormat, format, type] = storageOf(gl, this.options.format);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    this.textures.forEach((texture, i) => {
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, null);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, texture, 0);
    });
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

  /**
   * Throws unless the context draws into every attachment after `drawBuffers` (headless-gl
   * 9.0.0-rc.10 rejects any list beyond COLOR_ATTACHMENT0). Leaves the framebuffer bound.
   */
  private checkDrawBuffers(): void {
    const gl = this.gl, count = this.textures.length;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.drawBuffers(this.allBuffers as number[]);
    if (gl.getParameter(gl.DRAW_BUFFER0 + count - 1) === gl.COLOR_ATTACHMENT0 + count - 1 || gl.isContextLost()) return;
    // The failed call's INVALID_OPERATION is the renderer's, not the host's to find.
    gl.getError();
    throw new Error(`penumbra: this WebGL2 context cannot draw into ${count} colour attachments at once (drawBuffers did not take), which { normals: true } needs`);
  }

  /** The first colour attachment. */
  get texture(): WebGLTexture {
    return this.textures[0];
  }

  /** Binds the framebuffer, drawing into every colour attachment, and sets the viewport to the whole target. */
  bind(): void {
    this.bindWith(this.allBuffers);
  }

  /**
   * Binds the framebuffer, drawing into the first colour attachment only (a pass that writes one
   * colour, or a blit, would leave the others undefined or overwrite them), and sets the viewport.
   */
  bindFirst(): void {
    this.bindWith(this.firstBuffer);
  }

  private bindWith(buffers: readonly number[]): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    // Draw buffers are the framebuffer's own state: a target of one attachment keeps the default.
    if (this.textures.length > 1) gl.drawBuffers(buffers as number[]);
    gl.viewport(0, 0, this.width, this.height);
  }

  dispose(): void {
    const gl = this.gl;
    for (const texture of this.textures) gl.deleteTexture(texture);
    gl.deleteFramebuffer(this.framebuffer);
    if (this.depthStencil) gl.deleteRenderbuffer(this.depthStencil);
  }
}

/** A format's internal format, format and type, as `texImage2D` takes them. */
function storageOf(gl: WebGL2RenderingContext, format: TargetFormat): readonly [number, number, number] {
  switch (format) {
    case 'rgba8': return [gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE];
    case 'rgba16f': return [gl.RGBA16F, gl.RGBA, gl.HALF_FLOAT];
    case 'r8': return [gl.R8, gl.RED, gl.UNSIGNED_BYTE];
  }
}
