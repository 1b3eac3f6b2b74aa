// A hostile host's view of the context, shared by the headless-gl test (test/gl/hostParameters.test.ts)
// and the Chromium page (test/browser/reference-page/main.ts): every piece of WebGL2 state
// `getParameter` (and its indexed and per-attribute forms) exposes that a renderer could change is
// set to a value unlike its default, and read back in full after each public call.
import { Hull, PenumbraRenderer, PointLight, TexturedLight } from '../../src/index';
import { colorTarget } from './fixtures';

/** Context state that `getParameter` answers, by name (limits and strings left out: nothing can change them). */
const STATE_PARAMETERS = [
  'ACTIVE_TEXTURE', 'ARRAY_BUFFER_BINDING', 'BLEND', 'BLEND_COLOR', 'BLEND_DST_ALPHA', 'BLEND_DST_RGB',
  'BLEND_EQUATION_ALPHA', 'BLEND_EQUATION_RGB', 'BLEND_SRC_ALPHA', 'BLEND_SRC_RGB', 'COLOR_CLEAR_VALUE',
  'COLOR_WRITEMASK', 'COPY_READ_BUFFER_BINDING', 'COPY_WRITE_BUFFER_BINDING', 'CULL_FACE', 'CULL_FACE_MODE',
  'CURRENT_PROGRAM', 'DEPTH_CLEAR_VALUE', 'DEPTH_FUNC', 'DEPTH_RANGE', 'DEPTH_TEST', 'DEPTH_WRITEMASK', 'DITHER',
  'DRAW_BUFFER0', 'DRAW_FRAMEBUFFER_BINDING', 'ELEMENT_ARRAY_BUFFER_BINDING', 'FRAGMENT_SHADER_DERIVATIVE_HINT',
  'FRONT_FACE', 'GENERATE_MIPMAP_HINT', 'LINE_WIDTH', 'PACK_ALIGNMENT', 'PACK_ROW_LENGTH', 'PACK_SKIP_PIXELS',
  'PACK_SKIP_ROWS', 'PIXEL_PACK_BUFFER_BINDING', 'PIXEL_UNPACK_BUFFER_BINDING', 'POLYGON_OFFSET_FACTOR',
  'POLYGON_OFFSET_FILL', 'POLYGON_OFFSET_UNITS', 'RASTERIZER_DISCARD', 'READ_BUFFER', 'READ_FRAMEBUFFER_BINDING',
  'RENDERBUFFER_BINDING', 'SAMPLE_ALPHA_TO_COVERAGE', 'SAMPLE_COVERAGE', 'SAMPLE_COVERAGE_INVERT',
  'SAMPLE_COVERAGE_VALUE', 'SCISSOR_BOX', 'SCISSOR_TEST', 'STENCIL_BACK_FAIL', 'STENCIL_BACK_FUNC',
  'STENCIL_BACK_PASS_DEPTH_FAIL', 'STENCIL_BACK_PASS_DEPTH_PASS', 'STENCIL_BACK_REF', 'STENCIL_BACK_VALUE_MASK',
  'STENCIL_BACK_WRITEMASK', 'STENCIL_CLEAR_VALUE', 'STENCIL_FAIL', 'STENCIL_FUNC', 'STENCIL_PASS_DEPTH_FAIL',
  'STENCIL_PASS_DEPTH_PASS', 'STENCIL_REF', 'STENCIL_TEST', 'STENCIL_VALUE_MASK', 'STENCIL_WRITEMASK',
  'TRANSFORM_FEEDBACK_ACTIVE', 'TRANSFORM_FEEDBACK_BINDING', 'TRANSFORM_FEEDBACK_BUFFER_BINDING',
  'TRANSFORM_FEEDBACK_PAUSED', 'UNIFORM_BUFFER_BINDING', 'UNPACK_ALIGNMENT', 'UNPACK_COLORSPACE_CONVERSION_WEBGL',
  'UNPACK_FLIP_Y_WEBGL', 'UNPACK_IMAGE_HEIGHT', 'UNPACK_PREMULTIPLY_ALPHA_WEBGL', 'UNPACK_ROW_LENGTH',
  'UNPACK_SKIP_IMAGES', 'UNPACK_SKIP_PIXELS', 'UNPACK_SKIP_ROWS', 'VERTEX_ARRAY_BINDING', 'VIEWPORT',
] as const;

/** Bindings answered per texture unit (every unit up to MAX_COMBINED_TEXTURE_IMAGE_UNITS). */
const UNIT_PARAMETERS = ['TEXTURE_BINDING_2D', 'TEXTURE_BINDING_CUBE_MAP', 'TEXTURE_BINDING_3D', 'TEXTURE_BINDING_2D_ARRAY', 'SAMPLER_BINDING'] as const;

/** Per generic vertex attribute of the bound vertex array (`getVertexAttrib`). */
const ATTRIBUTE_PARAMETERS = [
  'VERTEX_ATTRIB_ARRAY_ENABLED', 'VERTEX_ATTRIB_ARRAY_BUFFER_BINDING', 'VERTEX_ATTRIB_ARRAY_SIZE',
  'VERTEX_ATTRIB_ARRAY_DIVISOR', 'CURRENT_VERTEX_ATTRIB',
] as const;

/** The parameters that may differ from the host's between `beginDraw()` and `draw()` (the scene target is bound). */
const FRAME_PARAMETERS: readonly string[] = ['DRAW_FRAMEBUFFER_BINDING', 'READ_FRAMEBUFFER_BINDING', 'VIEWPORT', 'DRAW_BUFFER0', 'READ_BUFFER'];

type GL = WebGL2RenderingContext;
type Snapshot = Map<string, unknown>;

/** The host's GL objects by name, so that a renderer object left bound reads 'renderer object'. */
export class HostObjects {
  private readonly names = new Map<unknown, string>();

  add<T>(name: string, object: T): T {
    this.names.set(object, name);
    return object;
  }

  /** A parameter's value in comparable form: objects by name, typed arrays as plain arrays. */
  describe(value: unknown): unknown {
    if (value === null || value === undefined || typeof value !== 'object') return value;
    if (ArrayBuffer.isView(value) || Array.isArray(value)) return Array.from(value as ArrayLike<unknown>);
    return this.names.get(value) ?? 'renderer object';
  }
}

/** Everything listed above, read without changing anything (the active unit is put back). */
export function snapshot(gl: GL, objects: HostObjects): Snapshot {
  const values: Snapshot = new Map();
  const read = (key: string, value: unknown) => values.set(key, objects.describe(value));
  for (const name of STATE_PARAMETERS) read(name, gl.getParameter(gl[name]));
  const active = gl.getParameter(gl.ACTIVE_TEXTURE) as number;
  const units = gl.getParameter(gl.MAX_COMBINED_TEXTURE_IMAGE_UNITS) as number;
  for (let unit = 0; unit < units; unit++) {
    gl.activeTexture(gl.TEXTURE0 + unit);
    for (const name of UNIT_PARAMETERS) read(`${name}[unit ${unit}]`, gl.getParameter(gl[name]));
  }
  gl.activeTexture(active);
  const attributes = gl.getParameter(gl.MAX_VERTEX_ATTRIBS) as number;
  for (let index = 0; index < attributes; index++) {
    for (const name of ATTRIBUTE_PARAMETERS) {
      const value = gl.getVertexAttrib(index, gl[name]);
      // headless-gl rejects the divisor query (INVALID_ENUM): what it cannot answer is not compared.
      if (gl.getError() === gl.NO_ERROR) read(`${name}[attribute ${index}]`, value);
    }
  }
  readIndexed(gl, values, objects, 'UNIFORM_BUFFER_BINDING', gl.MAX_UNIFORM_BUFFER_BINDINGS);
  readIndexed(gl, values, objects, 'TRANSFORM_FEEDBACK_BUFFER_BINDING', gl.MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS);
  return values;
}

function readIndexed(gl: GL, values: Snapshot, objects: HostObjects, name: 'UNIFORM_BUFFER_BINDING' | 'TRANSFORM_FEEDBACK_BUFFER_BINDING', limit: number): void {
  const count = gl.getParameter(limit) as number;
  for (let index = 0; index < count; index++) {
    values.set(`${name}[${index}]`, objects.describe(gl.getIndexedParameter(gl[name], index)));
  }
}

/** The keys whose values differ between two snapshots, with both values, except those in `allowed`. */
export function differences(before: Snapshot, after: Snapshot, allowed: readonly string[] = []): string[] {
  const found: string[] = [];
  for (const [key, value] of before) {
    if (allowed.includes(key)) continue;
    const now = after.get(key);
    if (JSON.stringify(now) !== JSON.stringify(value)) found.push(`${key}: ${JSON.stringify(value)} → ${JSON.stringify(now)}`);
  }
  return found;
}

function linkedProgram(gl: GL): WebGLProgram {
  const program = gl.createProgram();
  const stage = (type: number, source: string) => {
    const shader = gl.createShader(type)!;
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    gl.attachShader(program, shader);
  };
  stage(gl.VERTEX_SHADER, '#version 300 es\nin vec2 p;\nout float v;\nvoid main() { v = p.x; gl_Position = vec4(p, 0.0, 1.0); }');
  stage(gl.FRAGMENT_SHADER, '#version 300 es\nprecision mediump float;\nin float v;\nout vec4 c;\nvoid main() { c = vec4(v); }');
  gl.linkProgram(program);
  return program;
}

/** A host colour target of `width × height` (RGBA8), left bound as the draw and read framebuffer. */
function hostFramebuffer(gl: GL, objects: HostObjects, width: number, height: number): void {
  const target = colorTarget(gl, width, height);
  objects.add('host target texture', target.texture);
  objects.add('host framebuffer', target.framebuffer);
}

/** Sets the fixed-function state, masks and hints to values unlike the defaults. */
export function setFixedFunctionState(gl: GL): void {
  gl.viewport(3, 4, 50, 40);
  gl.scissor(1, 2, 30, 20);
  for (const capability of [gl.SCISSOR_TEST, gl.BLEND, gl.DEPTH_TEST, gl.STENCIL_TEST, gl.CULL_FACE, gl.POLYGON_OFFSET_FILL, gl.SAMPLE_ALPHA_TO_COVERAGE, gl.SAMPLE_COVERAGE]) gl.enable(capability);
  gl.disable(gl.DITHER);
  gl.blendEquationSeparate(gl.FUNC_SUBTRACT, gl.FUNC_REVERSE_SUBTRACT);
  gl.blendFuncSeparate(gl.SRC_COLOR, gl.ONE_MINUS_DST_ALPHA, gl.CONSTANT_ALPHA, gl.ZERO);
  gl.blendColor(0.25, 0.5, 0.75, 1);
  gl.colorMask(true, false, true, false);
  gl.clearColor(0.3, 0.6, 0.9, 0.5);
  gl.clearDepth(0.25);
  gl.clearStencil(3);
  gl.depthFunc(gl.GEQUAL);
  gl.depthMask(false);
  gl.depthRange(0.125, 0.75);
  gl.stencilFuncSeparate(gl.FRONT, gl.GREATER, 5, 0x0f);
  gl.stencilFuncSeparate(gl.BACK, gl.LESS, 6, 0xf0);
  gl.stencilOpSeparate(gl.FRONT, gl.INCR, gl.DECR, gl.INVERT);
  gl.stencilOpSeparate(gl.BACK, gl.REPLACE, gl.INCR_WRAP, gl.DECR_WRAP);
  gl.stencilMaskSeparate(gl.FRONT, 0x3c);
  gl.stencilMaskSeparate(gl.BACK, 0xc3);
  gl.cullFace(gl.FRONT);
  gl.frontFace(gl.CW);
  gl.polygonOffset(2, 3);
  gl.sampleCoverage(0.5, true);
  gl.hint(gl.GENERATE_MIPMAP_HINT, gl.NICEST);
}

/** Sets every pixel-store parameter (pack and unpack) away from its default; no pixel buffers bound. */
function setPixelStore(gl: GL): void {
  gl.pixelStorei(gl.PACK_ALIGNMENT, 2);
  gl.pixelStorei(gl.PACK_ROW_LENGTH, 7);
  gl.pixelStorei(gl.PACK_SKIP_PIXELS, 2);
  gl.pixelStorei(gl.PACK_SKIP_ROWS, 3);
  setUnpackParameters(gl);
}

/** Sets every unpack parameter away from its default (a layout under which no tightly packed upload reads right). */
export function setUnpackParameters(gl: GL): void {
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.pixelStorei(gl.UNPACK_ROW_LENGTH, 5);
  gl.pixelStorei(gl.UNPACK_SKIP_PIXELS, 3);
  gl.pixelStorei(gl.UNPACK_SKIP_ROWS, 2);
  gl.pixelStorei(gl.UNPACK_SKIP_IMAGES, 1);
  gl.pixelStorei(gl.UNPACK_IMAGE_HEIGHT, 4);
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, true);
  gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, true);
  gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
}

/** Binds a distinct host texture of every kind and a sampler on every unit, then makes a high unit active. */
function setTextureUnits(gl: GL, objects: HostObjects): void {
  const units = gl.getParameter(gl.MAX_COMBINED_TEXTURE_IMAGE_UNITS) as number;
  const targets = [[gl.TEXTURE_2D, '2D'], [gl.TEXTURE_CUBE_MAP, 'cube'], [gl.TEXTURE_3D, '3D'], [gl.TEXTURE_2D_ARRAY, 'array']] as const;
  for (let unit = 0; unit < units; unit++) {
    gl.activeTexture(gl.TEXTURE0 + unit);
    for (const [target, kind] of targets) gl.bindTexture(target, objects.add(`host ${kind} texture ${unit}`, gl.createTexture()));
    gl.bindSampler(unit, objects.add(`host sampler ${unit}`, gl.createSampler()));
  }
  // A unit above the renderer's own: what it binds on the active unit would land on the host's texture.
  gl.activeTexture(gl.TEXTURE0 + units - 3);
}

/** Binds host buffers on every generic and indexed buffer target that needs no pixel-buffer semantics. */
function setBuffers(gl: GL, objects: HostObjects, supported: (step: string, set: () => void) => void): void {
  const buffer = (name: string) => objects.add(name, gl.createBuffer());
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer('host array buffer'));
  gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffer('host element buffer'));
  supported('copy buffers', () => {
    gl.bindBuffer(gl.COPY_READ_BUFFER, buffer('host copy-read buffer'));
    gl.bindBuffer(gl.COPY_WRITE_BUFFER, buffer('host copy-write buffer'));
  });
  // Binds the generic uniform buffer binding too.
  supported('uniform buffers', () => gl.bindBufferBase(gl.UNIFORM_BUFFER, 1, buffer('host uniform buffer')));
  supported('transform feedback', () => {
    const feedback = objects.add('host transform feedback', gl.createTransformFeedback());
    gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, feedback);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, buffer('host transform-feedback buffer'));
  });
}

/** A vertex array with attribute 1 enabled on a host buffer with a divisor, and generic attribute values. */
function setVertexState(gl: GL, objects: HostObjects): WebGLVertexArrayObject {
  const vertexArray = objects.add('host vertex array', gl.createVertexArray());
  gl.bindVertexArray(vertexArray);
  const buffer = objects.add('host attribute buffer', gl.createBuffer());
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
  gl.bufferData(gl.ARRAY_BUFFER, 64, gl.STATIC_DRAW);
  gl.enableVertexAttribArray(1);
  gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 16, 4);
  gl.vertexAttribDivisor(1, 2);
  gl.vertexAttrib4f(0, 0.5, 0.25, 0.125, 2);
  gl.vertexAttrib4f(2, 1, 2, 3, 4);
  return vertexArray;
}

/** What {@link setHostState} managed to set: host objects by name, and the steps the implementation rejected. */
interface HostSetup {
  objects: HostObjects;
  unsupported: string[];
  /** The host's vertex array (bound). */
  vertexArray: WebGLVertexArrayObject;
}

/**
 * Sets a hostile host's state (every parameter above away from its default where the implementation
 * allows; the steps it rejects are listed, their parameters still compared at their defaults) with
 * a `width × height` host framebuffer bound. Leaves no GL error.
 */
function setHostState(gl: GL, width: number, height: number): HostSetup {
  const objects = new HostObjects();
  const unsupported: string[] = [];
  const supported = (step: string, set: () => void) => {
    set();
    if (gl.getError() !== gl.NO_ERROR) unsupported.push(step);
  };
  hostFramebuffer(gl, objects, width, height);
  setFixedFunctionState(gl);
  supported('derivative hint', () => gl.hint(gl.FRAGMENT_SHADER_DERIVATIVE_HINT, gl.FASTEST));
  setPixelStore(gl);
  gl.useProgram(objects.add('host program', linkedProgram(gl)));
  const vertexArray = setVertexState(gl, objects);
  setBuffers(gl, objects, supported);
  supported('renderbuffer', () => gl.bindRenderbuffer(gl.RENDERBUFFER, objects.add('host renderbuffer', gl.createRenderbuffer())));
  setTextureUnits(gl, objects);
  const error = gl.getError();
  if (error !== gl.NO_ERROR) throw new Error(`setting the host state left GL error 0x${error.toString(16)}`);
  return { objects, unsupported, vertexArray };
}

/** What {@link checkHostStateAcrossPublicCalls} found. */
export interface HostStateReport {
  /** Parameters compared after each call. */
  compared: number;
  /** Public calls after which they were compared. */
  calls: string[];
  /** Steps of the host setup the implementation rejected. */
  unsupported: string[];
  /** Whether the context answers VERTEX_ARRAY_BINDING with a raw name (the host rebinds its vertex array after each call). */
  rawNames: boolean;
  /** `call: parameter: before → after` for each difference, and any GL error a call left. */
  failures: string[];
}

/**
 * Sets a hostile host state, then runs every public call of the renderer (constructor, frames with
 * shadows, a textured light and the debug overlay, in place, lightmap only, resize, scene changes
 * that upload geometry, dispose), comparing every parameter after each with what the host set.
 * With `normals`, a renderer with normals, and the calls that take the host's surfaces; with a
 * `lightmapScale` below 1, the hull masks and the composite that reads them.
 */
export function checkHostStateAcrossPublicCalls(gl: GL, width: number, height: number, normals = false, lightmapScale = 1): HostStateReport {
  const cookie = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, cookie);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array([255, 255, 255, 255]));
  gl.bindTexture(gl.TEXTURE_2D, null);
  const { objects, unsupported, vertexArray } = setHostState(gl, width, height);
  objects.add('host cookie', cookie);
  // headless-gl answers the binding with a raw name: the renderer cannot restore the host's vertex
  // array there and promises to leave none bound (HostState), which the host then rebinds.
  const hostVertexArrayName: unknown = gl.getParameter(gl.VERTEX_ARRAY_BINDING);
  const rawNames = typeof hostVertexArrayName === 'number';
  const before = snapshot(gl, objects);
  const report: HostStateReport = { compared: before.size, calls: [], unsupported, rawNames, failures: [] };
  const check = (call: string, run: () => void, allowed: readonly string[] = []) => {
    run();
    report.calls.push(call);
    const error = gl.getError();
    if (error !== gl.NO_ERROR) report.failures.push(`${call}: GL error 0x${error.toString(16)}`);
    if (rawNames) {
      const left = gl.getParameter(gl.VERTEX_ARRAY_BINDING) as number;
      // Calls that do not touch GL (addLight, removeHull…) leave the host's own bound.
      if (left !== 0 && left !== hostVertexArrayName) report.failures.push(`${call}: vertex array ${left} left bound on a raw-name context (none or the host's promised)`);
      gl.bindVertexArray(vertexArray);
    }
    for (const difference of differences(before, snapshot(gl, objects), allowed)) report.failures.push(`${call}: ${difference}`);
  };
  let renderer!: PenumbraRenderer;
  const hull = new Hull([[36, 18], [42, 18], [42, 30], [36, 30]]);
  check('constructor', () => { renderer = new PenumbraRenderer(gl, { width, height, normals, lightmapScale }); });
  check('addLight/addHull', () => {
    renderer.addLight(new PointLight({ position: [20, 24], range: 50, radius: 3 }));
    renderer.addLight(new TexturedLight({ position: [40, 10], range: 30, texture: cookie }));
    renderer.addHull(hull);
  });
  check('beginDraw', () => renderer.beginDraw(), FRAME_PARAMETERS);
  check('draw', () => renderer.draw());
  check('renderLightmap after a hull moved', () => {
    hull.position = [2, 1];
    renderer.renderLightmap();
  });
  check('drawInPlace with debug', () => {
    renderer.debug = true;
    renderer.drawInPlace();
  });
  if (normals) {
    check('drawInPlace with surfaces', () => renderer.drawInPlace(undefined, { normals: renderer.normalTexture, material: renderer.materialTexture, flipY: true }));
    check('renderLightmap with surfaces', () => renderer.renderLightmap(undefined, { normals: renderer.normalTexture }));
  }
  check('resize', () => renderer.resize(width + 2, height + 1));
  check('frame after resize', () => {
    renderer.beginDraw();
    renderer.draw();
  });
  check('removeHull/removeLight', () => {
    renderer.removeHull(hull);
    renderer.removeLight(renderer.lights[0]);
  });
  check('dispose', () => renderer.dispose());
  return report;
}
