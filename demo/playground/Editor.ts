import { DirectionalLight, Hull, type Light } from 'penumbra-gl';
import { hullHit } from './hullShape';
import { LIGHT_HANDLE_RADIUS } from './Overlay';
import type { Playground, Selectable } from './Playground';
import { rotationTowards, sunUnder } from './sunCompass';
import type { TilePainter } from './TilePainter';

/** Keyboard panning speed in CSS pixels per second. */
const PAN_SPEED = 600;
/** Clicking this close (CSS pixels) to a new hull's first point closes it. */
const CLOSE_DISTANCE = 12;
/** A click this close (CSS pixels) to an open hull's line picks it. */
const OPEN_HULL_PICK_DISTANCE = 6;
const PAN_KEYS: Record<string, [number, number]> = {
  KeyW: [0, 1], ArrowUp: [0, 1], KeyS: [0, -1], ArrowDown: [0, -1],
  KeyA: [1, 0], ArrowLeft: [1, 0], KeyD: [-1, 0], ArrowRight: [-1, 0],
};

/** What a single-pointer drag is doing. */
type Drag =
  | { kind: 'move'; target: Selectable; offsetX: number; offsetY: number; moved: boolean }
  /** Turning a sun by its compass (centre in CSS pixels): its arrow follows the pointer. */
  | { kind: 'turn'; sun: DirectionalLight; centre: [number, number]; moved: boolean }
  | { kind: 'pan' }
  | { kind: 'paint' };

/**
 * Pointer and keyboard editing on the overlay canvas: click to select, drag lights and hulls
 * (mouse, pen or touch; an open hull is picked near its line), drag a sun's compass to turn it (its
 * arrow follows the pointer), drag empty space or press W/A/S/D or arrows to pan, wheel or pinch to
 * zoom, and in hull mode click points to draw a hull (click its first point, double-click or press
 * Enter to close; Escape cancels). While picking a light's ignored hulls, a click on a hull adds it
 * to them or takes it out (Escape ends). In tile mode a drag paints wall tiles, a right-drag or
 * Shift-drag erases them (Escape ends). Delete or Backspace removes the selection.
 */
export class Editor extends EventTarget {
  /** World points of the hull being drawn. */
  readonly draft: [number, number][] = [];
  /** Whether the hull being drawn would be valid (the renderer's own check). */
  draftValid = false;
  /** The world point under the pointer while it is over the view, or null. */
  hover: [number, number] | null = null;
  private _drawing = false;
  private _painting = false;
  /** The renderer's debug wireframe before tile mode turned it on. */
  private debugBefore = false;
  private _pickingIgnoredOf: Light | null = null;
  private readonly pointers = new Map<number, { x: number; y: number }>();
  private drag: Drag | null = null;
  private pinchDistance = 0;
  private readonly keys = new Set<string>();
  private readonly world: [number, number] = [0, 0];

  constructor(private readonly surface: HTMLElement, private readonly playground: Playground, readonly painter: TilePainter) {
    super();
    surface.addEventListener('pointerdown', this.onPointerDown);
    surface.addEventListener('pointermove', this.onPointerMove);
    surface.addEventListener('pointerup', this.onPointerUp);
    surface.addEventListener('pointercancel', this.onPointerUp);
    surface.addEventListener('dblclick', () => this.finishHull());
    surface.addEventListener('pointerleave', () => { this.hover = null; });
    surface.addEventListener('wheel', this.onWheel, { passive: false });
    // A right-drag erases tiles: no context menu in tile mode.
    surface.addEventListener('contextmenu', (event) => { if (this._painting) event.preventDefault(); });
    // Escape in the capture phase: the panel stops some keys from propagating, and Escape must end a mode wherever the focus is.
    window.addEventListener('keydown', this.onEscape, true);
    window.addEventListener('keydown', this.onKeyDown);
    window.addEventListener('keyup', (event) => this.keys.delete(event.code));
    window.addEventListener('blur', () => this.keys.clear());
    // Picking belongs to the selected light: selecting anything else ends it.
    playground.addEventListener('selection', () => {
      if (this._pickingIgnoredOf && playground.selection !== this._pickingIgnoredOf) this.pickingIgnoredOf = null;
    });
  }

  /** Whether clicks add points to a new hull instead of selecting. Fires `mode` on change. */
  get drawing(): boolean {
    return this._drawing;
  }
  set drawing(value: boolean) {
    if (value) {
      this._pickingIgnoredOf = null;
      this.leavePainting();
    }
    this._drawing = value;
    this.draft.length = 0;
    this.draftValid = false;
    if (value) this.playground.selection = null;
    this.dispatchEvent(new Event('mode'));
  }

  /**
   * The light whose ignored hulls clicks on hulls toggle, or null. Fires `mode` on change; drawing
   * a hull and picking exclude each other.
   */
  get pickingIgnoredOf(): Light | null {
    return this._pickingIgnoredOf;
  }
  set pickingIgnoredOf(light: Light | null) {
    if (light && this._drawing) this.drawing = false;
    if (light) this.leavePainting();
    this._pickingIgnoredOf = light;
    this.dispatchEvent(new Event('mode'));
  }

  /**
   * Whether drags paint wall tiles (the painter's tile size) instead of selecting and moving. Turns
   * the renderer's debug wireframe on while it lasts. Fires `mode` on change.
   */
  get painting(): boolean {
    return this._painting;
  }
  set painting(value: boolean) {
    if (value === this._painting) return;
    if (value) {
      if (this._drawing) this.drawing = false;
      this._pickingIgnoredOf = null;
      this.playground.selection = null;
      this.debugBefore = this.playground.renderer.debug;
      this.playground.renderer.debug = true;
    } else {
      this.painter.end();
      if (this.drag?.kind === 'paint') this.drag = null;
      this.playground.renderer.debug = this.debugBefore;
    }
    this._painting = value;
    this.dispatchEvent(new Event('mode'));
  }

  private leavePainting(): void {
    if (this._painting) this.painting = false;
  }

  /** Turns the hull being drawn into a hull (even an invalid one: it is kept and shown as invalid). */
  finishHull(): void {
    if (!this._drawing || this.draft.length < 3) return;
    const points = this.draft.slice();
    this.drawing = false;
    this.playground.addHull(points);
  }

  /** Applies held pan keys for `dt` seconds. */
  update(dt: number): void {
    for (const code of this.keys) {
      const direction = PAN_KEYS[code];
      if (direction) this.playground.camera.panBy(direction[0] * PAN_SPEED * dt, direction[1] * PAN_SPEED * dt);
    }
  }

  /**
   * The light or hull in the world under a canvas point (CSS pixels): lights with a position first,
   * topmost first (suns have none: their compasses are picked by {@link sunUnder}).
   */
  pick(x: number, y: number): Selectable | null {
    const { camera, renderer } = this.playground;
    const [wx, wy] = camera.screenToWorld(x, y, this.world);
    const lights = renderer.lights;
    const reach = LIGHT_HANDLE_RADIUS / camera.zoom;
    for (let i = lights.length - 1; i >= 0; i--) {
      if (lights[i] instanceof DirectionalLight) continue;
      const [lx, ly] = lights[i].position;
      if ((lx - wx) ** 2 + (ly - wy) ** 2 <= reach * reach) return lights[i];
    }
    const hulls = renderer.hulls;
    const lineReach = OPEN_HULL_PICK_DISTANCE / camera.zoom;
    for (let i = hulls.length - 1; i >= 0; i--) if (hullHit(hulls[i], wx, wy, lineReach)) return hulls[i];
    return null;
  }

  private readonly onPointerDown = (event: PointerEvent): void => {
    this.surface.setPointerCapture(event.pointerId);
    this.pointers.set(event.pointerId, { x: event.offsetX, y: event.offsetY });
    if (this.pointers.size === 2) {
      this.drag = null;
      this.painter.end();
      this.pinchDistance = this.pointerSpread().distance;
      return;
    }
    if (this.pointers.size > 2) return;
    if (this._drawing) {
      this.addDraftPoint(event.offsetX, event.offsetY);
      return;
    }
    if (this._painting) {
      const [wx, wy] = this.playground.camera.screenToWorld(event.offsetX, event.offsetY, this.world);
      this.painter.begin(wx, wy, !(event.button === 2 || event.shiftKey));
      this.drag = { kind: 'paint' };
      return;
    }
    // The compasses lie over the world, so they are picked first.
    const compass = sunUnder(this.playground.renderer.lights, this.playground.camera.height, event.offsetX, event.offsetY);
    if (compass) {
      this.playground.selection = compass.sun;
      this.drag = { kind: 'turn', ...compass, moved: false };
      return;
    }
    const target = this.pick(event.offsetX, event.offsetY);
    if (this._pickingIgnoredOf && target instanceof Hull) {
      this.toggleIgnored(this._pickingIgnoredOf, target);
      return;
    }
    this.playground.selection = target;
    if (!target) {
      this.drag = { kind: 'pan' };
      return;
    }
    const [wx, wy] = this.playground.camera.screenToWorld(event.offsetX, event.offsetY, this.world);
    this.drag = { kind: 'move', target, offsetX: target.position[0] - wx, offsetY: target.position[1] - wy, moved: false };
  };

  private readonly onPointerMove = (event: PointerEvent): void => {
    this.hover = this.playground.camera.screenToWorld(event.offsetX, event.offsetY, this.hover ?? [0, 0]);
    const previous = this.pointers.get(event.pointerId);
    if (!previous) return;
    const dx = event.offsetX - previous.x, dy = event.offsetY - previous.y;
    previous.x = event.offsetX;
    previous.y = event.offsetY;
    const camera = this.playground.camera;
    if (this.pointers.size === 2) {
      const { distance, x, y } = this.pointerSpread();
      camera.panBy(dx / 2, dy / 2);
      if (this.pinchDistance > 0 && distance > 0) camera.zoomAt(x, y, distance / this.pinchDistance);
      this.pinchDistance = distance;
      return;
    }
    const drag = this.drag;
    if (!drag) return;
    if (drag.kind === 'pan') {
      camera.panBy(dx, dy);
      return;
    }
    if (drag.kind === 'turn') {
      drag.sun.rotation = rotationTowards(drag.centre, event.offsetX, event.offsetY);
      drag.moved = true;
      return;
    }
    const [wx, wy] = camera.screenToWorld(event.offsetX, event.offsetY, this.world);
    if (drag.kind === 'paint') {
      this.painter.moveTo(wx, wy);
      return;
    }
    drag.target.setPosition(wx + drag.offsetX, wy + drag.offsetY);
    // Hulls traced from one image move together.
    if (drag.target instanceof Hull) for (const other of this.playground.companionsOf(drag.target)) other.setPosition(wx + drag.offsetX, wy + drag.offsetY);
    drag.moved = true;
  };

  private readonly onPointerUp = (event: PointerEvent): void => {
    this.pointers.delete(event.pointerId);
    if ((this.drag?.kind === 'move' || this.drag?.kind === 'turn') && this.drag.moved) this.playground.changed();
    if (this.drag?.kind === 'paint') this.painter.end();
    if (this.pointers.size === 0) this.drag = null;
  };

  private readonly onWheel = (event: WheelEvent): void => {
    event.preventDefault();
    this.playground.camera.zoomAt(event.offsetX, event.offsetY, Math.exp(-event.deltaY * 0.0015));
  };

  /** Escape ends hull drawing, tile painting or picking, from any focus; otherwise it clears the selection, but not while typing in a field. */
  private readonly onEscape = (event: KeyboardEvent): void => {
    if (event.key !== 'Escape') return;
    if (this._drawing) this.drawing = false;
    else if (this._painting) this.painting = false;
    else if (this._pickingIgnoredOf) this.pickingIgnoredOf = null;
    else if (!isTextField(event.target)) this.playground.selection = null;
  };

  private readonly onKeyDown = (event: KeyboardEvent): void => {
    // Typing into the panel's fields must not pan or delete.
    if (isTextField(event.target)) return;
    if (event.code in PAN_KEYS) {
      this.keys.add(event.code);
      event.preventDefault();
    } else if (event.key === 'Enter') {
      this.finishHull();
    } else if (event.key === 'Delete' || event.key === 'Backspace') {
      this.playground.deleteSelection();
    }
  };

  private toggleIgnored(light: Light, hull: Hull): void {
    if (!light.ignoredHulls.delete(hull)) light.ignoredHulls.add(hull);
    this.playground.changed();
  }

  private addDraftPoint(x: number, y: number): void {
    const camera = this.playground.camera;
    if (this.draft.length >= 3) {
      const [fx, fy] = camera.worldToScreen(this.draft[0][0], this.draft[0][1], this.world);
      if (Math.hypot(fx - x, fy - y) <= CLOSE_DISTANCE) {
        this.finishHull();
        return;
      }
    }
    const [wx, wy] = camera.screenToWorld(x, y, this.world);
    this.draft.push([wx, wy]);
    this.draftValid = new Hull(this.draft).valid;
  }

  /** Distance between the two active pointers and their midpoint. */
  private pointerSpread(): { distance: number; x: number; y: number } {
    const [a, b] = [...this.pointers.values()];
    return { distance: Math.hypot(a.x - b.x, a.y - b.y), x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
  }
}

/** Whether keys typed at `target` are text (a field of the panel). */
function isTextField(target: EventTarget | null): boolean {
  return target instanceof HTMLInputElement || target instanceof HTMLTextAreaElement;
}
