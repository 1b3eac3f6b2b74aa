import { expect, it } from 'vitest';
import {
  createSceneObjects, describeScene, readScene, SceneFormatError, writeScene, type Hull, type Light, type SceneDocument,
} from '../../src/index';
import { docsExample, fullScene, referenceDocuments } from './sceneDocuments';

/**
 * A seeded fuzz test of the scene reader: mutations of the reference documents, given as values
 * or as JSON text. Every rejection must be a SceneFormatError with a path, every acceptance must
 * save and load back to the same file, and a failed load must change nothing. PENUMBRA_FUZZ_SEED
 * and PENUMBRA_FUZZ_MUTATIONS choose the run; a failure names the mutation's number.
 */
const SEED = Number(process.env.PENUMBRA_FUZZ_SEED ?? 14);
const MUTATIONS = Number(process.env.PENUMBRA_FUZZ_MUTATIONS ?? 3000);

type Random = () => number;

/** A seeded generator of floats in [0, 1) (mulberry32). */
function random(seed: number): Random {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const pick = <T>(next: Random, items: readonly T[]): T => items[Math.floor(next() * items.length)];

const BASES: readonly unknown[] = [fullScene(), docsExample(), ...referenceDocuments()];

/** Values a mutation puts in place of a field or an element: wrong types, edges of ranges, names of the format. */
function replacement(next: Random, jsonOnly: boolean): unknown {
  const plain = [
    NaN, Infinity, -Infinity, -1, 0, -0, 0.5, 1, 2, 3.5, 1e308, -1e308, 5e-324, 2 ** 53, 4, Math.PI, 3.2,
    '', 'x', 'point', 'spot', 'textured', 'directional', 'solid', 'illuminated', 'penumbra-scene', 'flame', null, true, false,
    [], {}, [1], [1, 2], [1, 2, 3], [-1, 0], [0, -1], [[0, 0], [1, 0], [0, 1]], { kind: 'point', position: [0, 0] },
    'x'.repeat(1000), nested(100),
  ];
  const exotic = [10n, Symbol.for('fuzz'), undefined, cycle(), sparse(), A_FUNCTION];
  return pick(next, jsonOnly ? plain : [...plain, ...exotic]);
}

/** One function for every mutation, so that a mutation made twice compares equal. */
const A_FUNCTION = () => 1;

function nested(depth: number): unknown {
  let value: unknown = 1;
  for (let i = 0; i < depth; i++) value = [value];
  return value;
}

function cycle(): unknown {
  const value: unknown[] = [1];
  value.push(value);
  return value;
}

function sparse(): unknown[] {
  const value = [1, 2, 3];
  delete value[1];
  return value;
}

/** A random object or array inside `root` (the root itself included), with its keys. */
function randomContainer(next: Random, root: object): object {
  let at = root;
  for (;;) {
    const children = Object.values(at).filter((v): v is object => typeof v === 'object' && v !== null);
    if (children.length === 0 || next() < 0.3) return at;
    at = pick(next, children);
  }
}

/** Changes `document` in place in one random way. */
function mutate(next: Random, document: object, jsonOnly: boolean): void {
  const container = randomContainer(next, document) as Record<string, unknown>;
  const keys = Object.keys(container);
  const key = keys.length > 0 ? pick(next, keys) : '0';
  switch (Math.floor(next() * 6)) {
    case 0:
      container[key] = replacement(next, jsonOnly);
      break;
    case 1:
      if (Array.isArray(container) && jsonOnly) container.splice(Number(key), 1);
      else delete container[key];
      break;
    case 2:
      // Defined, not assigned: an own "__proto__" field, as JSON.parse makes, not a new prototype.
      // Objects only: an array's fields are not read, and an own `constructor` breaks `splice`.
      if (!Array.isArray(container)) Object.defineProperty(container, pick(next, ['extra', 'kind', 'size', 'cookie', 'coneAngle', 'angularSize', 'position', 'points', '__proto__', 'constructor']), {
        value: replacement(next, jsonOnly), enumerable: true, writable: true, configurable: true,
      });
      break;
    case 3:
      if (Array.isArray(container)) container.push(container[Number(key)]);
      break;
    case 4:
      if (typeof container[key] === 'number') container[key] = container[key] * pick(next, [-1, 0, 2, 1e300, 1e-300]);
      break;
    default:
      if (Array.isArray(container)) container.length = Math.floor(next() * container.length);
  }
}

/** Edits JSON text one character at a time: most edits make it invalid, some change a value. */
function mutateText(next: Random, text: string): string {
  const at = Math.floor(next() * text.length);
  switch (Math.floor(next() * 3)) {
    case 0: return text.slice(0, at) + text.slice(at + 1);
    case 1: return text.slice(0, at) + pick(next, [...'{}[],:"-.0123456789eaxnul ']) + text.slice(at);
    default: return text.slice(0, at);
  }
}

/** Mutation number `index`: always the same input for the same seed, so it can be made twice and compared. */
function mutation(index: number): unknown {
  const next = random(SEED * 100_003 + index);
  const asText = next() < 0.25;
  const document = structuredClone(pick(next, BASES)) as object;
  const edits = 1 + Math.floor(next() * 3);
  for (let i = 0; i < edits; i++) mutate(next, document, asText);
  return asText ? (next() < 0.5 ? mutateText(next, JSON.stringify(document)) : JSON.stringify(document)) : document;
}

/** What an application holds: the objects of the scene it loaded last. */
interface LoadedScene {
  hulls: Hull[];
  lights: Light[];
}

const cookie = {} as WebGLTexture;

/** Loads `input` into `scene` as an application would: read, build, then replace. */
function load(input: unknown, scene: LoadedScene): SceneDocument {
  const document = readScene(input);
  const objects = createSceneObjects(document, () => cookie);
  scene.hulls = objects.hulls;
  scene.lights = objects.lights;
  return document;
}

/** Saves what `scene` holds, as an application would. */
function save(scene: LoadedScene, document: SceneDocument): string {
  return writeScene(describeScene({ ...scene, ambient: document.ambient, camera: document.camera, look: document.look, app: document.app, cookieName: () => 'flame' }));
}

function expectRejectionWithPath(error: unknown, index: number): void {
  if (!(error instanceof SceneFormatError)) throw new Error(`mutation ${index}: readScene threw ${String(error)}, not a SceneFormatError`);
  expect(error.path.length, `mutation ${index}`).toBeGreaterThan(0);
  expect(error.message.startsWith(`${error.path}: `), `mutation ${index}: ${error.message}`).toBe(true);
  expect(error.message, `mutation ${index}: an exotic failure for plain data`).not.toMatch(/could not be read/);
  expect(error.message.length, `mutation ${index}`).toBeLessThan(400);
}

function expectRoundTrip(document: SceneDocument, scene: LoadedScene, index: number): void {
  const text = writeScene(document);
  expect(writeScene(readScene(text)), `mutation ${index}`).toBe(text);
  expect(save(scene, document), `mutation ${index}: saved from the built objects`).toBe(text);
}

it(`reads ${MUTATIONS} mutated scene files: SceneFormatError with a path, or a file that saves back the same`, () => {
  let rejected = 0, accepted = 0;
  const scene: LoadedScene = { hulls: [], lights: [] };
  for (let index = 0; index < MUTATIONS; index++) {
    const input = mutation(index);
    const before = { ...scene };
    try {
      expectRoundTrip(load(input, scene), scene, index);
      accepted++;
    } catch (error) {
      if (scene.hulls !== before.hulls) throw error;
      expectRejectionWithPath(error, index);
      expect(scene.lights, `mutation ${index}: a failed load changed the scene`).toBe(before.lights);
      rejected++;
    }
    // The reader reads and never writes: the input is as it was made.
    expect(input, `mutation ${index}: readScene changed its input`).toEqual(mutation(index));
  }
  expect(Object.keys(Object.prototype)).toEqual([]);
  console.log(`scene fuzz (seed ${SEED}): ${MUTATIONS} mutations, ${rejected} rejected, ${accepted} accepted`);
  expect(rejected).toBeGreaterThan(MUTATIONS / 10);
  expect(accepted).toBeGreaterThan(MUTATIONS / 10);
});
