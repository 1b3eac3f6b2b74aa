/**
 * PixiJS v8 integration of penumbra-gl: `import { PenumbraLayer } from 'penumbra-gl/pixi'`.
 * Re-exports the core API so that one import is enough.
 */
export { PenumbraLayer, type PenumbraLayerOptions } from './PenumbraLayer';
export { hullFromBounds, hullFromPolygon } from './hulls';
export * from '../../index';
