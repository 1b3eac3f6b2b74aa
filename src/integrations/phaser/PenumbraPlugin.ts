import Phaser from 'phaser';
import { Light, PenumbraRenderer, type Hull, type LightOptions, type PenumbraRendererOptions } from '../../index';
import { ALL_LAYERS, assertLayerMask } from '../../util/validate';
import { isOpaqueMultisampledCanvas, isWebGL2, notWebGL2Error } from '../../gl/capabilities';
import { InPlaceLighting, type InPlaceView } from '../inPlaceLighting';
import { LightFollower, LightFollowers, type LightFollowOptions } from '../LightFollower';
import type { Affine2D } from '../viewProjection';
import { PHASER_WEBGL2_FIX } from './gameConfig';
import { PenumbraGroup, type PenumbraGroupOptions } from './PenumbraGroup';
import { describe, readPlacement, type Placed, type Placement } from './shared';
import { SpriteHulls, type FrameObject, type SpriteHullsOptions } from './SpriteHulls';
import { PhaserSurfaces, type MaterialOptions } from './surfaces';
import { TilemapLayerHulls, type TilemapLayerHullsOptions } from './TilemapLayerHulls';

/** Depth of the lighting layer unless changed: objects above it (the HUD) stay unlit. */
export const DEFAULT_LAYER_DEPTH = 1000;

/**
 * Options of a {@link PenumbraPlugin}: the core renderer's options, less the size and the view,
 * which follow Phaser's camera and drawing context every frame.
 */
export type PenumbraPluginOptions = Omit<PenumbraRendererOptions, 'viewProjection' | 'width' | 'height'>;

/**
 * A Phaser 4 scene plugin: `this.penumbra.addLight(…)` inside a scene. Install it in the game
 * config with `plugins: { scene: [{ key: 'PenumbraPlugin', plugin: PenumbraPlugin, mapping: 'penumbra' }] }`,
 * and pass that config through {@link penumbraGameConfig}, which gives Phaser the WebGL2 context
 * the lighting needs (Phaser 4 makes a WebGL1 one by default, and the plugin then throws, saying so).
 * Renderer options ({@link PenumbraPluginOptions}: `ambientColor`, `lightmapScale`, `measureCpuTime`, …)
 * go in that entry's `data`, for every scene: `{ key: 'PenumbraPlugin', plugin: PenumbraPlugin,
 * mapping: 'penumbra', data: { lightmapScale: 0.5 } }`; one scene can change them with
 * {@link PenumbraPlugin.configure}.
 *
 * It adds a lighting layer to the scene's display list, at depth {@link DEFAULT_LAYER_DEPTH}:
 * everything the camera drew below that depth is multiplied by the lightmap (with the lights of
 * {@link PenumbraPlugin.layers}), what is drawn above it stays unlit: the HUD, and glowing world
 * objects, which follow the camera as any object does. Above it too, {@link PenumbraPlugin.addGroup}
 * makes groups lit apart, by some lights only. Lights and hulls are in world units: the camera's
 * scroll, zoom and rotation are honoured. The layer is an `Extern`, Phaser's own hook for foreign GL
 * code, so Phaser yields the context before and rebinds its state after. On scene shutdown the
 * lights and hulls are dropped; when the scene or the plugin is destroyed the GL resources are freed.
 *
 * Game content casts shadows through {@link PenumbraPlugin.addTilemapLayer} (a tilemap layer's
 * solid tiles, kept in step as tiles change) and {@link PenumbraPlugin.addSprite} (a sprite's
 * opaque pixels, following the sprite); lights follow game objects through {@link PenumbraPlugin.follow}.
 */
export class PenumbraPlugin extends Phaser.Plugins.ScenePlugin {
  /** The renderer, and what lights in place with it; null before boot and once destroyed. */
  private inPlace: InPlaceLighting | null = null;
  private options: PenumbraPluginOptions = {};
  private extern: Phaser.GameObjects.Extern | null = null;
  private _layers = ALL_LAYERS;
  /** The drawing context's viewport and its world → context map, filled before each lighting. */
  private readonly view: InPlaceView = { pixelWidth: 0, pixelHeight: 0, width: 0, height: 0, flipY: false };
  private readonly camera: Affine2D = { a: 1, b: 0, c: 0, d: 1, tx: 0, ty: 0 };
  /** The materials and the normal pass, made with the first renderer that has normals; kept across `configure`. */
  private surfaces: PhaserSurfaces | null = null;
  /** The tilemap layers and sprites added, with their hulls. */
  private readonly occluders = new Map<Phaser.GameObjects.GameObject, TilemapLayerHulls | SpriteHulls>();
  private readonly _followers = new LightFollowers<Placed>({
    listen: (object, destroyed) => object.on(Phaser.GameObjects.Events.DESTROY, destroyed),
    ignore: (object, destroyed) => object.off(Phaser.GameObjects.Events.DESTROY, destroyed),
    removeLight: (light) => this.inPlace?.renderer.removeLight(light),
  });
  /** Scratch for a follower's object placement and its object → world transform. */
  private readonly followedPlacement: Placement = { x: 0, y: 0, rotation: 0, scaleX: 1, scaleY: 1 };
  private readonly followedTransform = new Float64Array(6);

  /** The core renderer: ambient colour, debug wireframe, stats, lights and hulls. */
  get penumbra(): PenumbraRenderer {
    if (!this.inPlace) throw new Error('penumbra: the plugin is not booted or was destroyed');
    return this.inPlace.renderer;
  }

  /**
   * The content layers the lighting layer lights, a bit mask: it lights with the lights whose
   * `litLayers` share a bit with it (see {@link LightOptions.litLayers}). Default `0xffffffff`
   * (every light). Kept across scene restarts and {@link PenumbraPlugin.configure}.
   */
  get layers(): number {
    return this._layers;
  }
  set layers(value: number) {
    this._layers = assertLayerMask('PenumbraPlugin.layers', value);
  }

  /** The lighting layer: set its depth to choose what is lit (below) and what is not (above). */
  get layer(): Phaser.GameObjects.Extern {
    if (!this.extern) throw new Error('penumbra: the lighting layer exists only while the scene runs');
    return this.extern;
  }

  /**
   * Rebuilds the renderer with `options` over the current ones (those of the plugin entry's `data`
   * and earlier calls), keeping its lights and hulls: for options fixed at construction, such as
   * `lightmapScale`. Call it in the scene's `init` or `create`; {@link PenumbraPlugin.penumbra} is a
   * new renderer afterwards. Options the renderer can change in place (`ambientColor`, `debug`,
   * `measureCpuTime`, `onContextRestored`, `exposure`, `toneMapping`, `dithering`, `lightmapBlur`)
   * can also be set on {@link PenumbraPlugin.penumbra}, and survive a later `configure`.
   */
  configure(options: PenumbraPluginOptions): this {
    const old = this.penumbra;
    const merged: PenumbraPluginOptions = {
      ...this.options,
      ambientColor: old.ambientColor,
      debug: old.debug,
      measureCpuTime: old.measureCpuTime,
      onContextRestored: old.onContextRestored,
      exposure: old.exposure,
      toneMapping: old.toneMapping,
      dithering: old.dithering,
      lightmapBlur: old.lightmapBlur,
      ...options,
    };
    const lighting = this.createLighting(merged);
    for (const light of old.lights) lighting.renderer.addLight(light);
    for (const hull of old.hulls) lighting.renderer.addHull(hull);
    old.dispose();
    this.inPlace = lighting;
    this.options = merged;
    return this;
  }

  /**
   * Sets the material of normal-mapped images, sprites and tilemap layers: of one game object, or of
   * every object showing a texture (by key; for a tilemap layer, its tileset's image); `null` takes
   * it away. An object's own material wins over its texture's; without either, a map has no
   * highlight and no emission.
   *
   * With a renderer made with `normals: true` (in the plugin entry's `data`, or {@link PenumbraPlugin.configure}),
   * the lighting layer lights images and sprites through the normal maps Phaser loaded with their
   * textures: each frame it draws the objects drawn before it, in Phaser's order, from their normal
   * maps turned by their rotation and flips, into textures the renderer reads (docs/normal-maps.md).
   * Tilemap layers (`TilemapLayer` and `TilemapGPULayer`) are drawn tile by tile from their tilesets'
   * normal maps (the tileset image's data source, as for an image), turned by each tile's rotation
   * and flips. Objects without a normal map are lit as without normals. Images, sprites and tilemap
   * layers of the scene and of its layers are drawn so; those inside a `Container`, and other kinds
   * of objects, are lit as without normals.
   *
   * ```ts
   * this.load.image('wall', ['wall.png', 'wall_n.png']);                        // in preload
   * this.penumbra.setMaterial('wall', { specular: 0.4, shininess: 24 });        // in create
   * this.load.image('tiles', ['tiles.png', 'tiles_n.png']);                     // a tileset: map.createLayer(0, map.addTilesetImage('tiles'))
   * ```
   * @throws TypeError or RangeError for a target or option that does not fit.
   */
  setMaterial(target: Phaser.GameObjects.GameObject | string, material: MaterialOptions | null): void {
    this.ownSurfaces().setMaterial(target, material);
  }

  /** Adds a light in world units; see {@link PenumbraRenderer.addLight}. */
  addLight<T extends Light>(light: T): T {
    return this.penumbra.addLight(light);
  }
  /** Removes a light, and stops it following a game object; returns whether it was there. */
  removeLight(light: Light): boolean {
    this._followers.drop(light, false);
    return this.penumbra.removeLight(light);
  }

  /**
   * Makes a light follow a game object (a sprite, an image, a container, any object with a
   * transform): it sits at `options.offset` in the object's local space (default the object's
   * origin point; a sprite's flipX and flipY mirror it within the frame, as Phaser draws the
   * picture) and, with `options.rotation`, turns with the object; it shines while the object is
   * visible and on a display list. The light is added to the scene's lighting and placed before
   * every render. Following the same light again replaces the follower. It ends when the object is
   * destroyed (the light is removed too), when the scene shuts down, on
   * {@link PenumbraPlugin.removeLight} or on {@link PenumbraPlugin.unfollow}. See {@link LightFollower}.
   *
   * ```ts
   * const player = this.physics.add.sprite(100, 100, 'hero');
   * this.penumbra.follow(player, new PointLight({ range: 200, radius: 6 }), { offset: [0, -12] });  // a torch over its head
   * this.penumbra.follow(turret, new Spotlight({ range: 300, coneAngle: 0.4 }), { rotation: 0 });   // a beam along the turret's +x
   * ```
   * @throws TypeError for an object without a transform, or an option of the wrong type.
   */
  follow(object: Phaser.GameObjects.GameObject, light: Light, options: LightFollowOptions = {}): LightFollower<Placed> {
    if (!(object instanceof Phaser.GameObjects.GameObject) || typeof (object as Partial<Placed>).scaleX !== 'number') {
      throw new TypeError(`penumbra: PenumbraPlugin.follow takes a game object with a transform (a Sprite, an Image, a Container…), got ${describe(object)}`);
    }
    if (!(light instanceof Light)) throw new TypeError(`penumbra: PenumbraPlugin.follow takes a Light to move, got ${describe(light)}`);
    const placed = object as Placed;
    const follower = new LightFollower(placed, light, options, 'PenumbraPlugin.follow');
    this._followers.add(follower);
    this.penumbra.addLight(light);
    this.placeFollower(follower);
    return follower;
  }

  /** The lights following game objects, in the order they started. */
  get followers(): readonly LightFollower<Placed>[] {
    return this._followers.list;
  }

  /**
   * Stops a light following its game object, or every light following a game object: the lights
   * stay in the lighting where they are, enabled. Returns whether one was following.
   */
  unfollow(target: LightFollower<Placed> | Light | Phaser.GameObjects.GameObject): boolean {
    return this._followers.unfollow(target);
  }

  /**
   * Places every following light for its object's current transform. Runs before every render of
   * the scene; call it yourself only to read the lights' placement right after a change.
   */
  updateFollowers(): void {
    const followers = this._followers.list;
    for (let i = 0; i < followers.length; i++) this.placeFollower(followers[i]);
  }
  /** Adds a hull in world units; see {@link PenumbraRenderer.addHull}. */
  addHull(hull: Hull): Hull {
    return this.penumbra.addHull(hull);
  }
  /** Removes a hull; returns whether it was there (false once the plugin is destroyed). */
  removeHull(hull: Hull): boolean {
    return this.inPlace?.renderer.removeHull(hull) ?? false;
  }

  /**
   * Adds a {@link PenumbraGroup} to the scene: a `Layer` whose children are lit apart, by the
   * ambient colour and the lights whose `litLayers` share a bit with `options.layers` only (0: the
   * ambient colour only). It is drawn after the lighting layer (its depth defaults to the layer's);
   * to keep objects unlit, put them above the lighting layer's depth, in no group.
   *
   * ```ts
   * const WORLD = 0b01, PLAYER = 0b10;
   * this.penumbra.layers = WORLD;                                          // the level: lamps only
   * this.penumbra.addLight(new PointLight({ position: [200, 150], range: 300, litLayers: WORLD }));
   * const torch = this.penumbra.addLight(new PointLight({ range: 80, litLayers: PLAYER }));
   * const actors = this.penumbra.addGroup({ layers: PLAYER });             // the player: its torch only
   * actors.add(this.add.sprite(320, 240, 'hero'));
   * this.add.image(400, 100, 'neon').setDepth(DEFAULT_LAYER_DEPTH + 1);    // glows: unlit
   * ```
   * @throws Error while the scene is not running (the lighting layer exists only then).
   */
  addGroup(options?: PenumbraGroupOptions): PenumbraGroup {
    const scene = this.scene!;
    return scene.add.existing(new PenumbraGroup(scene, this, options));
  }

  /**
   * Makes a tilemap layer's solid tiles cast shadows: by default the tiles that collide (set with
   * `layer.setCollision…`), or `options.solid` (tile indices, or a test of a tile). The hulls
   * (one per group of touching tiles) follow the layer's position and scale, and are rebuilt
   * around any tile that changes (`putTileAt`, `removeTileAt`, `fill`, …) before the next render.
   * Adding a layer again replaces its hulls. See {@link TilemapLayerHulls}.
   *
   * ```ts
   * const layer = map.createLayer(0, tileset)!.setCollision([1, 2, 3]);
   * this.penumbra.addTilemapLayer(layer);
   * ```
   * @throws TypeError or RangeError for a layer or option that does not fit (see {@link TilemapLayerHulls}).
   */
  addTilemapLayer(layer: Phaser.Tilemaps.TilemapLayerBase, options?: TilemapLayerHullsOptions): TilemapLayerHulls {
    this.occluders.get(layer)?.destroy();
    return this.track(layer, new TilemapLayerHulls(layer, this, options));
  }

  /** Removes a tilemap layer's hulls; returns whether it had some. Destroying the layer does it too. */
  removeTilemapLayer(layer: Phaser.Tilemaps.TilemapLayerBase): boolean {
    return this.untrack(layer);
  }

  /**
   * Makes a sprite (or image) cast the shadow of its opaque pixels: hulls traced from the alpha of
   * the frame it shows (read once per frame and shared), following its position, rotation, scale,
   * origin, flips, frame and visibility every frame. Adding a sprite again replaces its hulls.
   * See {@link SpriteHulls}.
   *
   * ```ts
   * const barrel = this.add.sprite(320, 240, 'props', 'barrel');
   * this.penumbra.addSprite(barrel, { tolerance: 1.5, maxPoints: 16 });
   * ```
   * @throws TypeError when the frame's pixels cannot be read (then give `options.image`), or for
   * an option of the wrong type; RangeError for an option out of range.
   */
  addSprite(sprite: FrameObject, options?: SpriteHullsOptions): SpriteHulls {
    this.occluders.get(sprite)?.destroy();
    return this.track(sprite, new SpriteHulls(sprite, this, options));
  }

  /** Removes a sprite's hulls; returns whether it had some. Destroying the sprite does it too. */
  removeSprite(sprite: FrameObject): boolean {
    return this.untrack(sprite);
  }

  /** Called by Phaser once, when the scene boots. @internal */
  override boot(): void {
    this.options = this.entryData();
    this.inPlace = this.createLighting(this.options);
    const events = this.systems!.events;
    events.on(Phaser.Scenes.Events.START, this.onStart, this);
    events.on(Phaser.Scenes.Events.SHUTDOWN, this.onShutdown, this);
    events.on(Phaser.Scenes.Events.PRE_RENDER, this.updateFollowers, this);
    events.once(Phaser.Scenes.Events.DESTROY, this.destroy, this);
  }

  /** Frees the GL resources; safe to call twice. */
  override destroy(): void {
    const events = this.systems?.events;
    events?.off(Phaser.Scenes.Events.START, this.onStart, this);
    events?.off(Phaser.Scenes.Events.SHUTDOWN, this.onShutdown, this);
    events?.off(Phaser.Scenes.Events.PRE_RENDER, this.updateFollowers, this);
    events?.off(Phaser.Scenes.Events.DESTROY, this.destroy, this);
    this.dropOccluders();
    this._followers.clear();
    this.extern?.destroy();
    this.extern = null;
    this.inPlace?.renderer.dispose();
    this.inPlace = null;
    this.surfaces?.dispose();
    this.surfaces = null;
    super.destroy();
  }

  private ownSurfaces(): PhaserSurfaces {
    return (this.surfaces ??= new PhaserSurfaces((this.game.renderer as Phaser.Renderer.WebGL.WebGLRenderer).gl as WebGL2RenderingContext));
  }

  private track<T extends TilemapLayerHulls | SpriteHulls>(object: Phaser.GameObjects.GameObject, occluder: T): T {
    this.occluders.set(object, occluder);
    occluder.onDestroy = () => {
      if (this.occluders.get(object) === occluder) this.occluders.delete(object);
    };
    return occluder;
  }

  private untrack(object: Phaser.GameObjects.GameObject): boolean {
    const occluder = this.occluders.get(object);
    occluder?.destroy();
    return occluder !== undefined;
  }

  private dropOccluders(): void {
    for (const occluder of [...this.occluders.values()]) occluder.destroy();
  }

  /**
   * Places a follower's light by its object's world transform T(x, y) · R(rotation) · S(scale),
   * after the mirror that flipX and flipY make of a frame object: Phaser draws a flipped frame
   * mirrored within its untrimmed size (about the frame's custom pivot, if it has one), so a local
   * x becomes `realWidth − 2 · displayOriginX − x`.
   */
  private placeFollower(follower: LightFollower<Placed>): void {
    const object = follower.object;
    const p = readPlacement(object, true, this.followedPlacement);
    let fx = 1, fy = 1, ex = 0, ey = 0;
    const framed = object as Partial<FrameObject>;
    if (framed.frame) {
      const pivot = framed.frame.customPivot;
      if (framed.flipX) {
        fx = -1;
        if (!pivot) ex = framed.frame.realWidth - 2 * framed.displayOriginX!;
      }
      if (framed.flipY) {
        fy = -1;
        if (!pivot) ey = framed.frame.realHeight - 2 * framed.displayOriginY!;
      }
    }
    const cos = Math.cos(p.rotation), sin = Math.sin(p.rotation);
    const a = cos * p.scaleX, b = sin * p.scaleX, c = -sin * p.scaleY, d = cos * p.scaleY;
    const m = this.followedTransform;
    m[0] = a * fx;
    m[1] = b * fx;
    m[2] = c * fy;
    m[3] = d * fy;
    m[4] = a * ex + c * ey + p.x;
    m[5] = b * ex + d * ey + p.y;
    const visible = (object as Partial<Phaser.GameObjects.Components.Visible>).visible !== false;
    const shown = visible && (object.displayList != null || object.parentContainer != null);
    follower.place(m, shown);
  }

  private createLighting(options: PenumbraPluginOptions): InPlaceLighting {
    const renderer = this.game.renderer as Partial<Phaser.Renderer.WebGL.WebGLRenderer>;
    if (!renderer.gl) throw new TypeError('penumbra: PenumbraPlugin needs Phaser\'s WebGL renderer (type: Phaser.WEBGL)');
    const gl: unknown = renderer.gl;
    if (!isWebGL2(gl)) throw notWebGL2Error('PenumbraPlugin', gl, PHASER_WEBGL2_FIX);
    if (isOpaqueMultisampledCanvas(gl)) {
      throw new Error('penumbra: PenumbraPlugin cannot light Phaser\'s canvas: its context is antialiased and opaque (antialias: true, '
        + 'alpha: false), and the lighting copies a multisampled canvas only into its own RGBA format; make the game with '
        + 'penumbraGameConfig, or make the context with antialias: false or alpha: true');
    }
    const penumbra = new PenumbraRenderer(gl, {
      ...options,
      viewProjection: null,
      width: gl.drawingBufferWidth,
      height: gl.drawingBufferHeight,
    });
    return new InPlaceLighting(penumbra, gl.drawingBufferWidth, gl.drawingBufferHeight);
  }

  /** The `data` of this plugin's entry in the game config's `plugins.scene` (Phaser passes it to global plugins only). */
  private entryData(): PenumbraPluginOptions {
    const entries = (this.game.config.installScenePlugins ?? []) as Phaser.Types.Core.PluginObjectItem[];
    const own = entries.filter((entry) => entry.plugin === this.constructor);
    const entry = own.find((e) => e.mapping === this.pluginKey) ?? own[0];
    const data: unknown = entry?.data ?? {};
    if (typeof data !== 'object' || data === null) {
      throw new TypeError(`penumbra: the PenumbraPlugin entry's data must be an object of renderer options, got ${typeof data}`);
    }
    return data;
  }

  private onStart(): void {
    const extern = this.scene!.add.extern();
    extern.setDepth(DEFAULT_LAYER_DEPTH);
    extern.render = this.renderLayer;
    this.extern = extern;
  }

  private onShutdown(): void {
    this.extern = null;
    this.dropOccluders();
    this._followers.clear();
    const penumbra = this.inPlace?.renderer;
    if (!penumbra) return;
    for (let i = penumbra.lights.length - 1; i >= 0; i--) penumbra.removeLight(penumbra.lights[i]);
    for (let i = penumbra.hulls.length - 1; i >= 0; i--) penumbra.removeHull(penumbra.hulls[i]);
  }

  /** The Extern's render: `calcMatrix` is world → drawing context, since the layer sits at the origin. */
  private readonly renderLayer = (
    _renderer: Phaser.Renderer.WebGL.WebGLRenderer,
    context: Phaser.Renderer.WebGL.DrawingContext,
    calcMatrix: Phaser.GameObjects.Components.TransformMatrix,
  ): void => {
    this.lightContext(context, calcMatrix, this._layers, this.systems!.displayList.list, this.extern);
  };

  /** Whether the plugin has a renderer to light with: booted and not destroyed. @internal */
  get canLight(): boolean {
    return this.inPlace !== null;
  }

  /**
   * Lights what is drawn in `context` in place with the lights of content `layers`,
   * `worldToContext` mapping world units to the context's; with normals, through the normal maps of
   * the objects of `content` drawn before `stop` (all when null). Call it between Phaser's
   * YieldContext and RebindContext nodes, which the Extern's renderer runs around the layer's render. @internal
   */
  lightContext(
    context: Phaser.Renderer.WebGL.DrawingContext, worldToContext: Phaser.GameObjects.Components.TransformMatrix, layers: number,
    content: readonly Phaser.GameObjects.GameObject[], stop: Phaser.GameObjects.GameObject | null,
  ): void {
    const lighting = this.inPlace;
    if (!lighting) return;
    // Binds the context's framebuffer and viewport, which the lighting reads and writes.
    context.beginDraw();
    // Phaser 4 draws every context, the canvas and framebuffers (camera filters, lit groups) alike,
    // with the same projection, y down (setProjectionMatrixFromDrawingContext): none upside down.
    const view = this.view;
    view.pixelWidth = view.width = context.width;
    view.pixelHeight = view.height = context.height;
    const camera = this.camera;
    camera.a = worldToContext.a;
    camera.b = worldToContext.b;
    camera.c = worldToContext.c;
    camera.d = worldToContext.d;
    camera.tx = worldToContext.e;
    camera.ty = worldToContext.f;
    let surfaces = null;
    if (lighting.renderer.normals) {
      surfaces = this.ownSurfaces().render(context, content, stop, view);
    }
    lighting.draw(view, camera, layers, surfaces);
  }
}
