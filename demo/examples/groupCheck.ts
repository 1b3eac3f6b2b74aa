// What test/browser/pixiGroups.test.ts and phaserGroups.test.ts check in the engine examples'
// pages: a lit group's content against the lights of its layers, computed from the geometry here.
// Made by each page's group check on request, in the open floor east of the prop. Not part of the examples.
import type { LightOptions } from 'penumbra-gl';
import type { Rect } from './level';

/** Content layers of the check's lights, apart from the examples' WORLD and PLAYER layers. */
export const CHECK_LAYER_A = 1 << 4;
export const CHECK_LAYER_B = 1 << 5;

/** Where the player stands for the check (the camera follows it): west of the squares, clear of them. */
export const CHECK_PLAYER: readonly [number, number] = [700, 320];

/** A square in a group of layers A (x, y, width, height, world units), and its colour. */
export const LIT_SQUARE: Rect = [760, 250, 60, 60];
/** A square in a group of layers 0: the ambient colour only. */
export const AMBIENT_SQUARE: Rect = [850, 330, 50, 50];
export const SQUARE_COLOR = 0xc8c8c8;

/** Light A lights layer A; light B, which reaches both squares, layer B. Neither casts shadows. */
export const LIGHT_A = { position: [775, 265], range: 200, color: [1, 0.6, 0.3], intensity: 1, castsShadows: false, litLayers: CHECK_LAYER_A } satisfies LightOptions;
export const LIGHT_B = { position: [805, 300], range: 200, color: [0.3, 0.5, 1], intensity: 1, castsShadows: false, litLayers: CHECK_LAYER_B } satisfies LightOptions;

/** What both engines' group checks expose (`window.penumbraPixiGroups`, `window.penumbraPhaserGroups`), beside their life-cycle checks. */
export interface GroupCheckBase {
  /** Adds the squares, each in a group of its own, and lights A and B, once. */
  setUp(): void;
  /** Sets the content layers of the lit square's group. */
  setLayers(layers: number): void;
}
