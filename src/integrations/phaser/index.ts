/**
 * With Phaser 4: {@link PenumbraPlugin}, a scene plugin, and {@link penumbraGameConfig} for a WebGL2 game.
 * `import { PenumbraPlugin, penumbraGameConfig } from 'penumbra-gl/phaser'`.
 *
 * - {@link PenumbraPlugin}: a scene plugin, `this.penumbra` in every scene.
 * - {@link penumbraGameConfig} gives Phaser the WebGL2 context the lighting needs.
 * - Occluders from game objects: {@link TilemapLayerHulls}, {@link SpriteHulls}; {@link PenumbraGroup} lights a group apart.
 *
 * Re-exports the core API (`penumbra-gl`), so that one import is enough.
 *
 * @module penumbra-gl/phaser
 */
export { PenumbraPlugin, DEFAULT_LAYER_DEPTH, type PenumbraPluginOptions } from './PenumbraPlugin';
export { penumbraGameConfig } from './gameConfig';
export { PenumbraGroup, type PenumbraGroupOptions } from './PenumbraGroup';
export type { MaterialOptions } from './surfaces';
export { TilemapLayerHulls, type TilemapLayerHullsOptions } from './TilemapLayerHulls';
export { SpriteHulls, type SpriteHullsOptions, type FrameObject } from './SpriteHulls';
export type { HullTarget, Placed } from './shared';
export { LightFollower, type LightFollowOptions } from '../LightFollower';
export * from '../../index';
