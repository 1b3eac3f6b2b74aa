import Phaser from 'phaser';
import { TileHulls, type Hull, type TileHullsChange } from '../../index';
import { describe, readPlacement, type HullTarget, type Placement } from './shared';

/** Options of {@link TilemapLayerHulls} and {@link PenumbraPlugin.addTilemapLayer}; every field has the default shown. */
export interface TilemapLayerHullsOptions {
  /**
   * Which tiles cast shadows: `'collides'`, the tiles that collide (set with the layer's
   * `setCollision…` methods, which `putTileAt` follows); a list of tile indices; or a test of a
   * tile. Empty cells (`null`, or index −1) never do, and the test is not asked about them.
   * Default `'collides'`.
   */
  solid?: 'collides' | readonly number[] | ((tile: Phaser.Tilemaps.Tile) => boolean);
  /**
   * Compare the layer's tiles with the hulls before every render, so that any change made through
   * Phaser (`putTileAt`, `removeTileAt`, `fill`, `setCollision`, a tile's `index`…) shows in the
   * same frame. It reads every tile (O(tiles), no allocation) and rebuilds only around the tiles
   * that changed. `false`: call {@link TilemapLayerHulls.refresh} after changing tiles, with the
   * area changed for the cost of that area only. Default `true`.
   */
  autoRefresh?: boolean;
}

/** A test of a layer cell. */
type SolidTest = (tile: Phaser.Tilemaps.Tile | null) => boolean;

/**
 * The hulls of a Phaser tilemap layer's solid tiles, kept in step with the layer: built with the
 * core's {@link TileHulls} (one hull per group of touching tiles in a chunk, not one per tile), placed at
 * the layer's position and scale, and, when tiles change, rebuilt only around the changed tiles
 * with {@link TileHulls.setTile}. Usually made with {@link PenumbraPlugin.addTilemapLayer}:
 *
 * ```ts
 * const layer = map.createLayer('walls', tileset)!.setCollisionByExclusion([-1]);
 * const walls = this.penumbra.addTilemapLayer(layer);
 * layer.removeTileAt(4, 7); // its shadow is gone in the next frame
 * ```
 *
 * Phaser has no event for tile changes, so by default the layer's tiles are compared with the
 * hulls before each render (see {@link TilemapLayerHullsOptions.autoRefresh}). The layer's
 * position and scale (and a Container's transform) are followed every frame; its scroll factor
 * is not (keep it at 1). Orthogonal layers only; tiles are cells of the map's base tile size,
 * whatever the size of the tileset's images.
 *
 * The hulls go when the layer is destroyed, when its scene shuts down, or on {@link TilemapLayerHulls.destroy}.
 */
export class TilemapLayerHulls {
  /** The tilemap layer whose tiles cast the shadows. */
  readonly layer: Phaser.Tilemaps.TilemapLayerBase;
  /** Tiles per row of the layer. */
  readonly width: number;
  /** Rows of tiles of the layer. */
  readonly height: number;
  private readonly target: HullTarget;
  private readonly tiles: TileHulls<Phaser.Tilemaps.Tile | null>;
  private readonly solid: SolidTest;
  private readonly autoRefresh: boolean;
  /** 1 for a cell the hulls now cover, row-major. */
  private readonly cells: Uint8Array;
  private readonly events: Phaser.Events.EventEmitter;
  private readonly placement: Placement = { x: 0, y: 0, rotation: 0, scaleX: 1, scaleY: 1 };
  private placedX = 0;
  private placedY = 0;
  private placedRotation = 0;
  private placedScaleX = 1;
  private placedScaleY = 1;
  private destroyed = false;
  /** Called once when destroyed (the plugin forgets it). @internal */
  onDestroy: (() => void) | null = null;

  /**
   * Builds the hulls of `layer`'s solid tiles and adds them to `target`.
   * @throws TypeError for something that is not a tilemap layer, or an option of the wrong type;
   * RangeError for a layer that is not orthogonal.
   */
  constructor(layer: Phaser.Tilemaps.TilemapLayerBase, target: HullTarget, options: TilemapLayerHullsOptions = {}) {
    const data = (layer as Partial<Phaser.Tilemaps.TilemapLayerBase> | null)?.layer;
    if (!data || !Array.isArray(data.data)) throw new TypeError(`penumbra: TilemapLayerHulls needs a Phaser tilemap layer, got ${describe(layer)}`);
    if (data.orientation !== Phaser.Tilemaps.Orientation.ORTHOGONAL) {
      throw new RangeError(`penumbra: TilemapLayerHulls supports orthogonal tilemap layers only, layer "${data.name}" has orientation ${String(data.orientation)}`);
    }
    if (typeof target?.addHull !== 'function' || typeof target.removeHull !== 'function') {
      throw new TypeError(`penumbra: TilemapLayerHulls target must have addHull and removeHull (the plugin or a PenumbraRenderer), got ${describe(target)}`);
    }
    const { solid = 'collides', autoRefresh = true } = options;
    if (typeof autoRefresh !== 'boolean') throw new TypeError(`penumbra: TilemapLayerHulls options.autoRefresh must be true or false, got ${describe(autoRefresh)}`);
    this.layer = layer;
    this.target = target;
    this.solid = readSolid(solid);
    this.autoRefresh = autoRefresh;
    this.width = data.width;
    this.height = data.height;
    const rows = data.data;
    this.tiles = new TileHulls((x, y) => rows[y][x], {
      width: this.width,
      height: this.height,
      tileSize: [data.baseTileWidth, data.baseTileHeight],
      solid: (tile) => this.solid(tile),
    });
    this.cells = new Uint8Array(this.width * this.height);
    for (let y = 0; y < this.height; y++) {
      for (let x = 0; x < this.width; x++) this.cells[y * this.width + x] = this.tiles.isSolid(x, y) ? 1 : 0;
    }
    this.place();
    for (const hull of this.tiles.hulls) this.target.addHull(this.placeHull(hull));

    this.events = layer.scene.sys.events;
    layer.once(Phaser.GameObjects.Events.DESTROY, this.destroy, this);
    this.events.on(Phaser.Scenes.Events.PRE_RENDER, this.update, this);
    this.events.once(Phaser.Scenes.Events.SHUTDOWN, this.destroy, this);
  }

  /** The current hulls, in the layer's place (a new array after each change; the same one until then). */
  get hulls(): readonly Hull[] {
    return this.tiles.hulls;
  }

  /** Whether {@link TilemapLayerHulls.destroy} ran (or the layer or scene went). */
  get isDestroyed(): boolean {
    return this.destroyed;
  }

  /**
   * Brings the hulls in step with the layer: its place, and with `autoRefresh` its tiles. Runs
   * before every render of the layer's scene; call it yourself only to read {@link TilemapLayerHulls.hulls}
   * right after a change.
   */
  update(): void {
    if (this.destroyed) return;
    this.place();
    if (this.autoRefresh) this.refresh();
  }

  /**
   * Re-reads the tiles of an area (the whole layer unless given; clipped to it) and rebuilds the
   * hulls around each tile that became solid or empty. O(area) reads plus the rebuilds.
   * @returns how many tiles changed.
   */
  refresh(tileX = 0, tileY = 0, width = this.width - tileX, height = this.height - tileY): number {
    if (this.destroyed) return 0;
    const x0 = Math.max(0, Math.floor(tileX)), y0 = Math.max(0, Math.floor(tileY));
    const x1 = Math.min(this.width, Math.ceil(tileX + width)), y1 = Math.min(this.height, Math.ceil(tileY + height));
    const rows = this.layer.layer.data, cells = this.cells, w = this.width;
    let changed = 0;
    for (let y = y0; y < y1; y++) {
      const row = rows[y];
      for (let x = x0; x < x1; x++) {
        const solid = this.solid(row[x]) ? 1 : 0;
        if (cells[y * w + x] === solid) continue;
        cells[y * w + x] = solid;
        this.apply(this.tiles.setTile(x, y, solid === 1));
        changed++;
      }
    }
    return changed;
  }

  /** Removes the hulls from the target and stops following the layer; safe to call twice. */
  destroy(): void {
    if (this.destroyed) return;
    this.destroyed = true;
    this.layer.off(Phaser.GameObjects.Events.DESTROY, this.destroy, this);
    this.events.off(Phaser.Scenes.Events.PRE_RENDER, this.update, this);
    this.events.off(Phaser.Scenes.Events.SHUTDOWN, this.destroy, this);
    for (const hull of this.tiles.hulls) this.target.removeHull(hull);
    this.onDestroy?.();
    this.onDestroy = null;
  }

  private apply({ added, removed }: TileHullsChange): void {
    for (const hull of removed) this.target.removeHull(hull);
    for (const hull of added) this.target.addHull(this.placeHull(hull));
  }

  /** Reads the layer's place; when it moved, moves every hull. */
  private place(): void {
    const p = readPlacement(this.layer, false, this.placement);
    if (p.x === this.placedX && p.y === this.placedY && p.rotation === this.placedRotation
      && p.scaleX === this.placedScaleX && p.scaleY === this.placedScaleY) return;
    const moved = p.x !== this.placedX || p.y !== this.placedY;
    const turned = p.rotation !== this.placedRotation;
    const scaled = p.scaleX !== this.placedScaleX || p.scaleY !== this.placedScaleY;
    this.placedX = p.x;
    this.placedY = p.y;
    this.placedRotation = p.rotation;
    this.placedScaleX = p.scaleX;
    this.placedScaleY = p.scaleY;
    for (const hull of this.tiles.hulls) {
      if (moved) hull.setPosition(p.x, p.y);
      if (turned) hull.rotation = p.rotation;
      if (scaled) hull.scale = [p.scaleX, p.scaleY];
    }
  }

  /** Gives a new hull (made at the origin, unscaled) the layer's current place. */
  private placeHull(hull: Hull): Hull {
    if (this.placedX !== 0 || this.placedY !== 0) hull.setPosition(this.placedX, this.placedY);
    if (this.placedRotation !== 0) hull.rotation = this.placedRotation;
    if (this.placedScaleX !== 1 || this.placedScaleY !== 1) hull.scale = [this.placedScaleX, this.placedScaleY];
    return hull;
  }
}

function readSolid(solid: TilemapLayerHullsOptions['solid']): SolidTest {
  if (solid === 'collides') return (tile) => tile !== null && tile !== undefined && tile.collides;
  if (Array.isArray(solid)) {
    for (const index of solid) {
      if (!Number.isInteger(index)) throw new TypeError(`penumbra: TilemapLayerHulls options.solid must list integer tile indices, got ${describe(index)}`);
    }
    const indices = new Set<number>(solid);
    return (tile) => tile !== null && tile !== undefined && tile.index !== -1 && indices.has(tile.index);
  }
  if (typeof solid === 'function') {
    return (tile) => {
      if (tile === null || tile === undefined || tile.index === -1) return false;
      const answer = solid(tile);
      if (typeof answer !== 'boolean') {
        throw new TypeError(`penumbra: TilemapLayerHulls options.solid must return true or false, got ${describe(answer)} for tile (${tile.x}, ${tile.y})`);
      }
      return answer;
    };
  }
  throw new TypeError(`penumbra: TilemapLayerHulls options.solid must be 'collides', a list of tile indices or a function of a tile, got ${describe(solid)}`);
}
