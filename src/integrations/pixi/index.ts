/**
 * With PixiJS 8: {@link PenumbraLayer} lights the stage, occluders follow display objects.
 * `import { PenumbraLayer } from 'penumbra-gl/pixi'`.
 *
 * - {@link PenumbraLayer} lights what the stage draws before it; {@link PenumbraGroup} lights a group of display objects apart.
 * - Occluders from display objects: {@link SpriteOccluder}, {@link GraphicsOccluder}, {@link Occluder}, {@link hullFromBounds}.
 * - {@link LightFollower}: lights that follow display objects.
 *
 * Re-exports the core API (`penumbra-gl`), so that one import is enough.
 *
 * @module penumbra-gl/pixi
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
