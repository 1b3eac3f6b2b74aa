/** What a value given as a rendering context is. */
type ContextKind = 'webgl2' | 'webgl1' | 'other';

/** WebGL2-only enums, with their values: a WebGL1 context has none of them, whatever methods it has. */
const VERTEX_ARRAY_BINDING = 0x85b5;
const RGBA16F = 0x881a;

/**
 * Whether `gl` is a WebGL2 context, a WebGL1 context, or something else, by feature rather than
 * `instanceof`: headless-gl's contexts are not instances of the browser classes, and a context of
 * another window (an iframe) is not an instance of this window's. headless-gl 9's WebGL1 context
 * has every WebGL2 method (which then fail) but none of the WebGL2 enums, so both are checked.
 */
function contextKind(gl: unknown): ContextKind {
  if (typeof gl !== 'object' || gl === null) return 'other';
  const candidate = gl as Record<string, unknown>;
  if (typeof candidate.drawArrays !== 'function' || typeof candidate.getParameter !== 'function') return 'other';
  const webgl2 = typeof candidate.createVertexArray === 'function'
    && typeof candidate.texStorage2D === 'function'
    && typeof candidate.drawElementsInstanced === 'function'
    && candidate.VERTEX_ARRAY_BINDING === VERTEX_ARRAY_BINDING
    && candidate.RGBA16F === RGBA16F;
  return webgl2 ? 'webgl2' : 'webgl1';
}

/** True when `gl` is a WebGL2 context; see {@link contextKind}. */
export function isWebGL2(gl: unknown): gl is WebGL2RenderingContext {
  return contextKind(gl) === 'webgl2';
}

/**
 * What to pass instead of a context that is not WebGL2, in a browser and in Node; the engine
 * integrations say it in their own terms.
 */
export const WEBGL2_CONTEXT_FIX = 'in a browser pass canvas.getContext(\'webgl2\'); in Node, a headless-gl 9 context made with createGL(width, height, { createWebGL2Context: true })';

/**
 * The `TypeError` that `owner` throws for a context `gl` that is not WebGL2: it names what was
 * passed (a WebGL1 context, or another value) and ends with `fix`, what to pass instead.
 */
export function notWebGL2Error(owner: string, gl: unknown, fix: string): TypeError {
  return new TypeError(`penumbra: ${owner} needs a WebGL2 rendering context, got ${describeContext(gl)}: ${fix}`);
}

/** A value given as a context, for a message: its kind and class, never running its own code. */
function describeContext(gl: unknown): string {
  if (gl === null || gl === undefined) return String(gl);
  if (typeof gl !== 'object') return `a ${typeof gl}`;
  let name: unknown;
  try {
    name = (Object.getPrototypeOf(gl) as { constructor?: { name?: unknown } } | null)?.constructor?.name;
  } catch {
    name = undefined;
  }
  const named = typeof name === 'string' && name !== '' && name !== 'Object' ? ` (${name})` : '';
  return contextKind(gl) === 'webgl1' ? `a WebGL1 context${named}` : `an object${named}`;
}

/**
 * Whether the context's canvas is multisampled and has no alpha channel (made with `antialias:
 * true, alpha: false`). `drawInPlace` cannot copy such a canvas: `blitFramebuffer` from a
 * multisampled buffer needs the RGBA format of its target, and fails (the lighting draws black).
 */
export function isOpaqueMultisampledCanvas(gl: WebGL2RenderingContext): boolean {
  const attributes = gl.getContextAttributes();
  return attributes !== null && attributes.antialias === true && attributes.alpha === false;
}

/** Whether half-float colour targets can be rendered to and blended. */
export function supportsFloatTargets(gl: WebGL2RenderingContext): boolean {
  return gl.getExtension('EXT_color_buffer_float') != null;
}
