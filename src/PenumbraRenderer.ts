import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import type { FrameStats } from './FrameStats';
import { checkClassificationBudget, RENDERER_OPTION_KEYS, type PenumbraRendererOptions } from './options';
import { FramePlan } from './shadow/FramePlan';
import { ShadowGeometry } from './shadow/ShadowGeometry';
import { TILE_CLASSES } from './shadow/shadowLayout';
import { isWebGL2, notWebGL2Error, supportsFloatTargets, WEBGL2_CONTEXT_FIX } from './gl/capabilities';
import { HostDrawBuffers, HostState } from './gl/HostState';
import { RenderTarget, type TargetFormat } from './gl/RenderTarget';
import { LightShapes } from './passes/LightShapes';
import { BlurPass } from './passes/BlurPass';
import { CompositePass, CompositeUnits } from './passes/CompositePass';
import { HullMaskPass } from './passes/HullMaskPass';
import { Dithering, MAX_BLUR_RADIUS, MIN_BLUR_RADIUS, ToneMapping } from './scene/look';
import { DebugPass } from './passes/DebugPass';
import { LightPass, type Surface } from './passes/LightPass';
import { LIGHT_TEXTURE_UNITS, SHADOW_TEXTURE_UNITS } from './passes/lightLayout';
import { ShadowTextures } from './shadow/ShadowTextures';
import { LightmapAttachments, SceneAttachments, type SurfaceTextures } from './passes/surfaceLayout';
import { Hull } from './scene/Hull';
import {
  checkIlluminationQuery, ILLUMINATION_OPTION_KEYS, IlluminationQuery, IS_LIT_OPTION_KEYS, type Illumination, type IlluminationOptions,
} from './scene/illumination';
import { DirectionalLight } from './scene/DirectionalLight';
import { Light, type LightOptions } from './scene/Light';
import { describeTexture, TexturedLight } from './scene/TexturedLight';
import {
  ALL_LAYERS, assertBoolean, assertFinite, assertLayerMask, assertNonNegative, assertOneOf, assertOptions, describeValue, frozenColor, type ColorLike,
} from './util/validate';

/** GL objects of the renderer, rebuilt together after a context loss. */
interface Resources {
  shapes: LightShapes;
  shadows: ShadowTextures;
  scene: RenderTarget;
  light: LightPass;
  composite: CompositePass;
  /** With a lightmap smaller than the scene (see {@link PenumbraRenderer.edgeAware}); else null. */
  hullMask: HullMaskPass | null;
  blur: BlurPass;
  debug: DebugPass;
}

/** Clear value of the scene target. */
const TRANSPARENT = new Float32Array(4);

/**
 * The texture units the passes bind (from 0: the light pass's, see LIGHT_TEXTURE_UNITS, and the
 * composite's scene and lightmap; with normals its surface's; upsampling aware of hull edges the
 * hull masks'), saved and restored around every draw.
 */
function textureUnits(normals: boolean, edgeAware: boolean): number {
  const { u_normals, u_material, ...lightUnits } = LIGHT_TEXTURE_UNITS;
  const last = Math.max(...Object.values(lightUnits), CompositeUnits.scene, CompositeUnits.lightmap,
    ...(normals ? [u_normals, u_material, CompositeUnits.specular, CompositeUnits.material] : []),
    ...(edgeAware ? [CompositeUnits.hullMask, CompositeUnits.lightmapHullMask] : []));
  return last + 1;
}

/**
 * Real-time 2D lights with soft shadows for an existing WebGL2 context.
 *
 * Each frame: call {@link PenumbraRenderer.beginDraw}, draw the scene to be lit, then call
 * {@link PenumbraRenderer.draw}, which builds the lightmap (ambient + every light, each masked by
 * the exact fraction of its disk the hulls leave visible) and writes scene × lightmap into the
 * framebuffer that was bound at `beginDraw`. What you draw afterwards (UI) is unlit.
 *
 * State contract: after every call the context state the renderer touches is as it was: draw and
 * read framebuffers, viewport, scissor box, the enables (blend, cull, depth, stencil, scissor,
 * polygon offset, sample coverage, rasterizer discard, dither), blend equations and factors, colour,
 * depth and stencil write masks, depth function, cull and front face, program, vertex array, array
 * and pixel-unpack buffers, renderbuffer, the unpack pixel-store parameters, the active texture
 * unit, the texture and sampler bound on every unit it uses, and the draw and read buffers of the
 * framebuffer it composites into. After `beginDraw()` only the framebuffer and viewport differ (they
 * point at the internal scene target), and an exception cannot leave them so (see
 * {@link PenumbraRenderer.beginDraw}).
 *
 * Context loss: while `gl.isContextLost()` is true every call is a no-op, also in the window between
 * the loss and the `webglcontextlost` event. A renderer made on a lost context waits likewise; a
 * `width` or `height` not given is the restored drawing buffer's. When the context is restored the
 * renderer rebuilds its GL objects, keeps its lights and hulls, and calls
 * {@link PenumbraRenderer.onContextRestored}.
 */
export class PenumbraRenderer {
  /** Draw wireframes of light quads and shadow geometry over the result. */
  debug: boolean;
  /**
   * Time the renderer's JavaScript per frame into `stats.cpuTime`. Off by default: the two clock
   * reads are the only heap the frame allocates (V8 boxes the double each one returns, 16 bytes).
   */
  measureCpuTime: boolean;
  /**
   * Called after the renderer rebuilt itself on a restored context: the textures of the old
   * context are gone, so give each {@link TexturedLight} a new cookie texture here. A textured light
   * left with an old texture is named in a console warning, and the next frame throws naming it.
   */
  onContextRestored: ((renderer: PenumbraRenderer) => void) | null;
  /** Figures about the last frame. */
  readonly stats: FrameStats = { lights: 0, lightsDrawn: 0, lightsFiled: 0, hulls: 0, edges: 0, cpuTime: 0, tilesLit: 0, tilesDark: 0, tilesExact: 0, tilesLean: 0, tilesHeld: 0, tilesOutside: 0, lightsUnclassified: 0 };

  private readonly gl: WebGL2RenderingContext;
  private readonly _lights: Light[] = [];
  private readonly _hulls: Hull[] = [];
  private _ambient: readonly [number, number, number] = Object.freeze([0.2, 0.2, 0.2] as const);
  private _exposure = 1;
  private _toneMapping: ToneMapping = ToneMapping.None;
  private _dithering: Dithering = Dithering.None;
  private _lightmapBlur = 0;
  private readonly _viewProjection = mat4.create();
  private customViewProjection = false;
  private readonly geometry = new ShadowGeometry();
  private readonly plan = new FramePlan();
  private readonly hostState: HostState;
  /** Chosen with each build of the GL objects (see {@link PenumbraRenderer.chooseLightmapFormat}). */
  private lightmapFormat: TargetFormat = 'rgba16f';
  private resources: Resources | null = null;
  /** The targets' size; a side is 0 while a renderer made on a lost context without it waits for the restore. */
  private width: number;
  private height: number;
  /** The largest target side the context allows (MAX_TEXTURE_SIZE and MAX_RENDERBUFFER_SIZE); read again on restore. */
  private maxSize: number;
  private readonly lightmapScale: number;
  private readonly _normals: boolean;
  /** The surface the light and composite passes read this frame (with normals), refilled per frame rather than made. */
  private readonly surface: Surface = { normals: null!, material: null!, flipY: false };
  /** Whether a frame is open: between `beginDraw()` and its `draw()`. */
  private drawing = false;
  private warnedAbandonedFrame = false;
  /** The draw buffers of the framebuffer the open frame composites into. */
  private readonly hostDrawBuffers: HostDrawBuffers;
  /**
   * Each textured light's cookie texture once found to be a texture of this context (see
   * {@link PenumbraRenderer.checkCookies}): checked again only when it changes. Anew on a restored context.
   */
  private checkedCookies = new WeakMap<TexturedLight, WebGLTexture>();
  private contextLost = false;
  private disposed = false;
  private readonly compositeViewport = new Int32Array(4);
  private compositeDrawFramebuffer: WebGLFramebuffer | null = null;
  private compositeReadFramebuffer: WebGLFramebuffer | null = null;
  private readonly canvas: EventTarget | null;
  /** The host's surface textures during a `drawInPlace` or `renderLightmap` that was given some. */
  private externalSurfaces: SurfaceTextures | null = null;
  /** The CPU light query behind {@link PenumbraRenderer.illuminationAt}, made on first use. */
  private illumination: IlluminationQuery | null = null;

  constructor(gl: WebGL2RenderingContext, options: PenumbraRendererOptions = {}) {
    if (!isWebGL2(gl)) throw notWebGL2Error('PenumbraRenderer', gl, WEBGL2_CONTEXT_FIX);
    assertOptions('PenumbraRenderer', options, RENDERER_OPTION_KEYS);
    this.gl = gl;
    this.debug = options.debug ?? false;
    this.measureCpuTime = options.measureCpuTime ?? false;
    this.onContextRestored = options.onContextRestored ?? null;
    if (options.ambientColor !== undefined) this.ambientColor = options.ambientColor;
    if (options.exposure !== undefined) this.exposure = options.exposure;
    if (options.toneMapping !== undefined) this.toneMapping = options.toneMapping;
    if (options.dithering !== undefined) this.dithering = options.dithering;
    if (options.lightmapBlur !== undefined) this.lightmapBlur = options.lightmapBlur;
    this.maxSize = maxTargetSize(gl);
    // A lost context's drawing buffer is 0 × 0: a side left to it waits for the restore (0 until then).
    const lost = gl.isContextLost();
    this.width = options.width === undefined && lost ? 0 : checkSize('PenumbraRenderer.width', options.width ?? gl.drawingBufferWidth, this.maxSize);
    this.height = options.height === undefined && lost ? 0 : checkSize('PenumbraRenderer.height', options.height ?? gl.drawingBufferHeight, this.maxSize);
    this.lightmapScale = checkScale(options.lightmapScale ?? 1);
    if (options.classificationBudget !== undefined) this.plan.classificationBudget = checkClassificationBudget(options.classificationBudget);
    this._normals = options.normals === undefined ? false : assertBoolean('PenumbraRenderer.normals', options.normals);
    if (options.viewProjection) this.viewProjection = options.viewProjection;
    else this.updateDefaultViewProjection();
    this.hostState = new HostState(gl, textureUnits(this._normals, this.edgeAware));
    this.hostDrawBuffers = new HostDrawBuffers(gl);
    // Made in the loss window, it waits for the restored context to build its GL objects.
    if (lost) this.contextLost = true;
    else this.createResources();
    const canvas = (gl as { canvas?: unknown }).canvas as EventTarget | undefined;
    this.canvas = canvas && typeof canvas.addEventListener === 'function' ? canvas : null;
    this.canvas?.addEventListener('webglcontextlost', this.onContextLost);
    this.canvas?.addEventListener('webglcontextrestored', this.handleContextRestored);
  }

  /**
   * Colour of unlit areas, read as a frozen `[r, g, b]` array, 0..1 per channel, as the lights'
   * vectors; assign any {@link ColorLike} form (`[r, g, b]`, `0x333344`, `'#334'`) to change it.
   */
  get ambientColor(): readonly [number, number, number] {
    return this._ambient;
  }
  set ambientColor(value: ColorLike) {
    this._ambient = frozenColor('PenumbraRenderer.ambientColor', value);
  }

  /**
   * Multiplier on the lit colour (scene × lightmap) before tone mapping, ≥ 0: brighter or darker
   * without changing the lights. Applies where the renderer composites (`draw`, `drawInPlace`), not
   * to `lightmapTexture`.
   */
  get exposure(): number {
    return this._exposure;
  }
  set exposure(value: number) {
    this._exposure = assertNonNegative('PenumbraRenderer.exposure', value);
  }

  /**
   * The curve from the lit colour × exposure to output colour, one of {@link ToneMapping}:
   * `'none'` (clipped at 1, as before), `'reinhard'`, `'aces'`. Applies where the renderer composites.
   */
  get toneMapping(): ToneMapping {
    return this._toneMapping;
  }
  set toneMapping(value: ToneMapping) {
    this._toneMapping = assertOneOf('PenumbraRenderer.toneMapping', value, Object.values(ToneMapping));
  }

  /**
   * Dithering of the composited output, one of {@link Dithering}: `'none'`, `'ordered'` (4 × 4
   * Bayer) or `'noise'` (interleaved gradient noise). It moves each 8-bit output value by at most
   * one step and removes the bands of dark gradients; meant for 8-bit targets.
   */
  get dithering(): Dithering {
    return this._dithering;
  }
  set dithering(value: Dithering) {
    this._dithering = assertOneOf('PenumbraRenderer.dithering', value, Object.values(Dithering));
  }

  /**
   * Blur of the lightmap, a radius in the renderer's pixels from 0 (off, the default) to 32: a
   * Gaussian of standard deviation radius / 2 cut at the radius, for a softer look. A look, not a
   * physics: it also spreads light past hull edges and into umbrae. The first frame with a blur
   * compiles its program and makes one more lightmap-sized texture; the blur costs two full-lightmap
   * passes a frame. A radius below 1/8 would change no pixel (its Gaussian's neighbour
   * weights are below the smallest float) and is off: it reads back as 0.
   */
  get lightmapBlur(): number {
    return this._lightmapBlur;
  }
  set lightmapBlur(value: number) {
    assertNonNegative('PenumbraRenderer.lightmapBlur', value);
    if (value > MAX_BLUR_RADIUS) throw new RangeError(`PenumbraRenderer.lightmapBlur must be at most ${MAX_BLUR_RADIUS}, got ${value}`);
    this._lightmapBlur = value < MIN_BLUR_RADIUS ? 0 : value;
  }

  /**
   * World → clip transform (gl-matrix `mat4`, column-major). Assign `null` to go back to the
   * default: pixel space of the targets, origin top-left, y down (as Canvas2D, PixiJS and Phaser).
   */
  get viewProjection(): ReadonlyMat4 {
    return this._viewProjection;
  }
  set viewProjection(value: ReadonlyMat4 | null) {
    if (value == null) {
      this.customViewProjection = false;
      this.updateDefaultViewProjection();
      return;
    }
    if (value.length !== 16) throw new RangeError(`PenumbraRenderer.viewProjection must have 16 elements, got ${value.length}`);
    for (let i = 0; i < 16; i++) assertFinite(`PenumbraRenderer.viewProjection[${i}]`, value[i]);
    mat4.copy(this._viewProjection, value);
    this.customViewProjection = true;
  }

  /** The lights, in drawing order. */
  get lights(): readonly Light[] {
    return this._lights;
  }
  /** The hulls. */
  get hulls(): readonly Hull[] {
    return this._hulls;
  }

  /** The lightmap texture (RGBA16F, or RGBA8 without EXT_color_buffer_float; `lightmapScale` × the renderer size), for hosts that composite themselves. */
  get lightmapTexture(): WebGLTexture {
    return this.requireResources().light.lightmap.texture;
  }
  /** The texture `beginDraw()` redirects drawing into. */
  get sceneTexture(): WebGLTexture {
    return this.requireResources().scene.texture;
  }
  /** Whether the renderer lights through normals (the `normals` option; docs/normal-maps.md). */
  get normals(): boolean {
    return this._normals;
  }
  /**
   * With `normals`, the scene target's normal attachment (location 1), for hosts that composite
   * themselves; RGBA8, the renderer's size.
   * @throws Error when the renderer has no normals.
   */
  get normalTexture(): WebGLTexture {
    return this.requireResources().scene.textures[this.requireNormals('normalTexture', SceneAttachments.normal)];
  }
  /** With `normals`, the scene target's material attachment (location 2). @throws Error when the renderer has no normals. */
  get materialTexture(): WebGLTexture {
    return this.requireResources().scene.textures[this.requireNormals('materialTexture', SceneAttachments.material)];
  }
  /**
   * With `normals`, the lights' highlights (the lightmap's second attachment, the lightmap's size
   * and format), which a host that composites itself adds after scene × lightmap.
   * @throws Error when the renderer has no normals.
   */
  get specularTexture(): WebGLTexture {
    return this.requireResources().light.lightmap.textures[this.requireNormals('specularTexture', LightmapAttachments.specular)];
  }

  /** `attachment` when the renderer has normals; else throws naming `property`. */
  private requireNormals(property: string, attachment: number): number {
    if (!this._normals) throw new Error(`penumbra: PenumbraRenderer.${property} needs a renderer made with { normals: true }`);
    return attachment;
  }

  /** Whether the lightmap is a half-float target (overlapping lights can exceed 1). */
  get hasFloatLightmap(): boolean {
    return this.lightmapFormat === 'rgba16f';
  }

  /**
   * Adds a light (no-op if already added).
   * @throws TypeError for a {@link TexturedLight} whose texture is not a texture of this renderer's
   *   context (another context's, deleted, or never bound), checked with `gl.isTexture` (unless the
   *   context is lost). A texture assigned later is checked likewise by the next frame, before it
   *   binds anything (`beginDraw`, `draw`, `drawInPlace`, `renderLightmap` throw naming the light);
   *   a texture deleted while a light holds it is not noticed.
   * @throws Error after {@link PenumbraRenderer.dispose}: a disposed renderer draws nothing.
   */
  addLight<T extends Light>(light: T): T {
    if (!(light instanceof Light)) throw new TypeError(`penumbra: addLight expects a Light, got ${String(light)}`);
    this.refuseIfDisposed('addLight');
    if (light instanceof TexturedLight && !this.isContextLost()) this.checkCookie(light, 'PenumbraRenderer.addLight: the TexturedLight\'s texture');
    if (!this._lights.includes(light)) this._lights.push(light);
    return light;
  }
  /** Removes a light; returns whether it was there. */
  removeLight(light: Light): boolean {
    return removeFrom(this._lights, light);
  }
  /**
   * Adds a hull (no-op if already added).
   * @throws Error after {@link PenumbraRenderer.dispose}: a disposed renderer draws nothing.
   */
  addHull(hull: Hull): Hull {
    if (!(hull instanceof Hull)) throw new TypeError(`penumbra: addHull expects a Hull, got ${String(hull)}`);
    this.refuseIfDisposed('addHull');
    if (!this._hulls.includes(hull)) this._hulls.push(hull);
    return hull;
  }
  private refuseIfDisposed(method: string): void {
    if (this.disposed) throw new Error(`penumbra: PenumbraRenderer.${method}: the renderer was disposed; make a new one`);
  }

  /**
   * Throws naming the first textured light whose cookie is not a texture of this context. Per frame:
   * `gl.isTexture` (a round trip to the GPU process in browsers) runs only for a texture not checked before.
   */
  private checkCookies(): void {
    const lights = this._lights;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      if (light instanceof TexturedLight && this.checkedCookies.get(light) !== light.texture) this.checkCookie(light, `PenumbraRenderer.lights[${i}] (TexturedLight).texture`);
    }
  }

  private checkCookie(light: TexturedLight, name: string): void {
    const texture = light.texture;
    if (!isTextureOf(this.gl, texture)) {
      throw new TypeError(`penumbra: ${name} must be a texture of the renderer's WebGL context (not another context's, a deleted one, ` +
        `one never bound, or one from before a context loss), got ${describeTexture(texture)}`);
    }
    this.checkedCookies.set(light, texture);
  }

  /** Removes a hull; its shadow is gone from the next frame. Returns whether it was there. */
  removeHull(hull: Hull): boolean {
    return removeFrom(this._hulls, hull);
  }

  /**
   * The light arriving at the world point (x, y), per light and summed, worked out on the CPU with
   * the renderer's own model and no read-back from the GPU: for gameplay (is the player in the
   * dark? can the guard see them?). It reflects the lights and hulls as they are now, every change
   * included, whether or not a frame was drawn since, and works while the context is lost.
   *
   * Per light: colour × intensity × its distance `falloff` curve (× the cone factor of a
   * {@link Spotlight}; × the cookie of a {@link TexturedLight}, which lives on the GPU: see
   * {@link IlluminationOptions.cookie}) × what its shadows let through: the exact fraction of its
   * disk visible from the point past every hull that shadows it (SPEC §6; disks may overlap hulls,
   * radius 0 gives hard shadows), mixed with its `shadowColor` and `shadowStrength`. It follows
   * `castsShadows`, `ignoredHulls`, `shadowLayers` against `Hull.layers`, `ShadowType` for points
   * inside a hull (Solid: dark, Illuminated: lit), open hulls, and disabled lights and hulls; a
   * light whose centre is inside a hull shines with the part of its disk outside the hulls. The sum adds `ambientColor` unless
   * `includeAmbient` is false. World coordinates, whatever the view: a point off screen gets what
   * it would get on screen. It matches the rendered lightmap at that point to within the lightmap's
   * precision (0.005 or better at the 950,000 pixels the headless-gl test compares); with
   * `lightmapScale` below 1 the lightmap is a coarser, filtered version of the same values, and an
   * RGBA8 lightmap (`hasFloatLightmap` false) clamps the sum at 1 where this does not.
   *
   * Cost: for each light that reaches the point, the hulls between the point and its disk, found
   * through a grid of the hulls' bounds (rebuilt by the first query after a hull changed); hulls in
   * front of the disk are taken whole, so a point deep in shadow costs little, and only a penumbra
   * needs the exact sweep. Every query also reads each hull's version once (about 13 ns a hull). 300
   * queries take about 1 ms in a scene of 10 lights and 50 hulls, 6 ms with 32 lights and 200
   * hulls (`node bench/illumination.mjs`).
   *
   * Allocation: without `out`, the result (an object, its colour array, the `lights` array and one
   * entry with a colour array per light listed). Pass a previous result as `out` to reuse it: then
   * nothing, once the query has seen the most lights listed (entries cut from a `lights` list are
   * kept for the next list that grows: do not hold on to them). Keep the options object too, rather
   * than a literal per call. Like any JavaScript call that is not inlined, the call itself boxes a
   * fractional `x` or `y` (16 bytes each).
   * @param x World x of the point.
   * @param y World y of the point.
   * @param options What to include; see {@link IlluminationOptions}.
   * @param out A result to overwrite and return instead of a new one.
   * @returns The light at the point: `out` when given.
   * @throws RangeError when x or y is not a finite number; TypeError or RangeError, naming the field,
   *   for an option or an `out` of the wrong shape, and for a cookie result that is not a number.
   */
  illuminationAt(x: number, y: number, options?: IlluminationOptions, out?: Illumination): Illumination {
    assertFinite('PenumbraRenderer.illuminationAt x', x);
    assertFinite('PenumbraRenderer.illuminationAt y', y);
    checkIlluminationQuery('PenumbraRenderer.illuminationAt', options, ILLUMINATION_OPTION_KEYS, out);
    return (this.illumination ??= new IlluminationQuery()).at(this._lights, this._hulls, this._ambient, x, y, options, out);
  }

  /**
   * Whether the renderer's lights give the world point (x, y) a luminance (Rec. 709, summed over
   * the lights, the ambient colour left out) above `threshold`: the stealth game's "is the player
   * lit?". The same model as {@link PenumbraRenderer.illuminationAt}, and cheaper: a light's
   * strength alone bounds its share, and shadows are worked out only while those bounds leave the
   * answer open. Allocates nothing (but the boxes of fractional arguments; see
   * {@link PenumbraRenderer.illuminationAt}).
   * @param x World x of the point.
   * @param y World y of the point.
   * @param threshold Luminance to exceed. Default `0.1`.
   * @param options The cookie of textured lights and the content layers (see {@link IlluminationOptions}).
   * @throws RangeError when x, y or threshold is not a finite number; TypeError or RangeError, naming
   *   the field, for an option of the wrong type and for a cookie result that is not a number.
   */
  isLit(x: number, y: number, threshold = 0.1, options?: Pick<IlluminationOptions, 'cookie' | 'layers'>): boolean {
    assertFinite('PenumbraRenderer.isLit x', x);
    assertFinite('PenumbraRenderer.isLit y', y);
    assertFinite('PenumbraRenderer.isLit threshold', threshold);
    checkIlluminationQuery('PenumbraRenderer.isLit', options, IS_LIT_OPTION_KEYS);
    const layers = (options?.layers ?? ALL_LAYERS) | 0;
    return (this.illumination ??= new IlluminationQuery()).isLit(this._lights, this._hulls, x, y, threshold, options?.cookie ?? null, layers);
  }

  /**
   * Resizes the internal targets (call when the canvas is resized). Throws a `RangeError` for a
   * size that is not a positive integer or exceeds the context's limit, and when the context runs
   * out of memory (it reads `gl.getError()` to see `OUT_OF_MEMORY`); the renderer then keeps its
   * previous size and keeps working.
   */
  resize(width: number, height: number): void {
    checkSize('PenumbraRenderer.resize width', width, this.maxSize);
    checkSize('PenumbraRenderer.resize height', height, this.maxSize);
    if (width === this.width && height === this.height) return;
    const previousWidth = this.width, previousHeight = this.height;
    this.setSize(width, height);
    if (this.isUnavailable()) return;
    const failure = this.allocateTargets(this.requireResources());
    if (failure === null) return;
    this.setSize(previousWidth, previousHeight);
    this.allocateTargets(this.requireResources());
    throw new RangeError(`PenumbraRenderer.resize(${width}, ${height}) failed: ${failure}; the renderer keeps its size ${previousWidth}×${previousHeight}`);
  }

  private setSize(width: number, height: number): void {
    this.width = width;
    this.height = height;
    if (!this.customViewProjection) this.updateDefaultViewProjection();
  }

  /** Reallocates the targets at the current size; returns why that failed, or null. */
  private allocateTargets(resources: Resources): string | null {
    try {
      this.withHostState(() => {
        resources.scene.resize(this.width, this.height);
        resources.light.resize(this.lightmapWidth, this.lightmapHeight);
        resources.hullMask?.resize(this.width, this.height, this.lightmapWidth, this.lightmapHeight);
      });
    } catch (error) {
      return (error as Error).message;
    }
    return this.gl.getError() === this.gl.OUT_OF_MEMORY ? 'the context is out of memory (OUT_OF_MEMORY)' : null;
  }

  /**
   * Starts a frame: remembers the bound framebuffer and viewport, then binds and clears the
   * internal scene target (colour to transparent black, depth to 1, stencil to 0). Draw the lit
   * scene after this call. With `normals` the target has three colour attachments, all cleared to
   * 0, with draw buffers for all three: the host's fragment shaders write colour, normal and
   * material at locations 0, 1, 2 (docs/normal-maps.md).
   *
   * A frame cannot be left open by an exception. What the renderer throws inside `draw()` or
   * `drawInPlace()` (a bad argument included) ends the frame first: the framebuffers and viewport
   * of its `beginDraw()` are bound again. A frame the host's own code abandoned (it threw between
   * `beginDraw()` and `draw()`) is closed by the next `beginDraw()` or `drawInPlace()`, with a
   * console warning the first time: when the scene target is still bound, the framebuffers and
   * viewport of the abandoned frame's `beginDraw()` are bound again first; a framebuffer the host
   * bound since is its choice and stays. The new frame then starts from what is bound.
   *
   * @throws TypeError before anything is bound when a {@link TexturedLight}'s texture is not a
   *   texture of this context (see {@link PenumbraRenderer.addLight}).
   */
  beginDraw(): void {
    this.openFrame(false);
  }

  /**
   * Ends a frame: builds the lightmap and writes scene × lightmap into the framebuffer that was
   * bound at `beginDraw()`, with the viewport of that moment. Then rebinds that framebuffer and
   * viewport and restores the rest of the state, also when it throws.
   *
   * A framebuffer with several draw buffers (a G-buffer, a chain of MRT passes) gets the lit
   * colour in the attachment of its draw buffer 0 only; the others keep what they hold, and its
   * draw buffers are as the host set them afterwards.
   *
   * @param layers - content layers (a bit mask): the lightmap holds only the lights whose
   *   `litLayers` share a bit with it (see {@link LightOptions.litLayers}). Default every layer.
   */
  draw(layers = ALL_LAYERS): void {
    try {
      assertLayerMask('PenumbraRenderer.draw: layers', layers);
    } catch (error) {
      if (this.drawing && !this.isUnavailable()) this.closeFrame();
      throw error;
    }
    this.endFrame(layers | 0);
  }

  /**
   * Opens a frame (see {@link PenumbraRenderer.beginDraw}); for `drawInPlace` (`inPlace`), after
   * checking that the bound framebuffer's viewport can be copied. Every check runs before the
   * scene target is bound. Returns whether a frame was opened (none while unavailable).
   */
  private openFrame(inPlace: boolean): boolean {
    if (this.isUnavailable()) return false;
    if (this.drawing) this.abandonFrame();
    this.checkCookies();
    const gl = this.gl;
    const resources = this.requireResources();
    this.enterHostState();
    try {
      const host = this.hostState;
      this.compositeDrawFramebuffer = host.savedDrawFramebuffer;
      this.compositeReadFramebuffer = host.savedReadFramebuffer;
      this.compositeViewport.set(host.savedViewport);
      if (inPlace) this.checkInPlaceSource();
      this.hostDrawBuffers.record(this.compositeDrawFramebuffer);
      resources.scene.bind();
      gl.depthMask(true);
      gl.stencilMask(0xff);
      // clearBuffer* leaves the clear values alone, so the host's need not be saved.
      gl.clearBufferfv(gl.COLOR, SceneAttachments.color, TRANSPARENT);
      if (this._normals) {
        gl.clearBufferfv(gl.COLOR, SceneAttachments.normal, TRANSPARENT);
        gl.clearBufferfv(gl.COLOR, SceneAttachments.material, TRANSPARENT);
      }
      gl.clearBufferfi(gl.DEPTH_STENCIL, 0, 1, 0);
    } finally {
      this.hostState.restore();
    }
    resources.scene.bind();
    this.drawing = true;
    return true;
  }

  /**
   * Closes a frame left open by the host (see {@link PenumbraRenderer.beginDraw}): its framebuffers
   * and viewport are bound again while the scene target still is.
   */
  private abandonFrame(): void {
    if (!this.warnedAbandonedFrame) {
      this.warnedAbandonedFrame = true;
      console.warn('penumbra: a frame was started while the previous one was still open (an exception between beginDraw() and draw()?): ' +
        'the open frame is abandoned and the framebuffer and viewport of its beginDraw() are bound again. Warned once.');
    }
    const scene = this.requireResources().scene.framebuffer;
    if (this.gl.getParameter(this.gl.DRAW_FRAMEBUFFER_BINDING) === scene) this.closeFrame();
    else this.drawing = false;
  }

  /** Ends the open frame's redirection: binds the framebuffers and viewport of its `beginDraw()` again. */
  private closeFrame(): void {
    this.drawing = false;
    this.bindCompositeTarget();
    this.gl.bindFramebuffer(this.gl.READ_FRAMEBUFFER, this.compositeReadFramebuffer);
  }

  /**
   * Throws, before anything is bound, unless `blitFramebuffer` can copy the viewport of the bound
   * framebuffer into the scene target: from a multisampled framebuffer (a browser canvas's, by
   * default) it copies only between identical rectangles and formats, so the framebuffer must have
   * alpha (an opaque canvas's is RGB) and the viewport must be the renderer's size at the origin.
   * Reads the viewport saved by the host state, and the samples and alpha bits of the bound draw
   * framebuffer.
   */
  private checkInPlaceSource(): void {
    const gl = this.gl, v = this.compositeViewport;
    const samples = gl.getParameter(gl.SAMPLES) as number | null;
    if (!samples) return;
    // A multisampled copy needs the same format at both ends, and the scene target has alpha.
    if (gl.getParameter(gl.ALPHA_BITS) === 0) {
      throw new Error(`penumbra: PenumbraRenderer.drawInPlace: the bound framebuffer is multisampled (${samples} samples) and has no alpha, ` +
        'so it cannot be copied into the renderer\'s RGBA scene target (WebGL refuses a multisampled copy between formats): make the canvas ' +
        'with getContext(\'webgl2\', { alpha: true }) or { antialias: false }, or draw into a framebuffer with alpha or without multisampling');
    }
    if (v[0] === 0 && v[1] === 0 && v[2] === this.width && v[3] === this.height) return;
    throw new Error(`penumbra: PenumbraRenderer.drawInPlace: the bound framebuffer is multisampled (${samples} samples), which can be copied ` +
      `only to the same rectangle: its viewport [${v.join(', ')}] must be [0, 0, ${this.width}, ${this.height}], the renderer's size at the origin ` +
      '(resize the renderer to the viewport and draw at the origin, or draw into a framebuffer without multisampling)');
  }

  /** What {@link PenumbraRenderer.draw} does, with the layers as an int32 (see `renderLightmapInto`). */
  private endFrame(layers: number): void {
    if (this.isUnavailable()) return;
    if (!this.drawing) throw new Error('penumbra: draw() called without beginDraw()');
    try {
      this.checkCookies();
      const resources = this.requireResources();
      this.enterHostState();
      try {
        this.renderLightmapInto(resources, layers);
        resources.hullMask?.render(resources.shadows.records, this.geometry.recordCount, this.geometry.recordsVersion, this._viewProjection);
        this.bindCompositeTarget();
        this.hostDrawBuffers.drawFirstOnly();
        try {
          resources.composite.render(resources.scene.texture, resources.light.lightmap.textures, this, this.surface, resources.hullMask);
          if (this.debug) {
            resources.debug.render(this.plan.draws, this.plan.drawCount, resources.shadows.records, this.geometry.recordCount, this._viewProjection);
          }
        } finally {
          this.hostDrawBuffers.restoreDraw();
        }
      } finally {
        this.hostState.restore();
      }
    } finally {
      this.closeFrame();
    }
  }

  /**
   * Lights, in place, what is already drawn in the bound framebuffer: copies its colour inside
   * the current viewport into the scene texture, then does what {@link PenumbraRenderer.draw}
   * does (lightmap, scene × lightmap written back to that framebuffer and viewport). For engines
   * such as PixiJS and Phaser that draw into their own targets, so that `beginDraw()` cannot
   * redirect their drawing. The copy is a `blitFramebuffer`, from the attachment of the
   * framebuffer's draw buffer 0 (see {@link PenumbraRenderer.draw}); a multisampled framebuffer (a
   * browser canvas's by default) must have an RGBA8 colour buffer and can be copied only to the same
   * rectangle: its viewport must be the renderer's size at the origin. The context state is left as
   * it was, also when it throws.
   *
   * @param layers - content layers: only the lights whose `litLayers` share a bit with it (see
   *   {@link PenumbraRenderer.draw}). Default every layer.
   * @param surfaces - with `normals`, the host's normal and material textures for what it drew
   *   (see {@link SurfaceTextures}). Default: none (lit as without normals).
   * @throws Error, before anything is bound, when the bound framebuffer is multisampled and has no
   *   alpha (a canvas made with `{ alpha: false }` and antialiasing) or its viewport is not the
   *   renderer's size at the origin.
   */
  drawInPlace(layers = ALL_LAYERS, surfaces?: SurfaceTextures): void {
    assertLayerMask('PenumbraRenderer.drawInPlace: layers', layers);
    this.checkSurfaces('drawInPlace', surfaces);
    if (!this.openFrame(true)) return;
    try {
      this.copyInPlaceSource(this.requireResources());
      this.externalSurfaces = surfaces ?? null;
      this.endFrame(layers | 0);
    } finally {
      this.externalSurfaces = null;
      if (this.drawing) this.closeFrame();
    }
  }

  /** Copies the colour of the host's framebuffer inside its viewport into the scene target (see `drawInPlace`). */
  private copyInPlaceSource(resources: Resources): void {
    const gl = this.gl, v = this.compositeViewport;
    this.enterHostState();
    try {
      // The colour only: a blit writes every draw buffer.
      resources.scene.bindFirst();
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.compositeDrawFramebuffer);
      this.hostDrawBuffers.readFirst();
      try {
        gl.blitFramebuffer(v[0], v[1], v[0] + v[2], v[1] + v[3], 0, 0, this.width, this.height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      } finally {
        this.hostDrawBuffers.restoreRead();
      }
    } finally {
      this.hostState.restore();
    }
  }

  /**
   * Builds the lightmap only (see {@link PenumbraRenderer.lightmapTexture}); the context state is left as it was.
   *
   * @param layers - content layers: only the lights whose `litLayers` share a bit with it (see
   *   {@link PenumbraRenderer.draw}). Default every layer.
   * @param surfaces - with `normals`, the normal and material textures to light through (see
   *   {@link SurfaceTextures}). Default: the scene target's, as the host last drew them.
   */
  renderLightmap(layers = ALL_LAYERS, surfaces?: SurfaceTextures): void {
    assertLayerMask('PenumbraRenderer.renderLightmap: layers', layers);
    this.checkSurfaces('renderLightmap', surfaces);
    if (this.isUnavailable()) return;
    this.checkCookies();
    const resources = this.requireResources();
    this.externalSurfaces = surfaces ?? null;
    this.enterHostState();
    try {
      this.renderLightmapInto(resources, layers | 0);
    } finally {
      this.hostState.restore();
      this.externalSurfaces = null;
    }
  }

  /**
   * Throws naming the method and field when `surfaces` is given to a renderer without normals or is
   * malformed. Per frame: the messages are built only on failure.
   */
  private checkSurfaces(method: string, surfaces: SurfaceTextures | undefined): void {
    if (surfaces === undefined) return;
    if (this._normals && isObject(surfaces) && isObject(surfaces.normals) && (surfaces.material == null || isObject(surfaces.material))
      && (surfaces.flipY === undefined || typeof surfaces.flipY === 'boolean')) return;
    const name = `PenumbraRenderer.${method}: surfaces`;
    if (!this._normals) throw new Error(`penumbra: ${name} needs a renderer made with { normals: true }`);
    if (!isObject(surfaces)) throw new TypeError(`${name} must be an object, got ${describeValue(surfaces)}`);
    if (!isObject(surfaces.normals)) throw new TypeError(`${name}.normals must be a WebGLTexture, got ${describeValue(surfaces.normals)}`);
    if (surfaces.material != null && !isObject(surfaces.material)) {
      throw new TypeError(`${name}.material must be a WebGLTexture, got ${describeValue(surfaces.material)}`);
    }
    assertBoolean(`${name}.flipY`, surfaces.flipY as boolean);
  }

  /** Points {@link PenumbraRenderer.surface} at the host's textures of this call, or at the scene target's. */
  private chooseSurface(resources: Resources): void {
    const surface = this.surface, scene = resources.scene.textures, external = this.externalSurfaces;
    surface.normals = external?.normals ?? scene[SceneAttachments.normal];
    // Without a material of the host's: the scene target's, which drawInPlace's beginDraw cleared.
    surface.material = external?.material ?? scene[SceneAttachments.material];
    surface.flipY = external?.flipY ?? false;
  }

  /**
   * Frees every GL resource and forgets lights and hulls; an open frame is closed first (its
   * `beginDraw()`'s framebuffers and viewport bound again). Safe to call twice. Afterwards the
   * frame calls do nothing, and `addLight` and `addHull` throw.
   */
  dispose(): void {
    if (this.disposed) return;
    if (this.drawing && !this.isContextLost()) this.closeFrame();
    this.disposed = true;
    this.canvas?.removeEventListener('webglcontextlost', this.onContextLost);
    this.canvas?.removeEventListener('webglcontextrestored', this.handleContextRestored);
    if (!this.isContextLost()) this.destroyResources();
    this.resources = null;
    this._lights.length = 0;
    this._hulls.length = 0;
  }

  /**
   * Builds the lightmap from the lights whose `litLayers` share a bit with `layers`, an int32 (`| 0`
   * of the mask): 0xffffffff itself is a double, which V8 boxes on the heap when it passes one.
   */
  private renderLightmapInto(resources: Resources, layers: number): void {
    const start = this.measureCpuTime ? performance.now() : 0;
    const plan = this.plan;
    const viewProjection = this._viewProjection;
    this.geometry.update(this._hulls);
    plan.build(this._lights, this._hulls, this.geometry, viewProjection, this.lightmapWidth, this.lightmapHeight);
    resources.shadows.upload(this.geometry, plan.bins);
    resources.shapes.uploadTileRectangles(plan.tiles.dirtyRows, plan.tiles.rectangles, plan.tiles.usedIndices);
    if (this._normals) this.chooseSurface(resources);
    resources.light.begin(this._ambient, viewProjection, this.surface);
    for (let i = 0; i < plan.drawCount; i++) {
      if ((plan.draws[i].light.litLayers & layers) !== 0) resources.light.render(plan.draws[i]);
    }
    if (this._lightmapBlur > 0) resources.blur.render(resources.light.lightmap, this._lightmapBlur * this.lightmapScale);
    this.updateStats(this.measureCpuTime ? performance.now() - start : 0);
  }

  private updateStats(cpuTime: number): void {
    const stats = this.stats;
    stats.lights = this._lights.length;
    stats.lightsDrawn = this.plan.drawCount;
    stats.lightsFiled = this.plan.filedCount;
    stats.hulls = this._hulls.length;
    stats.edges = this.geometry.validEdgeCount;
    stats.cpuTime = cpuTime;
    stats.tilesLit = stats.tilesDark = stats.tilesExact = stats.tilesLean = stats.tilesHeld = stats.tilesOutside = 0;
    stats.lightsUnclassified = this.plan.unclassifiedCount;
    for (let i = 0; i < this.plan.drawCount; i++) {
      const draw = this.plan.draws[i];
      if (draw.hullCount === 0 || draw.light instanceof DirectionalLight) continue;
      const counts = draw.tileCounts;
      stats.tilesLit += counts[TILE_CLASSES.lit];
      stats.tilesDark += counts[TILE_CLASSES.dark];
      stats.tilesExact += counts[TILE_CLASSES.lean] + counts[TILE_CLASSES.exact] + counts[TILE_CLASSES.held];
      stats.tilesLean += counts[TILE_CLASSES.lean];
      stats.tilesHeld += counts[TILE_CLASSES.held];
      stats.tilesOutside += counts[TILE_CLASSES.outside];
    }
  }

  private bindCompositeTarget(): void {
    const gl = this.gl;
    const v = this.compositeViewport;
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.compositeDrawFramebuffer);
    gl.viewport(v[0], v[1], v[2], v[3]);
  }

  /**
   * Saves the host's state and puts the renderer's neutral one; pair with `hostState.restore()` in
   * a `finally`. The per-frame paths use this pair directly: a closure would allocate every frame.
   */
  private enterHostState(): void {
    this.hostState.save();
    try {
      this.hostState.prepareForRenderer();
    } catch (error) {
      this.hostState.restore();
      throw error;
    }
  }

  /** Runs `run` between {@link PenumbraRenderer.enterHostState} and a restore (for calls that are not per frame). */
  private withHostState(run: () => void): void {
    this.enterHostState();
    try {
      run();
    } finally {
      this.hostState.restore();
    }
  }

  /**
   * Whether GL calls must be skipped: disposed, or the context lost. `gl.isContextLost()` is read
   * too because the browser dispatches `webglcontextlost` only after the loss: a frame in between
   * would meet the null answers of a lost context.
   */
  private isUnavailable(): boolean {
    return this.disposed || this.isContextLost();
  }
  private isContextLost(): boolean {
    return this.contextLost || this.gl.isContextLost();
  }

  /**
   * Whether the composite upsamples the lightmap aware of hull outlines: when it is smaller than
   * the scene (`lightmapScale` below 1), through the hull masks.
   */
  private get edgeAware(): boolean {
    return this.lightmapScale < 1;
  }

  private get lightmapWidth(): number {
    return Math.max(1, Math.round(this.width * this.lightmapScale));
  }
  private get lightmapHeight(): number {
    return Math.max(1, Math.round(this.height * this.lightmapScale));
  }

  private updateDefaultViewProjection(): void {
    // Without a size yet (made on a lost context) the identity stands in until the restore gives one.
    if (this.width === 0 || this.height === 0) return;
    mat4.ortho(this._viewProjection, 0, this.width, this.height, 0, -1, 1);
  }

  private requireResources(): Resources {
    if (this.disposed) throw new Error('penumbra: the renderer was disposed');
    if (!this.resources) throw new Error('penumbra: the WebGL context is lost; the renderer resumes when it is restored');
    return this.resources;
  }

  /**
   * Builds the GL objects. If one fails, those already made are freed before the error goes on (a
   * pass that fails part-way frees its own).
   */
  private createResources(): void {
    const gl = this.gl;
    this.chooseLightmapFormat();
    const made: { dispose(): void }[] = [];
    const keep = <T extends { dispose(): void }>(resource: T): T => {
      made.push(resource);
      return resource;
    };
    try {
      this.withHostState(() => {
        const shapes = keep(new LightShapes(gl));
        this.resources = {
          shapes,
          shadows: keep(new ShadowTextures(gl, SHADOW_TEXTURE_UNITS)),
          scene: keep(new RenderTarget(gl, { format: 'rgba8', depthStencil: true, colorAttachments: this._normals ? 3 : 1 }, this.width, this.height)),
          light: keep(new LightPass(gl, shapes, this.lightmapFormat, this.lightmapWidth, this.lightmapHeight, this._normals)),
          composite: keep(new CompositePass(gl, this._normals, this.edgeAware)),
          hullMask: this.edgeAware ? keep(new HullMaskPass(gl, this.width, this.height, this.lightmapWidth, this.lightmapHeight)) : null,
          blur: keep(new BlurPass(gl, this.lightmapFormat)),
          debug: keep(new DebugPass(gl, shapes)),
        };
      });
    } catch (error) {
      this.withHostState(() => {
        for (const resource of made) resource.dispose();
      });
      throw error;
    }
    this.geometry.invalidate();
  }

  private destroyResources(): void {
    const resources = this.resources;
    if (!resources) return;
    this.withHostState(() => {
      for (const resource of Object.values(resources)) resource?.dispose();
    });
    this.resources = null;
  }

  private readonly onContextLost = (event: Event): void => {
    // Without preventDefault the browser never restores the context.
    event.preventDefault();
    this.contextLost = true;
    this.drawing = false;
    this.resources = null;
  };

  /**
   * Half-float where the context can render to it (which enables the extension: a restored context
   * starts with none). Warns when it falls back to RGBA8, once until the format changes again.
   */
  private chooseLightmapFormat(): void {
    const format = supportsFloatTargets(this.gl) ? 'rgba16f' : 'rgba8';
    if (format === 'rgba8' && this.lightmapFormat !== 'rgba8') {
      console.warn('penumbra: EXT_color_buffer_float is missing; the lightmap falls back to RGBA8, so light sums clamp at 1.');
    }
    this.lightmapFormat = format;
  }

  /**
   * Rebuilds after a loss. Ignored without a loss before it (nothing to rebuild), and when the
   * context is lost again before this handler runs: the next restored event rebuilds.
   */
  private readonly handleContextRestored = (): void => {
    if (!this.contextLost || this.disposed || this.gl.isContextLost()) return;
    this.maxSize = maxTargetSize(this.gl);
    this.takeDrawingBufferSize();
    this.checkedCookies = new WeakMap();
    this.createResources();
    this.contextLost = false;
    this.onContextRestored?.(this);
    this.warnOfOldCookies();
  };

  /** Gives a side still 0 (the renderer was made on a lost context without it) the drawing buffer's. */
  private takeDrawingBufferSize(): void {
    if (this.width !== 0 && this.height !== 0) return;
    const gl = this.gl;
    this.setSize(this.width || checkSize('PenumbraRenderer.width', gl.drawingBufferWidth, this.maxSize),
      this.height || checkSize('PenumbraRenderer.height', gl.drawingBufferHeight, this.maxSize));
  }

  /** Names each textured light whose cookie texture is not one of the restored context's. */
  private warnOfOldCookies(): void {
    this._lights.forEach((light, index) => {
      if (light instanceof TexturedLight && !this.gl.isTexture(light.texture)) {
        console.warn(`penumbra: lights[${index}] (TexturedLight) still has its cookie texture from before the context loss; give it a new one in PenumbraRenderer.onContextRestored`);
      }
    });
  }
}

/** The largest side of a target the context can allocate: its texture and its depth/stencil renderbuffer. */
function maxTargetSize(gl: WebGL2RenderingContext): number {
  // A lost context answers null: no limit is known until it is back.
  const textureSize = (gl.getParameter(gl.MAX_TEXTURE_SIZE) as number | null) ?? Infinity;
  const renderbufferSize = (gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number | null) ?? Infinity;
  return Math.min(textureSize, renderbufferSize);
}

function checkSize(name: string, value: number, max: number): number {
  if (!Number.isInteger(value) || value <= 0) throw new RangeError(`${name} must be a positive integer, got ${describeValue(value)}`);
  if (value > max) throw new RangeError(`${name} ${value} exceeds this context's largest texture size ${max} (MAX_TEXTURE_SIZE / MAX_RENDERBUFFER_SIZE)`);
  return value;
}

/** Whether `texture` is a live texture of `gl` (`isTexture` throws for an object that is no WebGLTexture). */
function isTextureOf(gl: WebGL2RenderingContext, texture: WebGLTexture): boolean {
  try {
    return gl.isTexture(texture);
  } catch {
    return false;
  }
}

/** Whether `value` is a non-null object (a WebGL texture is an opaque one). */
function isObject(value: unknown): value is object {
  return typeof value === 'object' && value !== null;
}

function checkScale(value: number): number {
  if (typeof value !== 'number' || !(value > 0 && value <= 1)) throw new RangeError(`PenumbraRenderer.lightmapScale must be in (0, 1], got ${value}`);
  return value;
}

function removeFrom<T>(list: T[], item: T): boolean {
  const index = list.indexOf(item);
  if (index < 0) return false;
  list.splice(index, 1);
  return true;
}
