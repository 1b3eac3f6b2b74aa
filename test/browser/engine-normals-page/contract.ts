// What the engine-normals page and its test share (no engine imported here: the test runs in Node).

/** Size of each engine's canvas, in pixels. */
export const CANVAS: readonly [number, number] = [160, 120];
/** Side of the sprites, image pixels. */
export const SPRITE_SIZE = 24;
/** The sprites' colour, 0..255 (grey). */
export const ALBEDO = 200;
/** The ambient light, grey. */
export const AMBIENT = 0.1;
/** The directional light's elevation above the plane, radians. */
export const ELEVATION = Math.PI / 4;

/**
 * The normal map's one texel (every texel alike), RGB bytes, OpenGL-style (green up the image): the
 * normal (0.48, −0.36, 0.8) in image axes (x right, y down), facing right and up the image.
 */
export const NORMAL_TEXEL: readonly [number, number, number] = [189, 173, 230];

/** World centres of the sprites: N has the normal map; P has none; E has the normal map under a plain sprite of its size. */
export const SPRITES = { normal: [40, 40], plain: [100, 40], erased: [40, 90] } as const satisfies Record<string, readonly [number, number]>;

/** What the page is asked to draw. */
export interface NormalsState {
  /** Rotation of sprite N, radians. */
  rotation: number;
  /** Whether sprite N is mirrored left–right (Pixi: scale.x −1; Phaser: flipX). */
  mirrored: boolean;
  /** Direction the directional light travels, radians (π: from the east). */
  lightRotation: number;
  /** The camera's scroll (world point at the canvas's top-left) and zoom. */
  scroll: [number, number];
  zoom: number;
}

export type Engine = 'pixi' | 'phaser';

/** GL objects made (createTexture, createFramebuffer, createBuffer, createVertexArray, createProgram, createRenderbuffer). */
export type Created = number;

/** What main.ts puts on `window`. */
export interface EngineNormalsPage {
  /** Starts the engine (once), sets the state, renders one frame and returns RGBA at each canvas pixel. */
  read(engine: Engine, state: NormalsState, points: [number, number][]): Promise<[number, number, number, number][]>;
  /** GL objects made while rendering `frames` frames of the current state. */
  created(engine: Engine, frames: number): Promise<Created>;
  /**
   * Renders `state` and reads `points`, loses the context (WEBGL_lose_context), renders frames in
   * the window before the lost event and while lost, restores it, renders and reads again.
   */
  acrossContextLoss(engine: Engine, state: NormalsState, points: [number, number][]): Promise<ContextLossReport>;
}

/** What {@link EngineNormalsPage.acrossContextLoss} saw. */
export interface ContextLossReport {
  before: [number, number, number, number][];
  after: [number, number, number, number][];
  /** Errors thrown by frames rendered while the context was lost, each with when. */
  lostFrameErrors: string[];
  /** GL errors (getError) after the first frame of the restored context, other than none. */
  glErrors: number[];
}

declare global {
  interface Window {
    engineNormals?: EngineNormalsPage;
  }
}
