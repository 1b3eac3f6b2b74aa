import { childPath, readArray, readObject } from './fields';
import { SCENE_MAX_APP_DEPTH, SCENE_MAX_APP_SIZE, type JsonValue, type SceneAppData } from './SceneDocument';
import { SceneFormatError } from './SceneFormatError';
import { describeValue } from '../util/validate';

const JSON_KINDS = 'an object, an array, a string, a finite number, true, false or null';

/** What is left of {@link SCENE_MAX_APP_SIZE} while application data is read, in characters of compact JSON. */
interface SizeBudget {
  left: number;
}

/**
 * Reads a scene file's `app` object: any JSON value per non-empty application name, copied
 * exactly (an own `"__proto__"` key stays a key). Only JSON passes: no `undefined`, function,
 * symbol, bigint, NaN, Infinity, getter, hole, cycle or object of a class; nothing nested more than
 * {@link SCENE_MAX_APP_DEPTH} deep, nor more than {@link SCENE_MAX_APP_SIZE} characters in all.
 *
 * @throws {SceneFormatError} naming the path of the first bad value, e.g. `app.game.spawn[2]`.
 */
export function readAppData(value: unknown, path: string): SceneAppData {
  const budget: SizeBudget = { left: SCENE_MAX_APP_SIZE };
  const apps = readJsonObject(value, path, budget, new Set());
  for (const name of Object.keys(apps)) {
    if (name === '') throw new SceneFormatError(childPath(path, name), 'expected a non-empty application name, got ""');
  }
  return apps;
}

/** A JSON value at `depth` arrays and objects below the application names (the `app` object is 0). */
function readJson(value: unknown, path: string, depth: number, budget: SizeBudget, ancestors: Set<object>): JsonValue {
  switch (typeof value) {
    case 'string':
      spend(budget, value.length + 2 > budget.left ? value.length + 2 : JSON.stringify(value).length, path);
      return value;
    case 'number':
      if (!Number.isFinite(value)) throw new SceneFormatError(path, `expected a finite number (JSON has no NaN or Infinity), got ${describeValue(value)}`);
      spend(budget, String(value).length, path);
      return value;
    case 'boolean':
      spend(budget, value ? 4 : 5, path);
      return value;
    case 'object':
      if (value === null) {
        spend(budget, 4, path);
        return null;
      }
      if (depth >= SCENE_MAX_APP_DEPTH) {
        throw new SceneFormatError(path, `expected at most ${SCENE_MAX_APP_DEPTH} nested arrays and objects in an application's data, got more`);
      }
      return Array.isArray(value) ? readJsonArray(value, path, depth + 1, budget, ancestors) : readJsonObject(value, path, budget, ancestors, depth + 1);
    default:
      throw new SceneFormatError(path, `expected JSON data (${JSON_KINDS}), got ${describeValue(value)}`);
  }
}

function readJsonArray(value: unknown[], path: string, depth: number, budget: SizeBudget, ancestors: Set<object>): JsonValue[] {
  enter(value, path, ancestors);
  // Each element takes a character or more: a longer array is rejected before it is copied.
  spend(budget, 2 + Math.max(0, value.length - 1), path);
  const items = readArray(value, path).map((item, i) => readJson(item, `${path}[${i}]`, depth, budget, ancestors));
  ancestors.delete(value);
  return items;
}

function readJsonObject(value: unknown, path: string, budget: SizeBudget, ancestors: Set<object>, depth = 0): { [key: string]: JsonValue } {
  if (typeof value === 'object' && value !== null && !Array.isArray(value)) {
    const prototype = Object.getPrototypeOf(value) as object | null;
    if (prototype !== Object.prototype && prototype !== null) {
      throw new SceneFormatError(path, `expected JSON data (${JSON_KINDS}), got an object of class ${describeClass(prototype)}`);
    }
    enter(value, path, ancestors);
    spend(budget, 2 + Math.max(0, Object.keys(value).length - 1), path);
  }
  const fields = readObject(value, path);
  const copy: { [key: string]: JsonValue } = {};
  for (const key of Object.keys(fields.value)) {
    const keyPath = childPath(path, key);
    spend(budget, JSON.stringify(key).length + 1, keyPath);
    // A key named "__proto__" must stay a key, not become the copy's prototype.
    Object.defineProperty(copy, key, { value: readJson(fields.value[key], keyPath, depth, budget, ancestors), enumerable: true, writable: true, configurable: true });
  }
  ancestors.delete(value as object);
  return copy;
}

/** Marks `value` as being read; a value met again inside itself is a cycle, which JSON cannot hold. */
function enter(value: object, path: string, ancestors: Set<object>): void {
  if (ancestors.has(value)) throw new SceneFormatError(path, 'expected JSON data, got a cycle (a value that contains itself)');
  ancestors.add(value);
}

function spend(budget: SizeBudget, characters: number, path: string): void {
  budget.left -= characters;
  if (budget.left < 0) throw new SceneFormatError(path, `expected application data of at most ${SCENE_MAX_APP_SIZE} characters as JSON, got more`);
}

function describeClass(prototype: object): string {
  const constructor = Object.getOwnPropertyDescriptor(prototype, 'constructor')?.value as { name?: unknown } | null | undefined;
  const name = constructor?.name;
  return typeof name === 'string' && name !== '' ? name : 'unknown';
}
