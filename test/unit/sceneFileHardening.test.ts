import { afterEach, describe, expect, it } from 'vitest';
import { createSceneObjects, describeScene, SCENE_MAX_HULL_POINTS, readScene, writeScene, type SceneDocument, type ScenePointLight } from '../../src/index';
import { errorOf, fullScene } from './sceneDocuments';

/** A minimal scene whose light's `position` is `value`. */
function withPosition(value: unknown): unknown {
  return { format: 'penumbra-scene', version: 1, lights: [{ kind: 'point', position: value }] };
}

/** Saves a scene loaded from `input` the way an application does: objects built and described back. */
function saveAsBuilt(scene: SceneDocument): string {
  const cookie = {} as WebGLTexture;
  const objects = createSceneObjects(scene, () => cookie);
  return writeScene(describeScene({ ...objects, ambient: scene.ambient, camera: scene.camera, look: scene.look, cookieName: () => 'flame' }));
}

describe('readScene throws only SceneFormatError, with a path', () => {
  it('describes a value nested 10,000 deep without overflowing the stack', () => {
    let deep: unknown = 1;
    for (let i = 0; i < 10_000; i++) deep = [deep];
    const error = errorOf(withPosition(deep));
    expect(error.path).toBe('lights[0].position');
    expect(error.message).toMatch(/^lights\[0\]\.position: expected two finite numbers, got \[\[\[/);
    const text = `{"format": "penumbra-scene", "version": 1, "lights": [{"kind": "point", "position": ${'['.repeat(10_000)}1${']'.repeat(10_000)}}]}`;
    expect(errorOf(text).path).toBe('lights[0].position');
  });

  it('rejects a BigInt, a symbol and a function, naming them', () => {
    const bigint = errorOf({ ...fullScene(), version: 1n });
    expect(bigint.message).toBe('version: expected a finite number, got 1n');
    expect(errorOf(withPosition([1, Symbol('x')])).message).toBe('lights[0].position: expected two finite numbers, got [1,Symbol(x)]');
    expect(errorOf(withPosition(() => 1)).path).toBe('lights[0].position');
  });

  it('rejects cycles', () => {
    const cycle: unknown[] = [];
    cycle.push(cycle, cycle);
    expect(errorOf(withPosition(cycle)).path).toBe('lights[0].position');
    const scene = fullScene() as unknown as Record<string, unknown>;
    scene.camera = scene;
    expect(errorOf(scene).path).toBe('camera.format');
  });

  it('rejects getters instead of calling them, and turns exotic failures into a SceneFormatError', () => {
    const scene = fullScene() as unknown as Record<string, unknown>;
    Object.defineProperty(scene, 'ambient', { enumerable: true, get: () => { throw new Error('boom'); } });
    expect(errorOf(scene).message).toBe('ambient: expected a value, got a getter');
    const { proxy, revoke } = Proxy.revocable({}, {});
    revoke();
    expect(errorOf(proxy).path).toBe('(root)');
  });
});

describe('sparse arrays', () => {
  it('rejects a hole with its path, in every list of a scene', () => {
    const holes: [string, (scene: SceneDocument) => void][] = [
      ['lights[1]', (s) => { delete (s.lights as unknown[])[1]; }],
      ['hulls[0]', (s) => { delete (s.hulls as unknown[])[0]; }],
      ['hulls[1].points[2]', (s) => { delete (s.hulls[1].points as unknown[])[2]; }],
      ['lights[0].color[1]', (s) => { delete (s.lights[0].color as unknown[])[1]; }],
      ['lights[2].ignoredHulls[0]', (s) => { delete (s.lights[2].ignoredHulls as unknown[])[0]; }],
      ['lights[0].position[0]', (s) => { delete ((s.lights[0] as ScenePointLight).position as unknown[])[0]; }],
    ];
    for (const [path, makeHole] of holes) {
      const scene = fullScene();
      makeHole(scene);
      const error = errorOf(scene);
      expect(error.message).toBe(`${path}: expected a value, got a hole (an array element that is missing)`);
      expect(() => writeScene(scene)).toThrow(`${path}: expected a value`);
    }
  });

  it('rejects an array of holes only (`lights: [ , , ]`) at its first element', () => {
    expect(errorOf({ ...fullScene(), lights: new Array(3) }).path).toBe('lights[0]');
  });
});

describe('inherited properties', () => {
  afterEach(() => {
    for (const key of ['ambient', 'lights', 'size', 'enabled', '1']) {
      delete (Object.prototype as Record<string, unknown>)[key];
      delete (Array.prototype as unknown as Record<string, unknown>)[key];
    }
  });

  it('reads own fields only, whatever Object.prototype and Array.prototype hold', () => {
    Object.assign(Object.prototype, { ambient: [NaN], lights: 'polluted', size: [-1, -1], enabled: 'yes' });
    (Array.prototype as unknown as Record<string, unknown>)[1] = 7;
    const scene = readScene({ format: 'penumbra-scene', version: 1, hulls: [{ points: [[0, 0], [1, 0], [0, 1]] }] });
    expect(scene.ambient).toEqual([0.2, 0.2, 0.2]);
    expect(scene.lights).toEqual([]);
    expect(scene.hulls[0].enabled).toBe(true);
    expect(errorOf(withPosition([5])).path).toBe('lights[0].position');
  });
});

describe('messages stay short', () => {
  it('cuts values and keys to about 80 characters', () => {
    const huge = 'x'.repeat(5_000_000);
    const byValue = errorOf(withPosition(huge));
    expect(byValue.message.length).toBeLessThan(200);
    const byKey = errorOf({ ...fullScene(), [huge]: 1 });
    expect(byKey.message.length).toBeLessThan(300);
    expect(byKey.path.length).toBeLessThan(100);
    const byArray = errorOf(withPosition(new Array(1_000_000).fill(1)));
    expect(byArray.message.length).toBeLessThan(200);
    const byText = errorOf(`{"format": "penumbra-scene", "version": 1, "x": ${huge}`);
    expect(byText.message.length).toBeLessThan(300);
  });
});

describe('hull point cap', () => {
  const polygon = (count: number) => Array.from({ length: count }, (_, i) => [Math.cos(i), Math.sin(i)]);

  it(`accepts ${SCENE_MAX_HULL_POINTS} points and rejects more, before reading them`, () => {
    const atCap = { format: 'penumbra-scene', version: 1, hulls: [{ points: polygon(SCENE_MAX_HULL_POINTS) }] };
    expect(readScene(atCap).hulls[0].points).toHaveLength(SCENE_MAX_HULL_POINTS);
    const over = { format: 'penumbra-scene', version: 1, hulls: [{ points: polygon(SCENE_MAX_HULL_POINTS + 1) }] };
    expect(errorOf(over).message).toBe(`hulls[0].points: expected at most ${SCENE_MAX_HULL_POINTS} points, got ${SCENE_MAX_HULL_POINTS + 1}`);
  });
});

describe('values the GPU cannot take', () => {
  it('reads a lightmap blur below 1/8 (a denormal one included) as 0, the blur being off', () => {
    for (const lightmapBlur of [1e-320, 3e-162, 0.1]) {
      expect(readScene({ ...fullScene(), look: { ...fullScene().look, lightmapBlur } }).look.lightmapBlur).toBe(0);
    }
    expect(readScene({ ...fullScene(), look: { ...fullScene().look, lightmapBlur: 0.125 } }).look.lightmapBlur).toBe(0.125);
  });

  it('refuses a number beyond float32 in every numeric field, naming its path (a pair or triple by its own)', () => {
    /** Every number of `value` with the path readScene names for it. */
    const numbers = (value: unknown, path: string, out: [string[], string][], keys: string[] = []): [string[], string][] => {
      if (typeof value === 'number') out.push([keys, path]);
      else if (Array.isArray(value)) {
        // Pairs and triples are read whole; a list of hull indices element by element.
        const ofNumbers = keys[keys.length - 1] !== 'ignoredHulls' && value.every((item) => typeof item === 'number');
        value.forEach((item, i) => numbers(item, ofNumbers ? path : `${path}[${i}]`, out, [...keys, String(i)]));
      } else if (typeof value === 'object' && value !== null) {
        for (const [key, item] of Object.entries(value)) numbers(item, path === '' ? key : `${path}.${key}`, out, [...keys, key]);
      }
      return out;
    };
    const fields = numbers(fullScene(), '', []);
    expect(fields.length).toBeGreaterThan(60);
    for (const [keys, path] of fields) {
      for (const huge of [1e39, -1e39, Number.MAX_VALUE]) {
        const scene = fullScene() as unknown as Record<string, unknown>;
        let parent = scene;
        for (const key of keys.slice(0, -1)) parent = parent[key] as Record<string, unknown>;
        parent[keys[keys.length - 1]] = huge;
        expect(errorOf(scene).path, `${keys.join('.')} = ${huge}`).toBe(path);
      }
    }
    expect(errorOf({ ...fullScene(), look: { ...fullScene().look, exposure: 1e39 } }).message)
      .toBe('look.exposure: expected a number at most 3.4028234663852886e+38 in size (a float32), got 1e+39');
  });
});

describe('every scene that loads can be saved', () => {
  it('keeps a textured light that follows its range, even when twice the range overflows float32', () => {
    const scene = readScene({ format: 'penumbra-scene', version: 1, lights: [{ kind: 'textured', position: [0, 0], cookie: 'flame', range: 3e38 }] });
    const text = saveAsBuilt(scene);
    expect(readScene(text)).toEqual(scene);
  });

  it('rejects a hull listed twice in ignoredHulls, which a light keeps once', () => {
    const scene = fullScene();
    scene.lights[2].ignoredHulls = [1, 1];
    expect(errorOf(scene).message).toBe('lights[2].ignoredHulls[1]: hull 1 is already listed');
  });

  it('round-trips the full scene through objects', () => {
    expect(saveAsBuilt(fullScene())).toBe(writeScene(fullScene()));
  });
});
