/** A 2D vector given as an `[x, y]` pair. */
export type Vec2Like = readonly [number, number] | ArrayLike<number>;
/** An RGB colour with channels in 0..1 (values above 1 are allowed and over-brighten). */
export type ColorLike = readonly [number, number, number] | ArrayLike<number>;

/**
 * Checks of values given to the scene classes. A value of the wrong type is a `TypeError`, one of
 * the right type out of range (NaN, ∞, a negative range, an unknown name) a `RangeError`; every
 * message names the property (`PointLight.position[1]`) and shows the value, cut short.
 *
 * Numbers reach the GPU as float32: a "finite" number here is one that stays finite as a float32,
 * at most {@link FLOAT32_MAX} in size (a double up to half a float32 step above it rounds down to
 * it). A larger one would be ∞ in a uniform or a texture, and NaN after the first ∞ − ∞ or ∞ × 0.
 */

/** The largest finite float32, (2 − 2^−23) × 2^127 ≈ 3.4028235e38. */
export const FLOAT32_MAX = 3.4028234663852886e38;

/** Whether `value` is a number that stays finite as a float32 (NaN, ±∞ and doubles beyond {@link FLOAT32_MAX} do not). */
export function isFloat32Finite(value: number): boolean {
  // Number.isFinite first: it takes numbers only, where Math.fround would turn '' into 0.
  return Number.isFinite(value) && Number.isFinite(Math.fround(value));
}

/** Throws unless `value` is a number finite as a float32 (see above). */
export function assertFinite(name: string, value: number): number {
  if (typeof value !== 'number') throw new TypeError(`${name} must be a finite number, got ${describeValue(value)}`);
  if (!Number.isFinite(value)) throw new RangeError(`${name} must be a finite number, got ${describeValue(value)}`);
  if (!isFloat32Finite(value)) throw new RangeError(`${name} must be at most ${FLOAT32_MAX} in size (a float32, as the GPU takes it), got ${value}`);
  return value;
}

/** Throws unless `value` is a finite number ≥ 0. */
export function assertNonNegative(name: string, value: number): number {
  assertFinite(name, value);
  if (value < 0) throw new RangeError(`${name} must not be negative, got ${value}`);
  return value;
}

/** The largest layer mask: all 32 layers. */
export const ALL_LAYERS = 0xffffffff;

/** Throws unless `value` is a layer mask: an integer from 0 to {@link ALL_LAYERS} (bit k set: in layer k). */
export function assertLayerMask(name: string, value: number): number {
  if (typeof value !== 'number') throw new TypeError(`${name} must be an integer from 0 to 0xffffffff (a bit mask), got ${describeValue(value)}`);
  if (!Number.isInteger(value) || value < 0 || value > ALL_LAYERS) {
    throw new RangeError(`${name} must be an integer from 0 to 0xffffffff (a bit mask), got ${describeValue(value)}`);
  }
  return value;
}

/** Throws unless `value` is a finite number from 0 to 1. */
export function assertUnit(name: string, value: number): number {
  assertFinite(name, value);
  if (value < 0 || value > 1) throw new RangeError(`${name} must be from 0 to 1, got ${value}`);
  return value;
}

/** Throws a `TypeError` naming the class unless a constructor's `options` is an object. */
export function assertOptions(className: string, options: object): void {
  if (typeof options !== 'object' || options === null) throw new TypeError(`${className} options must be an object, got ${describeValue(options)}`);
}

/** Throws a `TypeError` unless `value` is `true` or `false` (no truthy stand-ins). */
export function assertBoolean(name: string, value: boolean): boolean {
  if (typeof value !== 'boolean') throw new TypeError(`${name} must be true or false, got ${describeValue(value)}`);
  return value;
}

/** Throws a `RangeError` unless `value` is one of `choices`. */
export function assertOneOf<T>(name: string, value: T, choices: readonly T[]): T {
  if (!choices.includes(value)) {
    throw new RangeError(`${name} must be one of ${choices.map(describeValue).join(', ')}, got ${describeValue(value)}`);
  }
  return value;
}

/**
 * Validates a 2D vector (extra elements are ignored) and returns it as a new frozen pair: the
 * scene classes hold their vectors frozen, so a vector handed out by a getter can never change.
 */
export function frozenVec2(name: string, value: Vec2Like): readonly [number, number] {
  assertArrayLike(name, value, 2, 'an [x, y] pair');
  return frozenPair(name, value[0], value[1]);
}

/** Validates `x` and `y` as the components of the 2D vector `name` and returns them as a new frozen pair. */
export function frozenPair(name: string, x: number, y: number): readonly [number, number] {
  // The labels are built only for a message: this runs for every point and every move.
  if (!isFloat32Finite(x)) assertFinite(`${name}[0]`, x);
  if (!isFloat32Finite(y)) assertFinite(`${name}[1]`, y);
  return Object.freeze([x, y] as const);
}

/**
 * Checks each vector of `list` as {@link frozenVec2} does (named `name[i]` in a message, the name
 * built only for one) and returns them as `[x0, y0, x1, y1, …]`.
 */
export function vec2ListCoords(name: string, list: ArrayLike<Vec2Like>): Float64Array {
  const coords = new Float64Array(2 * list.length);
  for (let i = 0; i < list.length; i++) {
    const value = list[i];
    if (!isFinitePair(value)) frozenVec2(`${name}[${i}]`, value);
    coords[2 * i] = value[0];
    coords[2 * i + 1] = value[1];
  }
  return coords;
}

function isFinitePair(value: Vec2Like): boolean {
  return typeof value === 'object' && value !== null && value.length >= 2 && isFloat32Finite(value[0]) && isFloat32Finite(value[1]);
}

/** Validates an RGB colour (finite, non-negative channels) and returns it as a new frozen triple. */
export function frozenColor(name: string, value: ColorLike): readonly [number, number, number] {
  assertArrayLike(name, value, 3, 'an [r, g, b] triple');
  return Object.freeze([
    assertNonNegative(`${name}[0]`, value[0]), assertNonNegative(`${name}[1]`, value[1]), assertNonNegative(`${name}[2]`, value[2]),
  ] as const);
}

function assertArrayLike(name: string, value: ArrayLike<number>, length: number, expected: string): void {
  if (typeof value !== 'object' || value === null || typeof value.length !== 'number') {
    throw new TypeError(`${name} must be ${expected}, got ${describeValue(value)}`);
  }
  if (value.length < length) throw new RangeError(`${name} must be ${expected}, got ${describeValue(value)}`);
}

/** How many characters of a value or key an error message shows: input may be megabytes long. */
const SHOWN_LENGTH = 80;
/** How deep {@link describeValue} shows nested arrays and objects: input may nest thousands deep, or loop. */
const SHOWN_DEPTH = 3;

/** `text`, cut to about 80 characters with an ellipsis. */
export function shortened(text: string): string {
  return text.length > SHOWN_LENGTH ? `${text.slice(0, SHOWN_LENGTH - 1)}…` : text;
}

/**
 * A short, JSON-like rendering of any value for an error message (`[1,NaN]`, `"text"`, `10n`,
 * `Symbol(x)`, holes as `[,1]`): at most about 80 characters and 3 levels deep, so cycles end.
 * It never throws and never runs the value's own code (no `toString`, no getters).
 */
export function describeValue(value: unknown): string {
  try {
    return shortened(render(value, 0));
  } catch {
    // A revoked proxy or a proxy whose traps throw.
    return 'an unreadable object';
  }
}

function render(value: unknown, depth: number): string {
  switch (typeof value) {
    case 'string': return JSON.stringify(shortened(value));
    case 'number': return Object.is(value, -0) ? '-0' : String(value);
    case 'bigint': return `${shortened(String(value))}n`;
    case 'symbol': return shortened(value.toString());
    case 'function': return 'a function';
    case 'object': return value === null ? 'null' : renderObject(value, depth);
    default: return String(value);
  }
}

/** An array as `[a,b]` (a hole as nothing), another object as `{"key":value}`; stops once past the shown length. */
function renderObject(value: object, depth: number): string {
  const isArray = Array.isArray(value);
  if (depth >= SHOWN_DEPTH) return isArray ? '[…]' : '{…}';
  const keys = isArray ? arrayIndices(value) : Object.keys(value);
  const parts: string[] = [];
  let length = 0;
  for (const key of keys) {
    if (length > SHOWN_LENGTH) {
      parts.push('…');
      break;
    }
    const descriptor = Object.getOwnPropertyDescriptor(value, key);
    const shown = descriptor === undefined ? '' : 'value' in descriptor ? render(descriptor.value, depth + 1) : 'a getter';
    const part = isArray ? shown : `${JSON.stringify(shortened(key))}:${shown}`;
    parts.push(part);
    length += part.length + 1;
  }
  return isArray ? `[${parts.join(',')}]` : `{${parts.join(',')}}`;
}

/** The indices of an array, lazily: a sparse array may be billions long. */
function* arrayIndices(array: readonly unknown[]): Generator<string> {
  for (let i = 0; i < array.length; i++) yield String(i);
}
