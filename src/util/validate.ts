/**
 * A point or 2D vector, in any of the forms engines use:
 * - an `[x, y]` pair, or any array-like of at least 2 numbers (a `Float32Array`; extra elements
 *   are ignored);
 * - an object with numeric `x` and `y`: `{ x: 3, y: 4 }`, a PixiJS `Point` or `ObservablePoint`
 *   (`sprite.position`, `sprite.anchor`, `sprite.scale`), a Phaser `Vector2`. Only `x` and `y` are
 *   read, once, when the value is given: the point is copied, not followed.
 *
 * Getters return the library's own form, a frozen `[x, y]` pair.
 */
export type Vec2Like = readonly [number, number] | ArrayLike<number> | {
  /** The x component. */
  readonly x: number;
  /** The y component. */
  readonly y: number;
};

/**
 * An RGB colour, in any of the forms engines use:
 * - an `[r, g, b]` triple of floats, 0..1 per channel (any array-like of at least 3 numbers; extra
 *   elements are ignored). Channels above 1 over-brighten; negative ones are errors;
 * - a hex number `0xrrggbb`, an integer from `0x000000` to `0xffffff`, as PixiJS and Phaser take
 *   colours (`0xff8800`);
 * - a CSS string: `'#rrggbb'`, `'#rgb'` or `'rgb(r, g, b)'` (each channel 0–255 or a percentage,
 *   separated by commas or spaces), in any letter case. CSS colour names (`'red'`) and alpha are
 *   not taken: a name table would weigh on every bundle, and a light's colour has no alpha.
 *
 * A hex or CSS colour gives each channel its byte / 255, as it is: no sRGB decoding, the value a
 * PixiJS or Phaser tint of the same colour multiplies by, so `0x808080` is `[0.502, 0.502, 0.502]`.
 * Getters return the library's own form, a frozen `[r, g, b]` triple.
 */
export type ColorLike = readonly [number, number, number] | ArrayLike<number> | number | string;

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

/**
 * Throws a `TypeError` unless `options` is an object whose own keys are all in `known`: a misspelt
 * key (`positon`) fails where it is written instead of being ignored, as the scene reader rejects
 * unknown fields. The message names the key and, when a known key is close to it (a letter or two
 * off, another letter case, or one that starts with the other), suggests it:
 * `PointLight options.positon is not an option (did you mean 'position'?)`. `owner` starts every
 * message (`PointLight`, `PenumbraRenderer.illuminationAt:`). Only own enumerable string keys are
 * checked, whatever their value (`undefined` too); inherited ones are not read.
 */
export function assertOptions(owner: string, options: object, known: readonly string[]): void {
  if (typeof options !== 'object' || options === null) throw new TypeError(`${owner} options must be an object, got ${describeValue(options)}`);
  for (const key of Object.keys(options)) {
    if (known.includes(key)) continue;
    const suggestion = closestKey(key, known);
    const hint = suggestion === undefined ? `the options are ${known.join(', ')}` : `did you mean '${suggestion}'?`;
    throw new TypeError(`${owner} options${propertyPath(key)} is not an option (${hint})`);
  }
}

/** `.key` for a key that reads as an identifier, else `["key"]`, cut short. */
function propertyPath(key: string): string {
  return /^[A-Za-z_$][\w$]*$/.test(key) && key.length <= SHOWN_LENGTH ? `.${key}` : `[${JSON.stringify(shortened(key))}]`;
}

/**
 * The known key a misspelt `key` most likely meant, or undefined: the same in another letter case,
 * one that starts with the other (`ambient`, `ambientColor`), or within 1 edit (keys up to 4
 * letters) or 2 edits (longer ones) of it.
 */
function closestKey(key: string, known: readonly string[]): string | undefined {
  if (key.length > 2 * SHOWN_LENGTH) return undefined;
  const typed = key.toLowerCase();
  let best: string | undefined;
  let bestDistance = typed.length <= 4 ? 2 : 3;
  for (const candidate of known) {
    const lower = candidate.toLowerCase();
    const distance = lower === typed ? 0
      : typed.length >= 3 && (lower.startsWith(typed) || typed.startsWith(lower)) ? 1
        : editDistance(typed, lower);
    if (distance < bestDistance) {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best;
}

/** Levenshtein distance: the fewest insertions, deletions and substitutions that turn `a` into `b`. */
function editDistance(a: string, b: string): number {
  let previous = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const current = [i];
    for (let j = 1; j <= b.length; j++) {
      current[j] = Math.min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    }
    previous = current;
  }
  return previous[b.length];
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

/** What a {@link Vec2Like} must be, for messages. */
const VEC2_FORMS = 'an [x, y] pair or an { x, y } point';

/**
 * Validates a 2D vector in any {@link Vec2Like} form and returns it as a new frozen pair: the
 * scene classes hold their vectors frozen, so a vector handed out by a getter can never change.
 * A component is named `name[0]` in a message when the vector is array-like, `name.x` when it is
 * a point object.
 */
export function frozenVec2(name: string, value: Vec2Like): readonly [number, number] {
  readVec2(name, value, scratchPair, 0);
  return Object.freeze([scratchPair[0], scratchPair[1]] as const);
}

const scratchPair = new Float64Array(2);

/**
 * Checks `value` as {@link frozenVec2} does and writes its components to `out[at]` and
 * `out[at + 1]`. An array-like is read as one even when it also has `x` and `y`.
 */
function readVec2(name: string, value: Vec2Like, out: Float64Array, at: number): void {
  if (typeof value !== 'object' || value === null) throw new TypeError(`${name} must be ${VEC2_FORMS}, got ${describeValue(value)}`);
  let x: number, y: number, pointObject: boolean;
  if (isArrayLike(value)) {
    if (value.length < 2) throw new RangeError(`${name} must be ${VEC2_FORMS}, got ${describeValue(value)}`);
    x = value[0];
    y = value[1];
    pointObject = false;
  } else if ('x' in value || 'y' in value) {
    x = value.x;
    y = value.y;
    pointObject = true;
  } else {
    throw new TypeError(`${name} must be ${VEC2_FORMS}, got ${describeValue(value)}`);
  }
  // The labels are built only for a message: this runs for every point and every move.
  if (!isFloat32Finite(x)) assertFinite(pointObject ? `${name}.x` : `${name}[0]`, x);
  if (!isFloat32Finite(y)) assertFinite(pointObject ? `${name}.y` : `${name}[1]`, y);
  out[at] = x;
  out[at + 1] = y;
}

function isArrayLike(value: object): value is ArrayLike<number> {
  return typeof (value as Partial<ArrayLike<number>>).length === 'number';
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
 * built only for one; the forms may mix) and returns them as `[x0, y0, x1, y1, …]`.
 */
export function vec2ListCoords(name: string, list: ArrayLike<Vec2Like>): Float64Array {
  const coords = new Float64Array(2 * list.length);
  for (let i = 0; i < list.length; i++) {
    const value = list[i];
    if (isFinitePair(value)) {
      coords[2 * i] = value[0];
      coords[2 * i + 1] = value[1];
    } else {
      readVec2(`${name}[${i}]`, value, coords, 2 * i);
    }
  }
  return coords;
}

/** Whether `value` is an array-like whose first two elements are finite as float32: the common case, checked without building a name. */
function isFinitePair(value: Vec2Like): value is ArrayLike<number> {
  return typeof value === 'object' && value !== null && isArrayLike(value) && value.length >= 2 && isFloat32Finite(value[0]) && isFloat32Finite(value[1]);
}

/** What a {@link ColorLike} must be, for messages. */
const COLOR_FORMS = "an [r, g, b] triple, a 0xrrggbb number or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string";

/**
 * Validates an RGB colour in any {@link ColorLike} form and returns it as a new frozen `[r, g, b]`
 * triple of floats. A malformed array-like names its channel (`name[1]`); a malformed number or
 * string is a `RangeError` that shows it and the forms taken.
 */
export function frozenColor(name: string, value: ColorLike): readonly [number, number, number] {
  if (typeof value === 'number') return Object.freeze(hexColor(name, value));
  if (typeof value === 'string') return Object.freeze(cssColor(name, value));
  if (typeof value !== 'object' || value === null || !isArrayLike(value)) throw new TypeError(`${name} must be ${COLOR_FORMS}, got ${describeValue(value)}`);
  if (value.length < 3) throw new RangeError(`${name} must be ${COLOR_FORMS}, got ${describeValue(value)}`);
  return Object.freeze([
    assertNonNegative(`${name}[0]`, value[0]), assertNonNegative(`${name}[1]`, value[1]), assertNonNegative(`${name}[2]`, value[2]),
  ] as const);
}

/** The channels of `0xrrggbb`, each byte / 255. */
function hexColor(name: string, value: number): [number, number, number] {
  if (!Number.isInteger(value) || value < 0 || value > 0xffffff) {
    throw new RangeError(`${name} must be ${COLOR_FORMS}; a number must be an integer from 0x000000 to 0xffffff, got ${describeValue(value)}`);
  }
  return [(value >> 16) / 255, ((value >> 8) & 0xff) / 255, (value & 0xff) / 255];
}

/** `#rgb` and `#rrggbb` (any letter case). */
const HEX_COLOR = /^#([0-9a-f]{3}|[0-9a-f]{6})$/i;
/** `rgb(r, g, b)` or `rgb(r g b)`: three numbers, each alone or as a percentage. */
const RGB_COLOR = /^rgb\(\s*([^\s,()]+)\s*(?:,\s*|\s+)([^\s,()]+)\s*(?:,\s*|\s+)([^\s,()]+)\s*\)$/i;
/** A CSS number, optionally a percentage. */
const CSS_CHANNEL = /^(?:\d+(?:\.\d*)?|\.\d+)(?:e[+-]?\d+)?%?$/i;

/** The channels of a CSS colour string (see {@link ColorLike}), surrounding spaces ignored. */
function cssColor(name: string, value: string): [number, number, number] {
  const text = value.trim();
  const hex = HEX_COLOR.exec(text);
  if (hex) {
    const digits = hex[1].length === 3 ? hex[1].replace(/./g, '$&$&') : hex[1];
    return hexColor(name, parseInt(digits, 16));
  }
  const rgb = RGB_COLOR.exec(text);
  if (rgb) {
    const channels = [rgb[1], rgb[2], rgb[3]].map(cssChannel);
    if (channels.every((channel) => channel >= 0 && channel <= 1)) return channels as [number, number, number];
  }
  throw new RangeError(`${name} must be ${COLOR_FORMS} (channels 0–255 or 0–100%), got ${describeValue(value)}`);
}

/** One `rgb()` channel as 0..1 (0–255, or a percentage), NaN when it is not a CSS number. */
function cssChannel(text: string): number {
  if (!CSS_CHANNEL.test(text)) return NaN;
  return text.endsWith('%') ? parseFloat(text) / 100 : parseFloat(text) / 255;
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
