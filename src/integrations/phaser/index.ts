/**
 * Phaser 4 integration of penumbra-gl: `import { PenumbraPlugin } from 'penumbra-gl/phaser'`.
 * Re-exports the core API so that one import is enough.
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
