import { writeScene, type FrameStats, type Hull } from 'penumbra-gl';
import type { Editor } from './Editor';
import { hullWorldPoint } from './hullShape';
import type { ImageTracer } from './ImageTracer';
import type { Playground } from './Playground';
import { PRESETS } from './presets';
import type { OverlayFigures, StatsOverlay } from './StatsOverlay';
import { compassCentre } from './sunCompass';

/** What the page exposes as `window.playground`, so browser tests can drive it without brittle clicks. */
interface PlaygroundTestHook {
  /** Preset names, in menu order. */
  readonly presets: string[];
  /** Loads a preset by name. */
  selectPreset(name: string): void;
  /** Loads scene-file text as the file picker would; returns whether it loaded (on failure the page shows the error). */
  loadScene(text: string): boolean;
  /** The current scene as scene-file text (what "save" downloads). */
  sceneText(): string;
  /** The error message shown, or null when none is. */
  errorMessage(): string | null;
  /** Turns the animation (spotlight sweep, walkers) on or off, for deterministic pictures. */
  setAnimation(on: boolean): void;
  /** The canvas point (CSS pixels) of a world point. */
  worldToScreen(x: number, y: number): [number, number];
  /** The canvas point (CSS pixels) of the centre of the compass of sun `index` (the directional lights in the renderer's order). */
  sunCompass(index: number): [number, number];
  /** Draws a frame now and returns the canvas colour (0..255 RGB) at a CSS pixel point. */
  readPixel(x: number, y: number): [number, number, number];
  /** Draws a frame now and returns the whole canvas, RGBA bytes bottom row first, base64-encoded. */
  readFrame(): string;
  /** `gl.getError()` after a frame: 0 when WebGL reported nothing. */
  glError(): number;
  /** The renderer's stats of a frame drawn now (the last animation frame may predate a change). */
  rendererStats(): FrameStats;
  /** The overlay's figures (fps, mean CPU time per frame, counts). */
  overlayFigures(): OverlayFigures;
  /** Each hull's points in world units, in the renderer's order. */
  hullOutlines(): [number, number][][];
  /** A number per hull object, in the renderer's order: the same hull keeps its number, a new one gets a new number. */
  hullIds(): number[];
  /** Whether the renderer's debug wireframe is on. */
  debugWireframe(): boolean;
  /** Tile mode: whether it is on, and the tile size strokes paint. */
  tileMode(): { painting: boolean; tileSize: number };
  /** What the last image trace did, as the panel shows it. */
  traceStatus(): string;
  /** Draws a frame now and returns the gizmo overlay's alpha (0..255) at a CSS pixel point. */
  overlayAlpha(x: number, y: number): number;
  /** Puts the view's centre on a world point at a zoom (CSS pixels per world unit). */
  setCamera(x: number, y: number, zoom: number): void;
  /** Changes light `index` (the renderer's order): enabled, position (lights with one), intensity. */
  setLight(index: number, fields: { enabled?: boolean; position?: [number, number]; intensity?: number }): void;
  /** Whether the scene is the showcase level, and its daylight (0 night, 1 noon). */
  showcase(): { active: boolean; daylight: number };
}

/** Dependencies of the test hook. */
interface TestHookParts {
  playground: Playground;
  editor: Editor;
  tracer: ImageTracer;
  gizmos: HTMLCanvasElement;
  stats: StatsOverlay;
  message: HTMLElement;
  loadText(text: string, source: string): boolean;
  selectPreset(name: string): void;
  frame(): void;
}

declare global {
  interface Window {
    playground: PlaygroundTestHook;
  }
}

/** Installs `window.playground`. */
export function installTestHook(parts: TestHookParts): void {
  const { playground, editor, tracer, stats, message } = parts;
  const gl = playground.gl;
  const pixel = new Uint8Array(4);
  const ids = new WeakMap<Hull, number>();
  let nextId = 0;
  window.playground = {
    presets: Object.keys(PRESETS),
    selectPreset: parts.selectPreset,
    loadScene: (text) => parts.loadText(text, 'the scene'),
    sceneText: () => writeScene(playground.document()),
    errorMessage: () => (message.hidden ? null : message.textContent),
    setAnimation: (on) => { playground.animate = on; },
    worldToScreen: (x, y) => playground.camera.worldToScreen(x, y, [0, 0]),
    sunCompass: (index) => compassCentre(index, playground.camera.height, [0, 0]),
    readPixel(x, y) {
      parts.frame();
      const scale = gl.drawingBufferWidth / playground.camera.width;
      gl.readPixels(Math.floor(x * scale), gl.drawingBufferHeight - 1 - Math.floor(y * scale), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      return [pixel[0], pixel[1], pixel[2]];
    },
    readFrame() {
      parts.frame();
      const frame = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
      gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, frame);
      let binary = '';
      // In chunks: String.fromCharCode takes a bounded number of arguments.
      for (let i = 0; i < frame.length; i += 0x8000) binary += String.fromCharCode(...frame.subarray(i, i + 0x8000));
      return btoa(binary);
    },
    glError() {
      parts.frame();
      return gl.getError();
    },
    rendererStats() {
      parts.frame();
      return { ...playground.renderer.stats };
    },
    overlayFigures: () => ({ ...stats.figures }),
    hullOutlines: () => playground.renderer.hulls.map((hull) => hull.points.map((_, i) => hullWorldPoint(hull, i, [0, 0]))),
    hullIds: () => playground.renderer.hulls.map((hull) => {
      if (!ids.has(hull)) ids.set(hull, nextId++);
      return ids.get(hull)!;
    }),
    debugWireframe: () => playground.renderer.debug,
    tileMode: () => ({ painting: editor.painting, tileSize: editor.painter.tileSize }),
    traceStatus: () => tracer.status,
    overlayAlpha(x, y) {
      parts.frame();
      const scale = parts.gizmos.width / playground.camera.width;
      return parts.gizmos.getContext('2d')!.getImageData(Math.floor(x * scale), Math.floor(y * scale), 1, 1).data[3];
    },
    setCamera(x, y, zoom) {
      playground.camera.center[0] = x;
      playground.camera.center[1] = y;
      playground.camera.zoom = zoom;
    },
    setLight(index, { enabled, position, intensity }) {
      const light = playground.renderer.lights[index];
      if (enabled !== undefined) light.enabled = enabled;
      if (position) light.setPosition(...position);
      if (intensity !== undefined) light.intensity = intensity;
    },
    showcase: () => ({ active: playground.showcaseActive, daylight: playground.showcase.daylight }),
  };
}
