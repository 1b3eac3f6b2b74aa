import type { ShadowType } from '../scene/Light';

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
 * - **Entries** (per frame): per light and angular bin, the hulls whose shadow can reach the bin,
 *   ordered by distance buckets of the light's bin row, nearest first: `(code, x, y, radius)` with
 *   the records' code ({@link entryCode}) and a circle around the hull, from which the shader tells
 *   whether the hull can be between the pixel and the disk. A hull of more than
 *   {@link ENTRY_MAX_RECORDS} records takes several entries.
 * - **Bins** (per frame): one row per shadowed light, {@link BIN_COUNT} texels; bin `k` holds the
 *   directions from the light's centre whose pseudo-angle lies in `[4k / N, 4(k + 1) / N)`
 *   (the pseudo-angle of (x, y) is p = y / (|x| + |y|), then 2 − p for x < 0, else 4 + p for
 *   y < 0, else p: in [0, 4), 0 along +x, 1 along +y, increasing counter-clockwise in x-right,
 *   y-up axes, and growing at most 1 per radian, within a factor 2 of the angle; `pseudoAngle` in
 *   the chunk shadow-visibility, written inline by the filing, ShadowBins): two lists of entries,
 *   each ordered nearest first, as `(first entry, entry count)` at {@link STILL_LIST} and at {@link MOVING_LIST}: the hulls that
 *   stood still (kept with the light's filing) and those that moved lately (filed every frame). The
 *   width of the distance buckets is the light's uniform `u_binning.w`.
 *
 * - **Record tags** (one R32F texel per record, {@link RECORDS_PER_ROW} per row like the records,
 *   changed with them): which hull a record belongs to and which of its edges lie on that hull's
 *   outline ({@link recordTag}); what an Occluded light needs for a pixel inside a hull.
 *
 * Records are found by number: floats hold integers exactly below 2^24, so a scene may have up to
 * 2^24 / (2 × ENTRY_MAX_RECORDS) records.
 */

/** Points per record: a tile or a box is one record, a triangle repeats its last point. */
export const RECORD_POINTS = 4;
/** Texels per record: two points each. */
const RECORD_TEXELS = RECORD_POINTS / 2;
/** Floats per record. */
export const RECORD_FLOATS = RECORD_POINTS * 2;
/**
 * log2 of the width in texels of the records, entries and tile records textures. The widths, the
 * records per row and ENTRY_MAX_RECORDS are powers of two, so that the shaders address texels and
 * decode entries with shifts and masks: integer division and remainder are many instructions on
 * GPUs and on CPU rasterizers, even by a constant.
 */
const TEXTURE_WIDTH_BITS = 10;
/** Width in texels of the records, entries and tile records textures. */
export const TEXTURE_WIDTH = 1 << TEXTURE_WIDTH_BITS;
/** log2 of RECORDS_PER_ROW (RECORD_TEXELS is 2). */
const RECORDS_PER_ROW_BITS = TEXTURE_WIDTH_BITS - 1;
/** Records per row of the records texture. */
export const RECORDS_PER_ROW = 1 << RECORDS_PER_ROW_BITS;
/** Floats per entry: one texel. */
export const ENTRY_FLOATS = 4;
/** log2 of ENTRY_MAX_RECORDS. */
const ENTRY_RECORD_BITS = 5;
/** The most records one entry covers. */
export const ENTRY_MAX_RECORDS = 1 << ENTRY_RECORD_BITS;
/**
 * An entry's first record, record count and whether they are a whole convex hull's fan (the shader
 * then takes the hull's outline as the records' edges less the fan's inner diagonals), in one float:
 * `(first × ENTRY_MAX_RECORDS + count − 1) × 2 + fan`.
 */
export function entryCode(first: number, count: number, fan: boolean): number {
  return (first * ENTRY_MAX_RECORDS + count - 1) * 2 + (fan ? 1 : 0);
}

/** Bits of a record tag that flag its outline edges: one per edge, edge k from point k to k + 1. */
const TAG_EDGE_BITS = RECORD_POINTS;
/**
 * A record's tag: the first record of its hull (all a hull's records share it) and a mask of its
 * edges that lie on the hull's outline (a fan's or a triangulation's inner diagonals do not, nor do
 * an open hull's box sides, nor an edge of no length), as `hullFirst × 2^TAG_EDGE_BITS + mask`.
 */
export function recordTag(hullFirst: number, outlineEdges: number): number {
  return hullFirst * 2 ** TAG_EDGE_BITS + outlineEdges;
}

/**
 * How a light treats the inside of hulls, as the shader's codes (see `ShadowType`): 0 dark, 1 lit,
 * 2 lit where the light reaches it.
 */
export const SHADOW_TYPE_CODES = { solid: 0, illuminated: 1, occluded: 2 } as const satisfies Record<ShadowType, number>;

/** Angular bins per light: the width of the bins texture. */
export const BIN_COUNT = 32;
/** Floats per bin. */
export const BIN_FLOATS = 4;
/** Where a bin's list of hulls that stood still starts, in floats: the texel's x and y. */
export const STILL_LIST = 0;
/** Where a bin's list of hulls that moved lately starts, in floats: the texel's z and w. */
export const MOVING_LIST = 2;

/**
 * A shadowed point light's grid (see `LightTiles`): its filed bounds cut into TILE_COLUMNS ×
 * TILE_ROWS tiles, drawn as rectangles of tiles of one class whose corners are points of the grid
 * ({@link tileCorner}). A tile row is one int32 mask, so TILE_COLUMNS ≤ 32; rows cost a word each,
 * and more of them fit the tiles closer to the penumbrae's slanted edges.
 */
export const TILE_COLUMNS = 32;
export const TILE_ROWS = 64;

/**
 * The index of the grid's corner point (i, j), 0 ≤ i ≤ TILE_COLUMNS, 0 ≤ j ≤ TILE_ROWS, in the
 * tile grid's vertex buffer (`LightShapes`), which holds the points row by row as (i, j).
 */
export function tileCorner(i: number, j: number): number {
  return j * (TILE_COLUMNS + 1) + i;
}

/** Tiles per light. */
export const TILE_COUNT = TILE_COLUMNS * TILE_ROWS;

/**
 * **Tile records** (RG16UI: a 32-bit word's low and high halves, {@link TEXTURE_WIDTH} texels a row, {@link TILE_COUNT} per light from
 * texel `row × TILE_COUNT`, written by `TileRecordLists` when a light is classified): per tile
 * (`j × TILE_COLUMNS + i`), a mask of the light's listed records, bit k for its k-th (the light
 * pass's `u_listedRecords`, at most LISTED_RECORDS, nearest first), set when the record's shadow
 * region or box touches the tile. What a pixel of a listed tile walks instead of its bin.
 */
export const LISTED_RECORDS = 32;

/** Indices per light in the tile rectangles' index buffer: two triangles for each of its tiles, the most rectangles it can have. */
export const ROW_INDICES = 6 * TILE_COLUMNS * TILE_ROWS;

/**
 * A tile's class, what the light pass draws it with: nothing (outside the light's reach, or dark
 * where the shadows keep nothing), the plain light program (lit; dark with the colour the shadows
 * keep), the held program (an Illuminated light's tile in a record's umbra with hulls in it: lit
 * inside a hull, dark elsewhere; HELD_SHADOW), the lean exact program (every record that hides
 * part of the disk from a pixel of the tile lies wholly in front of the disk, and none holds a
 * pixel of an Occluded light: LEAN_SHADOW; see the chunk shadow-visibility), or the general exact
 * program; a lean tile whose records are listed (see {@link LISTED_RECORDS}) is **listed**, drawn
 * with the lean program that reads its tile's records instead of walking the bins (LISTED_TILES).
 */
export const TILE_CLASSES = { outside: 0, lit: 1, dark: 2, lean: 3, exact: 4, held: 5, listed: 6 } as const;
/** How many classes TILE_CLASSES has: the length of a light's tile counts. */
export const TILE_CLASS_COUNT = 7;

/** The layout constants the shader reads, as `#define`s. */
export const SHADOW_DEFINES: Readonly<Record<string, number>> = {
  RECORD_TEXELS, TEXTURE_WIDTH, TEXTURE_WIDTH_BITS, RECORDS_PER_ROW, RECORDS_PER_ROW_BITS, BIN_COUNT, ENTRY_MAX_RECORDS, ENTRY_RECORD_BITS, TAG_EDGE_BITS,
  TILE_COLUMNS, TILE_ROWS, TILE_COUNT, LISTED_RECORDS,
  SHADOW_SOLID: SHADOW_TYPE_CODES.solid, SHADOW_ILLUMINATED: SHADOW_TYPE_CODES.illuminated, SHADOW_OCCLUDED: SHADOW_TYPE_CODES.occluded,
};
