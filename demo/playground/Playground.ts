import {
  createSceneObjects, describeScene, DirectionalLight, Hull, PenumbraRenderer, PointLight, readScene, Spotlight, TexturedLight,
  type Light, type SceneAppData, type SceneDocument,
} from 'penumbra-gl';
import { PLAYGROUND_APP, readPlaygroundState, writePlaygroundState } from './appState';
import { Camera } from './Camera';
import { Cookies } from './Cookies';
import { SceneArt, type ImageSprite, type Sprite } from './SceneArt';
import { Showcase } from './showcase/Showcase';
import { createTexture } from './textures';

/** What can be selected and edited. */
export type Selectable = Light | Hull;
/** Kinds of light the page can add. */
type NewLightKind = 'point' | 'spot' | 'textured' | 'directional';

/** How far apart (CSS pixels) a new light is put from the others: a few handle radii. */
const NEW_LIGHT_SPACING = 48;
/** The angle between successive points of a sunflower spiral, which spreads them evenly. */
const GOLDEN_ANGLE = Math.PI * (3 - Math.sqrt(5));
/** Spotlights sweep this far (radians) either side when animation is on. */
const SWEEP = 0.5;
/** A new sun's light: shadows fall down and to the right, as under a low afternoon sun; its angular size is the library's (the sun's). */
const NEW_SUN = { rotation: Math.PI / 4, color: [1, 0.95, 0.85], intensity: 0.8 } as const;

/**
 * The playground's model: the renderer with its lights and hulls, the camera, the selection and
 * the art. Fires `scene` when the scene was edited or replaced and `selection` when the selection
 * changed; the animation changes the scene without firing (it is not an edit).
 */
export class Playground extends EventTarget {
  readonly camera = new Camera();
  readonly renderer: PenumbraRenderer;
  readonly cookies: Cookies;
  /** Whether spotlights sweep and walkers walk. */
  animate = true;
  private _selection: Selectable | null = null;
  private readonly art: SceneArt;
  /** The showcase level's art and animation; drawn instead of the generic art while {@link showcaseActive}. */
  readonly showcase: Showcase;
  private _showcaseActive = false;
  private readonly sprites: Sprite[] = [
    { texture: 'barrel', x: 560, y: 560, size: 44, rotation: 0 },
    { texture: 'barrel', x: 1240, y: 880, size: 40, rotation: 1 },
    { texture: 'barrel', x: 150, y: 900, size: 46, rotation: 2 },
    { texture: 'walker', x: 0, y: 0, size: 56, rotation: 0 },
    { texture: 'walker', x: 0, y: 0, size: 56, rotation: 0 },
  ];
  /** Images traced into hulls, drawn as sprites that follow their hulls; forgotten once their hulls are gone. */
  private images: ImageSprite[] = [];
  /**
   * The hulls traced from the same image: they move together. One array per image, shared with its
   * sprite, so a hull rebuilt in place ({@link setHullClosed}) is swapped in both at once.
   */
  private readonly companions = new WeakMap<Hull, Hull[]>();
  private readonly view = new Float32Array(4);
  /** The hulls the showcase does not draw (added in the editor), refilled each frame rather than made. */
  private readonly editorHulls: Hull[] = [];
  /** The loaded file's data of other applications: kept, and saved back. */
  private otherApps: SceneAppData = {};
  private time = 0;

  constructor(readonly gl: WebGL2RenderingContext) {
    super();
    // Normals: the showcase's art writes normals and materials; the generic art writes none (coverage 0), lit as without.
    this.renderer = new PenumbraRenderer(gl, { measureCpuTime: true, normals: true });
    this.cookies = new Cookies(gl);
    this.art = new SceneArt(gl);
    this.showcase = new Showcase(gl);
  }

  /** Whether the scene is the showcase level, drawn with its own art (fires `art` when this changes). */
  get showcaseActive(): boolean {
    return this._showcaseActive;
  }

  get selection(): Selectable | null {
    return this._selection;
  }
  set selection(value: Selectable | null) {
    if (value === this._selection) return;
    this._selection = value;
    this.dispatchEvent(new Event('selection'));
  }

  /** Tells listeners (storage, panel) that the scene was edited. */
  changed(): void {
    this.dispatchEvent(new Event('scene'));
  }

  /**
   * Replaces the scene with a scene file's contents. Validates everything and builds every object
   * before touching the current scene, so on an error (thrown, naming the bad field) nothing changes.
   * The file's playground entry (appState.ts) says which art draws it: the showcase level's (its
   * document, or a save of it, with the state {@link document} kept) or the generic one.
   */
  load(source: string | SceneDocument): void {
    const document = readScene(source);
    const state = readPlaygroundState(document.app, { hulls: document.hulls.length, lights: document.lights.length }, this.showcase.roleCounts);
    const objects = createSceneObjects(document, this.cookies.resolve);
    const renderer = this.renderer;
    for (const light of [...renderer.lights]) renderer.removeLight(light);
    for (const hull of [...renderer.hulls]) renderer.removeHull(hull);
    for (const hull of objects.hulls) renderer.addHull(hull);
    for (const light of objects.lights) renderer.addLight(light);
    renderer.ambientColor = document.ambient;
    // readScene checked the look against the renderer's own ranges: these setters cannot throw.
    Object.assign(renderer, document.look);
    this.camera.center[0] = document.camera.center[0];
    this.camera.center[1] = document.camera.center[1];
    this.camera.zoom = document.camera.zoom;
    const { [PLAYGROUND_APP]: _, ...otherApps } = document.app;
    this.otherApps = otherApps;
    const showcase = state.art === 'showcase';
    if (state.art === 'showcase') this.showcase.attach(renderer, state.showcase);
    else this.showcase.detach();
    if (showcase !== this._showcaseActive) {
      this._showcaseActive = showcase;
      this.dispatchEvent(new Event('art'));
    }
    this.selection = null;
    this.changed();
  }

  /**
   * The current scene as a scene document, with the playground's entry in its application data
   * (the art, and the showcase's state) and the loaded file's entries of other applications.
   */
  document(): SceneDocument {
    const { renderer, camera } = this;
    const state = writePlaygroundState(this._showcaseActive ? { art: 'showcase', showcase: this.showcase.state() } : { art: 'generic' });
    return describeScene({
      lights: [...renderer.lights], hulls: [...renderer.hulls], ambient: renderer.ambientColor,
      camera: { center: [...camera.center], zoom: camera.zoom }, cookieName: this.cookies.nameOf, look: renderer,
      app: { ...this.otherApps, [PLAYGROUND_APP]: state },
    });
  }

  /**
   * Adds a light of `kind` and selects it: a sun (shown by a compass on the view), or a light near
   * the centre of the view, clear of the other lights' handles.
   */
  addLight(kind: NewLightKind): Light {
    const light = kind === 'directional' ? new DirectionalLight(NEW_SUN) : this.newPlacedLight(kind);
    this.renderer.addLight(light);
    this.selection = light;
    this.changed();
    return light;
  }

  /** A light of `kind` with a position, near the centre of the view. */
  private newPlacedLight(kind: Exclude<NewLightKind, 'directional'>): Light {
    const options = { position: this.freeSpotNearCentre(), range: 300, radius: 10, color: [1, 0.9, 0.7] as [number, number, number] };
    return kind === 'point' ? new PointLight(options)
      : kind === 'spot' ? new Spotlight({ ...options, coneAngle: 0.8 })
        : new TexturedLight({ ...options, texture: this.cookies.resolve('flame')!, size: [500, 500] });
  }

  /**
   * The centre of the view, or failing that the first point of a sunflower spiral around it that
   * is {@link NEW_LIGHT_SPACING} CSS pixels from every light with a handle in the world (suns have
   * none): lights added one after another do not hide each other's handles.
   */
  private freeSpotNearCentre(): [number, number] {
    const [cx, cy] = this.camera.center;
    const spacing = NEW_LIGHT_SPACING / this.camera.zoom;
    const lights = this.renderer.lights.filter((light) => !(light instanceof DirectionalLight));
    for (let k = 0; ; k++) {
      const radius = spacing * Math.sqrt(k), angle = k * GOLDEN_ANGLE;
      const x = cx + radius * Math.cos(angle), y = cy + radius * Math.sin(angle);
      if (lights.every(({ position: [lx, ly] }) => Math.hypot(lx - x, ly - y) >= spacing)) return [x, y];
    }
  }

  /** Adds a hull through world points (placed at their centroid, so it rotates about its middle) and selects it. */
  addHull(worldPoints: readonly (readonly [number, number])[]): Hull {
    let cx = 0, cy = 0;
    for (const [x, y] of worldPoints) {
      cx += x / worldPoints.length;
      cy += y / worldPoints.length;
    }
    const hull = new Hull(worldPoints.map(([x, y]) => [x - cx, y - cy]), { position: [cx, cy] });
    this.renderer.addHull(hull);
    this.selection = hull;
    this.changed();
    return hull;
  }

  /**
   * Takes hulls out of the scene and puts others in, without touching the selection unless it is
   * among those removed: the painter's edits. Removed hulls are forgotten by lights that ignored them.
   */
  replaceHulls(removed: readonly Hull[], added: readonly Hull[]): void {
    const renderer = this.renderer;
    for (const hull of removed) {
      renderer.removeHull(hull);
      for (const light of renderer.lights) light.ignoredHulls.delete(hull);
    }
    for (const hull of added) renderer.addHull(hull);
    if (this._selection instanceof Hull && removed.includes(this._selection)) this.selection = null;
    this.changed();
  }

  /**
   * Adds the hulls traced from an image, with the image (a canvas of `width` × `height` pixels, the
   * hulls' local space) drawn under them as a sprite that follows them. The hulls move together.
   */
  addTracedImage(hulls: readonly Hull[], image: TexImageSource, width: number, height: number): void {
    const group = [...hulls];
    for (const hull of group) {
      this.renderer.addHull(hull);
      this.companions.set(hull, group);
    }
    this.images.push({ texture: createTexture(this.gl, image, false), hulls: group, width, height });
    this.selection = null;
    this.changed();
  }

  /** The other hulls traced from the same image as `hull` (empty for any other hull). */
  companionsOf(hull: Hull): readonly Hull[] {
    return (this.companions.get(hull) ?? []).filter((other) => other !== hull);
  }

  /**
   * Makes a hull closed or open. That is fixed when a hull is built, so a new hull with every other
   * setting of the old one takes its place: in the scene (at the end of its order, which only the
   * file's order shows), in the lights that ignore it, in its traced image's group, and in the
   * selection. Returns the hull now in the scene.
   */
  setHullClosed(hull: Hull, closed: boolean): Hull {
    if (hull.closed === closed) return hull;
    const { points, position, origin, rotation, scale, enabled, layers } = hull;
    const rebuilt = new Hull(points, { closed, position, origin, rotation, scale, enabled, layers });
    this.renderer.removeHull(hull);
    this.renderer.addHull(rebuilt);
    for (const light of this.renderer.lights) if (light.ignoredHulls.delete(hull)) light.ignoredHulls.add(rebuilt);
    const group = this.companions.get(hull);
    if (group) {
      group[group.indexOf(hull)] = rebuilt;
      this.companions.set(rebuilt, group);
    }
    if (this._selection === hull) this.selection = rebuilt;
    this.changed();
    return rebuilt;
  }

  /** Removes the selected light or hull (and forgets it in lights' ignored hulls). */
  deleteSelection(): void {
    const selected = this._selection;
    if (!selected) return;
    if (selected instanceof Hull) {
      this.renderer.removeHull(selected);
      for (const light of this.renderer.lights) light.ignoredHulls.delete(selected);
    } else {
      this.renderer.removeLight(selected);
    }
    this.selection = null;
    this.changed();
  }

  /** Advances the animation by `dt` seconds and draws one frame into the canvas. */
  frame(dt: number): void {
    const { gl, renderer, camera } = this;
    this.time += dt;
    if (this.animate) this.step(dt);
    this.cookies.update(this.time);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    const viewProjection = camera.viewProjection();
    renderer.viewProjection = viewProjection;
    renderer.beginDraw();
    if (this.images.length > 0) this.forgetRemovedImages();
    const view = camera.visibleWorld(this.view);
    if (this._showcaseActive) {
      this.showcase.draw(viewProjection, view, renderer.hulls, renderer.lights);
      // Hulls added in the editor, and traced images, in the generic stone over the showcase's floor.
      const editorHulls = this.editorHulls;
      editorHulls.length = 0;
      const hulls = renderer.hulls;
      for (let i = 0; i < hulls.length; i++) if (!this.showcase.draws(hulls[i])) editorHulls.push(hulls[i]);
      this.art.draw(viewProjection, view, editorHulls, [], this.images, false);
    } else {
      this.art.draw(viewProjection, view, renderer.hulls, this.sprites, this.images);
    }
    renderer.draw();
  }

  /** Whether images traced into hulls are drawn: a scene file keeps their hulls, not their pictures. */
  get hasTracedImages(): boolean {
    const hulls = this.renderer.hulls;
    return this.images.some((image) => image.hulls.some((hull) => hulls.includes(hull)));
  }

  /** Drops (and frees) the images none of whose hulls is in the scene any more. */
  private forgetRemovedImages(): void {
    const hulls = this.renderer.hulls;
    this.images = this.images.filter((image) => {
      if (image.hulls.some((hull) => hulls.includes(hull))) return true;
      this.gl.deleteTexture(image.texture);
      return false;
    });
  }

  /** Sweeps spotlights back and forth and walks the walkers round their loops. */
  private step(dt: number): void {
    if (this._showcaseActive) {
      this.showcase.step(dt);
      return;
    }
    const t = this.time;
    // Adding the derivative of a sine keeps each spotlight swinging around its own rotation.
    const turn = SWEEP * 0.6 * Math.cos(t * 0.6) * dt;
    for (const light of this.renderer.lights) if (light instanceof Spotlight) light.rotation += turn;
    for (let i = 0; i < 2; i++) {
      const walker = this.sprites[3 + i];
      const angle = t * 0.35 + i * Math.PI;
      walker.x = 700 + Math.cos(angle) * 330;
      walker.y = 560 + Math.sin(angle) * 170;
      walker.rotation = angle + Math.PI / 2;
    }
  }
}
