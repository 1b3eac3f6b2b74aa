/**
 * The core, for any WebGL2 context (plain WebGL2 in a browser, or Node with headless-gl 9):
 * {@link PenumbraRenderer}, the lights, {@link Hull} and the scene files.
 * `import { PenumbraRenderer, PointLight, Hull } from 'penumbra-gl'`.
 *
 * - {@link PenumbraRenderer} lights a WebGL2 context: `beginDraw()` / `draw()`, or `drawInPlace()`.
 * - Lights: {@link PointLight}, {@link Spotlight}, {@link TexturedLight}, {@link DirectionalLight}.
 * - Occluders: {@link Hull}, from tile grids ({@link hullsFromTiles}, {@link TileHulls}) and sprite alpha ({@link hullsFromAlpha}).
 * - Scene files: {@link readScene}, {@link writeScene}, {@link createSceneObjects}.
 *
 * A bundle that imports only the scene format or the model classes leaves the shaders and GL code out.
 *
 * @module penumbra-gl
 */
export { PenumbraRenderer } from './PenumbraRenderer';
export type { PenumbraRendererOptions } from './options';
export type { FrameStats } from './FrameStats';
export { SURFACE_GLSL } from './passes/shaders';
export { encodeShininess, type SurfaceTextures } from './passes/surfaceLayout';
export { ToneMapping, Dithering } from './scene/look';
export type { Illumination, IlluminationOptions, LightIllumination, CookieSampler } from './scene/illumination';
export { Hull, type HullOptions } from './scene/Hull';
export { Light, ShadowType, DEFAULT_LIGHT_RADIUS, type LightOptions, type LightKind } from './scene/Light';
export { Falloff } from './scene/falloff';
export { PointLight } from './scene/PointLight';
export { Spotlight, type SpotlightOptions } from './scene/Spotlight';
export { TexturedLight, type TexturedLightOptions } from './scene/TexturedLight';
export { DirectionalLight, type DirectionalLightOptions } from './scene/DirectionalLight';
export type { Vec2Like, ColorLike } from './util/validate';
export { isSimplePolygon, signedArea2 } from './geometry/polygon';
export { hullsFromTiles, TileHulls, type TileGrid, type TileHullsOptions, type TileHullsChange } from './scene/tileHulls';
export { hullsFromAlpha, type AlphaImage, type HullsFromAlphaOptions } from './scene/hullsFromAlpha';
export { readScene } from './format/readScene';
export { writeScene } from './format/writeScene';
export { SceneFormatError } from './format/SceneFormatError';
export { createSceneObjects, describeScene, type SceneObjects, type CookieResolver, type SceneDescriptionInput } from './format/sceneObjects';
export {
  SCENE_FORMAT, SCENE_FORMAT_VERSION, SCENE_MAX_HULL_POINTS, SCENE_MAX_APP_DEPTH, SCENE_MAX_APP_SIZE, SCENE_SCHEMA_URL, type SceneDocument,
  type SceneCamera, type SceneHull, type SceneLight, type SceneLightBase, type ScenePointLight, type SceneSpotlight, type SceneTexturedLight,
  type SceneDirectionalLight, type SceneLook, type SceneAppData, type JsonValue,
} from './format/SceneDocument';
