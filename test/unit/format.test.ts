import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  createSceneObjects, describeScene, DirectionalLight, Hull, readScene, SCENE_MAX_APP_DEPTH, SCENE_MAX_APP_SIZE, SCENE_SCHEMA_URL, SceneFormatError, Spotlight,
  TexturedLight, writeScene as writeSceneText, type SceneDocument, type ScenePointLight,
} from '../../src/index';
import { docsExample, errorOf, fullScene, referenceDocuments } from './sceneDocuments';
import { SCENE_SCHEMA, schemaErrors } from './sceneSchema';

/** writeScene, checking that every file it writes validates against the JSON Schema the package ships. */
function writeScene(scene: SceneDocument): string {
  const text = writeSceneText(scene);
  expect(schemaErrors(text)).toEqual([]);
  return text;
}

/** A full scene with one field replaced (or deleted, with `undefined`) at a path of keys. */
function withField(path: (string | number)[], value: unknown): unknown {
  const scene = JSON.parse(JSON.stringify(fullScene()));
  let parent = scene;
  for (const key of path.slice(0, -1)) parent = parent[key];
  const last = path[path.length - 1];
  if (value === undefined) delete parent[last];
  else parent[last] = value;
  return scene;
}

describe('scene format', () => {
  it('round-trips a scene through writeScene and readScene', () => {
    const scene = fullScene();
    const text = writeScene(scene);
    expect(readScene(text)).toEqual(scene);
    expect(writeScene(readScene(text))).toBe(text);
  });

  it('fills in the documented defaults of a minimal file', () => {
    const scene = readScene({
      format: 'penumbra-scene', version: 1,
      hulls: [{ points: [[0, 0], [1, 0], [0, 1]] }],
      lights: [{ kind: 'point', position: [1, 2] }, { kind: 'spot', position: [0, 0] }, { kind: 'textured', position: [0, 0], cookie: 'c' }],
    });
    expect(scene.ambient).toEqual([0.2, 0.2, 0.2]);
    expect(scene.camera).toEqual({ center: [0, 0], zoom: 1 });
    expect(scene.hulls[0]).toEqual({ points: [[0, 0], [1, 0], [0, 1]], position: [0, 0], origin: [0, 0], rotation: 0, scale: [1, 1], enabled: true, closed: true, layers: 1 });
    expect(scene.lights[0]).toEqual({
      kind: 'point', position: [1, 2], range: 100, radius: 0, color: [1, 1, 1], intensity: 1, rotation: 0,
      origin: [0.5, 0.5], shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [],
      shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, falloff: 'linear', height: null,
    });
    expect(scene.lights[1]).toMatchObject({ coneAngle: Math.PI / 2, coneDecay: 1 });
    expect(scene.lights[2]).toMatchObject({ cookie: 'c', size: null });
  });

  it('keeps invalid polygons: the renderer flags them, the file format does not', () => {
    const scene = readScene(withField(['hulls', 0, 'points'], [[0, 0], [1, 1]]));
    expect(scene.hulls[0].points).toEqual([[0, 0], [1, 1]]);
  });

  it('reads version 1 files, which have no open hulls', () => {
    const v1 = { format: 'penumbra-scene', version: 1, hulls: [{ points: [[0, 0], [1, 0], [0, 1]] }] };
    const scene = readScene(v1);
    expect(scene.version).toBe(3);
    expect(scene.hulls[0].closed).toBe(true);
    expect(errorOf({ ...v1, hulls: [{ points: [[0, 0], [1, 0]], closed: false }] }).message)
      .toBe('hulls[0].closed: unknown field (allowed: points, position, origin, rotation, scale, enabled)');
    expect(errorOf({ ...v1, look: { exposure: 2 } }).message).toBe('look: unknown field (allowed: $schema, format, version, ambient, camera, hulls, lights)');
    expect(errorOf({ ...v1, lights: [{ kind: 'point', position: [0, 0], shadowType: 'occluded' }] }).message)
      .toBe('lights[0].shadowType: expected one of "solid", "illuminated", got "occluded"');
    expect(readScene({ ...v1, version: 2, lights: [{ kind: 'point', position: [0, 0], shadowType: 'occluded' }] }).lights[0].shadowType).toBe('occluded');
    expect(scene.look).toEqual({ exposure: 1, toneMapping: 'none', dithering: 'none', lightmapBlur: 0 });
  });

  it('reads a directional light from version 2 on, with its defaults, and rejects one in a version 1 file', () => {
    const v2 = { format: 'penumbra-scene', version: 2, lights: [{ kind: 'directional' }] };
    expect(readScene(v2).lights[0]).toEqual({
      kind: 'directional', color: [1, 1, 1], intensity: 1, rotation: 0, shadowType: 'illuminated', enabled: true, castsShadows: true,
      ignoredHulls: [], shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, angularSize: new DirectionalLight().angularSize, elevation: Math.PI / 4,
    });
    expect(readScene({ ...v2, lights: [{ kind: 'directional', angularSize: 0 }] }).lights[0]).toMatchObject({ angularSize: 0 });
    expect(readScene({ ...v2, lights: [{ kind: 'directional', angularSize: Math.PI / 2 }] }).lights[0]).toMatchObject({ angularSize: Math.PI / 2 });
    expect(errorOf({ ...v2, version: 1 }).message).toBe('lights[0].kind: expected one of "point", "spot", "textured", got "directional"');
  });

  it('rejects an unknown version and another format', () => {
    expect(errorOf(withField(['version'], 4)).message).toBe('version: unsupported version 4 (this reader knows versions 1 to 3)');
    expect(errorOf(withField(['version'], undefined)).message).toBe('version: required field is missing');
    expect(errorOf(withField(['format'], 'tiled-map')).message).toBe('format: expected "penumbra-scene", got "tiled-map"');
  });

  it('rejects text that is not JSON and a root that is not an object', () => {
    expect(errorOf('{ "format": ').path).toBe('(root)');
    expect(errorOf('{ "format": ').message).toMatch(/^\(root\): not valid JSON/);
    expect(errorOf('[1, 2]').message).toBe('(root): expected an object, got [1,2]');
  });

  // Every check of the reader, with the path it must name.
  const cases: [string, (string | number)[], unknown, string][] = [
    ['unknown top-level field', ['light'], [], 'light: unknown field (allowed: $schema, format, version, ambient, camera, hulls, lights, look, app)'],
    ['ambient not a triple', ['ambient'], [1, 1], 'ambient: expected three finite numbers ≥ 0, got [1,1]'],
    ['ambient negative', ['ambient'], [1, -1, 1], 'ambient: expected three finite numbers ≥ 0, got [1,-1,1]'],
    ['camera not an object', ['camera'], 3, 'camera: expected an object, got 3'],
    ['camera zoom zero', ['camera', 'zoom'], 0, 'camera.zoom: expected a number > 0, got 0'],
    ['camera center', ['camera', 'center'], [0], 'camera.center: expected two finite numbers, got [0]'],
    ['camera unknown field', ['camera', 'angle'], 0, 'camera.angle: unknown field (allowed: center, zoom)'],
    ['hulls not an array', ['hulls'], {}, 'hulls: expected an array, got {}'],
    ['hull not an object', ['hulls', 1], 'box', 'hulls[1]: expected an object, got "box"'],
    ['hull points missing', ['hulls', 1, 'points'], undefined, 'hulls[1].points: required field is missing'],
    ['hull points not an array', ['hulls', 1, 'points'], 5, 'hulls[1].points: expected an array, got 5'],
    ['hull point not a pair', ['hulls', 1, 'points', 1], [1, null], 'hulls[1].points[1]: expected two finite numbers, got [1,null]'],
    ['hull point as a string', ['hulls', 0, 'points', 3], '0,30', 'hulls[0].points[3]: expected two finite numbers, got "0,30"'],
    ['hull position', ['hulls', 0, 'position'], [1, 2, 3], 'hulls[0].position: expected two finite numbers, got [1,2,3]'],
    ['hull origin', ['hulls', 0, 'origin'], null, 'hulls[0].origin: expected two finite numbers, got null'],
    ['hull rotation', ['hulls', 0, 'rotation'], '90deg', 'hulls[0].rotation: expected a finite number, got "90deg"'],
    ['hull scale', ['hulls', 0, 'scale'], 2, 'hulls[0].scale: expected two finite numbers, got 2'],
    ['hull enabled', ['hulls', 0, 'enabled'], 1, 'hulls[0].enabled: expected true or false, got 1'],
    ['hull unknown field', ['hulls', 0, 'colour'], 'red', 'hulls[0].colour: unknown field (allowed: points, position, origin, rotation, scale, enabled, closed, layers)'],
    ['lights not an array', ['lights'], 'none', 'lights: expected an array, got "none"'],
    ['light not an object', ['lights', 0], null, 'lights[0]: expected an object, got null'],
    ['light kind missing', ['lights', 0, 'kind'], undefined, 'lights[0].kind: required field is missing'],
    ['light kind unknown', ['lights', 0, 'kind'], 'area', 'lights[0].kind: expected one of "point", "spot", "textured", "directional", got "area"'],
    ['light position missing', ['lights', 0, 'position'], undefined, 'lights[0].position: required field is missing'],
    ['light position', ['lights', 0, 'position'], [1, 'a'], 'lights[0].position: expected two finite numbers, got [1,"a"]'],
    ['light range negative', ['lights', 0, 'range'], -1, 'lights[0].range: expected a number ≥ 0, got -1'],
    ['light radius not a number', ['lights', 1, 'radius'], '4', 'lights[1].radius: expected a finite number, got "4"'],
    ['light color', ['lights', 1, 'color'], [1, 1], 'lights[1].color: expected three finite numbers ≥ 0, got [1,1]'],
    ['light intensity negative', ['lights', 2, 'intensity'], -0.5, 'lights[2].intensity: expected a number ≥ 0, got -0.5'],
    ['light rotation', ['lights', 2, 'rotation'], null, 'lights[2].rotation: expected a finite number, got null'],
    ['light origin', ['lights', 2, 'origin'], [0.5], 'lights[2].origin: expected two finite numbers, got [0.5]'],
    ['light shadowType', ['lights', 0, 'shadowType'], 'dark', 'lights[0].shadowType: expected one of "solid", "illuminated", "occluded", got "dark"'],
    ['light enabled', ['lights', 0, 'enabled'], 'yes', 'lights[0].enabled: expected true or false, got "yes"'],
    ['light castsShadows', ['lights', 0, 'castsShadows'], 0, 'lights[0].castsShadows: expected true or false, got 0'],
    ['look toneMapping', ['look', 'toneMapping'], 'filmic', 'look.toneMapping: expected one of "none", "reinhard", "aces", got "filmic"'],
    ['look lightmapBlur', ['look', 'lightmapBlur'], 33, 'look.lightmapBlur: expected a number ≤ 32, got 33'],
    ['look unknown field', ['look', 'gamma'], 2.2, 'look.gamma: unknown field (allowed: exposure, toneMapping, dithering, lightmapBlur)'],
    ['light shadowLayers', ['lights', 0, 'shadowLayers'], -1, 'lights[0].shadowLayers: expected an integer from 0 to 4294967295 (a bit mask), got -1'],
    ['light falloff', ['lights', 0, 'falloff'], 'cubic', 'lights[0].falloff: expected one of "linear", "smooth", "inverseSquare", got "cubic"'],
    ['light height', ['lights', 0, 'height'], -1, 'lights[0].height: expected a number ≥ 0, got -1'],
    ['directional elevation', ['lights', 3, 'elevation'], 0, 'lights[3].elevation: expected a number > 0, got 0'],
    ['directional elevation above the zenith', ['lights', 3, 'elevation'], 2, 'lights[3].elevation: expected a number ≤ 1.5707963267948966, got 2'],
    ['light litLayers', ['lights', 0, 'litLayers'], 1.5, 'lights[0].litLayers: expected an integer from 0 to 4294967295 (a bit mask), got 1.5'],
    ['hull layers', ['hulls', 1, 'layers'], 0.5, 'hulls[1].layers: expected an integer from 0 to 4294967295 (a bit mask), got 0.5'],
    ['light shadowStrength', ['lights', 1, 'shadowStrength'], 2, 'lights[1].shadowStrength: expected a number ≤ 1, got 2'],
    ['light shadowColor', ['lights', 2, 'shadowColor'], [0, 0], 'lights[2].shadowColor: expected three finite numbers ≥ 0, got [0,0]'],
    ['ignoredHulls not an array', ['lights', 0, 'ignoredHulls'], 1, 'lights[0].ignoredHulls: expected an array, got 1'],
    ['ignoredHulls out of range', ['lights', 2, 'ignoredHulls', 1], 3, 'lights[2].ignoredHulls[1]: expected a hull index from 0 to 2, got 3'],
    ['ignoredHulls not an integer', ['lights', 2, 'ignoredHulls', 0], 0.5, 'lights[2].ignoredHulls[0]: expected a hull index from 0 to 2, got 0.5'],
    ['light unknown field', ['lights', 0, 'coneAngle'], 1, 'lights[0].coneAngle: unknown field (allowed: kind, position, range, radius, color, intensity, rotation, origin, shadowType, enabled, castsShadows, ignoredHulls, shadowLayers, shadowColor, shadowStrength, litLayers, falloff, height)'],
    ['spot coneAngle above π', ['lights', 1, 'coneAngle'], 4, 'lights[1].coneAngle: expected a number ≤ 3.141592653589793, got 4'],
    ['spot coneAngle negative', ['lights', 1, 'coneAngle'], -1, 'lights[1].coneAngle: expected a number ≥ 0, got -1'],
    ['spot coneDecay negative', ['lights', 1, 'coneDecay'], -2, 'lights[1].coneDecay: expected a number ≥ 0, got -2'],
    ['textured cookie missing', ['lights', 2, 'cookie'], undefined, 'lights[2].cookie: required field is missing'],
    ['textured cookie empty', ['lights', 2, 'cookie'], '', 'lights[2].cookie: expected a non-empty string, got ""'],
    ['textured size negative', ['lights', 2, 'size'], [10, -1], 'lights[2].size: expected numbers ≥ 0, got [10,-1]'],
    ['textured size not a pair', ['lights', 2, 'size'], 'big', 'lights[2].size: expected two finite numbers, got "big"'],
    ['directional angularSize negative', ['lights', 3, 'angularSize'], -0.1, 'lights[3].angularSize: expected a number ≥ 0, got -0.1'],
    ['directional angularSize above π/2', ['lights', 3, 'angularSize'], 2, 'lights[3].angularSize: expected a number ≤ 1.5707963267948966, got 2'],
    ['directional angularSize not a number', ['lights', 3, 'angularSize'], '0.5°', 'lights[3].angularSize: expected a finite number, got "0.5°"'],
    ['directional rotation', ['lights', 3, 'rotation'], null, 'lights[3].rotation: expected a finite number, got null'],
    ['directional shadowType', ['lights', 3, 'shadowType'], 'dark', 'lights[3].shadowType: expected one of "solid", "illuminated", "occluded", got "dark"'],
    ['directional ignoredHulls out of range', ['lights', 3, 'ignoredHulls', 0], 5, 'lights[3].ignoredHulls[0]: expected a hull index from 0 to 2, got 5'],
    ...['position', 'range', 'radius', 'origin', 'coneAngle'].map((field): [string, (string | number)[], unknown, string] => [
      `directional ${field}, a field it does not have`, ['lights', 3, field], field === 'position' || field === 'origin' ? [0, 0] : 1,
      `lights[3].${field}: unknown field (allowed: kind, color, intensity, rotation, shadowType, enabled, castsShadows, ignoredHulls, shadowLayers, shadowColor, shadowStrength, litLayers, angularSize, elevation)`,
    ]),
  ];
  /** Checks that need the file as a whole: a JSON Schema cannot tell how many hulls there are. */
  const beyondTheSchema = ['ignoredHulls out of range', 'directional ignoredHulls out of range'];
  it.each(cases)('names the path of a bad field: %s', (name, path, value, message) => {
    const error = errorOf(withField(path, value));
    expect(error.message).toBe(message);
    expect(error.path).toBe(message.slice(0, message.indexOf(': ')));
    expect(schemaErrors(withField(path, value)).length > 0).toBe(!beyondTheSchema.includes(name));
  });

  it('rejects NaN and Infinity in a scene given as a value', () => {
    const scene = fullScene();
    const point = scene.lights[0] as ScenePointLight;
    point.range = Number.NaN;
    expect(errorOf(scene).message).toBe('lights[0].range: expected a finite number, got NaN');
    point.range = 1;
    scene.hulls[1].points[2] = [Infinity, 0];
    expect(errorOf(scene).message).toBe('hulls[1].points[2]: expected two finite numbers, got [Infinity,0]');
  });

  it('refers to no hull when there are none', () => {
    expect(errorOf(withField(['hulls'], [])).message)
      .toBe('lights[0].ignoredHulls[0]: expected no hull index (the file has no hulls), got 1');
  });

  it('writes $schema first, and reads a file with any $schema string the same as without', () => {
    const text = writeScene(fullScene());
    expect(Object.keys(JSON.parse(text))[0]).toBe('$schema');
    expect(JSON.parse(text).$schema).toBe('https://unpkg.com/penumbra-gl/schema/scene.schema.json');
    expect(readScene(withField(['$schema'], './my.schema.json'))).toEqual(fullScene());
    expect(readScene({ $schema: 'x', format: 'penumbra-scene', version: 1 }).hulls).toEqual([]);
    expect(errorOf(withField(['$schema'], 3)).message).toBe("$schema: expected a string (the URL of the file's JSON Schema), got 3");
  });

  it('writeScene refuses a bad document instead of writing a file that would not load', () => {
    const scene = fullScene();
    scene.camera.zoom = -1;
    expect(() => writeScene(scene)).toThrow('camera.zoom: expected a number > 0, got -1');
  });
});

describe('scene schema', () => {
  it('is the file $schema names, shipped in the package as penumbra-gl/scene.schema.json', () => {
    expect(SCENE_SCHEMA.$id).toBe(SCENE_SCHEMA_URL);
    const pkg = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8'));
    expect(pkg.exports['./scene.schema.json']).toBe('./schema/scene.schema.json');
    expect(pkg.files).toContain('schema');
  });

  it('accepts the files readScene reads: the docs example, minimal files, every version', () => {
    for (const scene of [docsExample(), ...referenceDocuments(), { format: 'penumbra-scene', version: 1 }, { $schema: 'x', format: 'penumbra-scene', version: 3, app: { game: [1] } }]) {
      readScene(scene);
      expect(schemaErrors(scene)).toEqual([]);
    }
  });

  it('rejects what a version does not have, as readScene does', () => {
    const v1 = { format: 'penumbra-scene', version: 1 };
    const tooNew = [
      { ...v1, look: { exposure: 2 } },
      { ...v1, hulls: [{ points: [[0, 0], [1, 0], [0, 1]], closed: false }] },
      { ...v1, lights: [{ kind: 'point', position: [0, 0], shadowType: 'occluded' }] },
      { ...v1, lights: [{ kind: 'point', position: [0, 0], falloff: 'smooth' }] },
      { ...v1, lights: [{ kind: 'directional' }] },
      { ...v1, version: 2, app: {} },
    ];
    for (const scene of tooNew) {
      errorOf(scene);
      expect(schemaErrors(scene)).not.toEqual([]);
    }
    expect(schemaErrors({ ...v1, version: 2, lights: [{ kind: 'directional' }] })).toEqual([]);
  });

  it('rejects malformed documents', () => {
    const malformed = [
      {}, [], { format: 'tiled-map', version: 3 }, { format: 'penumbra-scene', version: 4 }, { format: 'penumbra-scene' },
      withField(['$schema'], 3), withField(['app'], []), withField(['app'], { '': 1 }),
      withField(['lights', 0, 'position'], undefined), withField(['lights', 2, 'cookie'], undefined), withField(['hulls', 0, 'points'], undefined),
      withField(['lights', 0, 'range'], 1e39), withField(['lights', 3, 'elevation'], 0), withField(['camera', 'zoom'], 0),
      withField(['lights', 0, 'ignoredHulls'], [1, 1]),
    ];
    for (const scene of malformed) {
      expect(() => readScene(scene)).toThrow(SceneFormatError);
      expect(schemaErrors(scene)).not.toEqual([]);
    }
  });
});

describe('application data', () => {
  /** Nested JSON of every kind, with keys that mean something to JavaScript. */
  const gameData = {
    version: 4, name: 'crypt', spawn: [[10, -2.5e-7], [1e300, 0]], flags: { lit: true, boss: false, note: null },
    text: 'é "quoted" \\ \n \u0000 \ud800', empty: {}, none: [], ['__proto__']: { polluted: true }, constructor: 'x', toJSON: 1,
    deep: [{ a: [{ b: [[[{}]]] }] }],
  };
  const withApp = (app: unknown) => withField(['app'], app);

  it('keeps every application\'s data through writeScene and readScene, verbatim', () => {
    const app = JSON.parse(JSON.stringify({ 'my-game': gameData, 'penumbra-gl/playground': { version: 1, art: 'showcase' }, other: [1, 'two'] }));
    // JSON.parse made an own "__proto__" key, as it does for a file.
    expect(Object.hasOwn(app['my-game'], '__proto__')).toBe(true);
    const text = writeScene(readScene(withApp(app)));
    const read = readScene(text);
    expect(JSON.stringify(read.app)).toBe(JSON.stringify(app));
    expect(read.app).toEqual(app);
    expect(Object.getPrototypeOf(read.app['my-game'])).toBe(Object.prototype);
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
    expect(writeScene(read)).toBe(text);
  });

  it('shares nothing with the input, and is {} when absent', () => {
    const app = { game: { list: [1, { x: 2 }] } };
    const read = readScene(withApp(app));
    app.game.list.push(3);
    expect(read.app).toEqual({ game: { list: [1, { x: 2 }] } });
    expect(readScene(withField(['app'], undefined)).app).toEqual({});
  });

  it('is carried by describeScene', () => {
    const scene = fullScene();
    const objects = createSceneObjects(scene, () => ({}) as WebGLTexture);
    const app = { game: gameData };
    const described = describeScene({ ...objects, ambient: scene.ambient, camera: scene.camera, cookieName: () => 'flame', app });
    expect(readScene(writeScene(described)).app).toEqual(JSON.parse(JSON.stringify(app)));
  });

  it('is not in version 1 or 2 files', () => {
    const scene = { format: 'penumbra-scene', version: 2, app: { game: 1 } };
    expect(errorOf(scene).message).toBe('app: unknown field (allowed: $schema, format, version, ambient, camera, hulls, lights, look)');
    expect(errorOf({ ...scene, version: 1 }).path).toBe('app');
  });

  const cycle: Record<string, unknown> = { a: 1 };
  cycle.self = { again: cycle };
  class Spawn { x = 1; }
  const getter = Object.defineProperty({}, 'score', { get: () => 1, enumerable: true });
  const bad: [string, unknown, string][] = [
    ['not an object', [1], 'app: expected an object, got [1]'],
    ['an empty application name', { '': 1 }, 'app.: expected a non-empty application name, got ""'],
    ['undefined', { game: { hp: undefined } }, 'app.game.hp: expected JSON data (an object, an array, a string, a finite number, true, false or null), got undefined'],
    ['a function', { game: { onLoad: () => 1 } }, 'app.game.onLoad: expected JSON data (an object, an array, a string, a finite number, true, false or null), got a function'],
    ['a symbol', { game: [Symbol('s')] }, 'app.game[0]: expected JSON data (an object, an array, a string, a finite number, true, false or null), got Symbol(s)'],
    ['a bigint', { game: 10n }, 'app.game: expected JSON data (an object, an array, a string, a finite number, true, false or null), got 10n'],
    ['NaN', { game: { x: NaN } }, 'app.game.x: expected a finite number (JSON has no NaN or Infinity), got NaN'],
    ['Infinity', { game: [0, -Infinity] }, 'app.game[1]: expected a finite number (JSON has no NaN or Infinity), got -Infinity'],
    ['a Date', { game: { saved: new Date(0) } }, 'app.game.saved: expected JSON data (an object, an array, a string, a finite number, true, false or null), got an object of class Date'],
    ['a Map', { game: new Map() }, 'app.game: expected JSON data (an object, an array, a string, a finite number, true, false or null), got an object of class Map'],
    ['a class instance', { game: new Spawn() }, 'app.game: expected JSON data (an object, an array, a string, a finite number, true, false or null), got an object of class Spawn'],
    ['a hole', { game: [1, , 2] }, 'app.game[1]: expected a value, got a hole (an array element that is missing)'],
    ['a getter', { game: getter }, 'app.game.score: expected a value, got a getter'],
    ['a cycle', { game: cycle }, 'app.game.self.again: expected JSON data, got a cycle (a value that contains itself)'],
  ];
  it.each(bad)('rejects a value JSON cannot hold, naming its path: %s', (_name, app, message) => {
    expect(errorOf(withApp(app)).message).toBe(message);
  });

  it(`bounds the nesting to SCENE_MAX_APP_DEPTH (${SCENE_MAX_APP_DEPTH}) arrays and objects`, () => {
    const nested = (depth: number): unknown => (depth === 0 ? 0 : depth % 2 ? [nested(depth - 1)] : { k: nested(depth - 1) });
    expect(readScene(withApp({ game: nested(SCENE_MAX_APP_DEPTH) })).app.game).toEqual(nested(SCENE_MAX_APP_DEPTH));
    const error = errorOf(withApp({ game: nested(SCENE_MAX_APP_DEPTH + 1) }));
    expect(error.message).toMatch(/^app\.game(\[0\]|\.k)+: expected at most 32 nested arrays and objects in an application's data, got more$/);
    // A deep file is refused without a stack overflow.
    expect(errorOf(`{"format":"penumbra-scene","version":3,"app":{"game":${'['.repeat(100_000)}${']'.repeat(100_000)}}}`).message)
      .toMatch(/^app\.game(\[0\])+: expected at most 32 nested/);
  });

  it(`bounds the size to SCENE_MAX_APP_SIZE (${SCENE_MAX_APP_SIZE}) characters of JSON, counted exactly`, () => {
    // {"g":"…"} is 8 characters around the string's contents.
    const fits = { g: 'x'.repeat(SCENE_MAX_APP_SIZE - 8) };
    expect(JSON.stringify(fits).length).toBe(SCENE_MAX_APP_SIZE);
    expect(readScene(withApp(fits)).app).toEqual(fits);
    expect(errorOf(withApp({ g: 'x'.repeat(SCENE_MAX_APP_SIZE - 7) })).message)
      .toBe('app.g: expected application data of at most 1000000 characters as JSON, got more');
    // Escapes count as written: a newline is two characters.
    expect(errorOf(withApp({ g: '\n'.repeat(SCENE_MAX_APP_SIZE / 2) })).path).toBe('app.g');
    // A long array is refused before its elements are read.
    expect(errorOf(withApp({ g: new Array(SCENE_MAX_APP_SIZE) })).message).toBe('app.g: expected application data of at most 1000000 characters as JSON, got more');
  });
});

describe('scene objects', () => {
  const flame = { name: 'flame texture' } as unknown as WebGLTexture;
  const resolve = (name: string) => (name === 'flame' ? flame : null);

  it('builds lights and hulls and describes them back to the same document', () => {
    const scene = fullScene();
    const objects = createSceneObjects(scene, resolve);
    expect(objects.hulls).toHaveLength(3);
    expect(objects.hulls[1].enabled).toBe(false);
    expect(objects.hulls.map((hull) => hull.closed)).toEqual([true, true, false]);
    const spot = objects.lights[1] as Spotlight;
    expect(spot).toBeInstanceOf(Spotlight);
    expect(spot.coneAngle).toBe(0.9);
    const textured = objects.lights[2] as TexturedLight;
    expect(textured).toBeInstanceOf(TexturedLight);
    expect(textured.texture).toBe(flame);
    expect([...textured.ignoredHulls]).toEqual(objects.hulls.slice(0, 2));
    const described = describeScene({ ...objects, ambient: scene.ambient, camera: scene.camera, look: scene.look, cookieName: () => 'flame' });
    expect(described).toEqual(scene);
  });

  it('builds a directional light and describes it without the position, range, radius and origin it ignores', () => {
    const objects = createSceneObjects(fullScene(), resolve);
    const sun = objects.lights[3] as DirectionalLight;
    expect(sun).toBeInstanceOf(DirectionalLight);
    expect(sun).toMatchObject({ angularSize: 0.2, rotation: 2.1, intensity: 0.7, shadowType: 'occluded', shadowLayers: 5, shadowStrength: 0.9 });
    expect([...sun.ignoredHulls]).toEqual([objects.hulls[2]]);
    const moved = new DirectionalLight({ angularSize: 0, ignoredHulls: [new Hull([[0, 0], [1, 0], [0, 1]])] });
    moved.setPosition(5, 6);
    moved.range = 10;
    const described = describeScene({ hulls: [], lights: [moved], ambient: [0, 0, 0], camera: { center: [0, 0], zoom: 1 }, cookieName: () => 'flame' });
    expect(described.lights[0]).toEqual({
      kind: 'directional', color: [1, 1, 1], intensity: 1, rotation: 0, shadowType: 'illuminated', enabled: true, castsShadows: true,
      ignoredHulls: [], shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, angularSize: 0, elevation: Math.PI / 4,
    });
    expect(readScene(writeScene(described))).toEqual(described);
  });

  it('names the light whose cookie is unknown and builds nothing', () => {
    const scene = fullScene();
    if (scene.lights[2].kind === 'textured') scene.lights[2].cookie = 'torch';
    expect(() => createSceneObjects(scene, resolve)).toThrow(new SceneFormatError('lights[2].cookie', 'unknown cookie "torch"'));
  });
});
