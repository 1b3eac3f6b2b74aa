import { TileHulls, type Hull } from 'penumbra-gl';
import { hullContains } from './hullShape';
import type { Playground } from './Playground';

/** Tile sizes the panel offers, in world units. */
export const TILE_SIZES = [16, 32, 64] as const;
/** Tiles per side of the painted grid: it is centred where painting starts, and moves when a stroke leaves it. */
const GRID_TILES = 256;
/**
 * Tiles per side of the grid's chunks (TileHulls' chunkSize). The grid starts at a multiple of it, so
 * the seams where joined walls are cut lie at the same places in the world whichever tile started it.
 */
const CHUNK_TILES = 32;

/**
 * Paints wall tiles on a world-aligned grid (tile (tx, ty) spans `[tx, tx + 1) × [ty, ty + 1) ×
 * tileSize`) and keeps them merged into hulls through a `TileHulls`: each painted or erased tile
 * swaps only the hulls of the group it touches in the renderer. The hulls are ordinary hulls (saved,
 * selected, moved like any other); the painter adopts back those it made that are still in the
 * scene, unmoved and on the grid, whenever its grid no longer matches the scene.
 */
export class TilePainter {
  /** World units per tile for the next stroke. */
  tileSize: number = TILE_SIZES[1];
  private tiles: TileHulls | null = null;
  /** Tile size and world tile index of grid cell (0, 0) of `tiles`. */
  private gridSize = 0;
  private gridX = 0;
  private gridY = 0;
  /**
   * The `points` of each hull of `tiles` when it was made (the same frozen array until new points
   * are assigned): a changed hull means the grid is out of date.
   */
  private readonly made = new Map<Hull, unknown>();
  /** Every hull the painter has made: the ones it may adopt back into a new grid. */
  private readonly painted = new WeakSet<Hull>();
  /** Whether `tiles` still matches the scene: checked when a stroke starts (nothing else edits hulls during one). */
  private current = false;
  private last: [number, number] | null = null;
  private solid = true;

  constructor(private readonly playground: Playground) {}

  /** Whether a stroke that erases is in progress. */
  get erasing(): boolean {
    return this.last !== null && !this.solid;
  }

  /** Starts a stroke at a world point: paints walls when `solid`, erases them otherwise. */
  begin(x: number, y: number, solid: boolean): void {
    this.solid = solid;
    this.last = [x, y];
    this.current = this.matchesScene();
    this.paintSegment(x, y, x, y);
  }

  /** Continues the stroke to a world point, through every tile on the way. */
  moveTo(x: number, y: number): void {
    if (!this.last) return;
    const [x0, y0] = this.last;
    this.last = [x, y];
    this.paintSegment(x0, y0, x, y);
  }

  end(): void {
    this.last = null;
  }

  /** The world tile index under a world point. */
  tileAt(x: number, y: number): [number, number] {
    return [Math.floor(x / this.tileSize), Math.floor(y / this.tileSize)];
  }

  /** Sets every tile the segment crosses (sampled at a quarter tile), then swaps the changed hulls in one go. */
  private paintSegment(x0: number, y0: number, x1: number, y1: number): void {
    const size = this.tileSize;
    const steps = Math.max(1, Math.ceil(Math.hypot(x1 - x0, y1 - y0) / (size / 4)));
    const added = new Set<Hull>(), removed: Hull[] = [];
    let previousX = NaN, previousY = NaN;
    for (let i = 0; i <= steps; i++) {
      const [tx, ty] = this.tileAt(x0 + ((x1 - x0) * i) / steps, y0 + ((y1 - y0) * i) / steps);
      if (tx === previousX && ty === previousY) continue;
      previousX = tx;
      previousY = ty;
      const tiles = this.gridFor(tx, ty);
      const change = tiles.setTile(tx - this.gridX, ty - this.gridY, this.solid);
      for (const hull of change.removed) {
        this.made.delete(hull);
        // A hull made earlier in this segment never reached the renderer.
        if (!added.delete(hull)) removed.push(hull);
      }
      for (const hull of change.added) {
        this.made.set(hull, hull.points);
        this.painted.add(hull);
        added.add(hull);
      }
    }
    if (removed.length > 0 || added.size > 0) this.playground.replaceHulls(removed, [...added]);
  }

  /**
   * The grid to paint tile (tx, ty) in: the current one while it still matches the scene and holds
   * the tile, otherwise a new one centred on the tile that adopts the painted hulls it can.
   */
  private gridFor(tx: number, ty: number): TileHulls {
    const inside = (grid: TileHulls) => tx >= this.gridX && ty >= this.gridY && tx < this.gridX + grid.width && ty < this.gridY + grid.height;
    if (this.tiles && this.current && this.gridSize === this.tileSize && inside(this.tiles)) return this.tiles;
    // A grid of the same size that still holds the tile keeps its place; otherwise one around the tile, on the chunks.
    if (!(this.tiles && this.gridSize === this.tileSize && inside(this.tiles))) {
      this.gridX = Math.floor((tx - GRID_TILES / 2) / CHUNK_TILES) * CHUNK_TILES;
      this.gridY = Math.floor((ty - GRID_TILES / 2) / CHUNK_TILES) * CHUNK_TILES;
    }
    this.gridSize = this.tileSize;
    this.current = true;
    return this.adopt();
  }

  /** Whether every hull of the grid is still in the scene as the painter made it. */
  private matchesScene(): boolean {
    const inScene = new Set(this.playground.renderer.hulls);
    for (const [hull, points] of this.made) if (!inScene.has(hull) || hull.points !== points || !isPlain(hull)) return false;
    return true;
  }

  /**
   * Builds a new grid from the painted hulls that are still in the scene, unmoved, enabled,
   * rectilinear with corners on this grid, and inside it: their tiles are the tiles whose centres
   * they contain. They are swapped in the renderer for the new grid's hulls (the same shapes).
   */
  private adopt(): TileHulls {
    const size = this.gridSize, cells = new Uint8Array(GRID_TILES * GRID_TILES);
    const adopted: Hull[] = [];
    for (const hull of this.playground.renderer.hulls) {
      if (!this.painted.has(hull) || !isPlain(hull) || !onGrid(hull, size)) continue;
      const [x0, y0, x1, y1] = tileBounds(hull, size);
      if (x0 < this.gridX || y0 < this.gridY || x1 > this.gridX + GRID_TILES || y1 > this.gridY + GRID_TILES) continue;
      adopted.push(hull);
      for (let ty = y0; ty < y1; ty++) {
        for (let tx = x0; tx < x1; tx++) {
          if (hullContains(hull, (tx + 0.5) * size, (ty + 0.5) * size)) cells[(ty - this.gridY) * GRID_TILES + tx - this.gridX] = 1;
        }
      }
    }
    const tiles = new TileHulls(cells, { width: GRID_TILES, tileSize: size, position: [this.gridX * size, this.gridY * size], chunkSize: CHUNK_TILES });
    this.tiles = tiles;
    this.made.clear();
    for (const hull of tiles.hulls) {
      this.made.set(hull, hull.points);
      this.painted.add(hull);
    }
    if (adopted.length > 0 || tiles.hulls.length > 0) this.playground.replaceHulls(adopted, [...tiles.hulls]);
    return tiles;
  }
}

/** Whether a hull's points are its world points: no move, turn or scale, and enabled. */
function isPlain(hull: Hull): boolean {
  const { position, origin, scale } = hull;
  return hull.enabled && hull.rotation === 0 && scale[0] === 1 && scale[1] === 1 && position[0] === origin[0] && position[1] === origin[1];
}

/** Whether every edge runs along a line of the grid of `size`. */
function onGrid(hull: Hull, size: number): boolean {
  const points = hull.points;
  if (!hull.valid) return false;
  for (let i = 0; i < points.length; i++) {
    const [x, y] = points[i], [nx, ny] = points[(i + 1) % points.length];
    if (x % size !== 0 || y % size !== 0 || (x !== nx && y !== ny)) return false;
  }
  return true;
}

/** The world tile range `[x0, y0, x1, y1)` a plain hull's points span. */
function tileBounds(hull: Hull, size: number): [number, number, number, number] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of hull.points) {
    x0 = Math.min(x0, x);
    y0 = Math.min(y0, y);
    x1 = Math.max(x1, x);
    y1 = Math.max(y1, y);
  }
  return [x0 / size, y0 / size, x1 / size, y1 / size];
}
