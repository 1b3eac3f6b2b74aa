import {
  booleanField, childPath, choiceField, colorField, layersField, nameField, numberField, positiveField, readArray, readObject,
  readVec2, vec2Field, type Fields,
} from './fields';
import { readAppData } from './appData';
import { MAX_BLUR_RADIUS, MIN_BLUR_RADIUS } from '../scene/look';
import { describeValue, shortened } from '../util/validate';
import {
  DEFAULT_LOOK, SCENE_FORMAT, SCENE_FORMAT_VERSION, SCENE_MAX_HULL_POINTS,
  type SceneCamera, type SceneDirectionalLight, type SceneDocument, type SceneHull, type SceneLight, type SceneLightBase, type SceneLook,
} from './SceneDocument';
import { SceneFormatError } from './SceneFormatError';

/** `$schema` names the file's JSON Schema for editors: allowed in every version, and ignored. */
const DOCUMENT_FIELDS_V2 = ['$schema', 'format', 'version', 'ambient', 'camera', 'hulls', 'lights', 'look'] as const;
const CAMERA_FIELDS = ['center', 'zoom'] as const;
const LOOK_FIELDS = ['exposure', 'toneMapping', 'dithering', 'lightmapBlur'] as const;

const HULL_FIELDS_V1 = ['points', 'position', 'origin', 'rotation', 'scale', 'enabled'];
const LIGHT_FIELDS_V1 = [
  'kind', 'position', 'range', 'radius', 'color', 'intensity', 'rotation', 'origin', 'shadowType', 'enabled',
  'castsShadows', 'ignoredHulls',
];
const SHADOW_TYPES_V1 = ['solid', 'illuminated'] as const;
const FALLOFFS = ['linear', 'smooth', 'inverseSquare'] as const;
const LIGHT_KINDS_V1 = ['point', 'spot', 'textured'] as const;
/** The fields hulls and lights (besides their kind's) may have, the shadow types and the light kinds, per version this reader knows. */
interface VersionFields {
  readonly document: readonly string[];
  readonly hull: readonly string[];
  readonly light: readonly string[];
  readonly shadowTypes: readonly SceneLightBase['shadowType'][];
  readonly lightKinds: readonly SceneLight['kind'][];
}
const VERSION_2: VersionFields = {
  document: DOCUMENT_FIELDS_V2,
  hull: [...HULL_FIELDS_V1, 'closed', 'layers'],
  light: [...LIGHT_FIELDS_V1, 'shadowLayers', 'shadowColor', 'shadowStrength', 'litLayers', 'falloff', 'height'],
  shadowTypes: [...SHADOW_TYPES_V1, 'occluded'],
  lightKinds: [...LIGHT_KINDS_V1, 'directional'],
};
const VERSION_FIELDS: Readonly<Record<number, VersionFields>> = {
  1: {
    document: DOCUMENT_FIELDS_V2.filter((field) => field !== 'look'), hull: HULL_FIELDS_V1, light: LIGHT_FIELDS_V1, shadowTypes: SHADOW_TYPES_V1,
    lightKinds: LIGHT_KINDS_V1,
  },
  2: VERSION_2,
  [SCENE_FORMAT_VERSION]: { ...VERSION_2, document: [...DOCUMENT_FIELDS_V2, 'app'] },
};
/**
 * A light's radius in a file that gives none, in every version: the format's own, not the
 * constructors' `DEFAULT_LIGHT_RADIUS`, so that a file means what it meant when it was written.
 */
const FILE_DEFAULT_RADIUS = 0;
/** The light fields a directional light lacks: it has no position and lights everything alike. */
const POSITION_FIELDS: readonly string[] = ['position', 'range', 'radius', 'origin', 'falloff', 'height'];
const KIND_FIELDS = { point: [], spot: ['coneAngle', 'coneDecay'], textured: ['cookie', 'size'], directional: ['angularSize', 'elevation'] } as const;
/** `DirectionalLight`'s default `angularSize`: the sun's apparent diameter, in radians. */
const SUN_ANGULAR_SIZE = 0.0093;
/** The fields every light kind has, a directional light included. */
type SharedLightFields = Omit<SceneDirectionalLight, 'kind' | 'angularSize' | 'elevation'>;

/**
 * Reads a scene file (its JSON text, or the already parsed value) and checks every field. Only
 * own data fields count: inherited properties are ignored and getters are never run.
 *
 * @returns a complete {@link SceneDocument} with defaults filled in; it shares nothing with the input.
 * @throws {SceneFormatError} and nothing else, for any input, naming the path of the first bad
 *   field, e.g. `hulls[3].points[1]: expected two finite numbers, got [1,null]`; also for text
 *   that is not JSON, another `format`, a `version` other than 1 to {@link SCENE_FORMAT_VERSION}, a hole
 *   in an array, or a hull of more than {@link SCENE_MAX_HULL_POINTS} points. Bad values are shown
 *   cut to about 80 characters and 3 levels deep.
 */
export function readScene(input: unknown): SceneDocument {
  try {
    return readDocument(typeof input === 'string' ? parseJson(input) : input);
  } catch (error) {
    if (error instanceof SceneFormatError) throw error;
    // Plain data never gets here; an exotic value does (a proxy whose traps throw).
    throw new SceneFormatError('(root)', `could not be read (${describeError(error)})`);
  }
}

function readDocument(input: unknown): SceneDocument {
  // The version decides which fields are allowed, so it is read before the field check.
  const unchecked = readObject(input, '');
  if (unchecked.value.format !== SCENE_FORMAT) {
    throw new SceneFormatError('format', `expected "${SCENE_FORMAT}", got ${describeValue(unchecked.value.format)}`);
  }
  const version = numberField(unchecked, 'version');
  if (!Object.hasOwn(VERSION_FIELDS, version)) {
    throw new SceneFormatError('version', `unsupported version ${version} (this reader knows versions 1 to ${SCENE_FORMAT_VERSION})`);
  }
  const fields = VERSION_FIELDS[version];
  const root = readObject(input, '', fields.document);
  if (root.value.$schema !== undefined && typeof root.value.$schema !== 'string') {
    throw new SceneFormatError('$schema', `expected a string (the URL of the file's JSON Schema), got ${describeValue(root.value.$schema)}`);
  }
  const hulls = readList(root.value.hulls, 'hulls', (value, path) => readHull(value, path, fields.hull));
  const lights = readList(root.value.lights, 'lights', (value, path) => readLight(value, path, fields, hulls.length));
  return {
    format: SCENE_FORMAT,
    version: SCENE_FORMAT_VERSION,
    ambient: colorField(root, 'ambient', [0.2, 0.2, 0.2]),
    camera: root.value.camera === undefined ? { center: [0, 0], zoom: 1 } : readCamera(root.value.camera, 'camera'),
    hulls,
    lights,
    look: root.value.look === undefined ? { ...DEFAULT_LOOK } : readLook(root.value.look, 'look'),
    app: root.value.app === undefined ? {} : readAppData(root.value.app, 'app'),
  };
}

function describeError(error: unknown): string {
  return error instanceof Error ? shortened(error.message) : describeValue(error);
}

function parseJson(text: string): unknown {
  try {
    return JSON.parse(text);
  } catch (error) {
    throw new SceneFormatError('(root)', `not valid JSON (${describeError(error)})`);
  }
}

function readList<T>(value: unknown, path: string, read: (item: unknown, path: string) => T): T[] {
  if (value === undefined) return [];
  return readArray(value, path).map((item, i) => read(item, `${path}[${i}]`));
}

function readCamera(value: unknown, path: string): SceneCamera {
  const camera = readObject(value, path, CAMERA_FIELDS);
  return { center: vec2Field(camera, 'center', [0, 0]), zoom: positiveField(camera, 'zoom', 1) };
}

function readLook(value: unknown, path: string): SceneLook {
  const look = readObject(value, path, LOOK_FIELDS);
  return {
    exposure: numberField(look, 'exposure', DEFAULT_LOOK.exposure, 0),
    toneMapping: choiceField(look, 'toneMapping', ['none', 'reinhard', 'aces'] as const, DEFAULT_LOOK.toneMapping),
    dithering: choiceField(look, 'dithering', ['none', 'ordered', 'noise'] as const, DEFAULT_LOOK.dithering),
    lightmapBlur: blurField(look),
  };
}

/** The look's blur radius, 0..{@link MAX_BLUR_RADIUS}; one below {@link MIN_BLUR_RADIUS} is off and reads as 0, as the renderer's setter has it. */
function blurField(look: Fields): number {
  const radius = numberField(look, 'lightmapBlur', DEFAULT_LOOK.lightmapBlur, 0, MAX_BLUR_RADIUS);
  return radius < MIN_BLUR_RADIUS ? 0 : radius;
}

function readHull(value: unknown, path: string, fields: readonly string[]): SceneHull {
  const hull = readObject(value, path, fields);
  const pointsPath = childPath(path, 'points');
  if (hull.value.points === undefined) throw new SceneFormatError(pointsPath, 'required field is missing');
  return {
    points: readArray(hull.value.points, pointsPath, SCENE_MAX_HULL_POINTS, 'points').map((point, i) => readVec2(point, `${pointsPath}[${i}]`)),
    position: vec2Field(hull, 'position', [0, 0]),
    origin: vec2Field(hull, 'origin', [0, 0]),
    rotation: numberField(hull, 'rotation', 0),
    scale: vec2Field(hull, 'scale', [1, 1]),
    enabled: booleanField(hull, 'enabled', true),
    closed: booleanField(hull, 'closed', true),
    layers: layersField(hull, 'layers', 1),
  };
}

function readLight(value: unknown, path: string, fields: VersionFields, hullCount: number): SceneLight {
  // The kind decides which fields are allowed, so it is read before the field check.
  const kindFields = readObject(value, path);
  const kind = choiceField(kindFields, 'kind', fields.lightKinds);
  const shared = kind === 'directional' ? fields.light.filter((field) => !POSITION_FIELDS.includes(field)) : fields.light;
  const light = readObject(value, path, [...shared, ...KIND_FIELDS[kind]]);
  if (kind === 'directional') {
    return {
      kind, ...readSharedLightFields(light, fields.shadowTypes, hullCount),
      angularSize: numberField(light, 'angularSize', SUN_ANGULAR_SIZE, 0, Math.PI / 2),
      elevation: elevationField(light),
    };
  }
  const base = readLightBase(light, fields.shadowTypes, hullCount);
  switch (kind) {
    case 'point':
      return { kind, ...base };
    case 'spot':
      return {
        kind, ...base,
        coneAngle: numberField(light, 'coneAngle', Math.PI / 2, 0, Math.PI),
        coneDecay: numberField(light, 'coneDecay', 1, 0),
      };
    case 'textured':
      return {
        kind, ...base,
        cookie: nameField(light, 'cookie'),
        size: light.value.size === undefined || light.value.size === null ? null : vec2Field(light, 'size', undefined, 0),
      };
  }
}

/** The fields of a light with a position, in the order files have always been written. */
function readLightBase(light: Fields, shadowTypes: VersionFields['shadowTypes'], hullCount: number): SceneLightBase {
  const position = vec2Field(light, 'position');
  const range = numberField(light, 'range', 100, 0);
  const radius = numberField(light, 'radius', FILE_DEFAULT_RADIUS, 0);
  const { color, intensity, rotation, ...rest } = readSharedLightFields(light, shadowTypes, hullCount);
  const origin = vec2Field(light, 'origin', [0.5, 0.5]);
  const falloff = choiceField(light, 'falloff', FALLOFFS, 'linear');
  const height = light.value.height === undefined || light.value.height === null ? null : numberField(light, 'height', undefined, 0);
  return { position, range, radius, color, intensity, rotation, origin, ...rest, falloff, height };
}

/** A directional light's elevation: in (0, π/2], π/4 when absent. */
function elevationField(light: Fields): number {
  const elevation = numberField(light, 'elevation', Math.PI / 4, 0, Math.PI / 2);
  if (elevation === 0) throw new SceneFormatError(childPath(light.path, 'elevation'), 'expected a number > 0, got 0');
  return elevation;
}

function readSharedLightFields(light: Fields, shadowTypes: VersionFields['shadowTypes'], hullCount: number): SharedLightFields {
  return {
    color: colorField(light, 'color', [1, 1, 1]),
    intensity: numberField(light, 'intensity', 1, 0),
    rotation: numberField(light, 'rotation', 0),
    shadowType: choiceField(light, 'shadowType', shadowTypes, 'illuminated'),
    enabled: booleanField(light, 'enabled', true),
    castsShadows: booleanField(light, 'castsShadows', true),
    ignoredHulls: readIgnoredHulls(light, hullCount),
    shadowLayers: layersField(light, 'shadowLayers', 0xffffffff),
    litLayers: layersField(light, 'litLayers', 0xffffffff),
    shadowColor: colorField(light, 'shadowColor', [0, 0, 0]),
    shadowStrength: numberField(light, 'shadowStrength', 1, 0, 1),
  };
}

function readIgnoredHulls(light: Fields, hullCount: number): number[] {
  const path = childPath(light.path, 'ignoredHulls');
  const value = light.value.ignoredHulls;
  if (value === undefined) return [];
  const indices = readArray(value, path);
  const listed = new Set<unknown>();
  indices.forEach((index, i) => {
    if (typeof index !== 'number' || !Number.isInteger(index) || index < 0 || index >= hullCount) {
      const expected = hullCount === 0 ? 'no hull index (the file has no hulls)' : `a hull index from 0 to ${hullCount - 1}`;
      throw new SceneFormatError(`${path}[${i}]`, `expected ${expected}, got ${describeValue(index)}`);
    }
    // A light keeps a set of hulls: a repeated index would not survive being saved again.
    if (listed.has(index)) throw new SceneFormatError(`${path}[${i}]`, `hull ${index} is already listed`);
    listed.add(index);
  });
  return indices as number[];
}
