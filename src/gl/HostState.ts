const CAPABILITIES = [
  'BLEND', 'CULL_FACE', 'DEPTH_TEST', 'STENCIL_TEST', 'SCISSOR_TEST', 'POLYGON_OFFSET_FILL',
  'SAMPLE_ALPHA_TO_COVERAGE', 'SAMPLE_COVERAGE', 'RASTERIZER_DISCARD', 'DITHER',
] as const;

/**
 * Every pixel-store parameter that changes how `texImage2D`/`texSubImage2D` read an array, with the
 * value the renderer's uploads assume (tightly packed rows of RGBA32F, top row first, unchanged).
 * The renderer never sets pixel-store state itself, so only what the host left elsewhere is
 * changed on entry and put back on restore.
 */
const UNPACK_PARAMETERS = [
  'UNPACK_ALIGNMENT', 'UNPACK_ROW_LENGTH', 'UNPACK_SKIP_PIXELS', 'UNPACK_SKIP_ROWS', 'UNPACK_IMAGE_HEIGHT',
  'UNPACK_SKIP_IMAGES', 'UNPACK_FLIP_Y_WEBGL', 'UNPACK_PREMULTIPLY_ALPHA_WEBGL',
] as const;
/** The renderer's values of {@link UNPACK_PARAMETERS}, in their order (the WebGL defaults). */
const UNPACK_DEFAULTS = Int32Array.of(4, 0, 0, 0, 0, 0, 0, 0);

/**
 * A snapshot of the context state the renderer touches, taken before it draws and put back
 * afterwards, so that it can share a context with a host engine. Saved: framebuffers (draw and
 * read), viewport, scissor, the enables above, blend equations/factors, colour/depth/stencil write
 * masks, depth function, cull face and front face, program, VAO, array/pixel-unpack buffers, renderbuffer,
 * every unpack parameter above, the active texture unit, and the 2D texture and sampler bound on
 * each texture unit the renderer uses. Between `prepareForRenderer` and `restore` unit 0 is active,
 * so that every texture the renderer binds (uploads and resizes too) lands on a saved unit: the
 * host's bindings on the other units are never touched.
 *
 * Saved once or twice a frame, so it queries only what the renderer changes: it never sets the blend
 * colour, and clears with `clearBuffer*` rather than through the clear values. The three array
 * answers of `getParameter` (viewport, scissor box, colour mask) are fresh objects by the WebGL API;
 * no other allocation happens here.
 *
 * Contexts whose `getParameter` answers the WebGL2-only bindings with raw GL names instead of
 * objects (headless-gl 9.0.0-rc.10 in Node, https://github.com/stackgl/headless-gl) are used as they
 * are, never patched. There:
 * - `VERTEX_ARRAY_BINDING` 0 (none bound) is saved as `null`: exact. A non-zero name cannot be turned
 *   back into the object `bindVertexArray` needs, so the renderer leaves **no vertex array bound**
 *   after each call and warns once (`console.warn`): such a host rebinds its own vertex array after
 *   calling the renderer.
 * - `SAMPLER_BINDING` 0 is saved as `null`; another name is put back as read (there `createSampler`
 *   returns that same raw name, which `bindSampler` takes).
 * - `PIXEL_UNPACK_BUFFER_BINDING` answers 0 (its `bindBuffer` rejects the target): nothing to restore.
 * - `blendEquation` rejects MIN/MAX: the renderer uses neither, and puts back only what the host set.
 * In browsers every answer is an object or `null`, and the restore is exact, but for one case GL
 * itself rules out: a program the host deleted while it was current is freed once the renderer
 * uses its own, so none is current afterwards (putting it back would be an INVALID_VALUE error).
 */
export class HostState {
  private readonly enabled = new Uint8Array(CAPABILITIES.length);
  private drawFramebuffer: WebGLFramebuffer | null = null;
  private readFramebuffer: WebGLFramebuffer | null = null;
  private viewport: Int32Array = new Int32Array(4);
  private scissorBox: Int32Array = new Int32Array(4);
  private blendEquations = [0, 0];
  private blendFactors = [0, 0, 0, 0];
  private colorMask: boolean[] = [true, true, true, true];
  private depthMask = true;
  private depthFunc = 0;
  private stencilMask = 0;
  private stencilBackMask = 0;
  private cullFaceMode = 0;
  private frontFace = 0;
  private program: WebGLProgram | null = null;
  private vertexArray: WebGLVertexArrayObject | null = null;
  private arrayBuffer: WebGLBuffer | null = null;
  private pixelUnpackBuffer: WebGLBuffer | null = null;
  private renderbuffer: WebGLRenderbuffer | null = null;
  /** The host's values of {@link UNPACK_PARAMETERS}, booleans as 0 or 1. */
  private readonly unpack = new Int32Array(UNPACK_PARAMETERS.length);
  private activeTexture = 0;
  private readonly textures: (WebGLTexture | null)[];
  private readonly samplers: (WebGLSampler | null)[];
  private warnedVertexArray = false;

  /** @param textureUnits how many texture units (from 0) the renderer binds. */
  constructor(private readonly gl: WebGL2RenderingContext, private readonly textureUnits: number) {
    this.textures = new Array<WebGLTexture | null>(textureUnits).fill(null);
    this.samplers = new Array<WebGLSampler | null>(textureUnits).fill(null);
  }

  save(): void {
    const gl = this.gl;
    for (let i = 0; i < CAPABILITIES.length; i++) this.enabled[i] = gl.isEnabled(gl[CAPABILITIES[i]]) ? 1 : 0;
    this.drawFramebuffer = gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING);
    this.readFramebuffer = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
    this.viewport = gl.getParameter(gl.VIEWPORT);
    this.scissorBox = gl.getParameter(gl.SCISSOR_BOX);
    this.blendEquations[0] = gl.getParameter(gl.BLEND_EQUATION_RGB);
    this.blendEquations[1] = gl.getParameter(gl.BLEND_EQUATION_ALPHA);
    this.blendFactors[0] = gl.getParameter(gl.BLEND_SRC_RGB);
    this.blendFactors[1] = gl.getParameter(gl.BLEND_DST_RGB);
    this.blendFactors[2] = gl.getParameter(gl.BLEND_SRC_ALPHA);
    this.blendFactors[3] = gl.getParameter(gl.BLEND_DST_ALPHA);
    this.colorMask = gl.getParameter(gl.COLOR_WRITEMASK);
    this.depthMask = gl.getParameter(gl.DEPTH_WRITEMASK);
    this.depthFunc = gl.getParameter(gl.DEPTH_FUNC);
    this.stencilMask = gl.getParameter(gl.STENCIL_WRITEMASK);
    this.stencilBackMask = gl.getParameter(gl.STENCIL_BACK_WRITEMASK);
    this.cullFaceMode = gl.getParameter(gl.CULL_FACE_MODE);
    this.frontFace = gl.getParameter(gl.FRONT_FACE);
    const program: WebGLProgram | null = gl.getParameter(gl.CURRENT_PROGRAM);
    // A program deleted while current stays current until unbound, and is freed then: it cannot be
    // made current again, so none is put back. (WebGL's isProgram says false for it; headless-gl's,
    // like GL's, says true until it is freed, and DELETE_STATUS says it is going.)
    this.program = program && gl.isProgram(program) && !gl.getProgramParameter(program, gl.DELETE_STATUS) ? program : null;
    const vertexArray: unknown = gl.getParameter(gl.VERTEX_ARRAY_BINDING);
    if (typeof vertexArray === 'object') this.vertexArray = vertexArray;
    else this.unrestorableVertexArray(vertexArray);
    this.arrayBuffer = gl.getParameter(gl.ARRAY_BUFFER_BINDING);
    // Touched only when the host has one bound (headless-gl rejects the target altogether).
    this.pixelUnpackBuffer = gl.getParameter(gl.PIXEL_UNPACK_BUFFER_BINDING) || null;
    this.renderbuffer = gl.getParameter(gl.RENDERBUFFER_BINDING);
    for (let i = 0; i < UNPACK_PARAMETERS.length; i++) this.unpack[i] = Number(gl.getParameter(gl[UNPACK_PARAMETERS[i]]));
    this.activeTexture = gl.getParameter(gl.ACTIVE_TEXTURE);
    for (let unit = 0; unit < this.textureUnits; unit++) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      this.textures[unit] = gl.getParameter(gl.TEXTURE_BINDING_2D);
      // `|| null`: a raw-name host answers 0 for no sampler (see the class comment).
      this.samplers[unit] = gl.getParameter(gl.SAMPLER_BINDING) || null;
    }
    gl.activeTexture(this.activeTexture);
  }

  /** Puts the neutral state the renderer's passes assume: no sampler objects, plain unpacking, unit 0 active. */
  prepareForRenderer(): void {
    const gl = this.gl;
    for (let unit = 0; unit < this.textureUnits; unit++) gl.bindSampler(unit, null);
    gl.activeTexture(gl.TEXTURE0);
    if (this.pixelUnpackBuffer) gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, null);
    this.setUnpackWhereHostDiffers(UNPACK_DEFAULTS);
    for (let i = 0; i < CAPABILITIES.length; i++) gl.disable(gl[CAPABILITIES[i]]);
    gl.colorMask(true, true, true, true);
  }

  restore(): void {
    const gl = this.gl;
    for (let i = 0; i < CAPABILITIES.length; i++) {
      if (this.enabled[i]) gl.enable(gl[CAPABILITIES[i]]);
      else gl.disable(gl[CAPABILITIES[i]]);
    }
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.drawFramebuffer);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.readFramebuffer);
    gl.viewport(this.viewport[0], this.viewport[1], this.viewport[2], this.viewport[3]);
    gl.scissor(this.scissorBox[0], this.scissorBox[1], this.scissorBox[2], this.scissorBox[3]);
    gl.blendEquationSeparate(this.blendEquations[0], this.blendEquations[1]);
    gl.blendFuncSeparate(this.blendFactors[0], this.blendFactors[1], this.blendFactors[2], this.blendFactors[3]);
    gl.colorMask(this.colorMask[0], this.colorMask[1], this.colorMask[2], this.colorMask[3]);
    gl.depthMask(this.depthMask);
    gl.depthFunc(this.depthFunc);
    gl.stencilMaskSeparate(gl.FRONT, this.stencilMask);
    gl.stencilMaskSeparate(gl.BACK, this.stencilBackMask);
    gl.cullFace(this.cullFaceMode);
    gl.frontFace(this.frontFace);
    gl.useProgram(this.program);
    gl.bindVertexArray(this.vertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.arrayBuffer);
    if (this.pixelUnpackBuffer) gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, this.pixelUnpackBuffer);
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.renderbuffer);
    this.setUnpackWhereHostDiffers(this.unpack);
    for (let unit = 0; unit < this.textureUnits; unit++) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, this.textures[unit]);
      gl.bindSampler(unit, this.samplers[unit]);
    }
    gl.activeTexture(this.activeTexture);
  }

  /** A raw-name answer for the vertex array (see the class comment): saved as none, a warning once if one was bound. */
  private unrestorableVertexArray(name: unknown): void {
    this.vertexArray = null;
    if (!name || this.warnedVertexArray) return;
    this.warnedVertexArray = true;
    console.warn(
      'penumbra-gl: this WebGL2 context answers getParameter(VERTEX_ARRAY_BINDING) with a raw name (headless-gl), ' +
      'so the renderer cannot restore your vertex array: it leaves none bound after each call; rebind yours after calling it.',
    );
  }

  /** Sets each unpack parameter the host left away from the renderer's default to `values`' entry. */
  private setUnpackWhereHostDiffers(values: Int32Array): void {
    const gl = this.gl;
    for (let i = 0; i < UNPACK_PARAMETERS.length; i++) {
      if (this.unpack[i] !== UNPACK_DEFAULTS[i]) gl.pixelStorei(gl[UNPACK_PARAMETERS[i]], values[i]);
    }
  }

  /** The draw framebuffer saved by the last {@link HostState.save}. */
  get savedDrawFramebuffer(): WebGLFramebuffer | null {
    return this.drawFramebuffer;
  }
  /** The read framebuffer saved by the last {@link HostState.save}. */
  get savedReadFramebuffer(): WebGLFramebuffer | null {
    return this.readFramebuffer;
  }
  /** The viewport `[x, y, width, height]` saved by the last {@link HostState.save}. */
  get savedViewport(): Int32Array {
    return this.viewport;
  }
}

/**
 * The draw and read buffers of the host framebuffer a frame composites into (`draw`,
 * `drawInPlace`), which may have several draw buffers (a G-buffer, a chain of MRT passes). WebGL
 * refuses a draw while an active draw buffer has no output of the fragment shader
 * (INVALID_OPERATION), and the composite writes one colour: it writes the host's draw buffer 0
 * alone, and `drawInPlace` copies from that same attachment. Draw and read buffers are the
 * framebuffer's own state, which {@link HostState}'s bindings do not cover: each is set for the
 * renderer's use and put back right after. The default framebuffer has one colour buffer: left alone.
 * No allocation but when MAX_DRAW_BUFFERS changes (once).
 */
export class HostDrawBuffers {
  private framebuffer: WebGLFramebuffer | null = null;
  /** The host's DRAW_BUFFERi for every i below MAX_DRAW_BUFFERS. */
  private hostBuffers: number[] = [];
  /** The host's draw buffer 0, then NONE: what the composite draws with. */
  private firstOnly: number[] = [];
  /** Whether a draw buffer beyond 0 is active: only then are the draw buffers changed. */
  private several = false;
  private hostReadBuffer = 0;

  constructor(private readonly gl: WebGL2RenderingContext) {}

  /** Reads the draw buffers of `framebuffer`, the bound draw framebuffer (the host's, when a frame opens). */
  record(framebuffer: WebGLFramebuffer | null): void {
    const gl = this.gl;
    this.framebuffer = framebuffer;
    this.several = false;
    if (framebuffer === null) return;
    const count = (gl.getParameter(gl.MAX_DRAW_BUFFERS) as number | null) ?? 0;
    if (this.hostBuffers.length !== count) {
      this.hostBuffers = new Array<number>(count).fill(gl.NONE);
      this.firstOnly = new Array<number>(count).fill(gl.NONE);
    }
    for (let i = 0; i < count; i++) {
      const buffer = gl.getParameter(gl.DRAW_BUFFER0 + i) as number;
      this.hostBuffers[i] = buffer;
      if (i > 0 && buffer !== gl.NONE) this.several = true;
    }
    if (count > 0) this.firstOnly[0] = this.hostBuffers[0];
  }

  /** With the recorded framebuffer bound for drawing: leaves its draw buffer 0 the only one drawn into. */
  drawFirstOnly(): void {
    if (this.several) this.gl.drawBuffers(this.firstOnly);
  }

  /** Puts back the draw buffers of the recorded framebuffer, bound for drawing. */
  restoreDraw(): void {
    if (this.several) this.gl.drawBuffers(this.hostBuffers);
  }

  /** With the recorded framebuffer bound for reading: reads from the attachment of its draw buffer 0. */
  readFirst(): void {
    if (this.framebuffer === null || this.hostBuffers.length === 0) return;
    const gl = this.gl;
    this.hostReadBuffer = gl.getParameter(gl.READ_BUFFER) as number;
    if (this.hostReadBuffer !== this.hostBuffers[0]) gl.readBuffer(this.hostBuffers[0]);
  }

  /** Puts back the read buffer of the recorded framebuffer, bound for reading. */
  restoreRead(): void {
    if (this.framebuffer === null || this.hostBuffers.length === 0) return;
    if (this.hostReadBuffer !== this.hostBuffers[0]) this.gl.readBuffer(this.hostReadBuffer);
  }
}
