/**
 * PixiJS v8 integration of penumbra-gl: `import { PenumbraLayer } from 'penumbra-gl/pixi'`.
 * Re-exports the core API so that one import is enough.
 */
export { PenumbraLayer, type PenumbraLayerOptions } from './PenumbraLayer';
export { PenumbraGroup, type PenumbraGroupOptions } from './PenumbraGroup';
export type { SurfaceOptions } from './surfaces';
export { hullFromBounds, hullFromPolygon } from './hulls';
export { Occluder } from './Occluder';
export { LightFollower, type LightFollowOptions } from '../LightFollower';
export { SpriteOccluder, hullsFromTexture, forgetTextureHulls, type SpriteHullsOptions, type TextureHullsOptions } from './spriteHulls';
export { GraphicsOccluder, hullsFromGraphics, type GraphicsHullsOptions } from './graphicsHulls';
export * from '../../index';
