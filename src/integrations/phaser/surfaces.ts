import Phaser from 'phaser';
import type { SurfaceTextures } from '../../index';
import { assertBoolean, assertFinite, assertUnit, describeValue } from '../../util/validate';
import type { InPlaceView } from '../inPlaceLighting';
import { SurfacePass, createSurfaceQuad, setQuadMaterial, setQuadUvs, setWorldFromImage } from '../../passes/SurfacePass';

/**
 * The material of normal-mapped images and sprites, for a plugin made with `normals: true`
 * (docs/normal-maps.md); give it with {@link PenumbraPlugin.setMaterial}. The normal map itself is
 * Phaser's: the one loaded with the texture (`this.load.image(key, [url, normalUrl])`).
 */
export interface MaterialOptions {
  /** Green points up the image (OpenGL-style maps, as Phaser's own lights read them) rather than down. Default `true`. */
  greenUp?: boolean;
  /** Strength of the Blinn-Phong highlight, 0..1. Default `0` (no highlight). */
  specular?: number;
  /** Blinn-Phong exponent, 1..2048: higher is a smaller, sharper highlight. Default `32`. */
  shininess?: number;
  /** 0..1: adds `emissive` × the object's colour whatever the light. Default `0`. */
  emissive?: number;
}

type Material = Readonly<Required<MaterialOptions>>;

const DEFAULT_MATERIAL: Material = { greenUp: true, specular: 0, shininess: 32, emissive: 0 };

/** A game object's render nodes by role. */
type RenderNodes = Partial<Record<string, Phaser.Renderer.WebGL.RenderNodes.RenderNode>>;
/** Texture coordinates of a frame's corners: (u0, v0) at its top-left, (u1, v1) at its bottom-right. */
interface UvRect { u0: number; v0: number; u1: number; v1: number }

/** A game object the normal pass draws: an image or a sprite. */
type Drawn = Phaser.GameObjects.Image | Phaser.GameObjects.Sprite;

/** What Phaser's tile transformer reads of a texturer (TilemapLayerWebGLRenderer hands it the same). */
interface TileFrame { frameWidth: number; frameHeight: number }
/** A tile's pixel rectangle in its tileset image (Tileset.getTileTextureCoordinates; its typings say object). */
interface TileCoordinates { x: number; y: number }

/**
 * The plugin's materials and normal pass: the images, sprites and tilemap layers' tiles drawn before
 * the lighting layer (or a lit group's children), in Phaser's order, from the normal maps of their
 * textures (see {@link SurfacePass}). Phaser's own texturer and transformer nodes place each quad, as
 * Phaser draws it (a GPU tilemap layer's tiles, by the matrix of its submitter node).
 */
export class PhaserSurfaces {
  private readonly objectMaterials = new WeakMap<Phaser.GameObjects.GameObject, Material>();
  private readonly textureMaterials = new Map<string, Material>();
  private readonly pass: SurfacePass;
  private readonly quad = createSurfaceQuad();
  private context: Phaser.Renderer.WebGL.DrawingContext | null = null;
  private readonly tileFrame: TileFrame = { frameWidth: 0, frameHeight: 0 };
  /** A GPU tilemap layer's matrix (world → context), its own part, and a tile's quad; made on first use. */
  private gpuMatrix: Phaser.GameObjects.Components.TransformMatrix | null = null;
  private gpuOwnMatrix: Phaser.GameObjects.Components.TransformMatrix | null = null;
  private gpuQuad: Float32Array | null = null;
  private gpuCorner: Phaser.Math.Vector2 | null = null;

  constructor(gl: WebGL2RenderingContext) {
    this.pass = new SurfacePass(gl);
  }

  /** Sets or (with null) removes the material of a game object or of a texture (by key). */
  setMaterial(target: Phaser.GameObjects.GameObject | string, options: MaterialOptions | null): void {
    if (typeof target === 'string') {
      if (options === null) this.textureMaterials.delete(target);
      else this.textureMaterials.set(target, checkMaterial(options));
    } else if (target instanceof Phaser.GameObjects.GameObject) {
      if (options === null) this.objectMaterials.delete(target);
      else this.objectMaterials.set(target, checkMaterial(options));
    } else {
      throw new TypeError(`penumbra: setMaterial takes a game object or a texture key, got ${describeValue(target)}`);
    }
  }

  /**
   * Draws the normal pass of the objects of `list` drawn before `stop` (all when null) into
   * `context`'s size. Returns the textures for `drawInPlace`, or null when none has a normal map.
   */
  render(context: Phaser.Renderer.WebGL.DrawingContext, list: readonly Phaser.GameObjects.GameObject[], stop: Phaser.GameObjects.GameObject | null, view: InPlaceView): SurfaceTextures | null {
    this.context = context;
    this.pass.begin();
    this.collect(list, stop);
    this.context = null;
    return this.pass.render(view.width, view.height, view.pixelWidth, view.pixelHeight, false);
  }

  /** Frees the normal pass's GL objects. */
  dispose(): void {
    this.pass.dispose();
  }

  /** Adds the images, sprites and tilemap layers of `list`, and of the layers in it, in order; returns true once `stop` is reached. */
  private collect(list: readonly Phaser.GameObjects.GameObject[], stop: Phaser.GameObjects.GameObject | null): boolean {
    const camera = this.context!.camera!;
    for (let i = 0; i < list.length; i++) {
      const object = list[i];
      if (object === stop) return true;
      if (!object.willRender(camera)) continue;
      if (object instanceof Phaser.GameObjects.Image || object instanceof Phaser.GameObjects.Sprite) this.addObject(object);
      else if (object instanceof Phaser.Tilemaps.TilemapLayer) this.addTilemapLayer(object);
      else if (object instanceof Phaser.Tilemaps.TilemapGPULayer) this.addTilemapGPULayer(object);
      else if (object instanceof Phaser.GameObjects.Layer && this.collect(object.list, stop)) return true;
    }
    return false;
  }

  private addObject(object: Drawn): void {
    const context = this.context!;
    // The nodes Phaser draws the object with (ImageWebGLRenderer): the custom ones, else the defaults.
    const nodes = object.customRenderNodes as RenderNodes, defaults = object.defaultRenderNodes as RenderNodes;
    const texturer = (nodes.Texturer ?? defaults.Texturer) as Phaser.Renderer.WebGL.RenderNodes.TexturerImage;
    const transformer = (nodes.Transformer ?? defaults.Transformer) as Phaser.Renderer.WebGL.RenderNodes.TransformerImage;
    texturer.run(context, object);
    transformer.run(context, object, texturer);
    const quad = this.quad;
    const frame = texturer.frame;
    quad.color = frame.source.glTexture!.webGLTexture;
    // Phaser's normal map of the frame's source (Texture.setDataSource, the loader's [url, normalUrl]).
    const normalSource = object.texture.dataSource[frame.sourceIndex] as Phaser.Textures.TextureSource | undefined;
    quad.normals = normalSource?.glTexture?.webGLTexture ?? null;
    quad.alpha = object.alpha;
    // Phaser's quad is top-left, bottom-left, bottom-right, top-right (SubmitterQuad); the pass takes a strip.
    const q = transformer.quad, corners = quad.corners;
    corners[0] = q[0]; corners[1] = q[1];
    corners[2] = q[6]; corners[3] = q[7];
    corners[4] = q[2]; corners[5] = q[3];
    corners[6] = q[4]; corners[7] = q[5];
    // A frame, or a crop, which Phaser gives the same texture coordinates (its typings leave them out).
    const uv = texturer.uvSource as UvRect;
    setQuadUvs(quad, uv.u0, uv.v0, uv.u1, uv.v1);
    // Image axes → world axes: the object's rotation, scale and flips (the transformer's sprite matrix without the camera).
    setWorldFromImage(quad, object.rotation, object.flipX ? -object.scaleX : object.scaleX, object.flipY ? -object.scaleY : object.scaleY);
    if (quad.normals) setQuadMaterial(quad, this.objectMaterials.get(object) ?? this.textureMaterials.get(object.texture.key) ?? DEFAULT_MATERIAL);
    this.pass.add(quad);
  }

  /**
   * Adds the tiles of a tilemap layer that Phaser draws this frame (its culled tiles, in its render
   * order), each from its tileset's texture, through the layer's own tile transformer node: placed,
   * scaled, rotated and flipped as Phaser draws it (TilemapLayerWebGLRenderer).
   */
  private addTilemapLayer(layer: Phaser.Tilemaps.TilemapLayer): void {
    const context = this.context!;
    const tiles = layer.cull(context.camera!);
    if (tiles.length === 0 || layer.alpha <= 0) return;
    const nodes = layer.customRenderNodes as RenderNodes, defaults = layer.defaultRenderNodes as RenderNodes;
    const transformer = (nodes.Transformer ?? defaults.Transformer) as Phaser.Renderer.WebGL.RenderNodes.TransformerTile;
    const frame = this.tileFrame;
    for (let i = 0; i < tiles.length; i++) {
      const tile = tiles[i];
      const tileset = layer.gidMap[tile.index];
      if (!tileset) continue;
      const id = tileset.getAnimatedTileId(tile.index, layer.timeElapsed);
      if (id === null) continue;
      const coordinates = tileset.getTileTextureCoordinates(id) as TileCoordinates | null;
      if (!coordinates || tileset.tileWidth === 0 || tileset.tileHeight === 0) continue;
      frame.frameWidth = tileset.tileWidth;
      frame.frameHeight = tileset.tileHeight;
      // The tile transformer takes the tile as its element (its typings leave it out).
      (transformer.run as (...args: unknown[]) => void)(context, layer, frame, undefined, tile);
      this.addTile(layer, tileset, coordinates, transformer.quad, tile.rotation, tile.flipX, tile.flipY, layer.alpha * tile.alpha);
    }
  }

  /**
   * Adds the tiles of a GPU tilemap layer, which Phaser draws as one quad over the layer's grid
   * (SubmitterTilemapGPULayer): each cell with a tile in sight of the drawing context, placed by the
   * same matrix, from the layer's one tileset.
   */
  private addTilemapGPULayer(layer: Phaser.Tilemaps.TilemapGPULayer): void {
    const context = this.context!, camera = context.camera!;
    const tileset = layer.tileset;
    if (!tileset || layer.alpha <= 0) return;
    const matrix = (this.gpuMatrix ??= new Phaser.GameObjects.Components.TransformMatrix());
    const own = (this.gpuOwnMatrix ??= new Phaser.GameObjects.Components.TransformMatrix());
    matrix.copyWithScrollFactorFrom(camera.getViewMatrix(!context.useCanvas), camera.scrollX, camera.scrollY, layer.scrollFactorX, layer.scrollFactorY);
    own.applyITRS(layer.x, layer.y, 0, layer.scaleX, layer.scaleY);
    matrix.multiply(own);
    // The layer's size is the map's tile size times its cells (TilemapLayerBase).
    const data = layer.layer.data, cellWidth = layer.tilemap.tileWidth, cellHeight = layer.tilemap.tileHeight;
    // The cells in sight: the context's corners taken back to the layer's units, one cell of margin.
    const corner = (this.gpuCorner ??= new Phaser.Math.Vector2());
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (let i = 0; i < 4; i++) {
      matrix.applyInverse(i & 1 ? context.width : 0, i & 2 ? context.height : 0, corner);
      minX = Math.min(minX, corner.x);
      maxX = Math.max(maxX, corner.x);
      minY = Math.min(minY, corner.y);
      maxY = Math.max(maxY, corner.y);
    }
    const firstRow = Math.max(0, Math.floor((minY - layer.y) / cellHeight) - 1);
    const lastRow = Math.min(data.length - 1, Math.floor((maxY - layer.y) / cellHeight) + 1);
    const firstColumn = Math.max(0, Math.floor((minX - layer.x) / cellWidth) - 1);
    const quad = (this.gpuQuad ??= new Float32Array(8));
    for (let row = firstRow; row <= lastRow; row++) {
      const cells = data[row];
      const lastColumn = Math.min(cells.length - 1, Math.floor((maxX - layer.x) / cellWidth) + 1);
      for (let column = firstColumn; column <= lastColumn; column++) {
        const tile = cells[column];
        if (!tile || tile.index < 0) continue;
        const id = tileset.getAnimatedTileId(tile.index, layer.timeElapsed);
        if (id === null) continue;
        const coordinates = tileset.getTileTextureCoordinates(id) as TileCoordinates | null;
        if (!coordinates) continue;
        // The layer's quad spans (x, y) to (x + width, y + height) in its own units: one cell per tile.
        const left = layer.x + column * cellWidth, top = layer.y + row * cellHeight;
        const x0 = tile.flipX ? left + cellWidth : left, y0 = tile.flipY ? top + cellHeight : top;
        matrix.setQuad(x0, y0, tile.flipX ? left : left + cellWidth, tile.flipY ? top : top + cellHeight, quad);
        // Its data texture holds the index and flips only: the layer's alpha, not the tile's.
        this.addTile(layer, tileset, coordinates, quad, 0, tile.flipX, tile.flipY, layer.alpha);
      }
    }
  }

  /**
   * Adds one tile: `q` its quad as Phaser's transformers leave it (top-left, bottom-left,
   * bottom-right, top-right of the tile's image), its frame at `coordinates` in the tileset's image.
   */
  private addTile(
    layer: Phaser.Tilemaps.TilemapLayerBase, tileset: Phaser.Tilemaps.Tileset, coordinates: TileCoordinates, q: ArrayLike<number>,
    rotation: number, flipX: boolean, flipY: boolean, alpha: number,
  ): void {
    const image = tileset.image!;
    const quad = this.quad;
    quad.color = tileset.glTexture!.webGLTexture;
    // The tileset image's normal map (its data source), as Phaser's own lights read it.
    const normalSource = image.dataSource[0] as Phaser.Textures.TextureSource | undefined;
    quad.normals = normalSource?.glTexture?.webGLTexture ?? null;
    quad.alpha = alpha;
    const corners = quad.corners;
    corners[0] = q[0]; corners[1] = q[1];
    corners[2] = q[6]; corners[3] = q[7];
    corners[4] = q[2]; corners[5] = q[3];
    corners[6] = q[4]; corners[7] = q[5];
    // Phaser keeps texture rows bottom up: the tile's top is at v1 (TilemapLayerWebGLRenderer, SubmitterTile).
    const width = tileset.glTexture!.width, height = tileset.glTexture!.height;
    const u0 = coordinates.x / width, u1 = (coordinates.x + tileset.tileWidth) / width;
    const top = 1 - coordinates.y / height, bottom = 1 - (coordinates.y + tileset.tileHeight) / height;
    setQuadUvs(quad, u0, top, u1, bottom);
    // Image axes → world axes: the tile's rotation, the layer's scale and the tile's flips (the layer's rotation is not drawn).
    setWorldFromImage(quad, rotation, flipX ? -layer.scaleX : layer.scaleX, flipY ? -layer.scaleY : layer.scaleY);
    if (quad.normals) setQuadMaterial(quad, this.objectMaterials.get(layer) ?? this.textureMaterials.get(image.key) ?? DEFAULT_MATERIAL);
    this.pass.add(quad);
  }
}

function checkMaterial(options: MaterialOptions): Material {
  if (typeof options !== 'object' || options === null) throw new TypeError(`penumbra: a material must be an object, got ${describeValue(options)}`);
  const { greenUp = true, specular = 0, shininess = 32, emissive = 0 } = options;
  assertFinite('material.shininess', shininess);
  if (shininess < 1 || shininess > 2048) throw new RangeError(`material.shininess must be from 1 to 2048, got ${shininess}`);
  return {
    greenUp: assertBoolean('material.greenUp', greenUp),
    specular: assertUnit('material.specular', specular),
    shininess,
    emissive: assertUnit('material.emissive', emissive),
  };
}
