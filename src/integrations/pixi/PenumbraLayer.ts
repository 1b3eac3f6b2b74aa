import { Graphics, RenderContainer, Sprite, type Container, type Renderer, type TextureSource, type WebGLRenderer } from 'pixi.js';
import { Hull, Light, PenumbraRenderer, type LightOptions, type PenumbraRendererOptions } from '../../index';
import { isOpaqueMultisampledCanvas, isWebGL2, notWebGL2Error } from '../../gl/capabilities';
import { ALL_LAYERS, assertLayerMask, describeValue } from '../../util/validate';
import { InPlaceLighting, type InPlaceView } from '../inPlaceLighting';
import { LightFollower, LightFollowers, type LightFollowOptions } from '../LightFollower';
import { GraphicsOccluder, type GraphicsHullsOptions } from './graphicsHulls';
import { Occluder, placeInSpace, prepareSpace, type OccluderSpace } from './Occluder';
import { gpuReads, SpriteOccluder, type SpriteHullsOptions } from './spriteHulls';
import { PixiSurfaces, type SurfaceOptions } from './surfaces';

/** Options of a {@link PenumbraLayer}: the core renderer's options plus the camera. */
export interface PenumbraLayerOptions extends Omit<PenumbraRendererOptions, 'viewProjection' | 'width' | 'height'> {
  /**
   * The container whose local space is the world of the lights and hulls (typically the
   * "world" container you pan and zoom as a camera). Its world transform drives the lighting's
   * view-projection every frame. Default `null`: lights and hulls are in stage (screen) pixels.
   */
  camera?: Container | null;
  /**
   * The content layers this layer lights, a bit mask: it lights with the lights whose `litLayers`
   * share a bit with it (see {@link LightOptions.litLayers}). Default `0xffffffff` (every light).
   */
  layers?: number;
}

type BindState = ReturnType<WebGLRenderer['renderTarget']['getBindState']>;

/** What to do when Pixi's context is not WebGL2: Pixi falls back to WebGL1 when asked to, or without WebGL2. */
const PIXI_WEBGL2_FIX = 'Pixi made a WebGL1 context (preferWebGLVersion: 1, or no WebGL2 in this browser); '
  + 'init the Application with preference: \'webgl\' and preferWebGLVersion: 2 (the default) in a browser with WebGL2';

/**
 * A PixiJS v8 display object that lights everything drawn before it in the same render target.
 * Put it in the stage after the world and before the HUD: the world is multiplied by the
 * lightmap (ambient + lights, with soft shadows from the hulls), the HUD drawn after it stays
 * unlit. It shares Pixi's WebGL2 context; after lighting it calls `renderer.resetState()` and
 * rebinds Pixi's current render target, so Pixi carries on with a correct state.
 *
 * ```ts
 * const lighting = new PenumbraLayer(app.renderer, { camera: world, ambientColor: [0.1, 0.1, 0.15] });
 * app.stage.addChild(world, lighting, hud);
 * lighting.addLight(new PointLight({ position: [200, 150], range: 300, radius: 10 }));
 * ```
 *
 * Content drawn after the layer is drawn as it is, unlit: a HUD, or glowing world sprites (put them
 * after the layer inside the camera container, and they follow the camera). Content in a
 * {@link PenumbraGroup} placed after the layer is lit apart, by some lights only.
 *
 * Hulls can also follow display objects: {@link PenumbraLayer.addOccluder} traces a `Sprite`'s
 * alpha or reads a `Graphics`' shapes, {@link PenumbraLayer.follow} takes your own hulls; the
 * layer moves them with their objects each time it renders (see {@link Occluder}). Lights follow
 * display objects the same way: `follow(object, light)` (see {@link LightFollower}).
 *
 * Only the WebGL renderer is supported (`preference: 'webgl'`), on a WebGL2 context (Pixi's default),
 * and not on an antialiased opaque canvas (`antialias: true` with an opaque background), which the
 * lighting cannot copy: the constructor throws, saying so. `destroy()` frees the GL resources.
 * The members it inherits from Pixi's `RenderContainer` are documented by Pixi.
 *
 * @noInheritDoc
 */
export class PenumbraLayer extends RenderContainer {
  /** The core renderer: lights, hulls, ambient colour, debug wireframe and stats. */
  readonly penumbra: PenumbraRenderer;
  /** See {@link PenumbraLayerOptions.camera}. */
  camera: Container | null;

  private readonly bindState = {} as BindState;
  private readonly pixi: Renderer;
  private readonly _occluders: Occluder[] = [];
  private readonly _followers = new LightFollowers<Container>({
    listen: (object, destroyed) => object.on('destroyed', destroyed),
    ignore: (object, destroyed) => object.off('destroyed', destroyed),
    removeLight: (light) => this.penumbra.removeLight(light),
  });
  /** Scratch for a follower's object → camera transform. */
  private readonly followerPlacement = new Float64Array(6);
  private readonly space: OccluderSpace = { camera: null, root: null, fromRoot: new Float64Array(6) };
  private readonly removeDestroyed = (occluder: Occluder): void => {
    this.removeOccluder(occluder);
  };
  /** Lights Pixi's bound target; shared with the groups, which light with the same renderer. */
  private readonly inPlace: InPlaceLighting;
  /** The bound target's viewport, filled before each lighting. */
  private readonly view: InPlaceView = { pixelWidth: 0, pixelHeight: 0, width: 0, height: 0, flipY: false };
  private _layers = ALL_LAYERS;
  /** The sprites' surfaces and the normal pass, with a renderer made with `normals: true`. */
  private readonly surfaces: PixiSurfaces | null;

  constructor(renderer: Renderer, options: PenumbraLayerOptions = {}) {
    super({ label: 'PenumbraLayer' });
    const gl = (renderer as Partial<WebGLRenderer>).gl;
    if (!gl) throw new TypeError('penumbra: PenumbraLayer needs Pixi\'s WebGL renderer (Application.init({ preference: \'webgl\' }))');
    if (!isWebGL2(gl)) throw notWebGL2Error('PenumbraLayer', gl, PIXI_WEBGL2_FIX);
    if (isOpaqueMultisampledCanvas(gl)) {
      throw new Error('penumbra: PenumbraLayer cannot light Pixi\'s canvas: it is antialiased and opaque (antialias: true with an opaque '
        + 'background), and the lighting copies a multisampled canvas only into its own RGBA format; init the Application with antialias: false');
    }
    const { camera = null, layers = ALL_LAYERS, ...rendererOptions } = options;
    this.camera = camera;
    this.layers = layers;
    this.pixi = renderer;
    // Every renderer option goes through; the size and the view follow Pixi's target each frame.
    this.penumbra = new PenumbraRenderer(gl, {
      ...rendererOptions,
      viewProjection: null,
      width: gl.drawingBufferWidth,
      height: gl.drawingBufferHeight,
    });
    this.inPlace = new InPlaceLighting(this.penumbra, gl.drawingBufferWidth, gl.drawingBufferHeight);
    this.surfaces = this.penumbra.normals ? new PixiSurfaces(gl) : null;
  }

  /** The content layers this layer lights; see {@link PenumbraLayerOptions.layers}. */
  get layers(): number {
    return this._layers;
  }
  set layers(value: number) {
    this._layers = assertLayerMask('PenumbraLayer.layers', value);
  }

  /** Adds a light (in the camera's space); see {@link PenumbraRenderer.addLight}. */
  addLight<T extends Light>(light: T): T {
    return this.penumbra.addLight(light);
  }
  /** Removes a light, and stops it following a display object; returns whether it was there. */
  removeLight(light: Light): boolean {
    this._followers.drop(light, false);
    return this.penumbra.removeLight(light);
  }
  /** Adds a hull (in the camera's space); see {@link PenumbraRenderer.addHull}. */
  addHull(hull: Hull): Hull {
    return this.penumbra.addHull(hull);
  }
  /** Removes a hull; returns whether it was there. */
  removeHull(hull: Hull): boolean {
    return this.penumbra.removeHull(hull);
  }

  /**
   * Gives a sprite, or every sprite drawn from a texture source, a normal map and a material
   * (see {@link SurfaceOptions}); `null` takes it away. The layer then lights such sprites through
   * their normals: each frame it draws the sprites drawn before it, in Pixi's order, from their normal
   * maps turned by their world transform (a rotated or mirrored sprite lights correctly), into textures
   * the renderer reads (docs/normal-maps.md). A sprite's own surface wins over its texture source's.
   * Sprites without a surface are lit as without normals. Only `Sprite`s (and subclasses) take a
   * surface; other display objects drawn over a sprite with one do not hide its relief.
   *
   * ```ts
   * const lighting = new PenumbraLayer(app.renderer, { camera: world, normals: true });
   * lighting.setSurface(wall, { normalMap: await Assets.load('wall_n.png'), specular: 0.3, shininess: 24 });
   * lighting.setSurface(sheet.textureSource, { normalMap: sheetNormals });   // every frame of a sheet
   * ```
   * @throws Error when the layer was not made with `normals: true`; TypeError or RangeError for a
   * target or option that does not fit.
   */
  setSurface(target: Sprite | TextureSource, surface: SurfaceOptions | null): void {
    if (!this.surfaces) throw new Error('penumbra: PenumbraLayer.setSurface needs a layer made with { normals: true }');
    this.surfaces.set(target, surface);
  }

  /** The occluders: hulls following display objects, in the order they were added. */
  get occluders(): readonly Occluder[] {
    return this._occluders;
  }

  /**
   * Makes a display object cast shadows: hulls traced from a `Sprite`'s texture alpha (see
   * {@link hullsFromTexture}; `options` are the tracing options), or covering a `Graphics`' filled
   * shapes (see {@link hullsFromGraphics}; `options.tolerance` for its curves). The hulls follow
   * the object from then on (its transform relative to {@link PenumbraLayer.camera}, its
   * visibility, its texture and anchor, its redrawn shapes) until it is destroyed or
   * {@link PenumbraLayer.removeOccluder} is called. See {@link Occluder}.
   *
   * ```ts
   * const crate = world.addChild(new Sprite(await Assets.load('crate.png')));
   * lighting.addOccluder(crate);                                   // its opaque pixels cast shadows
   * lighting.addOccluder(world.addChild(new Graphics().circle(0, 0, 30).fill(0x555555)));
   * ```
   * @throws the errors of {@link hullsFromTexture} or {@link hullsFromGraphics}.
   */
  addOccluder(sprite: Sprite, options?: SpriteHullsOptions): SpriteOccluder;
  addOccluder(graphics: Graphics, options?: GraphicsHullsOptions): GraphicsOccluder;
  addOccluder(object: Sprite | Graphics, options: SpriteHullsOptions & GraphicsHullsOptions = {}): SpriteOccluder | GraphicsOccluder {
    let occluder: SpriteOccluder | GraphicsOccluder;
    if (object instanceof Sprite) occluder = new SpriteOccluder(object, this.penumbra, this.pixi, options, this.removeDestroyed);
    else if (object instanceof Graphics) occluder = new GraphicsOccluder(object, this.penumbra, options, this.removeDestroyed);
    else throw new TypeError(`penumbra: addOccluder takes a Sprite or a Graphics (for another object, lighting.follow(object, hulls)), got ${String(object)}`);
    return this.start(occluder);
  }

  /**
   * Makes `hulls` follow a display object: their points are in the object's local space (placed
   * within it by each hull's `position`, `origin`, `rotation` and `scale` as they are now), and
   * from now on the layer moves them with the object. The hulls are added to the renderer. See
   * {@link Occluder}.
   *
   * ```ts
   * const door = world.addChild(new Sprite(doorTexture));
   * lighting.follow(door, new Hull([[0, 0], [64, 0], [64, 8], [0, 8]]));  // a thin slab, not every pixel
   * ```
   */
  follow(object: Container, hulls: Hull | readonly Hull[]): Occluder;
  /**
   * Makes a light follow a display object: it sits at `options.offset` in the object's local space
   * (default its position point) and, with `options.rotation`, turns with it; it shines while the
   * object is shown. The light is added to the renderer; the layer places it each time it renders,
   * relative to {@link PenumbraLayer.camera} as hulls are. Following the same light again replaces
   * the follower. It ends when the object is destroyed (the light is removed too), on
   * {@link PenumbraLayer.removeLight} or on {@link PenumbraLayer.unfollow}. See {@link LightFollower}.
   *
   * ```ts
   * const player = world.addChild(new Sprite(heroTexture));
   * lighting.follow(player, new PointLight({ range: 200, radius: 6 }), { offset: [0, -12] });     // a torch over its head
   * lighting.follow(turret, new Spotlight({ range: 300, coneAngle: 0.4 }), { rotation: 0 });      // a beam along the turret's +x
   * ```
   * @throws TypeError for an object that is no display object, or an option of the wrong type.
   */
  follow(object: Container, light: Light, options?: LightFollowOptions): LightFollower<Container>;
  follow(object: Container, target: Hull | readonly Hull[] | Light, options: LightFollowOptions = {}): Occluder | LightFollower<Container> {
    if (!(target instanceof Light)) {
      const list = target instanceof Hull ? [target] : target;
      return this.start(new Occluder(object, this.penumbra, list, this.removeDestroyed));
    }
    if (typeof (object as Partial<Container> | null)?.updateLocalTransform !== 'function') {
      throw new TypeError(`penumbra: PenumbraLayer.follow takes a Pixi display object to follow, got ${describeValue(object)}`);
    }
    const follower = new LightFollower(object, target, options, 'PenumbraLayer.follow');
    this._followers.add(follower);
    this.penumbra.addLight(target);
    prepareSpace(this.space, this, this.camera);
    this.placeFollower(follower);
    return follower;
  }

  /** The lights following display objects, in the order they started. */
  get followers(): readonly LightFollower<Container>[] {
    return this._followers.list;
  }

  /**
   * Stops a light following its display object, or every light following a display object: the
   * lights stay in the renderer where they are, enabled. Returns whether one was following.
   */
  unfollow(target: LightFollower<Container> | Light | Container): boolean {
    return this._followers.unfollow(target);
  }

  /**
   * Places every following light for its object's current transform. The layer does it each time
   * it renders; call it to read the lights' placement before then.
   */
  updateFollowers(): void {
    const followers = this._followers.list;
    if (followers.length === 0) return;
    prepareSpace(this.space, this, this.camera);
    for (let i = 0; i < followers.length; i++) this.placeFollower(followers[i]);
  }

  /**
   * Stops an occluder, or every occluder of a display object: its hulls are removed from the
   * renderer. Returns whether there was one. Called for you when the object is destroyed.
   */
  removeOccluder(target: Occluder | Container): boolean {
    let removed = false;
    for (let i = this._occluders.length - 1; i >= 0; i--) {
      const occluder = this._occluders[i];
      if (occluder !== target && occluder.object !== target) continue;
      this._occluders.splice(i, 1);
      occluder.detach();
      removed = true;
    }
    return removed;
  }

  /**
   * Places every occluder's hulls for its object's current transform. The layer does it each time
   * it renders; call it to read the hulls' placement before then.
   */
  updateOccluders(): void {
    const occluders = this._occluders;
    if (occluders.length === 0) return;
    prepareSpace(this.space, this, this.camera);
    for (let i = 0; i < occluders.length; i++) occluders[i].update(this.space);
  }

  private placeFollower(follower: LightFollower<Container>): void {
    const shown = placeInSpace(follower.object, this.space, this.followerPlacement);
    follower.place(this.followerPlacement, shown);
  }

  private start<T extends Occluder>(occluder: T): T {
    this._occluders.push(occluder);
    prepareSpace(this.space, this, this.camera);
    occluder.update(this.space);
    return occluder;
  }

  /** Called by Pixi's render pipe at this object's place in the draw order. @internal */
  override render(renderer: Renderer): void {
    const pixi = renderer as WebGLRenderer;
    const targets = pixi.renderTarget;
    targets.getBindState(this.bindState);
    const reads = gpuReads;
    this.updateOccluders();
    this.updateFollowers();
    // A texture read back from the GPU left its own framebuffer bound: back to Pixi's target.
    if (gpuReads !== reads) {
      pixi.resetState();
      targets.bind(this.bindState);
    }
    let root: Container = this;
    while (root.parent) root = root.parent;
    this.lightBoundTarget(pixi, this._layers, root, this);
  }

  /**
   * Lights the viewport of Pixi's bound target in place with the lights of content `layers`, seen
   * through the camera, then hands Pixi back its state with the target still bound. With normals,
   * through the surfaces of the sprites under `content` drawn before `stop` (all when null). @internal
   */
  lightBoundTarget(pixi: WebGLRenderer, layers: number, content: Container, stop: Container | null): void {
    const targets = pixi.renderTarget;
    targets.getBindState(this.bindState);
    const target = targets.renderTarget;
    const viewport = targets.viewport;
    const view = this.view;
    view.pixelWidth = viewport.width;
    view.pixelHeight = viewport.height;
    view.width = viewport.width / target.resolution;
    view.height = viewport.height / target.resolution;
    // As Pixi's own projection: render textures upside down (row 0 at the top), the screen right
    // side up, and either way round again when bound with flipY.
    view.flipY = !target.isRoot !== Boolean(target.flipY);
    const surfaces = this.surfaces?.render(pixi, content, stop, this.camera, view) ?? null;
    this.inPlace.draw(view, this.camera?.worldTransform ?? null, layers, surfaces);
    // The engine's own mechanism for foreign GL code; it forgets the bound target too, so bind it back.
    pixi.resetState();
    // resetState takes Pixi's cached clear colour to transparent black without setting GL's, which
    // still holds the frame's background: the next clear to transparent (a filter's texture, a
    // lit group's) would skip gl.clearColor and clear to the background. Make them agree.
    pixi.gl.clearColor(0, 0, 0, 0);
    targets.bind(this.bindState);
  }

  /** Stops the occluders, frees the lighting's GL resources, then destroys the display object. */
  override destroy(options?: Parameters<RenderContainer['destroy']>[0]): void {
    for (const occluder of this._occluders) occluder.detach();
    this._occluders.length = 0;
    this._followers.clear();
    this.penumbra.dispose();
    this.surfaces?.dispose();
    super.destroy(options);
  }
}
