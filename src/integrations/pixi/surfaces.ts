import { Sprite, Texture, TextureSource, type Container, type WebGLRenderer } from 'pixi.js';
import type { SurfaceTextures } from '../../index';
import { assertBoolean, assertFinite, assertUnit, describeValue } from '../../util/validate';
import type { InPlaceView } from '../inPlaceLighting';
import { SurfacePass, createSurfaceQuad, setQuadMaterial } from '../../passes/SurfacePass';

/**
 * A sprite's surface for a lighting layer made with `normals: true`: its normal map and material
 * (docs/normal-maps.md). Give it with {@link PenumbraLayer.setSurface}.
 */
export interface SurfaceOptions {
  /**
   * The normal map, laid out as the sprite's texture source: the sprite's frame is read from it
   * at the same texture coordinates (for a sprite sheet, a normal sheet of the same layout; for a
   * single image, its normal map of the same size). Opaque: the coverage is the colour's alpha.
   */
  normalMap: Texture | TextureSource;
  /** Green points up the image (OpenGL-style maps: Blender, Substance's default) rather than down (DirectX-style). Default `true`. */
  greenUp?: boolean;
  /** Strength of the Blinn-Phong highlight, 0..1. Default `0` (no highlight). */
  specular?: number;
  /** Blinn-Phong exponent, 1..2048: higher is a smaller, sharper highlight. Default `32`. */
  shininess?: number;
  /** 0..1: adds `emissive` × the sprite's colour whatever the light. Default `0`. */
  emissive?: number;
}

/** A surface checked and resolved to its texture source. */
interface Surface {
  readonly normalMap: TextureSource;
  readonly greenUp: boolean;
  readonly specular: number;
  readonly shininess: number;
  readonly emissive: number;
}

/**
 * The surfaces given to a lighting layer, and its normal pass: the sprites drawn before the layer
 * (or a lit group's children), in Pixi's order, from their normal maps (see {@link SurfacePass}).
 * Owned by the layer, shared with its groups.
 */
export class PixiSurfaces {
  private readonly surfaces = new WeakMap<Sprite | TextureSource, Surface>();
  private readonly pass: SurfacePass;
  private readonly quad = createSurfaceQuad();
  private pixi: WebGLRenderer | null = null;
  /** The camera's inverse linear part: target axes → world axes. */
  private ia = 1;
  private ib = 0;
  private ic = 0;
  private id = 1;

  constructor(gl: WebGL2RenderingContext) {
    this.pass = new SurfacePass(gl);
  }

  /** Sets or (with null) removes the surface of a sprite or of every sprite drawn from a texture source. */
  set(target: Sprite | TextureSource, options: SurfaceOptions | null): void {
    if (!(target instanceof Sprite) && !(target instanceof TextureSource)) {
      throw new TypeError(`penumbra: setSurface takes a Sprite or a TextureSource (texture.source), got ${describeValue(target)}`);
    }
    if (options === null) this.surfaces.delete(target);
    else this.surfaces.set(target, checkSurface(options));
  }

  /** The surface a sprite is drawn with: its own, else its texture source's; undefined when none. */
  get(sprite: Sprite): Surface | undefined {
    return this.surfaces.get(sprite) ?? this.surfaces.get(sprite.texture.source);
  }

  /**
   * Draws the normal pass of the sprites under `root` drawn before `stop` (all of them when null),
   * for Pixi's bound target of `view`, looking through `camera` (world → target units, or none).
   * Returns the textures for `drawInPlace`, or null when none of them has a surface.
   */
  render(pixi: WebGLRenderer, root: Container, stop: Container | null, camera: Container | null, view: InPlaceView): SurfaceTextures | null {
    this.pixi = pixi;
    if (camera) {
      const m = camera.worldTransform;
      const det = m.a * m.d - m.b * m.c;
      this.ia = m.d / det;
      this.ib = -m.b / det;
      this.ic = -m.c / det;
      this.id = m.a / det;
    } else {
      this.ia = this.id = 1;
      this.ib = this.ic = 0;
    }
    this.pass.begin();
    this.collect(root, stop);
    return this.pass.render(view.width, view.height, view.pixelWidth, view.pixelHeight, view.flipY);
  }

  /** Frees the normal pass's GL objects. */
  dispose(): void {
    this.pass.dispose();
  }

  /** Adds the sprites of `node`'s subtree in Pixi's draw order; returns true once `stop` is reached. */
  private collect(node: Container, stop: Container | null): boolean {
    if (node === stop) return true;
    // As Pixi's collectRenderables: hidden, culled or unrenderable subtrees and those drawn by a render layer are skipped.
    if (node.globalDisplayStatus < 7 || !node.includeInBuild || node.parentRenderLayer) return false;
    if (node instanceof Sprite) this.addSprite(node);
    const children = node.children;
    for (let i = 0; i < children.length; i++) {
      if (this.collect(children[i], stop)) return true;
    }
    return false;
  }

  private addSprite(sprite: Sprite): void {
    const surface = this.get(sprite);
    const textures = this.pixi!.texture;
    const quad = this.quad;
    const texture = sprite.texture;
    quad.color = textures.getGlSource(texture.source).texture;
    quad.normals = surface ? textures.getGlSource(surface.normalMap).texture : null;
    // Alpha relative to the render group, times the group's own (a render group's root has only the latter).
    quad.alpha = sprite.renderGroup ? sprite.renderGroup.worldAlpha : sprite.groupAlpha * (sprite.parentRenderGroup?.worldAlpha ?? 1);
    // Pixi's quad (DefaultBatcher.packQuadAttributes): the visual bounds through the world transform, uvs 0..3 clockwise from the top-left.
    const m = sprite.worldTransform;
    const bounds = sprite.visualBounds;
    setCorner(quad.corners, 0, m, bounds.minX, bounds.minY);
    setCorner(quad.corners, 2, m, bounds.maxX, bounds.minY);
    setCorner(quad.corners, 4, m, bounds.minX, bounds.maxY);
    setCorner(quad.corners, 6, m, bounds.maxX, bounds.maxY);
    const uvs = texture.uvs, out = quad.uvs;
    out[0] = uvs.x0; out[1] = uvs.y0;
    out[2] = uvs.x1; out[3] = uvs.y1;
    out[4] = uvs.x3; out[5] = uvs.y3;
    out[6] = uvs.x2; out[7] = uvs.y2;
    // Image axes → world axes: the sprite's world transform, then the camera's inverse.
    const w = quad.worldFromImage;
    w[0] = this.ia * m.a + this.ic * m.b;
    w[1] = this.ib * m.a + this.id * m.b;
    w[2] = this.ia * m.c + this.ic * m.d;
    w[3] = this.ib * m.c + this.id * m.d;
    if (surface) setQuadMaterial(quad, surface);
    this.pass.add(quad);
  }
}

function setCorner(out: Float32Array, at: number, m: { a: number; b: number; c: number; d: number; tx: number; ty: number }, x: number, y: number): void {
  out[at] = m.a * x + m.c * y + m.tx;
  out[at + 1] = m.b * x + m.d * y + m.ty;
}

function checkSurface(options: SurfaceOptions): Surface {
  if (typeof options !== 'object' || options === null) throw new TypeError(`penumbra: a surface must be an object, got ${describeValue(options)}`);
  const { normalMap, greenUp = true, specular = 0, shininess = 32, emissive = 0 } = options;
  let source: TextureSource;
  if (normalMap instanceof Texture) source = normalMap.source;
  else if (normalMap instanceof TextureSource) source = normalMap;
  else throw new TypeError(`penumbra: surface.normalMap must be a Texture or a TextureSource, got ${describeValue(normalMap)}`);
  return {
    normalMap: source,
    greenUp: assertBoolean('surface.greenUp', greenUp),
    specular: assertUnit('surface.specular', specular),
    shininess: checkShininess(shininess),
    emissive: assertUnit('surface.emissive', emissive),
  };
}

function checkShininess(value: number): number {
  assertFinite('surface.shininess', value);
  if (value < 1 || value > 2048) throw new RangeError(`surface.shininess must be from 1 to 2048, got ${value}`);
  return value;
}
