/** Counts the calls made on a WebGL context and the time spent inside them (bench only). */
interface GLProbe {
  /** Calls since the last {@link GLProbe.reset}. */
  calls: number;
  /** Milliseconds spent inside those calls (the driver's share, including any wait for the rasterizer). */
  time: number;
  reset(): void;
}

/**
 * Wraps every method of `gl` on the instance with a counting, timing forwarder. The forwarders
 * allocate (rest arguments), so measure the heap before probing a context.
 */
export function probeCalls(gl: WebGL2RenderingContext): GLProbe {
  const probe: GLProbe = { calls: 0, time: 0, reset() { probe.calls = 0; probe.time = 0; } };
  const target = gl as unknown as Record<string, unknown>;
  // headless-gl's methods call each other; only the outermost call is the caller's.
  let depth = 0;
  for (const name of methodNames(gl)) {
    const method = target[name] as (...args: unknown[]) => unknown;
    target[name] = function (this: unknown, ...args: unknown[]) {
      if (depth > 0) return method.apply(this, args);
      depth++;
      const start = performance.now();
      try {
        return method.apply(this, args);
      } finally {
        probe.time += performance.now() - start;
        probe.calls++;
        depth--;
      }
    };
  }
  return probe;
}

/**
 * Makes `gl.getParameter(VERTEX_ARRAY_BINDING)` answer the bound vertex array object (or `null`),
 * as browsers do, where headless-gl answers its raw name: the baseline renderers' host state hands
 * the answer back to `bindVertexArray`, which rejects a number. The context remembers what was
 * bound through it.
 */
export function answerVertexArrayLikeBrowsers(gl: WebGL2RenderingContext): void {
  const calls = gl as unknown as Record<'getParameter' | 'bindVertexArray' | 'deleteVertexArray', (...args: never[]) => unknown>;
  const realGetParameter = gl.getParameter.bind(gl), realBind = gl.bindVertexArray.bind(gl), realDelete = gl.deleteVertexArray.bind(gl);
  let bound: WebGLVertexArrayObject | null = null;
  calls.bindVertexArray = (vertexArray: WebGLVertexArrayObject | null) => {
    bound = vertexArray;
    realBind(vertexArray);
  };
  calls.deleteVertexArray = (vertexArray: WebGLVertexArrayObject | null) => {
    if (vertexArray === bound) bound = null;
    realDelete(vertexArray);
  };
  calls.getParameter = (pname: number) => (pname === gl.VERTEX_ARRAY_BINDING ? bound : realGetParameter(pname));
}

/**
 * Replaces every method of `gl` with a stub that does nothing and allocates nothing, so that heap
 * growth across a frame is the renderer's own: headless-gl's JavaScript layer allocates in many
 * calls (bindFramebuffer ~95 B, isEnabled ~29 B), which a browser's native WebGL does not.
 * `getParameter` answers from a cache filled by the real method. Returns a function that puts the
 * real methods back.
 */
export function stubCalls(gl: WebGL2RenderingContext): () => void {
  const target = gl as unknown as Record<string, unknown>;
  const names = methodNames(gl);
  const saved = names.map((name) => Object.getOwnPropertyDescriptor(target, name));
  const realGetParameter = gl.getParameter.bind(gl);
  const answers = new Map<number, unknown>();
  for (const name of names) target[name] = stub;
  target.getParameter = (pname: number) => {
    if (!answers.has(pname)) answers.set(pname, realGetParameter(pname));
    return answers.get(pname);
  };
  return () => {
    names.forEach((name, i) => {
      const descriptor = saved[i];
      if (descriptor) Object.defineProperty(target, name, descriptor);
      else delete target[name];
    });
  };
}

function stub(): undefined {
  return undefined;
}

function methodNames(gl: WebGL2RenderingContext): string[] {
  const names = new Set<string>();
  for (let proto: object | null = gl; proto && proto !== Object.prototype; proto = Object.getPrototypeOf(proto)) {
    for (const name of Object.getOwnPropertyNames(proto)) {
      if (name === 'constructor' || name.startsWith('_') || names.has(name)) continue;
      const descriptor = Object.getOwnPropertyDescriptor(proto, name);
      if (descriptor && typeof descriptor.value === 'function') names.add(name);
    }
  }
  return [...names];
}
