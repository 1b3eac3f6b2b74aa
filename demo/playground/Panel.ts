import GUI, { type Controller } from 'lil-gui';
import {
  DirectionalLight, Dithering, Falloff, Hull, PointLight, ShadowType, Spotlight, TexturedLight, ToneMapping, type Light,
} from 'penumbra-gl';
import type { Editor } from './Editor';
import type { ImageTracer } from './ImageTracer';
import type { Playground } from './Playground';
import { PRESETS } from './presets';
import { TILE_SIZES } from './TilePainter';

/** What the panel's buttons do outside the model: files and messages. */
interface PanelActions {
  selectPreset(name: string): void;
  save(): void;
  load(): void;
  /** Opens the file picker for an image to trace into hulls. */
  pickImage(): void;
  showError(message: string): void;
}

const DEGREES = 180 / Math.PI;
/** The tile-mode button's label outside and in tile mode. */
const PAINT_LABELS = { start: 'paint tiles (drag; right-drag or Shift erases)', stop: 'stop painting (Esc)' };
/** Below this page width (CSS pixels) the panel opens collapsed: it would cover most of the scene. */
const NARROW_SCREEN = 720;
/** Below this page height (CSS pixels) the content folder opens collapsed: the panel would run off the page. */
const SHORT_SCREEN = 640;

/** The layer bits the panel has a checkbox for; a mask's higher bits are kept as they are. */
const LAYER_CHECKBOXES = 8;
/** A mask with every layer's bit: the default of `Light.shadowLayers` and `Light.litLayers`. */
const ALL_LAYERS = 0xffffffff;
/** The end of the angular size slider (radians): wider than this, a sun's shadows are mostly penumbra. */
const MAX_SLIDER_ANGULAR_SIZE = 0.8;

/**
 * A layer mask as a folder title shows it: `all`, `none`, or its layer numbers with runs as ranges
 * (`0 2–5 8–31`).
 */
function describeLayers(mask: number): string {
  if (mask === ALL_LAYERS) return 'all';
  const runs: string[] = [];
  for (let bit = 0; bit < 32; bit++) {
    if (!hasLayer(mask, bit)) continue;
    const first = bit;
    while (bit < 31 && hasLayer(mask, bit + 1)) bit++;
    runs.push(first === bit ? `${first}` : `${first}–${bit}`);
  }
  return runs.length > 0 ? runs.join(' ') : 'none';
}

function hasLayer(mask: number, bit: number): boolean {
  return ((mask >>> bit) & 1) === 1;
}

/** `mask` with layer `bit` on or off. JavaScript's bit operators give signed 32-bit results: `>>> 0` makes the mask unsigned again. */
function withLayer(mask: number, bit: number, on: boolean): number {
  return (on ? mask | (1 << bit) : mask & ~(1 << bit)) >>> 0;
}

/** `[r, g, b]` in 0..1 ↔ `#rrggbb` for lil-gui's colour picker (channels above 1 show as 1). */
function toHex(color: readonly number[]): string {
  return `#${color.map((c) => Math.round(Math.min(1, c) * 255).toString(16).padStart(2, '0')).join('')}`;
}
function fromHex(hex: string): [number, number, number] {
  return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255) as [number, number, number];
}

/**
 * A number field with its value shown to `decimals` places. No min or max: lil-gui would clamp a
 * typed value silently, while the model refuses one out of range with a message naming it.
 */
function number(folder: GUI, model: Record<string, unknown>, key: string, decimals: number): Controller {
  return folder.add(model, key).decimals(decimals).listen();
}

/**
 * Shows `text` while the pointer rests on a control or a folder (lil-gui has no tooltips: this is
 * the element's title attribute, which a folder's rows show too, having none of their own).
 */
function hint(control: { domElement: HTMLElement }, text: string): void {
  control.domElement.title = text;
}

/** Adds a property to `model` whose reads and writes go through `get` and `set`. */
function bind<T>(model: Record<string, unknown>, key: string, get: () => T, set: (value: T) => void): void {
  Object.defineProperty(model, key, { get, set, enumerable: true });
}

/**
 * The properties panel (lil-gui): scene settings, presets and files, adding and deleting, hulls
 * from content (painted tiles, traced images), and every property of the selected light or hull,
 * rebuilt when the selection changes.
 */
export class Panel {
  readonly gui = new GUI({ title: 'penumbra-gl playground' });
  private selectionFolder: GUI | null = null;
  /** The selected light's "pick ignored hulls" button; null while no light is selected. */
  private pickButton: Controller | null = null;
  private readonly settings = { preset: Object.keys(PRESETS)[0] };

  constructor(
    private readonly playground: Playground, private readonly editor: Editor, private readonly tracer: ImageTracer,
    private readonly actions: PanelActions,
  ) {
    const scene = this.gui.addFolder('Scene');
    scene.add(this.settings, 'preset', Object.keys(PRESETS)).name('preset').onChange((name: string) => actions.selectPreset(name));
    const sceneModel: Record<string, unknown> = {};
    bind(sceneModel, 'ambient', () => toHex(playground.renderer.ambientColor), (hex: string) => {
      playground.renderer.ambientColor = fromHex(hex);
      playground.changed();
    });
    scene.addColor(sceneModel, 'ambient').listen();
    // Tile mode and tracing turn the wireframe on: the box follows.
    scene.add(playground.renderer, 'debug').name('debug wireframe').listen();
    scene.add(playground, 'animate').name('animate');
    scene.add(actions, 'save').name('save scene (download)');
    scene.add(actions, 'load').name('load scene… (or drop a file)');
    this.showcaseControls();
    this.lookControls();

    const edit = this.gui.addFolder('Add / delete');
    const buttons = {
      point: () => playground.addLight('point'),
      spot: () => playground.addLight('spot'),
      textured: () => playground.addLight('textured'),
      sun: () => playground.addLight('directional'),
      hull: () => { editor.drawing = !editor.drawing; },
      remove: () => playground.deleteSelection(),
    };
    edit.add(buttons, 'point').name('add point light');
    edit.add(buttons, 'spot').name('add spotlight');
    edit.add(buttons, 'textured').name('add textured light');
    hint(edit.add(buttons, 'sun').name('add sun (directional light)'), 'Light from far away over the whole view; drag its compass (bottom left) to turn it');
    const drawHull = edit.add(buttons, 'hull').name('draw hull (click points)');
    hint(drawHull, 'Click points on the view; close the hull by clicking its first point, double-clicking or pressing Enter. Esc cancels.');
    edit.add(buttons, 'remove').name('delete selected (Del)');

    const paintTiles = this.contentControls();
    editor.addEventListener('mode', () => {
      drawHull.name(editor.drawing ? 'cancel hull (Enter closes)' : 'draw hull (click points)');
      paintTiles.name(editor.painting ? PAINT_LABELS.stop : PAINT_LABELS.start);
      this.labelPickButton();
    });

    playground.addEventListener('selection', () => this.showSelection());
    this.showSelection();
    if (window.innerWidth < NARROW_SCREEN) this.gui.close();
    this.gui.onOpenClose(() => this.measureCovered());
    window.addEventListener('resize', () => this.measureCovered());
    this.measureCovered();
  }

  /**
   * The showcase level's own controls, shown while it is the scene: its daylight (night's ambient
   * and cold moon through the windows to noon's warm ambient and high sun). Its torches flicker
   * while `animate` is on.
   */
  private showcaseControls(): void {
    const { playground } = this;
    const folder = this.gui.addFolder('Showcase');
    const m: Record<string, unknown> = {};
    this.field(m, 'daylight', () => playground.showcase.daylight, (v: number) => { playground.showcase.daylight = v; });
    hint(folder.add(m, 'daylight', 0, 1, 0.01).listen(), 'Night (0): dim ambient and a cold moon through the windows; noon (1): a warm ambient and a high sun.');
    const show = () => folder.show(playground.showcaseActive);
    playground.addEventListener('art', show);
    show();
  }

  /**
   * How the final image is made from the lightmap: the renderer's look, which scene files store.
   * The controllers listen, so a loaded scene's look shows as soon as it applies.
   */
  private lookControls(): void {
    const renderer = this.playground.renderer;
    const folder = this.gui.addFolder('Look');
    const m: Record<string, unknown> = {};
    this.field(m, 'exposure', () => renderer.exposure, (v: number) => { renderer.exposure = v; });
    this.field(m, 'toneMapping', () => renderer.toneMapping, (v: ToneMapping) => { renderer.toneMapping = v; });
    this.field(m, 'dithering', () => renderer.dithering, (v: Dithering) => { renderer.dithering = v; });
    this.field(m, 'lightmapBlur', () => renderer.lightmapBlur, (v: number) => { renderer.lightmapBlur = v; });
    // Sliders over the useful ranges (a value typed outside is clamped to them); a loaded file's value shows as it is.
    folder.add(m, 'exposure', 0.1, 4, 0.05).listen();
    // The library's constants as the menus: a curve or dithering added to them shows here too.
    folder.add(m, 'toneMapping', ToneMapping).name('tone mapping').listen();
    folder.add(m, 'dithering', Dithering).listen();
    folder.add(m, 'lightmapBlur', 0, 32, 1).name('lightmap blur').listen();
    if (window.innerHeight < SHORT_SCREEN) folder.close();
  }

  /**
   * Hulls from content: tile mode with its tile size, and tracing an image (picked, or dropped on
   * the view) with its tolerance and what the last trace did. Returns the tile-mode button.
   */
  private contentControls(): Controller {
    const { editor, tracer } = this;
    const folder = this.gui.addFolder('Hulls from content');
    const buttons = { paint: () => { editor.painting = !editor.painting; }, trace: () => this.actions.pickImage() };
    const paintTiles = folder.add(buttons, 'paint').name(PAINT_LABELS.start);
    folder.add(editor.painter, 'tileSize', [...TILE_SIZES]).name('tile size');
    folder.add(buttons, 'trace').name('trace image… (or drop a PNG)');
    const m: Record<string, unknown> = {};
    // Not a scene edit: a refused value is shown, an accepted one applies to the next trace.
    bind(m, 'tolerance', () => tracer.tolerance, (v: number) => {
      try {
        tracer.tolerance = v;
      } catch (error) {
        this.actions.showError((error as Error).message);
      }
    });
    bind(m, 'traced', () => tracer.status, () => undefined);
    number(folder, m, 'tolerance', 2);
    folder.add(m, 'traced').name('last image').disable().listen();
    if (window.innerHeight < SHORT_SCREEN) folder.close();
    return paintTiles;
  }

  /**
   * Tells the camera how much of the page's right the panel covers, so that the view centres in
   * the rest: all of its width when open, nothing when collapsed to its title (click the title to
   * collapse or open it; it opens collapsed on narrow screens). Measured when the panel opens or
   * closes and when the window resizes, not every frame.
   */
  private measureCovered(): void {
    // `_closed` is what lil-gui's own onOpenClose example reads: the class changes after the callback.
    this.playground.camera.insetRight = this.gui._closed ? 0 : window.innerWidth - this.gui.domElement.getBoundingClientRect().left;
  }

  /** Shows a preset's name in the menu without loading it again; any other text (a file's name) shows as it is. */
  showPreset(name: string): void {
    this.settings.preset = name;
    this.gui.controllersRecursive().forEach((controller) => controller.updateDisplay());
  }

  private showSelection(): void {
    this.selectionFolder?.destroy();
    const selected = this.playground.selection;
    this.selectionFolder = null;
    this.pickButton = null;
    if (!selected) return;
    const folder = this.gui.addFolder(selected instanceof Hull ? 'Selected hull' : `Selected ${selected.kind} light`);
    this.selectionFolder = folder;
    if (selected instanceof Hull) this.hullControls(folder, selected);
    else this.lightControls(folder, selected);
  }

  /** Binds a field, reporting a rejected value (RangeError naming the field) instead of throwing. */
  private field<T>(model: Record<string, unknown>, key: string, get: () => T, set: (value: T) => void): void {
    bind(model, key, get, (value: T) => {
      try {
        set(value);
        this.playground.changed();
      } catch (error) {
        this.actions.showError((error as Error).message);
      }
    });
  }

  private lightControls(folder: GUI, light: Light): void {
    const m: Record<string, unknown> = {};
    this.field(m, 'enabled', () => light.enabled, (v: boolean) => { light.enabled = v; });
    this.field(m, 'castsShadows', () => light.castsShadows, (v: boolean) => { light.castsShadows = v; });
    this.field(m, 'rotation°', () => light.rotation * DEGREES, (v: number) => { light.rotation = v / DEGREES; });
    this.field(m, 'color', () => toHex(light.color), (v: string) => { light.color = fromHex(v); });
    this.field(m, 'intensity', () => light.intensity, (v: number) => { light.intensity = v; });
    this.field(m, 'shadowType', () => light.shadowType, (v: ShadowType) => { light.shadowType = v; });
    this.field(m, 'shadowColor', () => toHex(light.shadowColor), (v: string) => { light.shadowColor = fromHex(v); });
    this.field(m, 'shadowStrength', () => light.shadowStrength, (v: number) => { light.shadowStrength = v; });
    folder.add(m, 'enabled').listen();
    folder.add(m, 'castsShadows').listen();
    if (light instanceof DirectionalLight) this.sunControls(folder, m, light);
    else this.placeControls(folder, m, light);
    folder.addColor(m, 'color').listen();
    number(folder, m, 'intensity', 2);
    // ShadowType itself is the menu (its entries): a type added to the library shows here too.
    folder.add(m, 'shadowType', ShadowType).listen();
    folder.addColor(m, 'shadowColor').listen();
    folder.add(m, 'shadowStrength', 0, 1, 0.01).listen();
    this.ignoredHullsControls(folder, light);
    if (light instanceof Spotlight) {
      this.field(m, 'coneAngle°', () => light.coneAngle * DEGREES, (v: number) => { light.coneAngle = v / DEGREES; });
      this.field(m, 'coneDecay', () => light.coneDecay, (v: number) => { light.coneDecay = v; });
      number(folder, m, 'coneAngle°', 1);
      number(folder, m, 'coneDecay', 2);
    }
    if (light instanceof TexturedLight) {
      const cookies = this.playground.cookies;
      this.field(m, 'cookie', () => cookies.nameOf(light.texture), (v: string) => { light.texture = cookies.resolve(v)!; });
      this.field(m, 'width', () => light.size[0], (v: number) => { light.size = [v, light.size[1]]; });
      this.field(m, 'height', () => light.size[1], (v: number) => { light.size = [light.size[0], v]; });
      folder.add(m, 'cookie', [...cookies.names]).listen();
      number(folder, m, 'width', 1);
      number(folder, m, 'height', 1);
    }
    this.layerControls(folder, 'shadow layers', () => light.shadowLayers, (mask) => { light.shadowLayers = mask; });
    const litLayers = this.layerControls(folder, 'lit layers', () => light.litLayers, (mask) => { light.litLayers = mask; });
    hint(litLayers, 'The content layers this light lights (renderer.draw(layers)). The playground draws every layer at once, '
      + 'so here it changes nothing on screen: it is saved with the scene, for games that draw layers apart.');
  }

  /**
   * Where a light with a position is and how far it reaches: position, range, radius, rotation and
   * origin, and the falloff of the lights that have one (textured lights' cookies replace it).
   * `m` holds the shared `rotation°` field.
   */
  private placeControls(folder: GUI, m: Record<string, unknown>, light: Light): void {
    this.field(m, 'x', () => light.position[0], (v: number) => light.setPosition(v, light.position[1]));
    this.field(m, 'y', () => light.position[1], (v: number) => light.setPosition(light.position[0], v));
    this.field(m, 'range', () => light.range, (v: number) => { light.range = v; });
    this.field(m, 'radius', () => light.radius, (v: number) => { light.radius = v; });
    this.field(m, 'originX', () => light.origin[0], (v: number) => { light.origin = [v, light.origin[1]]; });
    this.field(m, 'originY', () => light.origin[1], (v: number) => { light.origin = [light.origin[0], v]; });
    number(folder, m, 'x', 1);
    number(folder, m, 'y', 1);
    number(folder, m, 'range', 1);
    number(folder, m, 'radius', 1);
    if (light instanceof PointLight || light instanceof Spotlight) {
      this.field(m, 'falloff', () => light.falloff, (v: Falloff) => { light.falloff = v; });
      // Falloff itself is the menu, as ShadowType is.
      folder.add(m, 'falloff', Falloff).listen();
    }
    number(folder, m, 'rotation°', 1);
    number(folder, m, 'originX', 2);
    number(folder, m, 'originY', 2);
  }

  /**
   * A sun's direction and size: it has no position, range, radius or origin. `m` holds the shared
   * `rotation°` field, which its compass (bottom left of the view) also turns.
   */
  private sunControls(folder: GUI, m: Record<string, unknown>, sun: DirectionalLight): void {
    this.field(m, 'angularSize', () => sun.angularSize, (v: number) => { sun.angularSize = v; });
    hint(number(folder, m, 'rotation°', 1), 'The direction the light travels: shadows fall that way (0° is +x, 90° is down). Or drag the sun\'s compass, bottom left.');
    // A slider over the useful range (a value typed beyond it is clamped to it); a loaded file's
    // wider size (up to π/2) shows as it is. Steps of 0.0001 show the sun's 0.0093 as it is.
    const size = folder.add(m, 'angularSize', 0, MAX_SLIDER_ANGULAR_SIZE, 0.0001).listen();
    hint(size, 'Apparent diameter of the light\'s disk, radians: 0.0093 is the sun\'s; wider gives softer shadows, 0 hard ones.');
  }

  /**
   * How many hulls the light passes through, and a button that turns on picking them: clicks on
   * hulls then add or remove them (outlined orange while the light is selected).
   */
  private ignoredHullsControls(folder: GUI, light: Light): void {
    const m: Record<string, unknown> = { pick: () => { this.editor.pickingIgnoredOf = this.editor.pickingIgnoredOf ? null : light; } };
    bind(m, 'ignored', () => `${light.ignoredHulls.size} hull${light.ignoredHulls.size === 1 ? '' : 's'}`, () => undefined);
    folder.add(m, 'ignored').name('ignored hulls').disable().listen();
    this.pickButton = folder.add(m, 'pick');
    this.labelPickButton();
  }

  /**
   * A layer mask as a folder of checkboxes, one per layer below {@link LAYER_CHECKBOXES}, closed
   * with the mask summed up in its title. Only these checkboxes change a mask while its object is
   * selected (a loaded scene clears the selection), so the title follows their changes alone.
   * Returns the folder.
   */
  private layerControls(parent: GUI, label: string, get: () => number, set: (mask: number) => void): GUI {
    const folder = parent.addFolder(label).close();
    const showMask = () => folder.title(`${label}: ${describeLayers(get())}`);
    const m: Record<string, unknown> = {};
    for (let bit = 0; bit < LAYER_CHECKBOXES; bit++) {
      const key = `layer ${bit}`;
      this.field(m, key, () => hasLayer(get(), bit), (on: boolean) => set(withLayer(get(), bit, on)));
      folder.add(m, key).onChange(showMask);
    }
    showMask();
    return folder;
  }

  private labelPickButton(): void {
    this.pickButton?.name(this.editor.pickingIgnoredOf ? 'done picking (Esc)' : 'pick ignored hulls (click hulls)');
  }

  private hullControls(folder: GUI, hull: Hull): void {
    const m: Record<string, unknown> = {};
    this.field(m, 'enabled', () => hull.enabled, (v: boolean) => { hull.enabled = v; });
    this.field(m, 'x', () => hull.position[0], (v: number) => hull.setPosition(v, hull.position[1]));
    this.field(m, 'y', () => hull.position[1], (v: number) => hull.setPosition(hull.position[0], v));
    this.field(m, 'originX', () => hull.origin[0], (v: number) => { hull.origin = [v, hull.origin[1]]; });
    this.field(m, 'originY', () => hull.origin[1], (v: number) => { hull.origin = [hull.origin[0], v]; });
    this.field(m, 'rotation°', () => hull.rotation * DEGREES, (v: number) => { hull.rotation = v / DEGREES; });
    this.field(m, 'scaleX', () => hull.scale[0], (v: number) => { hull.scale = [v, hull.scale[1]]; });
    this.field(m, 'scaleY', () => hull.scale[1], (v: number) => { hull.scale = [hull.scale[0], v]; });
    this.field(m, 'points', () => JSON.stringify(hull.points), (v: string) => { hull.points = JSON.parse(v) as typeof hull.points; });
    // Off: an open polyline. Fixed when a hull is built: a rebuilt hull takes its place and the
    // selection, so this folder is replaced by the new hull's.
    bind(m, 'closed', () => hull.closed, (v: boolean) => this.playground.setHullClosed(hull, v));
    bind(m, 'valid', () => (hull.valid ? 'valid' : 'INVALID (ignored by the renderer)'), () => undefined);
    folder.add(m, 'enabled').listen();
    number(folder, m, 'x', 1);
    number(folder, m, 'y', 1);
    number(folder, m, 'originX', 1);
    number(folder, m, 'originY', 1);
    number(folder, m, 'rotation°', 1);
    number(folder, m, 'scaleX', 2);
    number(folder, m, 'scaleY', 2);
    folder.add(m, 'points').name('points (JSON)').listen();
    folder.add(m, 'valid').disable().listen();
    folder.add(m, 'closed');
    this.layerControls(folder, 'layers', () => hull.layers, (mask) => { hull.layers = mask; });
  }
}
