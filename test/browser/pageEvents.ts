// Events of a test page's canvas, for the pages that lose and restore their WebGL context.

/** Resolves on the canvas' next `type` event; rejects after 10 s so a missing event fails clearly. */
export function nextEvent(canvas: HTMLCanvasElement, type: string): Promise<void> {
  return new Promise((done, fail) => {
    const timer = setTimeout(() => fail(new Error(`no ${type} event within 10 s`)), 10_000);
    canvas.addEventListener(type, () => {
      clearTimeout(timer);
      done();
    }, { once: true });
  });
}

/** Resolves after the event being dispatched has reached every listener (a promise continuation runs inside the dispatch): Chromium allows restoring a lost context only then. */
export function afterDispatch(): Promise<void> {
  return new Promise((done) => setTimeout(done, 0));
}
