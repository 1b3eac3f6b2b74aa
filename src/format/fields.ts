import { SceneFormatError } from './SceneFormatError';

/** A JSON object being read, with the path that names it in errors. */
export type Fields = { readonly value: Record<string, unknown>; readonly path: string };

/** Joins a parent path and a key: `lights[0]` + `range` → `lights[0].range`. */
export function childPath(path: string, key: string): string {
  return path === '' ? key : `${path}.${key}`;
}

/**
 * Checks that `value` is a plain object with no keys outside `allowed` (a typo is an error, not a
 * silent default); without `allowed`, any keys pass.
 */
export function readObject(value: unknown, path: string, allowed?: readonly string[]): Fields {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) {
    throw new SceneFormatError(path || '(root)', `expected an object, got ${describe(value)}`);
  }
  const record = value as Record<string, unknown>;
  for (const key of Object.keys(record)) {
    if (allowed && !allowed.includes(key)) throw new SceneFormatError(childPath(path, key), `unknown field (allowed: ${allowed.join(', ')})`);
  }
  return { value: record, path };
}

/** Checks that `value` is an array. */
export function readArray(value: unknown, path: string): unknown[] {
  if (!Array.isArray(value)) throw new SceneFormatError(path, `expected an array, got ${describe(value)}`);
  return value;
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

/** A finite number within `[min, max]`. */
export function numberField(fields: Fields, key: string, fallback?: number, min = -Infinity, max = Infinity): number {
  return field(fields, key, fallback, (value, path) => {
    if (typeof value !== 'number' || !Number.isFinite(value)) throw new SceneFormatError(path, `expected a finite number, got ${describe(value)}`);
    if (value < min) throw new SceneFormatError(path, `expected a number ≥ ${min}, got ${value}`);
    if (value > max) throw new SceneFormatError(path, `expected a number ≤ ${max}, got ${value}`);
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
    if (typeof value !== 'boolean') throw new SceneFormatError(path, `expected true or false, got ${describe(value)}`);
    return value;
  });
}

/** One of `choices`. */
export function choiceField<T extends string>(fields: Fields, key: string, choices: readonly T[], fallback?: T): T {
  return field(fields, key, fallback, (value, path) => {
    if (!choices.includes(value as T)) throw new SceneFormatError(path, `expected one of ${choices.map((c) => `"${c}"`).join(', ')}, got ${describe(value)}`);
    return value as T;
  });
}

/** A non-empty string. */
export function nameField(fields: Fields, key: string): string {
  return field(fields, key, undefined, (value, path) => {
    if (typeof value !== 'string' || value.length === 0) throw new SceneFormatError(path, `expected a non-empty string, got ${describe(value)}`);
    return value;
  });
}

/** An `[x, y]` pair of finite numbers, each at least `min`. */
export function readVec2(value: unknown, path: string, min = -Infinity): [number, number] {
  if (!Array.isArray(value) || value.length !== 2 || !value.every(isFiniteNumber)) {
    throw new SceneFormatError(path, `expected two finite numbers, got ${describe(value)}`);
  }
  if (value[0] < min || value[1] < min) throw new SceneFormatError(path, `expected numbers ≥ ${min}, got ${describe(value)}`);
  return [value[0], value[1]];
}

/** An `[x, y]` field. */
export function vec2Field(fields: Fields, key: string, fallback?: [number, number], min = -Infinity): [number, number] {
  return field(fields, key, fallback, (value, path) => readVec2(value, path, min));
}

/** An `[r, g, b]` field with channels ≥ 0. */
export function colorField(fields: Fields, key: string, fallback?: [number, number, number]): [number, number, number] {
  return field(fields, key, fallback, (value, path) => {
    if (!Array.isArray(value) || value.length !== 3 || !value.every((c) => isFiniteNumber(c) && c >= 0)) {
      throw new SceneFormatError(path, `expected three finite numbers ≥ 0, got ${describe(value)}`);
    }
    return [value[0], value[1], value[2]];
  });
}

function isFiniteNumber(value: unknown): value is number {
  return typeof value === 'number' && Number.isFinite(value);
}

/** A short rendering of a bad value for error messages. */
function describe(value: unknown): string {
  if (value === undefined) return 'nothing';
  const text = JSON.stringify(value) ?? String(value);
  return text.length > 40 ? `${text.slice(0, 37)}…` : text;
}
