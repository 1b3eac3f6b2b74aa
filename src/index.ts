export { PenumbraRenderer, type PenumbraRendererOptions, type FrameStats } from './PenumbraRenderer';
export { Hull, type HullOptions } from './scene/Hull';
export {
  Light, PointLight, Spotlight, TexturedLight, ShadowType,
  type LightOptions, type SpotlightOptions, type TexturedLightOptions, type LightKind,
} from './scene/lights';
export type { Vec2Like, ColorLike } from './scene/validate';
export { isSimplePolygon, signedArea2 } from './geometry/polygon';
