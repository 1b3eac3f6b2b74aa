/**
 * The GPU layouts of the shadow data, written by `ShadowGeometry` and `ShadowBins` and read by
 * shaders/chunks/shadow-visibility.glsl, which receives these constants as defines
 * ({@link SHADOW_DEFINES}). All three textures are RGBA32F.
 *
 * - **Records** (one texture for all hulls, changed only when a hull does): each hull is one or
 *   more convex polygons of at most {@link RECORD_POINTS} world points, positive (counter-clockwise
 *   in x-right, y-up axes) area, two points per texel, unused slots repeating the last point. A
 *   convex hull of up to that many points is one record; a larger convex hull is a fan of records;
 *   a concave hull is its triangles. A segment is blocked by a hull exactly when it is blocked by one
 *   of its records, so the union over records is the union over hulls.
 * - **Entries** (per frame): per light and angular bin, the records whose shadow can reach the bin,
 *   nearest first: `(first texel of the record, point count, distance from the light's centre to the
 *   record, 0)`.
 * - **Bins** (per frame): one row per shadowed light, {@link BIN_COUNT} texels, bin `k` covering the
 *   directions from the light's centre with angle `atan(y, x)` in `[-π + 2πk/N, -π + 2π(k+1)/N)`:
 *   `(first entry, entry count, 0, 0)`.
 */

/** Points per record: a tile (4) or an octagon (8) is one record. */
export const RECORD_POINTS = 8;
/** Texels per record: two points each. */
export const RECORD_TEXELS = RECORD_POINTS / 2;
/** Floats per record. */
export const RECORD_FLOATS = RECORD_POINTS * 2;
/** Width in texels of the records and entries textures. */
export const TEXTURE_WIDTH = 1024;
/** Records per row of the records texture. */
export const RECORDS_PER_ROW = TEXTURE_WIDTH / RECORD_TEXELS;
/** Floats per entry. */
export const ENTRY_FLOATS = 4;
/** Angular bins per light: the width of the bins texture. */
export const BIN_COUNT = 256;
/** Floats per bin. */
export const BIN_FLOATS = 4;

/** The layout constants the shader reads, as `#define`s. */
export const SHADOW_DEFINES: Readonly<Record<string, number>> = { RECORD_TEXELS, TEXTURE_WIDTH, BIN_COUNT };
