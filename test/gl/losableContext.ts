/**
 * A headless-gl context that can be lost and restored as a browser's can (headless-gl has no
 * WEBGL_lose_context and always answers `isContextLost()` false). While lost it answers as the
 * WebGL specification says a lost context does: `isContextLost()` true, `getError()`
 * CONTEXT_LOST_WEBGL once, every other call null and without effect, and a drawing buffer of 0 × 0
 * (as browsers report it). The events go to its `canvas`
 * only when the test dispatches them, so a test can call in the window between a loss and its event,
 * as a `requestAnimationFrame` callback can in a browser.
 */
export interface LosableContext {
  gl: WebGL2RenderingContext;
  canvas: EventTarget;
  /** Loses the context; `webglcontextlost` waits for {@link LosableContext.dispatchLost}. */
  lose(): void;
  /** Dispatches `webglcontextlost` (cancelable, as the browser's). */
  dispatchLost(): void;
  /** Restores the context and dispatches `webglcontextrestored`. */
  restore(): void;
}

export function losableContext(real: WebGL2RenderingContext): LosableContext {
  const canvas = new EventTarget();
  let lost = false;
  let lossReported = false;
  const lostAnswer = (key: string) => {
    if (key === 'isContextLost') return () => true;
    if (key === 'getError') return () => (lossReported ? 0 : ((lossReported = true), real.CONTEXT_LOST_WEBGL));
    return () => null;
  };
  const gl = new Proxy(real, {
    get(target, key) {
      if (key === 'canvas') return canvas;
      if (lost && (key === 'drawingBufferWidth' || key === 'drawingBufferHeight')) return 0;
      const value = Reflect.get(target, key, target) as unknown;
      if (typeof value !== 'function') return value;
      return lost ? lostAnswer(String(key)) : (value as (...args: unknown[]) => unknown).bind(target);
    },
  });
  return {
    gl,
    canvas,
    lose: () => {
      lost = true;
      lossReported = false;
    },
    dispatchLost: () => canvas.dispatchEvent(new Event('webglcontextlost', { cancelable: true })),
    restore: () => {
      lost = false;
      canvas.dispatchEvent(new Event('webglcontextrestored'));
    },
  };
}
