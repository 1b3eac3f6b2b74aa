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

/**
 * Phaser only: a tilemap layer of three tiles (SPRITE_SIZE square) from a tileset of two, whose normal
 * map (the tileset texture's data source) is NORMAL_TEXEL on the first tile and, on the second,
 * TOP_TEXEL in its top rows and FLAT_TEXEL below. World centres: the first tile (T), the first tile flipped left–right (F), the second tile (S),
 * the first tile turned a quarter clockwise (R; a TilemapLayer's tile rotation: a TilemapGPULayer has none).
 */
export const TILES = { mapped: [84, 84], flipped: [108, 84], flat: [132, 84], rotated: [60, 84] } as const satisfies Record<string, readonly [number, number]>;
/**
 * The layer's data: the tiles in row 3, columns 2 (R) and 3 to 5, the rest empty. The layer sits at the world's
 * origin: Phaser 4.2.1's TilemapGPULayer counts its position twice (SubmitterTilemapGPULayer).
 */
export const TILE_DATA: readonly (readonly number[])[] = [
  [-1, -1, -1, -1, -1, -1], [-1, -1, -1, -1, -1, -1], [-1, -1, -1, -1, -1, -1], [-1, -1, 0, 0, 0, 1],
];
/** The second tile's normal below its top TOP_ROWS rows: straight up out of the image. */
export const FLAT_TEXEL: readonly [number, number, number] = [128, 128, 255];
/** The second tile's normal in its top TOP_ROWS rows (the tile's top, the right way up): (0, −0.6, 0.8), facing up the image. */
export const TOP_TEXEL: readonly [number, number, number] = [128, 204, 230];
export const TOP_ROWS = 8;

/**
 * Both engines: a sprite with the normal map in a lit group of layers GROUP_LAYERS, lit by the
 * ambient light and a directional light of those layers only; the world's light and lighting layer
 * have WORLD_LAYERS.
 */
export const GROUPED: readonly [number, number] = [140, 40];
export const WORLD_LAYERS = 0b01;
export const GROUP_LAYERS = 0b10;

/** What the page is asked to draw. */
export interface NormalsState {
  /** Rotation of sprite N, radians. */
  rotation: number;
  /** Whether sprite N is mirrored left–right (Pixi: scale.x −1; Phaser: flipX). */
  mirrored: boolean;
  /** Direction the world's directional light travels, radians (π: from the east). */
  lightRotation: number;
  /** Direction the group's directional light travels, radians. */
  groupLightRotation: number;
  /** Phaser: the tiles are drawn by a TilemapGPULayer rather than a TilemapLayer. */
  gpuTilemap: boolean;
  /** The camera's scroll (world point at the canvas's top-left) and zoom. */
  scroll: [number, number];
  zoom: number;
}

export type Engine = 'pixi' | 'phaser';

/** GL objects made (createTexture, createFramebuffer, createBuffer, createVertexArray, createProgram, createRenderbuffer). */
type Created = number;

/** What main.ts puts on `window`. */
interface EngineNormalsPage {
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
interface ContextLossReport {
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
