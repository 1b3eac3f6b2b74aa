// What the engine-setup page and its test share (no engine imported here: the test runs in Node).

/** Size of the engines' canvases, in pixels. */
export const CANVAS: readonly [number, number] = [200, 150];

/** Where the world's origin is on the canvas: both pages scroll their camera so. */
export const WORLD_ORIGIN: readonly [number, number] = [20, 10];

/** RGBA bytes of one pixel. */
export type Pixel = [number, number, number, number];

/** What an engine made of a game config or an application that has no WebGL2 context. */
export interface ContextReport {
  /** The message of the error the integration threw, or null. */
  error: string | null;
  /** Whether the engine's context was WebGL2 (`instanceof WebGL2RenderingContext`). */
  webgl2: boolean;
}

/** A game made through `penumbraGameConfig`: its context and pixels after a render. */
export interface LitGameReport extends ContextReport {
  /** The pixels at the points asked for, after one render. */
  pixels: Pixel[];
  /** Whether the config's own `callbacks.preBoot` ran. */
  ownPreBoot: boolean;
}

/** A change to the followed object; omitted fields stay. */
export interface CarrierChange {
  x?: number;
  y?: number;
  rotation?: number;
  scaleX?: number;
  scaleY?: number;
  visible?: boolean;
  /** Phaser only: the sprite's flipX. */
  flipX?: boolean;
}

/** How a light follows: `follow(carrier, light, { offset, rotation })`. */
export interface FollowOptions {
  offset: [number, number];
  rotation: number | null;
}

/** The light after one render, and pixels of the canvas. */
export interface FollowFrame {
  position: [number, number];
  rotation: number;
  enabled: boolean;
  /** Whether the light is in the renderer. */
  inRenderer: boolean;
  followers: number;
  /** Whether `light.position` is the same frozen pair as after the previous render: nothing was written. */
  positionKept: boolean;
  pixels: Pixel[];
}

/** One engine's following light, driven step by step. */
export interface FollowHost {
  /** Starts the engine with the followed object (the carrier) in its first state. */
  start(carrier: CarrierChange): Promise<void>;
  /** Makes the light follow the carrier (again). */
  follow(options: FollowOptions): void;
  /** Changes the followed object, renders once and reads `points` (canvas pixels). */
  frame(change: CarrierChange, points: readonly (readonly [number, number])[]): Promise<FollowFrame>;
  /** Stops following: `unfollow(light)`. Returns what it returned. */
  unfollow(): boolean;
  /** Destroys the followed object, renders once. */
  destroyCarrier(): Promise<FollowFrame>;
  /** Tears the engine down. */
  close(): void;
}

/** What main.ts puts on `window`. */
interface EngineSetupPage {
  /** Phaser 4 with its default game config (`type: AUTO`, no context) and the plugin. */
  phaserDefaultConfig(): Promise<ContextReport>;
  /** Phaser 4 through `penumbraGameConfig`, a light at world (x, y): the pixels at `points`. */
  phaserGameConfig(light: [number, number], points: readonly (readonly [number, number])[]): Promise<LitGameReport>;
  /** PixiJS asked for WebGL1 (`preferWebGLVersion: 1`), then a PenumbraLayer. */
  pixiWebGL1(): Promise<ContextReport>;
  /** An antialiased opaque canvas: PixiJS with `antialias: true`, Phaser given such a WebGL2 context. The errors thrown. */
  antialiasedOpaque(): Promise<{ pixi: string | null; phaser: string | null }>;
  pixi: FollowHost;
  phaser: FollowHost;
}

declare global {
  interface Window {
    engineSetup?: EngineSetupPage;
  }
}
