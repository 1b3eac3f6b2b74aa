import { holeFreeRegions } from '../geometry/gridRegions';
import { traceOutlines } from '../geometry/tileOutlines';
import { Hull } from './Hull';
import { assertOptions, describeValue, type Vec2Like } from './validate';

/**
 * A tile grid: an array of rows (`number[][]`, `boolean[][]`, strings…; all rows the same length),
 * a flat row-major array (`options.width` says how wide; e.g. a Tiled layer's `data`), or a
 * function `(x, y) => value` (`options.width` and `options.height` say how large).
 */
export type TileGrid<T = number | boolean> = ArrayLike<ArrayLike<T>> | ArrayLike<T> | ((x: number, y: number) => T);

/** Options of {@link hullsFromTiles} and {@link TileHulls}; every field has the default shown. */
export interface TileHullsOptions<T = number | boolean> {
  /** Width and height of a tile in world units: one number or `[w, h]`, each > 0. Default `1`. */
  tileSize?: number | Vec2Like;
  /** World position of the top-left corner of tile (0, 0); tile (x, y) spans `position + [x, y] × tileSize`. Default `[0, 0]`. */
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
}

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
 * Each 4-connected group of solid tiles becomes one hull, its outline traced along the tile edges
 * with collinear points removed (a 16-tile wall is a 4-point rectangle). A group that encloses
 * empty tiles (a room's walls) or touches itself at a corner is cut along tile-row boundaries into
 * a few simple polygons (a room's ring becomes 2 hulls): every hull is valid, and hulls only meet
 * along edges. Points are in world units (`position` + tile corner × `tileSize`); each hull's own
 * `position` is `[0, 0]`.
 *
 * O(tiles) plus the hulls' own triangulation. To change tiles later without rebuilding them all,
 * keep a {@link TileHulls} instead.
 * @throws TypeError or RangeError for a grid or option of the wrong shape, naming it and the value.
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
 * one tile and rebuilds only the hulls of the group of tiles it touches, returning the hulls to add
 * to and remove from the renderer. The other hulls stay the same objects.
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
  /** Tiles per row. */
  readonly width: number;
  /** Rows of tiles. */
  readonly height: number;
  private readonly tileWidth: number;
  private readonly tileHeight: number;
  private readonly originX: number;
  private readonly originY: number;
  private readonly name: string;
  /** 1 for a solid tile, row-major. */
  private readonly cells: Uint8Array;
  /** The piece (hull slot) of each solid tile, −1 for an empty one. */
  private readonly pieces: Int32Array;
  private readonly slots: Array<Hull | undefined> = [];
  private readonly freeSlots: number[] = [];
  private hullList: readonly Hull[] | null = null;
  /** Marks the tiles of one update: `mark[i] === markValue`. */
  private readonly mark: Int32Array;
  private markValue = 0;

  /**
   * Reads `grid` (see {@link TileGrid}) and builds its hulls, as {@link hullsFromTiles} does.
   * @throws TypeError or RangeError for a grid or option of the wrong shape, naming it and the value.
   */
  constructor(grid: ArrayLike<ArrayLike<T>>, options?: TileHullsOptions<T>);
  constructor(grid: ArrayLike<T>, options: TileHullsOptions<T> & { width: number });
  constructor(grid: (x: number, y: number) => T, options: TileHullsOptions<T> & { width: number; height: number });
  constructor(grid: TileGrid<T>, options: TileHullsOptions<T> = {}) {
    const name = this.name = messageName;
    assertOptions(name, options);
    [this.tileWidth, this.tileHeight] = readTileSize(name, options.tileSize);
    [this.originX, this.originY] = readPosition(name, options.position);
    const read = readGrid(name, grid, options as TileHullsOptions<unknown>, readSolid(name, options.solid));
    this.width = read.width;
    this.height = read.height;
    this.cells = read.cells;
    this.pieces = new Int32Array(this.cells.length).fill(-1);
    this.mark = new Int32Array(this.cells.length);
    this.rebuild(0, 0, this.width, this.height, (i) => this.cells[i] === 1);
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
   * Makes tile (x, y) solid or empty and rebuilds the hulls of the tiles it touches: the group of
   * solid tiles it joins or leaves (4-connected, so corners do not count). Returns the hulls that
   * replace the old ones of that group, and the old ones; both empty when the tile already was so.
   *
   * O(size of the group's bounding box), plus triangulating its new hulls; the rest of the grid is
   * not looked at.
   * @throws RangeError for a tile outside the grid, TypeError for a non-boolean `solid`.
   */
  setTile(x: number, y: number, solid: boolean): TileHullsChange {
    if (!Number.isInteger(x) || x < 0 || x >= this.width) throw new RangeError(`${this.name}.setTile x must be an integer in 0..${this.width - 1}, got ${describeValue(x)}`);
    if (!Number.isInteger(y) || y < 0 || y >= this.height) throw new RangeError(`${this.name}.setTile y must be an integer in 0..${this.height - 1}, got ${describeValue(y)}`);
    if (typeof solid !== 'boolean') throw new TypeError(`${this.name}.setTile solid must be true or false, got ${describeValue(solid)}`);
    const w = this.width, tile = y * w + x;
    if ((this.cells[tile] === 1) === solid) return { added: [], removed: [] };
    this.cells[tile] = solid ? 1 : 0;

    // The groups the tile now belongs to or leaves: flood the solid tiles from it (or its neighbours).
    const value = ++this.markValue, mark = this.mark, cells = this.cells;
    const stack: number[] = [];
    const push = (i: number) => {
      if (cells[i] === 1 && mark[i] !== value) {
        mark[i] = value;
        stack.push(i);
      }
    };
    if (solid) push(tile);
    else {
      if (x > 0) push(tile - 1);
      if (x + 1 < w) push(tile + 1);
      if (y > 0) push(tile - w);
      if (y + 1 < this.height) push(tile + w);
    }
    let x0 = x, y0 = y, x1 = x, y1 = y;
    const oldPieces = new Set<number>();
    if (this.pieces[tile] >= 0) oldPieces.add(this.pieces[tile]);
    this.pieces[tile] = -1;
    for (let k = 0; k < stack.length; k++) {
      const i = stack[k], cx = i % w, cy = (i - cx) / w;
      if (this.pieces[i] >= 0) oldPieces.add(this.pieces[i]);
      if (cx < x0) x0 = cx;
      if (cx > x1) x1 = cx;
      if (cy < y0) y0 = cy;
      if (cy > y1) y1 = cy;
      if (cx > 0) push(i - 1);
      if (cx + 1 < w) push(i + 1);
      if (cy > 0) push(i - w);
      if (cy + 1 < this.height) push(i + w);
    }

    const removed: Hull[] = [];
    for (const slot of oldPieces) {
      removed.push(this.slots[slot]!);
      this.slots[slot] = undefined;
      this.freeSlots.push(slot);
    }
    const added = stack.length === 0 ? [] : this.rebuild(x0, y0, x1 + 1, y1 + 1, (i) => mark[i] === value);
    this.hullList = null;
    return { added, removed };
  }

  /**
   * Splits the tiles `inSet` of the box [x0, x1) × [y0, y1) into regions, traces them and gives
   * each a hull in a free slot, labelling its tiles. Every tile `inSet` must be solid and its group
   * wholly in the set.
   */
  private rebuild(x0: number, y0: number, x1: number, y1: number, inSet: (i: number) => boolean): Hull[] {
    const w = this.width, bw = x1 - x0, bh = y1 - y0;
    const { labels, count } = holeFreeRegions({ width: bw, height: bh, solid: (x, y) => inSet((y + y0) * w + x + x0) });
    const outlines = traceOutlines(labels, bw, bh, count);
    const slotOf = new Int32Array(count), added: Hull[] = [];
    for (let r = 0; r < count; r++) {
      const outline = outlines[r], coords = new Float64Array(outline.length);
      for (let k = 0; k < outline.length; k += 2) {
        coords[k] = this.originX + (outline[k] + x0) * this.tileWidth;
        coords[k + 1] = this.originY + (outline[k + 1] + y0) * this.tileHeight;
      }
      const hull = Hull.fromCoords(coords);
      const slot = this.freeSlots.pop() ?? this.slots.length;
      this.slots[slot] = hull;
      slotOf[r] = slot;
      added.push(hull);
    }
    for (let by = 0; by < bh; by++) {
      for (let bx = 0; bx < bw; bx++) {
        const label = labels[by * bw + bx];
        if (label >= 0) this.pieces[(by + y0) * w + bx + x0] = slotOf[label];
      }
    }
    this.hullList = null;
    return added;
  }
}

function readTileSize(name: string, value: number | Vec2Like | undefined): [number, number] {
  if (value === undefined) return [1, 1];
  const pair = typeof value === 'number' ? [value, value] : value;
  const valid = typeof pair === 'object' && pair !== null && pair.length >= 2
    && [pair[0], pair[1]].every((v) => typeof v === 'number' && v > 0 && Number.isFinite(v));
  if (!valid) {
    const wrongType = typeof value !== 'number' && (typeof value !== 'object' || value === null || typeof value.length !== 'number');
    throw new (wrongType ? TypeError : RangeError)(`${name} options.tileSize must be a positive finite number or [w, h] pair, got ${describeValue(value)}`);
  }
  return [pair[0], pair[1]];
}

function readPosition(name: string, value: Vec2Like | undefined): [number, number] {
  if (value === undefined) return [0, 0];
  if (typeof value !== 'object' || value === null || typeof value.length !== 'number') {
    throw new TypeError(`${name} options.position must be an [x, y] pair, got ${describeValue(value)}`);
  }
  if (value.length < 2 || !Number.isFinite(value[0]) || !Number.isFinite(value[1])) {
    throw new RangeError(`${name} options.position must be an [x, y] pair of finite numbers, got ${describeValue(value)}`);
  }
  return [value[0], value[1]];
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
    const cells = new Uint8Array(width * height);
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) cells[y * width + x] = isSolid(grid(x, y), x, y, () => `grid(${x}, ${y})`) ? 1 : 0;
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
  const cells = new Uint8Array(width * height);
  for (let y = 0; y < height; y++) {
    const row = (grid as ArrayLike<ArrayLike<unknown>>)[y];
    for (let x = 0; x < width; x++) cells[y * width + x] = isSolid(row[x], x, y, () => `grid[${y}][${x}]`) ? 1 : 0;
  }
  return { width, height, cells };
}

function isArrayLike(value: unknown): value is ArrayLike<unknown> {
  return typeof value === 'string' || (typeof value === 'object' && value !== null && typeof (value as { length?: unknown }).length === 'number');
}
