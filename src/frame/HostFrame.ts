import { HostDrawBuffers, HostState } from '../gl/HostState';
import type { RenderTarget } from '../gl/RenderTarget';

/**
 * The host's side of the renderer's calls: its context state, saved around each call and put back
 * (see {@link HostState}), and the framebuffers, viewport and draw buffers of the frame it opened
 * (`beginDraw`, `drawInPlace`), which the frame composites into and binds again when it closes.
 */
export class HostFrame {
  readonly state: HostState;
  /** Whether a frame is open: between `beginDraw()` and its `draw()`. */
  open = false;
  private warnedAbandoned = false;
  /** The draw buffers of the framebuffer the open frame composites into. */
  private readonly drawBuffers: HostDrawBuffers;
  private readonly viewport = new Int32Array(4);
  private drawFramebuffer: WebGLFramebuffer | null = null;
  private readFramebuffer: WebGLFramebuffer | null = null;

  /** @param textureUnits how many texture units (from 0) the renderer binds. */
  constructor(private readonly gl: WebGL2RenderingContext, textureUnits: number) {
    this.state = new HostState(gl, textureUnits);
    this.drawBuffers = new HostDrawBuffers(gl);
  }

  /**
   * Saves the host's state and puts the renderer's neutral one; pair with `state.restore()` in a
   * `finally`. The per-frame paths use this pair directly: a closure would allocate every frame.
   */
  enter(): void {
    this.state.save();
    try {
      this.state.prepareForRenderer();
    } catch (error) {
      this.state.restore();
      throw error;
    }
  }

  /** Runs `run` between {@link HostFrame.enter} and a restore (for calls that are not per frame); returns what it returns. */
  run<T>(run: () => T): T {
    this.enter();
    try {
      return run();
    } finally {
      this.state.restore();
    }
  }

  /**
   * Between {@link HostFrame.enter} and the restore of a frame that opens: takes the saved
   * framebuffers and viewport as the frame's, and reads the draw buffers of its draw framebuffer.
   * For `drawInPlace` (`inPlace`), first throws unless its viewport can be copied into a scene
   * target of `width` × `height` (see {@link HostFrame.checkInPlaceSource}).
   */
  record(inPlace: boolean, width: number, height: number): void {
    const saved = this.state;
    this.drawFramebuffer = saved.savedDrawFramebuffer;
    this.readFramebuffer = saved.savedReadFramebuffer;
    this.viewport.set(saved.savedViewport);
    if (inPlace) this.checkInPlaceSource(width, height);
    this.drawBuffers.record(this.drawFramebuffer);
  }

  /**
   * Closes a frame left open by the host (see `PenumbraRenderer.beginDraw`): its framebuffers and
   * viewport are bound again while `sceneFramebuffer` still is.
   */
  abandon(sceneFramebuffer: WebGLFramebuffer): void {
    if (!this.warnedAbandoned) {
      this.warnedAbandoned = true;
      console.warn('penumbra: a frame was started while the previous one was still open (an exception between beginDraw() and draw()?): ' +
        'the open frame is abandoned and the framebuffer and viewport of its beginDraw() are bound again. Warned once.');
    }
    if (this.gl.getParameter(this.gl.DRAW_FRAMEBUFFER_BINDING) === sceneFramebuffer) this.close();
    else this.open = false;
  }

  /** Ends the open frame's redirection: binds the framebuffers and viewport of its `beginDraw()` again. */
  close(): void {
    this.open = false;
    this.bindTarget();
    this.gl.bindFramebuffer(this.gl.READ_FRAMEBUFFER, this.readFramebuffer);
  }

  /** Binds the frame's draw framebuffer and viewport with its draw buffer 0 the only one drawn into; pair with {@link HostFrame.endComposite}. */
  beginComposite(): void {
    this.bindTarget();
    this.drawBuffers.drawFirstOnly();
  }

  /** Puts back the draw buffers of the frame's framebuffer. */
  endComposite(): void {
    this.drawBuffers.restoreDraw();
  }

  /** Copies the colour of the frame's framebuffer inside its viewport into `scene`, `width` × `height` (see `drawInPlace`). */
  copyInto(scene: RenderTarget, width: number, height: number): void {
    const gl = this.gl, v = this.viewport;
    this.enter();
    try {
      // The colour only: a blit writes every draw buffer.
      scene.bindFirst();
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.drawFramebuffer);
      this.drawBuffers.readFirst();
      try {
        gl.blitFramebuffer(v[0], v[1], v[0] + v[2], v[1] + v[3], 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      } finally {
        this.drawBuffers.restoreRead();
      }
    } finally {
      this.state.restore();
    }
  }

  private bindTarget(): void {
    const gl = this.gl, v = this.viewport;
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.drawFramebuffer);
    gl.viewport(v[0], v[1], v[2], v[3]);
  }

  /**
   * Throws, before anything is bound, unless `blitFramebuffer` can copy the frame's viewport of the
   * bound framebuffer into a scene target of `width` × `height`: from a multisampled framebuffer (a
   * browser canvas's, by default) it copies only between identical rectangles and formats, so the
   * framebuffer must have alpha (an opaque canvas's is RGB) and the viewport must be the renderer's
   * size at the origin. Reads the samples and alpha bits of the bound draw framebuffer.
   */
  private checkInPlaceSource(width: number, height: number): void {
    const gl = this.gl, v = this.viewport;
    const samples = gl.getParameter(gl.SAMPLES) as number | null;
    if (!samples) return;
    // A multisampled copy needs the same format at both ends, and the scene target has alpha.
    if (gl.getParameter(gl.ALPHA_BITS) === 0) {
      throw new Error(`penumbra: PenumbraRenderer.drawInPlace: the bound framebuffer is multisampled (${samples} samples) and has no alpha, ` +
        'so it cannot be copied into the renderer\'s RGBA scene target (WebGL refuses a multisampled copy between formats): make the canvas ' +
        'with getContext(\'webgl2\', { alpha: true }) or { antialias: false }, or draw into a framebuffer with alpha or without multisampling');
    }
    if (v[0] === 0 && v[1] === 0 && v[2] === width && v[3] === height) return;
    throw new Error(`penumbra: PenumbraRenderer.drawInPlace: the bound framebuffer is multisampled (${samples} samples), which can be copied ` +
      `only to the same rectangle: its viewport [${v.join(', ')}] must be [0, 0, ${width}, ${height}], the renderer's size at the origin ` +
      '(resize the renderer to the viewport and draw at the origin, or draw into a framebuffer without multisampling)');
  }
}
