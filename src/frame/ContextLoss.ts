/** What the renderer does when its context is lost and when it is restored (see {@link ContextLoss}). */
export interface ContextLossHandlers {
  /** After the loss's event: drop every GL object without freeing it (the context freed them). */
  lost(): void;
  /** On the restored context: build the GL objects again. What it throws leaves the loss standing. */
  rebuild(): void;
  /** After a rebuild, with the loss over. */
  restored(): void;
}

/**
 * Follows the loss and restore of a context through its canvas's `webglcontextlost` and
 * `webglcontextrestored` events (a context without a canvas that dispatches events is never seen
 * lost but by `gl.isContextLost()`). Made on a lost context, it waits for the restore.
 */
export class ContextLoss {
  /** Whether a loss was seen and not yet recovered from (its event, or the context lost when made). */
  private waiting: boolean;
  private listening = true;
  private readonly canvas: EventTarget | null;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly handlers: ContextLossHandlers) {
    this.waiting = gl.isContextLost();
    const canvas = (gl as { canvas?: unknown }).canvas as EventTarget | undefined;
    this.canvas = canvas && typeof canvas.addEventListener === 'function' ? canvas : null;
    this.canvas?.addEventListener('webglcontextlost', this.onLost);
    this.canvas?.addEventListener('webglcontextrestored', this.onRestored);
  }

  /**
   * Whether GL calls must be skipped. `gl.isContextLost()` is read too because the browser
   * dispatches `webglcontextlost` only after the loss: a frame in between would meet the null
   * answers of a lost context.
   */
  get isLost(): boolean {
    return this.waiting || this.gl.isContextLost();
  }

  /** Stops listening: no handler runs afterwards. */
  dispose(): void {
    this.listening = false;
    this.canvas?.removeEventListener('webglcontextlost', this.onLost);
    this.canvas?.removeEventListener('webglcontextrestored', this.onRestored);
  }

  private readonly onLost = (event: Event): void => {
    // Without preventDefault the browser never restores the context.
    event.preventDefault();
    this.waiting = true;
    this.handlers.lost();
  };

  /**
   * Rebuilds after a loss. Ignored without a loss before it (nothing to rebuild), and when the
   * context is lost again before this handler runs: the next restored event rebuilds.
   */
  private readonly onRestored = (): void => {
    if (!this.waiting || !this.listening || this.gl.isContextLost()) return;
    this.handlers.rebuild();
    this.waiting = false;
    this.handlers.restored();
  };
}
