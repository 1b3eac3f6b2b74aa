import type { ReadonlyMat4 } from 'gl-matrix';
import type { FrameStats } from './FrameStats';
import { FramePipeline, type FrameLook } from './frame/FramePipeline';
import { Sizing } from './frame/Sizing';
import { checkSurfaces } from './frame/surfaces';
import { checkClassificationBudget, RENDERER_OPTION_KEYS, type PenumbraRendererOptions } from './options';
import { isWebGL2, notWebGL2Error, WEBGL2_CONTEXT_FIX } from './gl/capabilities';
import { LightmapAttachments, SceneAttachments, type SurfaceTextures } from './passes/surfaceLayout';
import { Dithering, MAX_BLUR_RADIUS, MIN_BLUR_RADIUS, ToneMapping } from './scene/look';
import { Hull } from './scene/Hull';
import {
  checkIlluminationQuery, ILLUMINATION_OPTION_KEYS, IlluminationQuery, IS_LIT_OPTION_KEYS, type Illumination, type IlluminationOptions,
} from './scene/illumination';
import { Light } from './scene/Light';
import { TexturedLight } from './scene/TexturedLight';
import {
  ALL_LAYERS, assertBoolean, assertFinite, assertLayerMask, assertNonNegative, assertOneOf, assertOptions, frozenColor, type ColorLike,
} from './util/validate';

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

  private readonly _lights: Light[] = [];
  private readonly _hulls: Hull[] = [];
  /** The look the frames read; the accessors below check what is assigned. */
  private readonly look: FrameLook = {
    ambient: Object.freeze([0.2, 0.2, 0.2] as const), exposure: 1, toneMapping: ToneMapping.None, dithering: Dithering.None, lightmapBlur: 0,
  };
  private readonly sizing: Sizing;
  private readonly _normals: boolean;
  private readonly pipeline: FramePipeline;
  /** The CPU light query behind {@link PenumbraRenderer.illuminationAt}, made on first use. */
  private illumination: IlluminationQuery | null = null;

  constructor(gl: WebGL2RenderingContext, options: PenumbraRendererOptions = {}) {
    if (!isWebGL2(gl)) throw notWebGL2Error('PenumbraRenderer', gl, WEBGL2_CONTEXT_FIX);
    assertOptions('PenumbraRenderer', options, RENDERER_OPTION_KEYS);
    this.debug = options.debug ?? false;
    this.measureCpuTime = options.measureCpuTime ?? false;
    this.onContextRestored = options.onContextRestored ?? null;
    if (options.ambientColor !== undefined) this.ambientColor = options.ambientColor;
    if (options.exposure !== undefined) this.exposure = options.exposure;
    if (options.toneMapping !== undefined) this.toneMapping = options.toneMapping;
    if (options.dithering !== undefined) this.dithering = options.dithering;
    if (options.lightmapBlur !== undefined) this.lightmapBlur = options.lightmapBlur;
    this.sizing = new Sizing(gl, options.width, options.height, options.lightmapScale ?? 1);
    const classificationBudget = options.classificationBudget === undefined ? undefined : checkClassificationBudget(options.classificationBudget);
    this._normals = options.normals === undefined ? false : assertBoolean('PenumbraRenderer.normals', options.normals);
    if (options.viewProjection) this.viewProjection = options.viewProjection;
    this.pipeline = new FramePipeline(gl, { lights: this._lights, hulls: this._hulls, look: this.look }, this.sizing, {
      normals: this._normals, classificationBudget, stats: this.stats, onRestored: () => this.onContextRestored?.(this),
    });
  }

  /**
   * Colour of unlit areas, read as a frozen `[r, g, b]` array, 0..1 per channel, as the lights'
   * vectors; assign any {@link ColorLike} form (`[r, g, b]`, `0x333344`, `'#334'`) to change it.
   */
  get ambientColor(): readonly [number, number, number] {
    return this.look.ambient;
  }
  set ambientColor(value: ColorLike) {
    this.look.ambient = frozenColor('PenumbraRenderer.ambientColor', value);
  }

  /**
   * Multiplier on the lit colour (scene × lightmap) before tone mapping, ≥ 0: brighter or darker
   * without changing the lights. Applies where the renderer composites (`draw`, `drawInPlace`), not
   * to `lightmapTexture`.
   */
  get exposure(): number {
    return this.look.exposure;
  }
  set exposure(value: number) {
    this.look.exposure = assertNonNegative('PenumbraRenderer.exposure', value);
  }

  /**
   * The curve from the lit colour × exposure to output colour, one of {@link ToneMapping}:
   * `'none'` (each channel clipped at 1), `'reinhard'`, `'aces'`. Applies where the renderer composites.
   */
  get toneMapping(): ToneMapping {
    return this.look.toneMapping;
  }
  set toneMapping(value: ToneMapping) {
    this.look.toneMapping = assertOneOf('PenumbraRenderer.toneMapping', value, Object.values(ToneMapping));
  }

  /**
   * Dithering of the composited output, one of {@link Dithering}: `'none'`, `'ordered'` (4 × 4
   * Bayer) or `'noise'` (interleaved gradient noise). It moves each 8-bit output value by at most
   * one step and removes the bands of dark gradients; meant for 8-bit targets.
   */
  get dithering(): Dithering {
    return this.look.dithering;
  }
  set dithering(value: Dithering) {
    this.look.dithering = assertOneOf('PenumbraRenderer.dithering', value, Object.values(Dithering));
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
    return this.look.lightmapBlur;
  }
  set lightmapBlur(value: number) {
    assertNonNegative('PenumbraRenderer.lightmapBlur', value);
    if (value > MAX_BLUR_RADIUS) throw new RangeError(`PenumbraRenderer.lightmapBlur must be at most ${MAX_BLUR_RADIUS}, got ${value}`);
    this.look.lightmapBlur = value < MIN_BLUR_RADIUS ? 0 : value;
  }

  /**
   * World → clip transform (gl-matrix `mat4`, column-major). Assign `null` to go back to the
   * default: pixel space of the targets, origin top-left, y down (as Canvas2D, PixiJS and Phaser).
   */
  get viewProjection(): ReadonlyMat4 {
    return this.sizing.viewProjection;
  }
  set viewProjection(value: ReadonlyMat4 | null) {
    this.sizing.setViewProjection(value);
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
    return this.pipeline.requireResources().light.lightmap.texture;
  }
  /** The texture `beginDraw()` redirects drawing into. */
  get sceneTexture(): WebGLTexture {
    return this.pipeline.requireResources().scene.texture;
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
    return this.pipeline.requireResources().scene.textures[this.requireNormals('normalTexture', SceneAttachments.normal)];
  }
  /** With `normals`, the scene target's material attachment (location 2). @throws Error when the renderer has no normals. */
  get materialTexture(): WebGLTexture {
    return this.pipeline.requireResources().scene.textures[this.requireNormals('materialTexture', SceneAttachments.material)];
  }
  /**
   * With `normals`, the lights' highlights (the lightmap's second attachment, the lightmap's size
   * and format), which a host that composites itself adds after scene × lightmap.
   * @throws Error when the renderer has no normals.
   */
  get specularTexture(): WebGLTexture {
    return this.pipeline.requireResources().light.lightmap.textures[this.requireNormals('specularTexture', LightmapAttachments.specular)];
  }

  /** `attachment` when the renderer has normals; else throws naming `property`. */
  private requireNormals(property: string, attachment: number): number {
    if (!this._normals) throw new Error(`penumbra: PenumbraRenderer.${property} needs a renderer made with { normals: true }`);
    return attachment;
  }

  /** Whether the lightmap is a half-float target (overlapping lights can exceed 1). */
  get hasFloatLightmap(): boolean {
    return this.pipeline.hasFloatLightmap;
  }

  /**
   * Adds a light (no-op if already added). The first light of a kind (point, spot, textured,
   * directional) compiles that kind's programs here, so that no frame waits for them: a renderer
   * compiles only the kinds of light it is given.
   * @throws TypeError for a {@link TexturedLight} whose texture is not a texture of this renderer's
   *   context (another context's, deleted, or never bound), checked with `gl.isTexture` (unless the
   *   context is lost). A texture assigned later is checked likewise by the next frame, before it
   *   binds anything (`beginDraw`, `draw`, `drawInPlace`, `renderLightmap` throw naming the light);
   *   a texture deleted while a light holds it is not noticed.
   * @throws Error after {@link PenumbraRenderer.dispose}: a disposed renderer draws nothing.
   */
  addLight<T extends Light>(light: T): T {
    if (!(light instanceof Light)) throw new TypeError(`penumbra: addLight expects a Light, got ${String(light)}`);
    this.pipeline.refuseIfDisposed('addLight');
    if (light instanceof TexturedLight) this.pipeline.checkCookie(light, 'PenumbraRenderer.addLight: the TexturedLight\'s texture');
    this.pipeline.prepareLight(light.kind);
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
    this.pipeline.refuseIfDisposed('addHull');
    if (!this._hulls.includes(hull)) this._hulls.push(hull);
    return hull;
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
   * disk visible from the point past every hull that shadows it (see docs/shadows.md; disks may overlap hulls,
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
   * needs the exact sweep. Every query also reads each hull's version once. `node
   * bench/illumination.mjs` times queries in scenes of several sizes.
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
    return (this.illumination ??= new IlluminationQuery()).at(this._lights, this._hulls, this.look.ambient, x, y, options, out);
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
    this.pipeline.resize(width, height);
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
    this.pipeline.openFrame(false);
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
      this.pipeline.closeOpenFrame();
      throw error;
    }
    this.pipeline.endFrame(layers | 0, null, this.debug, this.measureCpuTime);
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
    checkSurfaces('drawInPlace', this._normals, surfaces);
    this.pipeline.drawInPlace(layers | 0, surfaces ?? null, this.debug, this.measureCpuTime);
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
    checkSurfaces('renderLightmap', this._normals, surfaces);
    this.pipeline.renderLightmap(layers | 0, surfaces ?? null, this.measureCpuTime);
  }

  /**
   * Frees every GL resource and forgets lights and hulls; an open frame is closed first (its
   * `beginDraw()`'s framebuffers and viewport bound again). Safe to call twice. Afterwards the
   * frame calls do nothing, and `addLight` and `addHull` throw.
   */
  dispose(): void {
    this.pipeline.dispose();
    this._lights.length = 0;
    this._hulls.length = 0;
  }
}

function removeFrom<T>(list: T[], item: T): boolean {
  const index = list.indexOf(item);
  if (index < 0) return false;
  list.splice(index, 1);
  return true;
}
