import { describeValue, FLOAT32_MAX, isFloat32Finite, shortened } from '../util/validate';
import { SceneFormatError } from './SceneFormatError';

/**
 * A JSON object being read, with the path that names it in errors. `value` holds the object's own
 * data fields only, on a null prototype: a field the file lacks reads as undefined whatever
 * `Object.prototype` holds.
 */
export type Fields = { readonly value: Readonly<Record<string, unknown>>; readonly path: string };

/** Joins a parent path and a key: `lights[0]` + `range` → `lights[0].range`. Long keys are cut. */
export function childPath(path: string, key: string): string {
  return path === '' ? shortened(key) : `${path}.${shortened(key)}`;
}

/**
 * Checks that `value` is a plain object with no keys outside `allowed` (a typo is an error, not a
 * silent default); without `allowed`, any keys pass.
 */
export function readObject(value: unknown, path: string, allowed?: readonly string[]): Fields {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) {
    throw new SceneFormatError(path || '(root)', `expected an object, got ${describeValue(value)}`);
  }
  const fields = Object.create(null) as Record<string, unknown>;
  for (const key of Object.keys(value)) {
    if (allowed && !allowed.includes(key)) throw new SceneFormatError(childPath(path, key), `unknown field (allowed: ${allowed.join(', ')})`);
    fields[key] = ownValue(value, key, childPath(path, key));
  }
  return { value: fields, path };
}

/**
 * Checks that `value` is an array without holes and returns a copy of its elements, at most
 * `maxLength` of them (checked before any element is read), each an own data element.
 */
export function readArray(value: unknown, path: string, maxLength = Infinity, unit = 'elements'): unknown[] {
  if (!Array.isArray(value)) throw new SceneFormatError(path, `expected an array, got ${describeValue(value)}`);
  if (value.length > maxLength) throw new SceneFormatError(path, `expected at most ${maxLength} ${unit}, got ${value.length}`);
  const items: unknown[] = [];
  for (let i = 0; i < value.length; i++) {
    const itemPath = `${path}[${i}]`;
    if (!Object.hasOwn(value, i)) throw new SceneFormatError(itemPath, 'expected a value, got a hole (an array element that is missing)');
    items.push(ownValue(value, String(i), itemPath));
  }
  return items;
}

/** The value of an own property, which must be data: a getter is never run. */
function ownValue(object: object, key: string, path: string): unknown {
  const descriptor = Object.getOwnPropertyDescriptor(object, key);
  if (descriptor !== undefined && !('value' in descriptor)) throw new SceneFormatError(path, 'expected a value, got a getter');
  return descriptor?.value;
}

/** A field's value, or `fallback` when the field is absent. */
function field<T>(fields: Fields, key: string, fallback: T | undefined, read: (value: unknown, path: string) => T): T {
  const path = childPath(fields.path, key);
  const value = fields.value[key];
  if (value === undefined) {
    if (fallback === undefined) throw new SceneFormatError(path, 'required field is missing');
    return fallback;
  }
  return read(value, path);
}

/**
 * A finite number within `[min, max]`. Finite as a float32, as the scene classes take numbers (see
 * src/util/validate.ts): at most {@link FLOAT32_MAX} in size.
 */
export function numberField(fields: Fields, key: string, fallback?: number, min = -Infinity, max = Infinity): number {
  return field(fields, key, fallback, (value, path) => {
    if (typeof value !== 'number' || !Number.isFinite(value)) throw new SceneFormatError(path, `expected a finite number, got ${describeValue(value)}`);
    if (!isFloat32Finite(value)) throw new SceneFormatError(path, `expected a number at most ${FLOAT32_MAX} in size (a float32), got ${value}`);
    if (value < min) throw new SceneFormatError(path, `expected a number ≥ ${min}, got ${value}`);
    if (value > max) throw new SceneFormatError(path, `expected a number ≤ ${max}, got ${value}`);
    return value;
  });
}

/** A layer bit mask: an integer from 0 to 0xffffffff. */
export function layersField(fields: Fields, key: string, fallback: number): number {
  return field(fields, key, fallback, (value, path) => {
    if (typeof value !== 'number' || !Number.isInteger(value) || value < 0 || value > 0xffffffff) {
      throw new SceneFormatError(path, `expected an integer from 0 to 4294967295 (a bit mask), got ${describeValue(value)}`);
    }
    return value;
  });
}

/** A strictly positive finite number. */
export function positiveField(fields: Fields, key: string, fallback?: number): number {
  const value = numberField(fields, key, fallback);
  if (value <= 0) throw new SceneFormatError(childPath(fields.path, key), `expected a number > 0, got ${value}`);
  return value;
}

/** A boolean. */
export function booleanField(fields: Fields, key: string, fallback?: boolean): boolean {
  return field(fields, key, fallback, (value, path) => {
    if (typeof value !== 'boolean') throw new SceneFormatError(path, `expected true or false, got ${describeValue(value)}`);
    return value;
  });
}

/** One of `choices`. */
export function choiceField<T extends string>(fields: Fields, key: string, choices: readonly T[], fallback?: T): T {
  return field(fields, key, fallback, (value, path) => {
    if (!choices.includes(value as T)) throw new SceneFormatError(path, `expected one of ${choices.map(describeValue).join(', ')}, got ${describeValue(value)}`);
    return value as T;
  });
}

/** A non-empty string. */
export function nameField(fields: Fields, key: string): string {
  return field(fields, key, undefined, (value, path) => {
    if (typeof value !== 'string' || value.length === 0) throw new SceneFormatError(path, `expected a non-empty string, got ${describeValue(value)}`);
    return value;
  });
}

/** An `[x, y]` pair of finite numbers (float32, as {@link numberField}), each at least `min`. */
export function readVec2(value: unknown, path: string, min = -Infinity): [number, number] {
  const items = Array.isArray(value) && value.length === 2 ? readArray(value, path) : [];
  if (items.length !== 2 || !items.every(isFiniteNumber)) {
    throw new SceneFormatError(path, `expected two finite numbers, got ${describeValue(value)}`);
  }
  if (items[0] < min || items[1] < min) throw new SceneFormatError(path, `expected numbers ≥ ${min}, got ${describeValue(value)}`);
  return [items[0], items[1]];
}

/** An `[x, y]` field. */
export function vec2Field(fields: Fields, key: string, fallback?: [number, number], min = -Infinity): [number, number] {
  return field(fields, key, fallback, (value, path) => readVec2(value, path, min));
}

/** An `[r, g, b]` field with channels ≥ 0, finite as float32 (as {@link numberField}). */
export function colorField(fields: Fields, key: string, fallback?: [number, number, number]): [number, number, number] {
  return field(fields, key, fallback, (value, path) => {
    const items = Array.isArray(value) && value.length === 3 ? readArray(value, path) : [];
    if (items.length !== 3 || !items.every((c): c is number => isFiniteNumber(c) && c >= 0)) {
      throw new SceneFormatError(path, `expected three finite numbers ≥ 0, got ${describeValue(value)}`);
    }
    return [items[0], items[1], items[2]];
  });
}

function isFiniteNumber(value: unknown): value is number {
  return typeof value === 'number' && isFloat32Finite(value);
}
