// The level shared by the engine examples: walls (which are also the hulls), lamps, the player's
// movement with wall collisions, and the test hook the browser tests drive.

/** An axis-aligned wall in world units: x, y, width, height. */
export type Rect = readonly [number, number, number, number];

export const WORLD_WIDTH = 960;
export const WORLD_HEIGHT = 640;
/** Camera zoom (world units are drawn this many pixels wide), more in a window larger than the level. */
const ZOOM = 1.25;
export const PLAYER_RADIUS = 10;
export const PLAYER_SPEED = 160;
export const PLAYER_START: readonly [number, number] = [330, 300];

/** Width and height of a tile of the level's tile map, in world units. */
export const TILE_SIZE = 20;
const TILES_WIDE = WORLD_WIDTH / TILE_SIZE;
const TILES_HIGH = WORLD_HEIGHT / TILE_SIZE;

/** The walls, whole tiles each: the examples build them as a tile map, whose solid tiles are the hulls. */
const WALLS: readonly Rect[] = [
  [0, 0, WORLD_WIDTH, 20], [0, WORLD_HEIGHT - 20, WORLD_WIDTH, 20],
  [0, 0, 20, WORLD_HEIGHT], [WORLD_WIDTH - 20, 0, 20, WORLD_HEIGHT],
  [400, 140, 40, 320], [600, 20, 40, 200], [620, 420, 200, 40], [120, 440, 140, 40], [160, 140, 60, 60],
];

/** The level as a tile map, row by row: 1 for a wall tile, 0 for floor. A fresh copy on each call. */
export function levelTiles(): number[][] {
  const rows = Array.from({ length: TILES_HIGH }, () => new Array<number>(TILES_WIDE).fill(0));
  for (const [x, y, w, h] of WALLS) {
    for (let ty = y / TILE_SIZE; ty < (y + h) / TILE_SIZE; ty++) {
      for (let tx = x / TILE_SIZE; tx < (x + w) / TILE_SIZE; tx++) rows[ty][tx] = 1;
    }
  }
  return rows;
}

/** The prop: a sprite whose hulls are traced from its image's alpha; it turns slowly where it stands. */
export const PROP_POSITION: readonly [number, number] = [530, 330];
/** Size of the prop's image in pixels (drawn 1:1 in world units). */
export const PROP_SIZE = 48;
/** Turn rate of the prop, radians per second. */
export const PROP_SPIN = 0.4;

/**
 * The prop's image, drawn in code: a five-pointed star with a round hole, RGBA bytes (an `ImageData`
 * in the browser). Its alpha is what the hulls are traced from: the hole lets light through.
 */
export function propImage(): ImageData {
  const size = PROP_SIZE;
  const data = new Uint8ClampedArray(size * size * 4);
  const centre = size / 2;
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const dx = x + 0.5 - centre, dy = y + 0.5 - centre;
      const distance = Math.hypot(dx, dy);
      const angle = Math.atan2(dy, dx) + Math.PI / 2;
      // A star: the outer radius swings between 10 and 23 pixels five times around.
      const outline = 10 + 13 * Math.abs(Math.cos((angle * 5) / 2)) ** 2;
      const solid = distance <= outline && distance >= 5;
      const i = (y * size + x) * 4;
      data[i] = 200;
      data[i + 1] = 170;
      data[i + 2] = 90;
      data[i + 3] = solid ? 255 : 0;
    }
  }
  return new ImageData(data, size, size);
}

/** The examples' ambient colour: what every lit thing gets without any light. */
export const AMBIENT_COLOR: readonly [number, number, number] = [0.08, 0.08, 0.12];

/**
 * Content layers (bit masks): the level is lit by the lamps and the flashlight (`litLayers` WORLD),
 * the player, drawn in a lit group of layers PLAYER, by its own torch only (`litLayers` PLAYER).
 */
export const WORLD_LAYER = 0b01;
export const PLAYER_LAYER = 0b10;

/** The player's torch, at the player: it lights the player's own drawing and nothing else. */
export const PLAYER_TORCH = { range: 45, radius: 2, color: [1, 0.85, 0.6] as [number, number, number], intensity: 1.1, castsShadows: false } as const;

/**
 * A glowing sign on the floor, world units (x, y, width, height), drawn after the lighting: unlit,
 * it keeps exactly SIGN_COLOR whatever the lights, and follows the camera as the level does.
 */
export const SIGN: Rect = [246, 220, 48, 18];
export const SIGN_COLOR = 0xff2d6f;

/** Lamps: position and colour. */
export const LAMPS: readonly { position: [number, number]; color: [number, number, number] }[] = [
  { position: [120, 90], color: [1, 0.75, 0.45] },
  { position: [820, 110], color: [0.5, 0.7, 1] },
  { position: [760, 560], color: [0.6, 1, 0.6] },
];

/** Colour of the HUD badge, drawn after the lighting: the tests expect exactly these bytes. */
export const HUD_COLOR = 0x33cc66;

/** Which movement keys are held. */
export class Keys {
  private readonly held = new Set<string>();

  constructor(target: Window) {
    target.addEventListener('keydown', (event) => this.held.add(event.key.toLowerCase()));
    target.addEventListener('keyup', (event) => this.held.delete(event.key.toLowerCase()));
  }

  /** Unit-less direction from WASD / arrows, each axis −1..1. */
  direction(out: [number, number]): [number, number] {
    const h = this.held;
    out[0] = (h.has('d') || h.has('arrowright') ? 1 : 0) - (h.has('a') || h.has('arrowleft') ? 1 : 0);
    out[1] = (h.has('s') || h.has('arrowdown') ? 1 : 0) - (h.has('w') || h.has('arrowup') ? 1 : 0);
    return out;
  }
}

/** Moves `position` by `dx`, `dy`, one axis at a time so that the player slides along walls. */
export function moveWithCollisions(position: [number, number], dx: number, dy: number): void {
  position[0] += dx;
  if (hitsWall(position)) position[0] -= dx;
  position[1] += dy;
  if (hitsWall(position)) position[1] -= dy;
}

function hitsWall([x, y]: readonly [number, number]): boolean {
  for (const [wx, wy, ww, wh] of WALLS) {
    const nearestX = Math.max(wx, Math.min(x, wx + ww));
    const nearestY = Math.max(wy, Math.min(y, wy + wh));
    if ((x - nearestX) ** 2 + (y - nearestY) ** 2 < PLAYER_RADIUS ** 2) return true;
  }
  return false;
}

/** The camera: zoom, and scroll (top-left of the view, in world units). */
export interface View {
  zoom: number;
  scroll: [number, number];
}

/** How far the mouse wheel zooms in: the zoom factor's range, and its step per wheel notch. */
const ZOOM_FACTOR_MAX = 3;
const ZOOM_FACTOR_STEP = 1.1;

/** The zoom factor after a wheel event of `deltaY` (negative: zoom in), within 1..{@link ZOOM_FACTOR_MAX}. */
export function zoomFactorAfterWheel(factor: number, deltaY: number): number {
  const next = deltaY < 0 ? factor * ZOOM_FACTOR_STEP : deltaY > 0 ? factor / ZOOM_FACTOR_STEP : factor;
  return Math.min(Math.max(next, 1), ZOOM_FACTOR_MAX);
}

/**
 * The camera for a canvas of `width` × `height` CSS pixels (the examples fill the window): at least
 * {@link ZOOM}, more where the window is larger than the level so that the level still fills it,
 * times `zoomFactor` (the mouse wheel's, 1 or more); centred on the player, but never past the
 * level's edges.
 */
export function followPlayer(player: readonly [number, number], width: number, height: number, out: View, zoomFactor = 1): View {
  const zoom = Math.max(ZOOM, width / WORLD_WIDTH, height / WORLD_HEIGHT) * zoomFactor;
  const viewWidth = width / zoom;
  const viewHeight = height / zoom;
  out.zoom = zoom;
  out.scroll[0] = Math.min(Math.max(player[0] - viewWidth / 2, 0), WORLD_WIDTH - viewWidth);
  out.scroll[1] = Math.min(Math.max(player[1] - viewHeight / 2, 0), WORLD_HEIGHT - viewHeight);
  return out;
}

/** What the browser tests drive, as `window.penumbraExample`. */
interface ExampleHook {
  /** Puts the player at a world position (the camera follows). */
  setPlayer(x: number, y: number): void;
  /** Renders one frame now and reads back canvas pixels at CSS coordinates (top-left origin). */
  renderAndRead(points: readonly (readonly [number, number])[]): [number, number, number, number][];
  /** Resolves after `count` animation frames. */
  frames(count: number): Promise<void>;
  /** Removes the lighting plugin; returns whether it left no GL error behind. */
  removeLighting(): boolean;
  /** The canvas: its CSS size, and its drawing buffer's size (the engine resizes both with the window). */
  canvasSize(): { css: [number, number]; buffer: [number, number] };
  /** Makes tile (x, y) of the level's tile map a wall or floor, through the engine's own tile map API where it has one. */
  setTile(x: number, y: number, solid: boolean): void;
  /** Places the prop sprite (world position, rotation in radians, scale, mirrored left–right) and stops its spinning. */
  setProp(x: number, y: number, rotation: number, scale: number, flipX: boolean): void;
  /** Sets the mouse wheel's zoom factor (1 to {@link ZOOM_FACTOR_MAX}); the camera takes it at the next update. */
  setZoom(factor: number): void;
  /**
   * Lights the prop through its normal map, or flat (for tests of its shadow, whose lit points
   * would otherwise depend on which way the relief faces). Examples whose prop has no map of its
   * own leave it out.
   */
  setPropRelief?(on: boolean): void;
}

declare global {
  interface Window {
    penumbraExample?: ExampleHook;
  }
}

/** Reads RGBA bytes of the drawing buffer at CSS pixel coordinates (top-left origin). */
export function readPixels(gl: WebGL2RenderingContext, points: readonly (readonly [number, number])[]): [number, number, number, number][] {
  const canvas = gl.canvas as HTMLCanvasElement;
  const scale = gl.drawingBufferWidth / canvas.clientWidth;
  const pixel = new Uint8Array(4);
  return points.map(([x, y]) => {
    gl.readPixels(Math.floor(x * scale), gl.drawingBufferHeight - 1 - Math.floor(y * scale), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return [pixel[0], pixel[1], pixel[2], pixel[3]];
  });
}

/** See {@link ExampleHook.canvasSize}. */
export function canvasSize(gl: WebGL2RenderingContext): { css: [number, number]; buffer: [number, number] } {
  const canvas = gl.canvas as HTMLCanvasElement;
  return { css: [canvas.clientWidth, canvas.clientHeight], buffer: [gl.drawingBufferWidth, gl.drawingBufferHeight] };
}

/** Resolves after `count` animation frames. */
export function waitFrames(count: number): Promise<void> {
  return new Promise((done) => {
    const step = (left: number): void => {
      if (left <= 0) done();
      else requestAnimationFrame(() => step(left - 1));
    };
    step(count);
  });
}
