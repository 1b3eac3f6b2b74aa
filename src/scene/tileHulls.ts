import { holeFreeRegions } from '../geometry/gridRegions';
import { traceOutlines } from '../geometry/tileOutlines';
import { Hull } from './Hull';
import { assertFinite, assertOptions, describeValue, frozenVec2, type Vec2Like } from '../util/validate';

/**
 * A tile grid: an array of rows (`number[][]`, `boolean[][]`, strings…; all rows the same length),
 * a flat row-major array (`options.width` says how wide; e.g. a Tiled layer's `data`), or a
 * function `(x, y) => value` (`options.width` and `options.height` say how large).
 */
export type TileGrid<T = number | boolean> = ArrayLike<ArrayLike<T>> | ArrayLike<T> | ((x: number, y: number) => T);

/** Options of {@link hullsFromTiles} and {@link TileHulls}; every field has the default shown. */
export interface TileHullsOptions<T = number | boolean> {
  /** Width and height of a tile in world units: one number, `[w, h]` or `{ x: w, y: h }`, each > 0. Default `1`. */
  tileSize?: number | Vec2Like;
  /**
   * World position of the top-left corner of tile (0, 0), `[x, y]` or `{ x, y }`; tile (x, y) spans
   * `position + [x, y] × tileSize`. Default `[0, 0]`.
   */
  position?: Vec2Like;
  /**
   * Which tile values are solid: one value, a list of values, or a test `(value, x, y) => boolean`.
   * Default: non-zero numbers and `true` (any other value is then an error).
   */
  solid?: T | readonly T[] | ((value: T, x: number, y: number) => boolean);
  /** Tiles per row: required for a flat array (which it marks as flat) and for a function. */
  width?: number;
  /** Rows: required for a function; for a flat array, its length / `width` unless given. */
  height?: number;
  /**
   * Side, in tiles, of the square chunks the grid is cut into from tile (0, 0): a positive integer.
   * Each chunk's solid tiles make their own hulls, so a group of tiles that spans chunks (a level's
   * joined walls) is cut along the chunks' edges, and {@link TileHulls.setTile} rebuilds hulls of
   * one chunk only. Larger chunks make fewer hulls and slower edits. Default `32`.
   */
  chunkSize?: number;
}

/** The options {@link TileHulls} and {@link hullsFromTiles} take; any other key is an error (see {@link assertOptions}). */
const OPTION_KEYS: readonly string[] = Object.keys({
  tileSize: true, position: true, solid: true, width: true, height: true, chunkSize: true,
} satisfies Record<keyof TileHullsOptions, true>);

/** Tiles per side of a chunk unless `options.chunkSize` says otherwise. */
const DEFAULT_CHUNK_SIZE = 32;
/** Most tiles in a grid ({@link TileHulls.maxTiles}). */
const MAX_TILES = 2 ** 28;

/** What {@link TileHulls.setTile} changed: hulls to add to the renderer and hulls to remove from it. */
export interface TileHullsChange {
  /** New hulls, now in {@link TileHulls.hulls}: add them to the renderer. */
  readonly added: Hull[];
  /** Hulls no longer in {@link TileHulls.hulls}: remove them from the renderer. */
  readonly removed: Hull[];
}

/**
 * Hulls covering exactly the solid tiles of a grid: `hullsFromTiles(level, { tileSize: 32 })`.
 *
 * Each 4-connected group of solid tiles within a chunk (a square of `chunkSize` tiles, 32 by
 * default) becomes one hull, its outline traced along the tile edges with collinear points removed
 * (a 16-tile wall is a 4-point rectangle); a group that spans chunks is cut along their edges. A
 * group that encloses empty tiles (a room's walls) or touches itself at a corner is cut along
 * tile-row boundaries into a few simple polygons (a small room's ring becomes 2 hulls): every hull
 * is valid, and hulls only meet along edges, with exactly the same points on both sides, so their
 * shadows join without a gap (a light sees past the union of the hulls). Points are in world units
 * (`position` + tile corner × `tileSize`); each hull's own `position` is `[0, 0]`.
 *
 * O(tiles) plus the hulls' own triangulation. To change tiles later without rebuilding them all,
 * keep a {@link TileHulls} instead.
 * @throws TypeError or RangeError for a grid or option of the wrong shape, or a grid of more than
 * {@link TileHulls.maxTiles} tiles, naming it and the value.
 */
export function hullsFromTiles<T>(grid: ArrayLike<ArrayLike<T>>, options?: TileHullsOptions<T>): Hull[];
export function hullsFromTiles<T>(grid: ArrayLike<T>, options: TileHullsOptions<T> & { width: number }): Hull[];
export function hullsFromTiles<T>(grid: (x: number, y: number) => T, options: TileHullsOptions<T> & { width: number; height: number }): Hull[];
export function hullsFromTiles(grid: TileGrid<unknown>, options: TileHullsOptions<unknown> = {}): Hull[] {
  messageName = 'hullsFromTiles';
  try {
    return [...new TileHulls(grid as ArrayLike<ArrayLike<unknown>>, options).hulls];
  } finally {
    messageName = 'TileHulls';
  }
}

/** The name error messages start with: the function or the class the caller used. */
let messageName = 'TileHulls';

/**
 * The hulls of a tile grid, kept up to date as tiles change: {@link hullsFromTiles} that can be
 * edited. The grid is read once, into solid or empty; after that {@link TileHulls.setTile} changes
 * one tile and rebuilds only the hulls of its chunk whose outline changes, returning the hulls to
 * add to and remove from the renderer. The other hulls stay the same objects.
 *
 * ```ts
 * const walls = new TileHulls(level, { tileSize: 32 });
 * for (const hull of walls.hulls) renderer.addHull(hull);
 * const { added, removed } = walls.setTile(4, 7, false); // a wall knocked down
 * ```
 *
 * The hulls after any sequence of changes are those that {@link hullsFromTiles} makes of the
 * grid as it then is.
 */
export class TileHulls<T = unknown> {
  /**
   * Most tiles a grid may hold (`width × height`), and most tiles along one side: 2²⁸ =
   * 268,435,456 (16,384²). One byte is kept per tile; a larger grid is refused before anything is
   * allocated or read.
   */
  static readonly maxTiles = MAX_TILES;
  /** Tiles per row. */
  readonly width: number;
  /** Rows of tiles. */
  readonly height: number;
  /** Side of the square chunks, in tiles (see {@link TileHullsOptions.chunkSize}). */
  readonly chunkSize: number;
  private readonly tileWidth: number;
  private readonly tileHeight: number;
  private readonly originX: number;
  private readonly originY: number;
  private readonly name: string;
  /** 1 for a solid tile, row-major. */
  private readonly cells: Uint8Array;
  /** Chunks per row of chunks. */
  private readonly chunkColumns: number;
  /** Per chunk (row-major): the slots of its hulls; undefined when it has none. */
  private readonly chunkSlots: Array<number[] | undefined> = [];
  private readonly slots: Array<Hull | undefined> = [];
  /** Per slot: its hull's outline in tile corners, `[x0, y0, x1, y1, …]` from tile (0, 0). */
  private readonly outlines: Array<Int32Array | undefined> = [];
  private readonly freeSlots: number[] = [];
  private hullList: readonly Hull[] | null = null;

  /**
   * Reads `grid` (see {@link TileGrid}) and builds its hulls, as {@link hullsFromTiles} does.
   * @throws TypeError or RangeError for a grid or option of the wrong shape, or a grid of more than
   * {@link TileHulls.maxTiles} tiles, naming it and the value.
   */
  constructor(grid: ArrayLike<ArrayLike<T>>, options?: TileHullsOptions<T>);
  constructor(grid: ArrayLike<T>, options: TileHullsOptions<T> & { width: number });
  constructor(grid: (x: number, y: number) => T, options: TileHullsOptions<T> & { width: number; height: number });
  constructor(grid: TileGrid<T>, options: TileHullsOptions<T> = {}) {
    const name = this.name = messageName;
    assertOptions(name, options, OPTION_KEYS);
    [this.tileWidth, this.tileHeight] = readTileSize(name, options.tileSize);
    [this.originX, this.originY] = readPosition(name, options.position);
    this.chunkSize = readChunkSize(name, options.chunkSize);
    const read = readGrid(name, grid, options as TileHullsOptions<unknown>, readSolid(name, options.solid));
    this.width = read.width;
    this.height = read.height;
    this.cells = read.cells;
    this.chunkColumns = Math.ceil(this.width / this.chunkSize);
    const chunks = this.chunkColumns * Math.ceil(this.height / this.chunkSize);
    for (let chunk = 0; chunk < chunks; chunk++) this.rebuildChunk(chunk, [], []);
  }

  /** The current hulls (a new array after each change; the same one until then). */
  get hulls(): readonly Hull[] {
    return this.hullList ??= Object.freeze(this.slots.filter((hull): hull is Hull => hull !== undefined));
  }

  /** Whether tile (x, y) is solid; false outside the grid. */
  isSolid(x: number, y: number): boolean {
    return x >= 0 && y >= 0 && x < this.width && y < this.height && this.cells[y * this.width + x] === 1;
  }

  /**
   * Makes tile (x, y) solid or empty and rebuilds the hulls of its chunk whose outline that
   * changes. Returns the new hulls and the old ones they replace; both empty when the tile already
   * was so. Every other hull stays the same object, unchanged (a renderer does not see it move).
   *
   * O(chunkSize²), plus triangulating the new hulls; the rest of the grid is not looked at.
   * @throws RangeError for a tile outside the grid, TypeError for a non-boolean `solid`.
   */
  setTile(x: number, y: number, solid: boolean): TileHullsChange {
    if (!Number.isInteger(x) || x < 0 || x >= this.width) throw new RangeError(`${this.name}.setTile x must be an integer in 0..${this.width - 1}, got ${describeValue(x)}`);
    if (!Number.isInteger(y) || y < 0 || y >= this.height) throw new RangeError(`${this.name}.setTile y must be an integer in 0..${this.height - 1}, got ${describeValue(y)}`);
    if (typeof solid !== 'boolean') throw new TypeError(`${this.name}.setTile solid must be true or false, got ${describeValue(solid)}`);
    const tile = y * this.width + x;
    if ((this.cells[tile] === 1) === solid) return { added: [], removed: [] };
    this.cells[tile] = solid ? 1 : 0;
    const added: Hull[] = [], removed: Hull[] = [];
    this.rebuildChunk(Math.floor(y / this.chunkSize) * this.chunkColumns + Math.floor(x / this.chunkSize), added, removed);
    return { added, removed };
  }

  /**
   * Cuts the solid tiles of chunk `chunk` into regions and traces them. A region whose outline a
   * hull of the chunk already has keeps that hull; every other region gets a new hull (pushed to
   * `added`), and the chunk's hulls left over are dropped (pushed to `removed`).
   */
  private rebuildChunk(chunk: number, added: Hull[], removed: Hull[]): void {
    const size = this.chunkSize, width = this.width, cells = this.cells;
    const x0 = (chunk % this.chunkColumns) * size, y0 = Math.floor(chunk / this.chunkColumns) * size;
    const columns = Math.min(size, width - x0), rows = Math.min(size, this.height - y0);
    const { labels, count } = holeFreeRegions({ width: columns, height: rows, solid: (x, y) => cells[(y + y0) * width + x + x0] === 1 });
    const traced = traceOutlines(labels, columns, rows, count);
    // An outline starts at the top-left corner of its region's first tile: no two regions of a chunk share it.
    const cornerKey = (outline: Int32Array) => outline[1] * (width + 1) + outline[0];
    const oldSlots = new Map<number, number>();
    for (const slot of this.chunkSlots[chunk] ?? []) oldSlots.set(cornerKey(this.outlines[slot]!), slot);
    const slots: number[] = [];
    for (const local of traced) {
      const outline = new Int32Array(local.length);
      for (let k = 0; k < local.length; k += 2) {
        outline[k] = local[k] + x0;
        outline[k + 1] = local[k + 1] + y0;
      }
      const key = cornerKey(outline), old = oldSlots.get(key);
      if (old !== undefined && sameValues(this.outlines[old]!, outline)) {
        oldSlots.delete(key);
        slots.push(old);
      } else slots.push(this.addHull(outline, added));
    }
    for (const slot of oldSlots.values()) {
      removed.push(this.slots[slot]!);
      this.slots[slot] = this.outlines[slot] = undefined;
      this.freeSlots.push(slot);
    }
    this.chunkSlots[chunk] = slots.length > 0 ? slots : undefined;
    if (added.length > 0 || removed.length > 0) this.hullList = null;
  }

  /**
   * Makes the hull of `outline` (tile corners), puts it in a free slot and in `added`; returns the
   * slot. A corner's world point depends on the corner alone, so hulls that share an edge (across
   * a chunk's edge or a cut) have exactly the same points along it.
   */
  private addHull(outline: Int32Array, added: Hull[]): number {
    const coords = new Float64Array(outline.length);
    for (let k = 0; k < outline.length; k += 2) {
      coords[k] = this.originX + outline[k] * this.tileWidth;
      coords[k + 1] = this.originY + outline[k + 1] * this.tileHeight;
    }
    const hull = Hull.fromCoords(coords);
    const slot = this.freeSlots.pop() ?? this.slots.length;
    this.slots[slot] = hull;
    this.outlines[slot] = outline;
    added.push(hull);
    return slot;
  }
}

function sameValues(a: Int32Array, b: Int32Array): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

function readChunkSize(name: string, value: unknown): number {
  if (value === undefined) return DEFAULT_CHUNK_SIZE;
  if (typeof value !== 'number') throw new TypeError(`${name} options.chunkSize must be a positive integer, got ${describeValue(value)}`);
  if (!Number.isInteger(value) || value < 1) throw new RangeError(`${name} options.chunkSize must be a positive integer, got ${describeValue(value)}`);
  return value;
}

function readTileSize(name: string, value: number | Vec2Like | undefined): [number, number] {
  if (value === undefined) return [1, 1];
  const label = `${name} options.tileSize`;
  const [width, height] = typeof value === 'number' ? [assertFinite(label, value), value] : frozenVec2(label, value);
  if (!(width > 0 && height > 0)) throw new RangeError(`${label} must be a positive finite number or [w, h] pair, got ${describeValue(value)}`);
  return [width, height];
}

function readPosition(name: string, value: Vec2Like | undefined): readonly [number, number] {
  return value === undefined ? [0, 0] : frozenVec2(`${name} options.position`, value);
}

/** The test of a tile value: `undefined` for the default, which checks the value's type itself. */
type SolidTest = (value: unknown, x: number, y: number) => boolean;

function readSolid(name: string, solid: unknown): SolidTest | undefined {
  if (solid === undefined) return undefined;
  if (typeof solid === 'function') {
    return (value, x, y) => {
      const answer = (solid as SolidTest)(value, x, y);
      if (typeof answer !== 'boolean') throw new TypeError(`${name} options.solid must return true or false, got ${describeValue(answer)} for tile (${x}, ${y})`);
      return answer;
    };
  }
  if (Array.isArray(solid)) {
    const values = new Set<unknown>(solid);
    return (value) => values.has(value);
  }
  return (value) => value === solid;
}

/** The default test: a non-zero number or `true`; anything but a number or boolean is an error. */
function isSolidByDefault(name: string, label: () => string, value: unknown): boolean {
  if (typeof value === 'boolean') return value;
  if (typeof value === 'number' && !Number.isNaN(value)) return value !== 0;
  throw new TypeError(`${name} ${label()} must be a number or true/false (or say which values are solid with options.solid), got ${describeValue(value)}`);
}

function readGrid(name: string, grid: unknown, options: TileHullsOptions<unknown>, test: SolidTest | undefined): { width: number; height: number; cells: Uint8Array } {
  const size = (field: 'width' | 'height', value: unknown): number => {
    if (typeof value !== 'number') throw new TypeError(`${name} options.${field} must be a non-negative integer, got ${describeValue(value)}`);
    if (!Number.isInteger(value) || value < 0) throw new RangeError(`${name} options.${field} must be a non-negative integer, got ${describeValue(value)}`);
    return value;
  };
  const isSolid = (value: unknown, x: number, y: number, label: () => string) => (test ? test(value, x, y) : isSolidByDefault(name, label, value));

  if (typeof grid === 'function') {
    if (options.width === undefined || options.height === undefined) {
      throw new TypeError(`${name} options.width and options.height must be given for a grid function, got ${describeValue(options.width)} and ${describeValue(options.height)}`);
    }
    const width = size('width', options.width), height = size('height', options.height);
    assertTileCount(name, 'options.width', 'options.height', width, height);
    const cells = new Uint8Array(width * height), tileAt = grid as (x: number, y: number) => unknown;
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) cells[y * width + x] = isSolid(tileAt(x, y), x, y, () => `grid(${x}, ${y})`) ? 1 : 0;
    }
    return { width, height, cells };
  }
  if (!isArrayLike(grid)) {
    throw new TypeError(`${name} grid must be an array of rows, a flat array with options.width, or a function (x, y) => value, got ${describeValue(grid)}`);
  }

  if (options.width !== undefined) {
    const width = size('width', options.width);
    const height = options.height === undefined ? (width === 0 ? 0 : grid.length / width) : size('height', options.height);
    if (!Number.isInteger(height) || width * height !== grid.length) {
      throw new RangeError(`${name} grid must hold width × height = ${options.height === undefined ? `a multiple of ${width}` : width * height} tiles, got ${grid.length}`);
    }
    assertTileCount(name, 'options.width', 'height', width, height);
    const cells = new Uint8Array(width * height);
    for (let i = 0; i < cells.length; i++) {
      const x = i % width, y = (i - x) / width;
      cells[i] = isSolid(grid[i], x, y, () => `grid[${i}]`) ? 1 : 0;
    }
    return { width, height, cells };
  }

  const height = grid.length;
  if (options.height !== undefined && size('height', options.height) !== height) {
    throw new RangeError(`${name} options.height must match the grid's ${height} rows, got ${describeValue(options.height)}`);
  }
  let width = 0;
  for (let y = 0; y < height; y++) {
    const row = grid[y];
    if (!isArrayLike(row)) {
      throw new TypeError(`${name} grid[${y}] must be a row (an array or string of tiles; for a flat array give options.width), got ${describeValue(row)}`);
    }
    if (y === 0) width = row.length;
    else if (row.length !== width) throw new RangeError(`${name} grid[${y}] must have ${width} tiles like grid[0], got ${row.length}`);
  }
  assertTileCount(name, 'grid[0].length', 'grid.length', width, height);
  const cells = new Uint8Array(width * height);
  for (let y = 0; y < height; y++) {
    const row = (grid as ArrayLike<ArrayLike<unknown>>)[y];
    for (let x = 0; x < width; x++) cells[y * width + x] = isSolid(row[x], x, y, () => `grid[${y}][${x}]`) ? 1 : 0;
  }
  return { width, height, cells };
}

/**
 * Refuses a grid of more than {@link MAX_TILES} tiles, or with a side longer than that (an empty
 * grid of 0 × 2⁴⁰ tiles would still be walked row by row), before its tiles are allocated or read.
 */
function assertTileCount(name: string, widthField: string, heightField: string, width: number, height: number): void {
  for (const [field, value] of [[widthField, width], [heightField, height]] as const) {
    if (value > MAX_TILES) throw new RangeError(`${name} ${field} must be at most ${MAX_TILES} (TileHulls.maxTiles), got ${value}`);
  }
  if (width * height > MAX_TILES) {
    throw new RangeError(`${name} ${widthField} × ${heightField} must be at most ${MAX_TILES} tiles (TileHulls.maxTiles), got ${width} × ${height} = ${width * height}`);
  }
}

function isArrayLike(value: unknown): value is ArrayLike<unknown> {
  return typeof value === 'string' || (typeof value === 'object' && value !== null && typeof (value as { length?: unknown }).length === 'number');
}
