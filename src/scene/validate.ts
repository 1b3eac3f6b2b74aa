/** A 2D vector given as an `[x, y]` pair. */
export type Vec2Like = readonly [number, number] | ArrayLike<number>;
/** An RGB colour with channels in 0..1 (values above 1 are allowed and over-brighten). */
export type ColorLike = readonly [number, number, number] | ArrayLike<number>;

/** Throws a `RangeError` naming `name` unless `value` is a finite number. */
export function assertFinite(name: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new RangeError(`${name} must be a finite number, got ${String(value)}`);
  }
  return value;
}

/** Throws a `RangeError` naming `name` unless `value` is a finite number ≥ 0. */
export function assertNonNegative(name: string, value: number): number {
  assertFinite(name, value);
  if (value < 0) throw new RangeError(`${name} must not be negative, got ${value}`);
  return value;
}

/** Validates a 2D vector and copies it into `target`. */
export function copyVec2(name: string, value: Vec2Like, target: [number, number]): void {
  if (value == null || typeof value.length !== 'number' || value.length < 2) {
    throw new RangeError(`${name} must be an [x, y] pair, got ${describe(value)}`);
  }
  target[0] = assertFinite(`${name}[0]`, value[0]);
  target[1] = assertFinite(`${name}[1]`, value[1]);
}

/** Validates an RGB colour (finite, non-negative channels) and copies it into `target`. */
export function copyColor(name: string, value: ColorLike, target: [number, number, number]): void {
  if (value == null || typeof value.length !== 'number' || value.length < 3) {
    throw new RangeError(`${name} must be an [r, g, b] triple, got ${describe(value)}`);
  }
  for (let i = 0; i < 3; i++) target[i] = assertNonNegative(`${name}[${i}]`, value[i]);
}

function describe(value: unknown): string {
  try {
    return JSON.stringify(value) ?? String(value);
  } catch {
    return String(value);
  }
}
