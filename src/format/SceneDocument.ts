/**
 * The penumbra scene file: plain, versioned JSON describing ambient colour, camera, hulls and
 * lights. See `docs/scene-format.md` for a worked example. Every field below is written by
 * {@link writeScene}; {@link readScene} also accepts files that leave out the fields marked
 * optional, and fills in the defaults shown.
 */

/** The value of a scene file's `format` field. */
export const SCENE_FORMAT = 'penumbra-scene';
/**
 * The format version this package writes. {@link readScene} also reads versions 1 and 2 (the same
 * without some fields, see `docs/scene-format.md`) and rejects any other version.
 */
export const SCENE_FORMAT_VERSION = 3;

/**
 * The `$schema` that {@link writeScene} writes at the top of a file: the JSON Schema of the scene
 * format shipped in the package (`penumbra-gl/scene.schema.json`), so editors validate and
 * complete scene files. {@link readScene} accepts any string there and ignores it.
 */
export const SCENE_SCHEMA_URL = 'https://unpkg.com/penumbra-gl/schema/scene.schema.json';

/**
 * How deep an application's data ({@link SceneDocument.app}) may nest arrays and objects: an
 * application's value that is an object of numbers is 1 deep. {@link readScene} rejects deeper
 * data, which also bounds its recursion.
 */
export const SCENE_MAX_APP_DEPTH = 32;

/**
 * The most characters all application data ({@link SceneDocument.app}) may take written as compact
 * JSON; {@link readScene} rejects more as soon as it has counted past it (about 1 MB).
 */
export const SCENE_MAX_APP_SIZE = 1_000_000;

/**
 * The most points a hull of a scene file may have; {@link readScene} rejects a file with more
 * before reading them. Checking and triangulating a hull takes O(n log n) for most outlines, but
 * up to O(n²) for some crafted ones: the cap bounds what a hostile file can cost (load times of
 * hulls this size: `npm run bench:hulls`, logged in docs/performance.md). Hulls built in code have
 * no cap.
 */
export const SCENE_MAX_HULL_POINTS = 20_000;

/** A JSON value, as `JSON.parse` returns it: application data ({@link SceneDocument.app}) is made of these. */
export type JsonValue = null | boolean | number | string | JsonValue[] | { [key: string]: JsonValue };

/**
 * Application data of a scene file: each application's own JSON value, keyed by its name (its
 * package name, or a package name and a path such as `"penumbra-gl/playground"`). The library
 * neither reads nor changes it: it is kept verbatim. Keep a version inside your value to evolve it.
 */
export type SceneAppData = { [application: string]: JsonValue };

/** A whole scene file, version 3 (what {@link readScene} returns for a version 1 or 2 file too). */
export interface SceneDocument {
  /** Always `"penumbra-scene"`. */
  format: typeof SCENE_FORMAT;
  /** Always `3`. */
  version: typeof SCENE_FORMAT_VERSION;
  /** Colour of unlit areas `[r, g, b]`, channels ≥ 0. Optional, default `[0.2, 0.2, 0.2]`. */
  ambient: [number, number, number];
  /** Where the view looks. Optional, default centre `[0, 0]`, zoom `1`. */
  camera: SceneCamera;
  /** Occluders, in order; lights refer to them by index in `ignoredHulls`. Optional, default `[]`. */
  hulls: SceneHull[];
  /** Lights, in drawing order. Optional, default `[]`. */
  lights: SceneLight[];
  /**
   * How the final image is made from the lightmap: the renderer's properties of the same names.
   * Apply it with `Object.assign(renderer, scene.look)`. Optional, default the renderer's defaults;
   * not in version 1 files.
   */
  look: SceneLook;
  /**
   * Data that applications keep with the scene (what an editor shows, a game's own fields), by
   * application name; read and written without loss. Any JSON, at most {@link SCENE_MAX_APP_DEPTH}
   * arrays and objects deep and {@link SCENE_MAX_APP_SIZE} characters in all; names are non-empty.
   * Optional, default `{}`; not in version 1 or 2 files.
   */
  app: SceneAppData;
}

/** The look of a file that has none: the renderer's defaults. @internal */
export const DEFAULT_LOOK: Readonly<SceneLook> = Object.freeze({ exposure: 1, toneMapping: 'none', dithering: 'none', lightmapBlur: 0 });

/** The renderer's look (`PenumbraRenderer.exposure` and the next three), as a scene file stores it. */
export interface SceneLook {
  /** ≥ 0. Optional, default `1`. */
  exposure: number;
  /** `"none"`, `"reinhard"` or `"aces"`. Optional, default `"none"`. */
  toneMapping: 'none' | 'reinhard' | 'aces';
  /** `"none"`, `"ordered"` or `"noise"`. Optional, default `"none"`. */
  dithering: 'none' | 'ordered' | 'noise';
  /** 0..32; below 1/8 is off and reads as `0`. Optional, default `0`. */
  lightmapBlur: number;
}

/** The view: the world point at the centre of the screen and how many screen pixels a world unit covers. */
export interface SceneCamera {
  /** World point at the centre of the view. */
  center: [number, number];
  /** Screen pixels (CSS pixels) per world unit, > 0. */
  zoom: number;
}

/** A hull, with the fields of `Hull` and `HullOptions`. */
export interface SceneHull {
  /**
   * Local points `[x, y]`, either winding, at most {@link SCENE_MAX_HULL_POINTS}. An invalid
   * polygon is kept and flagged by the renderer.
   */
  points: [number, number][];
  /** Optional, default `[0, 0]`. */
  position: [number, number];
  /** Optional, default `[0, 0]`. */
  origin: [number, number];
  /** Radians. Optional, default `0`. */
  rotation: number;
  /** `[sx, sy]`, any finite values (negative mirrors). Optional, default `[1, 1]`. */
  scale: [number, number];
  /** Optional, default `true`. */
  enabled: boolean;
  /** `false` for an open polyline (see `Hull.closed`). Optional, default `true`; not in version 1 files. */
  closed: boolean;
  /** Layer bit mask, an integer 0..0xffffffff (see `Hull.layers`). Optional, default `1`; not in version 1 files. */
  layers: number;
}

/**
 * Fields of the lights with a position (point, spot, textured), as in `LightOptions`. A
 * {@link SceneDirectionalLight} has all of them but `position`, `range`, `radius`, `origin`,
 * `falloff` and `height`.
 */
export interface SceneLightBase {
  /** Required. */
  position: [number, number];
  /** ≥ 0. Optional, default `100`. */
  range: number;
  /**
   * ≥ 0. Optional, default `0` in every version: the format's own default, kept so that a file means
   * what it meant when written; a light made in code has `DEFAULT_LIGHT_RADIUS` (10).
   */
  radius: number;
  /** `[r, g, b]`, channels ≥ 0. Optional, default `[1, 1, 1]`. */
  color: [number, number, number];
  /** ≥ 0. Optional, default `1`. */
  intensity: number;
  /** Radians. Optional, default `0`. */
  rotation: number;
  /** Optional, default `[0.5, 0.5]`. */
  origin: [number, number];
  /** `"solid"`, `"illuminated"` or (version 2) `"occluded"`. Optional, default `"illuminated"`. */
  shadowType: 'solid' | 'illuminated' | 'occluded';
  /** Optional, default `true`. */
  enabled: boolean;
  /** Optional, default `true`. */
  castsShadows: boolean;
  /** Indices into the file's `hulls` that this light passes through. Optional, default `[]`. */
  ignoredHulls: number[];
  /** Hull layers that shadow the light, an integer 0..0xffffffff. Optional, default `0xffffffff`; not in version 1 files. */
  shadowLayers: number;
  /** `[r, g, b]`, channels ≥ 0. Optional, default `[0, 0, 0]`; not in version 1 files. */
  shadowColor: [number, number, number];
  /** 0..1. Optional, default `1`; not in version 1 files. */
  shadowStrength: number;
  /** Content layers the light lights, an integer 0..0xffffffff. Optional, default `0xffffffff`; not in version 1 files. */
  litLayers: number;
  /** `"linear"`, `"smooth"` or `"inverseSquare"` (see `Falloff`). Optional, default `"linear"`; not in version 1 files, nor for directional lights. */
  falloff: 'linear' | 'smooth' | 'inverseSquare';
  /**
   * Height above the plane for normal-mapped lighting, ≥ 0, or `null` for a quarter of the range
   * (see `Light.height`). Optional, default `null`; not in version 1 files, nor for directional lights.
   */
  height: number | null;
}

/** A `PointLight`. */
export interface ScenePointLight extends SceneLightBase {
  /** Which light class this is. */
  kind: 'point';
}

/** A `Spotlight`. */
export interface SceneSpotlight extends SceneLightBase {
  /** Which light class this is. */
  kind: 'spot';
  /** Full cone angle in radians, 0..π. Optional, default `π / 2`. */
  coneAngle: number;
  /** ≥ 0. Optional, default `1`. */
  coneDecay: number;
}

/** A `TexturedLight`. Textures are not stored in the file: `cookie` names one the application provides. */
export interface SceneTexturedLight extends SceneLightBase {
  /** Which light class this is. */
  kind: 'textured';
  /** Name of the light cookie texture, resolved by the application. Required, non-empty. */
  cookie: string;
  /** Quad size `[width, height]` in world units, ≥ 0, or `null` for `2 × range`. Optional, default `null`. */
  size: [number, number] | null;
}

/**
 * A `DirectionalLight` (version 2): light from infinitely far, travelling along `rotation`, with
 * every field of {@link SceneLightBase} but those about a position and a range (`position`,
 * `range`, `radius`, `origin`), which a file must not have.
 */
export interface SceneDirectionalLight extends Omit<SceneLightBase, 'position' | 'range' | 'radius' | 'origin' | 'falloff' | 'height'> {
  /** Which light class this is. */
  kind: 'directional';
  /** Apparent diameter of the light's disk in radians, 0..π/2. Optional, default `0.0093` (the sun). */
  angularSize: number;
  /** Angle above the plane in radians for normal-mapped lighting, in (0, π/2]. Optional, default `π / 4`. */
  elevation: number;
}

/** Any light of a scene file, told apart by `kind`. */
export type SceneLight = ScenePointLight | SceneSpotlight | SceneTexturedLight | SceneDirectionalLight;
