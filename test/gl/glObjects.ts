/** Kinds of GL object a WebGL2 context creates and deletes, by the suffix of their create/delete calls. */
const KINDS = ['Buffer', 'Framebuffer', 'Program', 'Query', 'Renderbuffer', 'Sampler', 'Shader', 'Texture', 'TransformFeedback', 'VertexArray'] as const;

/** Live GL objects of one context, counted by wrapping its create and delete calls. */
interface GLObjectCount {
  /** Objects created and not deleted since the count began. */
  live(): number;
  /** The live objects by kind, for messages. */
  byKind(): Record<string, number>;
}

/**
 * Starts counting the GL objects `gl` creates and deletes (its own `create*` and `delete*` calls,
 * replaced on the instance; a `delete*` of an object made before counting began does not count).
 */
export function countGLObjects(gl: WebGL2RenderingContext): GLObjectCount {
  const live = new Map<unknown, string>();
  const methods = gl as unknown as Record<string, (...args: unknown[]) => unknown>;
  for (const kind of KINDS) {
    const create = methods[`create${kind}`].bind(gl);
    const remove = methods[`delete${kind}`].bind(gl);
    methods[`create${kind}`] = (...args: unknown[]) => {
      const object = create(...args);
      if (object) live.set(object, kind);
      return object;
    };
    methods[`delete${kind}`] = (object: unknown) => {
      live.delete(object);
      return remove(object);
    };
  }
  return {
    live: () => live.size,
    byKind: () => {
      const counts: Record<string, number> = {};
      for (const kind of live.values()) counts[kind] = (counts[kind] ?? 0) + 1;
      return counts;
    },
  };
}
