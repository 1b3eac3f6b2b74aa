import { TILE_COLUMNS } from './shadowLayout';

/**
 * A row of a light's tiles as a bit mask, tile i at bit i: marking a span, the classes' logic and
 * counting are word operations, not per tile (TILE_COLUMNS ≤ 32). Masks are int32 (Int32Array),
 * and no function returns one (see Hot-path rules in docs/architecture.md).
 */
export const FULL_ROW = TILE_COLUMNS === 32 ? -1 : (1 << TILE_COLUMNS) - 1;

/** Sets tiles `first` to `last` (0 ≤ first ≤ last < TILE_COLUMNS) in the mask `masks[index]`. */
export function markSpan(masks: Int32Array, index: number, first: number, last: number): void {
  masks[index] |= (FULL_ROW >>> (TILE_COLUMNS - 1 - last)) & (FULL_ROW << first);
}

/**
 * The set bits of `mask` from bit `i` (set) on, before the first clear one: at least 1. Int32
 * shifts only (`>>>` makes a uint32).
 */
export function runFrom(mask: number, i: number): number {
  // Its lowest set bit is the first clear bit from i on; none when the bits from i on are all set
  // (the shift copies bit 31 into those above 31 − i).
  const rest = ~(mask >> i);
  return rest === 0 ? TILE_COLUMNS - i : 31 - Math.clz32(rest & -rest);
}

/** The set bits of a 32-bit word. */
export function bitCount(word: number): number {
  let v = word - ((word >>> 1) & 0x55555555);
  v = (v & 0x33333333) + ((v >>> 2) & 0x33333333);
  return Math.imul((v + (v >>> 4)) & 0x0f0f0f0f, 0x01010101) >>> 24;
}
