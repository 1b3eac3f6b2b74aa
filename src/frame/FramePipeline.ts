import type { FrameStats } from '../FrameStats';
import type { CompositeLook } from '../passes/CompositePass';
import type { Surface } from '../passes/LightPass';
import { SceneAttachments, type SurfaceTextures } from '../passes/surfaceLayout';
import type { Hull } from '../scene/Hull';
import { DirectionalLight } from '../scene/DirectionalLight';
import type { Light, LightKind } from '../scene/Light';
import type { TexturedLight } from '../scene/TexturedLight';
import type { Dithering, ToneMapping } from '../scene/look';
import { ShadowCache } from '../shadow/ShadowCache';
import { ShadowGeometry } from '../shadow/ShadowGeometry';
import { TILE_CLASSES } from '../shadow/shadowLayout';
import { ContextLoss } from './ContextLoss';
import { CookieChecks } from './CookieChecks';
import { ResourceBuilder, textureUnits, type FrameResources } from './FrameResources';
import { HostFrame } from './HostFrame';
import type { Sizing } from './Sizing';
import { chooseSurface } from './surfaces';

/** The renderer's look as a frame reads it: the lightmap's ambient colour and blur, and the composite's. */
export interface FrameLook extends CompositeLook {
  ambient: readonly [number, number, number];
  exposure: number;
  toneMapping: ToneMapping;
  dithering: Dithering;
  /** The blur radius in the renderer's pixels; 0 is off. */
  lightmapBlur: number;
}

/** What the frames draw, read at each one: the renderer's lights (in drawing order), hulls and look. */
export interface FrameScene {
  readonly lights: readonly Light[];
  readonly hulls: readonly Hull[];
  readonly look: FrameLook;
}

/** The renderer's settings fixed for its life, beside its scene and sizing. */
export interface PipelineSettings {
  /** Whether the renderer lights through normals. */
  readonly normals: boolean;
  /** See `PenumbraRendererOptions.classificationBudget`; the shadow cache's default when undefined. */
  readonly classificationBudget: number | undefined;
  /** Where each lightmap's figures go. */
  readonly stats: FrameStats;
  /** Called after the GL objects were rebuilt on a restored context. */
  readonly onRestored: () => void;
}

/** Clear value of the scene target. */
const TRANSPARENT = new Float32Array(4);

/**
 * The renderer's frames: owns the GL objects through context loss and restore and resizes them,
 * opens the host's frame and closes it (also when something throws), and runs the passes in order,
 * the host's state saved around each call: the shadow cache (which lights, which hulls shadow each),
 * the shadow uploads, the light pass, the blur, then for a composited frame the hull masks, the
 * composite into the host's framebuffer and the debug wireframes. Every frame call does nothing
 * while the context is lost or after {@link FramePipeline.dispose}.
 */
export class FramePipeline {
  private readonly normals: boolean;
  private readonly stats: FrameStats;
  private readonly host: HostFrame;
  private readonly builder: ResourceBuilder;
  private readonly cookies: CookieChecks;
  private readonly loss: ContextLoss;
  private readonly geometry = new ShadowGeometry();
  private readonly shadowCache = new ShadowCache();
  /** The surface the light and composite passes read this frame (with normals), refilled per frame rather than made. */
  private readonly surface: Surface = { normals: null!, material: null!, flipY: false };
  /** Null while the context is lost and after dispose. */
  private resources: FrameResources | null = null;
  private disposed = false;

  /** Builds the GL objects unless the context is lost (then it waits for the restore). */
  constructor(private readonly gl: WebGL2RenderingContext, private readonly scene: FrameScene, private readonly sizing: Sizing, settings: PipelineSettings) {
    this.normals = settings.normals;
    this.stats = settings.stats;
    if (settings.classificationBudget !== undefined) this.shadowCache.classificationBudget = settings.classificationBudget;
    this.host = new HostFrame(gl, textureUnits(this.normals, sizing.edgeAware));
    this.builder = new ResourceBuilder(gl, this.host, sizing, this.normals);
    this.cookies = new CookieChecks(gl);
    if (!gl.isContextLost()) this.build();
    this.loss = new ContextLoss(gl, {
      lost: () => {
        this.host.open = false;
        this.resources = null;
      },
      rebuild: () => {
        sizing.adoptRestoredContext(gl);
        this.cookies.forget();
        this.build();
      },
      restored: () => {
        settings.onRestored();
        this.cookies.warnOfOld(scene.lights);
      },
    });
  }

  /** Whether the lightmap is a half-float target. */
  get hasFloatLightmap(): boolean {
    return this.builder.lightmapFormat === 'rgba16f';
  }

  /** Whether frame calls must be skipped: disposed, or the context lost (see {@link ContextLoss.isLost}). */
  get unavailable(): boolean {
    return this.disposed || this.loss.isLost;
  }

  /** The GL objects; throws when there are none (disposed, or the context lost). */
  requireResources(): FrameResources {
    if (this.disposed) throw new Error('penumbra: the renderer was disposed');
    if (!this.resources) throw new Error('penumbra: the WebGL context is lost; the renderer resumes when it is restored');
    return this.resources;
  }

  /** Throws naming `method` of the renderer after {@link FramePipeline.dispose}. */
  refuseIfDisposed(method: string): void {
    if (this.disposed) throw new Error(`penumbra: PenumbraRenderer.${method}: the renderer was disposed; make a new one`);
  }

  /**
   * Makes the programs of a kind of light not drawn yet, so that no frame compiles them; left to
   * the rebuild while the context is lost. Throws when a program cannot be made on a context that
   * is not lost.
   */
  prepareLight(kind: LightKind): void {
    const resources = this.resources;
    if (resources === null || this.loss.isLost || resources.light.prepared(kind)) return;
    this.host.run(() => {
      try {
        resources.light.prepare(kind);
      } catch (error) {
        // Lost meanwhile: the rebuild after the restore makes them.
        if (!this.gl.isContextLost()) throw error;
      }
    });
  }

  /** Throws naming `name` when the light's cookie is not a texture of the context; skipped while the context is lost. */
  checkCookie(light: TexturedLight, name: string): void {
    if (!this.loss.isLost) this.cookies.check(light, name);
  }

  /**
   * Resizes the targets; on failure (a size out of range, or out of memory) keeps the previous size
   * and throws (see `PenumbraRenderer.resize`).
   */
  resize(width: number, height: number): void {
    const sizing = this.sizing;
    sizing.checkSize('PenumbraRenderer.resize width', width);
    sizing.checkSize('PenumbraRenderer.resize height', height);
    if (width === sizing.width && height === sizing.height) return;
    const previousWidth = sizing.width, previousHeight = sizing.height;
    sizing.setSize(width, height);
    if (this.unavailable) return;
    const failure = this.builder.resize(this.requireResources());
    if (failure === null) return;
    sizing.setSize(previousWidth, previousHeight);
    this.builder.resize(this.requireResources());
    throw new RangeError(`PenumbraRenderer.resize(${width}, ${height}) failed: ${failure}; the renderer keeps its size ${previousWidth}×${previousHeight}`);
  }

  /**
   * Opens a frame (see `PenumbraRenderer.beginDraw`); for `drawInPlace` (`inPlace`), after checking
   * that the bound framebuffer's viewport can be copied. Every check runs before the scene target is
   * bound. Returns whether a frame was opened (none while unavailable).
   */
  openFrame(inPlace: boolean): boolean {
    if (this.unavailable) return false;
    const host = this.host;
    if (host.open) host.abandon(this.requireResources().scene.framebuffer);
    this.cookies.checkAll(this.scene.lights);
    const scene = this.requireResources().scene;
    host.enter();
    try {
      host.record(inPlace, this.sizing.width, this.sizing.height);
      this.clearScene(scene);
    } finally {
      host.state.restore();
    }
    scene.bind();
    host.open = true;
    return true;
  }

  /** Ends the open frame before an error of `draw()`'s arguments goes on. */
  closeOpenFrame(): void {
    if (this.host.open && !this.unavailable) this.host.close();
  }

  /**
   * Ends the open frame (see `PenumbraRenderer.draw`): the lightmap, then the composite into the
   * host's framebuffer; the frame is closed also when it throws.
   * @param layers - the content layers as an int32 (see {@link FramePipeline.renderLightmapInto}).
   * @param surfaces - the host's surface textures (`drawInPlace`), or null for the scene target's.
   */
  endFrame(layers: number, surfaces: SurfaceTextures | null, debug: boolean, measureCpuTime: boolean): void {
    if (this.unavailable) return;
    const host = this.host;
    if (!host.open) throw new Error('penumbra: draw() called without beginDraw()');
    try {
      this.cookies.checkAll(this.scene.lights);
      const resources = this.requireResources();
      host.enter();
      try {
        this.renderLightmapInto(resources, layers, surfaces, measureCpuTime);
        this.composite(resources, debug);
      } finally {
        host.state.restore();
      }
    } finally {
      host.close();
    }
  }

  /** What `PenumbraRenderer.drawInPlace` does once its arguments are checked (see {@link FramePipeline.endFrame}). */
  drawInPlace(layers: number, surfaces: SurfaceTextures | null, debug: boolean, measureCpuTime: boolean): void {
    if (!this.openFrame(true)) return;
    try {
      this.host.copyInto(this.requireResources().scene, this.sizing.width, this.sizing.height);
      this.endFrame(layers, surfaces, debug, measureCpuTime);
    } finally {
      if (this.host.open) this.host.close();
    }
  }

  /** What `PenumbraRenderer.renderLightmap` does once its arguments are checked (see {@link FramePipeline.endFrame}). */
  renderLightmap(layers: number, surfaces: SurfaceTextures | null, measureCpuTime: boolean): void {
    if (this.unavailable) return;
    this.cookies.checkAll(this.scene.lights);
    const resources = this.requireResources();
    this.host.enter();
    try {
      this.renderLightmapInto(resources, layers, surfaces, measureCpuTime);
    } finally {
      this.host.state.restore();
    }
  }

  /** Closes an open frame, stops following the context and frees the GL objects. Safe to call twice. */
  dispose(): void {
    if (this.disposed) return;
    if (this.host.open && !this.loss.isLost) this.host.close();
    this.disposed = true;
    this.loss.dispose();
    if (this.resources && !this.loss.isLost) this.builder.destroy(this.resources);
    this.resources = null;
  }

  private build(): void {
    this.resources = this.builder.build(this.scene.lights);
    this.geometry.invalidate();
  }

  /** Binds the scene target and clears it: colour (and with normals the normal and material) to 0, depth to 1, stencil to 0. */
  private clearScene(scene: FrameResources['scene']): void {
    const gl = this.gl;
    scene.bind();
    gl.depthMask(true);
    gl.stencilMask(0xff);
    // clearBuffer* leaves the clear values alone, so the host's need not be saved.
    gl.clearBufferfv(gl.COLOR, SceneAttachments.color, TRANSPARENT);
    if (this.normals) {
      gl.clearBufferfv(gl.COLOR, SceneAttachments.normal, TRANSPARENT);
      gl.clearBufferfv(gl.COLOR, SceneAttachments.material, TRANSPARENT);
    }
    gl.clearBufferfi(gl.DEPTH_STENCIL, 0, 1, 0);
  }

  /**
   * Builds the lightmap from the lights whose `litLayers` share a bit with `layers`, an int32 (`| 0`
   * of the mask; see Hot-path rules in docs/architecture.md).
   * With normals it lights through `surfaces`, or the scene target's when null.
   */
  private renderLightmapInto(resources: FrameResources, layers: number, surfaces: SurfaceTextures | null, measureCpuTime: boolean): void {
    const start = measureCpuTime ? performance.now() : 0;
    const cache = this.shadowCache, geometry = this.geometry, sizing = this.sizing, scene = this.scene;
    geometry.update(scene.hulls);
    cache.build(scene.lights, scene.hulls, geometry, sizing.viewProjection, sizing.lightmapWidth, sizing.lightmapHeight);
    resources.shadows.upload(geometry, cache.bins, cache.tiles.lists);
    resources.shapes.uploadTileRectangles(cache.tiles.dirtyRows, cache.tiles.rectangles, cache.tiles.usedIndices);
    if (this.normals) chooseSurface(this.surface, resources.scene, surfaces);
    resources.light.begin(scene.look.ambient, sizing.viewProjection, this.surface);
    for (let i = 0; i < cache.drawCount; i++) {
      if ((cache.draws[i].light.litLayers & layers) !== 0) resources.light.render(cache.draws[i]);
    }
    const blur = scene.look.lightmapBlur;
    if (blur > 0) resources.blur.render(resources.light.lightmap, blur * sizing.lightmapScale);
    this.updateStats(measureCpuTime ? performance.now() - start : 0);
  }

  /** The hull masks (upsampling aware of hull edges), then scene × lightmap into the host's framebuffer, then the debug wireframes. */
  private composite(resources: FrameResources, debug: boolean): void {
    const records = resources.shadows.records, recordCount = this.geometry.recordCount, viewProjection = this.sizing.viewProjection;
    resources.hullMask?.render(records, recordCount, this.geometry.recordsVersion, viewProjection);
    this.host.beginComposite();
    try {
      resources.composite.render(resources.scene.texture, resources.light.lightmap.textures, this.scene.look, this.surface, resources.hullMask);
      if (debug) resources.debug.render(this.shadowCache.draws, this.shadowCache.drawCount, records, recordCount, viewProjection);
    } finally {
      this.host.endComposite();
    }
  }

  private updateStats(cpuTime: number): void {
    const stats = this.stats, cache = this.shadowCache;
    stats.lights = this.scene.lights.length;
    stats.lightsDrawn = cache.drawCount;
    stats.lightsFiled = cache.filedCount;
    stats.hulls = this.scene.hulls.length;
    stats.edges = this.geometry.validEdgeCount;
    stats.cpuTime = cpuTime;
    stats.tilesLit = stats.tilesDark = stats.tilesExact = stats.tilesLean = stats.tilesHeld = stats.tilesOutside = 0;
    stats.lightsUnclassified = cache.unclassifiedCount;
    for (let i = 0; i < cache.drawCount; i++) {
      const draw = cache.draws[i];
      if (draw.hullCount === 0 || draw.light instanceof DirectionalLight) continue;
      const counts = draw.tileCounts;
      stats.tilesLit += counts[TILE_CLASSES.lit];
      stats.tilesDark += counts[TILE_CLASSES.dark];
      const lean = counts[TILE_CLASSES.lean] + counts[TILE_CLASSES.listed];
      stats.tilesExact += lean + counts[TILE_CLASSES.exact] + counts[TILE_CLASSES.held];
      stats.tilesLean += lean;
      stats.tilesHeld += counts[TILE_CLASSES.held];
      stats.tilesOutside += counts[TILE_CLASSES.outside];
    }
  }
}
