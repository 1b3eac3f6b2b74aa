import { DOMAdapter, type PointData, type Renderer, type Sprite, type Texture } from 'pixi.js';
import { Hull, hullsFromAlpha, type AlphaImage, type HullsFromAlphaOptions, type PenumbraRenderer } from '../../index';
import { Occluder } from './Occluder';

/**
 * How a texture's alpha becomes hulls: {@link HullsFromAlphaOptions}' `threshold`, `tolerance`
 * (in texture pixels), `maxPoints` and `minArea`, with their defaults there.
 */
export type SpriteHullsOptions = Pick<HullsFromAlphaOptions, 'threshold' | 'tolerance' | 'maxPoints' | 'minArea'>;

/** Options of {@link hullsFromTexture}: the tracing options, and where the texture is drawn. */
export interface TextureHullsOptions extends SpriteHullsOptions {
  /**
   * The anchor of the sprite the hulls are for (`sprite.anchor`), as a fraction of the texture's
   * original size. Default: the texture's `defaultAnchor`, else `{ x: 0, y: 0 }`.
   */
  anchor?: PointData;
  /**
   * Pixi's renderer, to read a texture that has no pixels on the CPU (a `RenderTexture`) back
   * from the GPU. Not needed for textures of images, canvases or pixel buffers.
   */
  renderer?: Renderer;
}

/** The traced outlines of one texture with one set of options, in texture pixels. */
interface Trace {
  width: number;
  height: number;
  outlines: ReadonlyArray<ReadonlyArray<readonly [number, number]>>;
}

/** Traces by texture, then by options. Weak: a texture that is dropped takes its traces with it. */
let traces = new WeakMap<Texture, Map<string, Trace>>();
/** How many textures were read back from the GPU: the layer rebinds Pixi's target after one. @internal */
export let gpuReads = 0;

/**
 * Hulls of a texture's opaque pixels, in the local space of a sprite showing it with `anchor`
 * (world units are the texture's, as a sprite at scale 1 draws it; trimmed atlas frames are
 * placed within their original size). Place them like the sprite (`position`, `rotation`,
 * `scale` of each hull) for a snapshot, or let them follow it with {@link PenumbraLayer.follow};
 * {@link PenumbraLayer.addOccluder} does that and also follows the sprite's texture and anchor.
 *
 * The texture's pixels are read once per texture and set of options, and the outlines kept for
 * as long as the texture lives: from its image, canvas or pixel buffer when it has one (exact
 * alpha), else back from the GPU through `options.renderer`. After drawing new pixels into a
 * texture, call {@link forgetTextureHulls}.
 *
 * ```ts
 * const hulls = hullsFromTexture(sprite.texture, { anchor: sprite.anchor, tolerance: 1.5 });
 * lighting.follow(sprite, hulls);
 * ```
 * @throws TypeError when the pixels cannot be read (a texture without CPU pixels and no
 *   renderer), RangeError for a frame rotated in its atlas, and the errors of {@link hullsFromAlpha}.
 */
export function hullsFromTexture(texture: Texture, options: TextureHullsOptions = {}): Hull[] {
  const trace = traceTexture(texture, options, options.renderer);
  const anchor = options.anchor ?? texture.defaultAnchor ?? { x: 0, y: 0 };
  const m = texturePlacement(texture, trace, anchor.x, anchor.y);
  return trace.outlines.map((outline) => new Hull(outline.map(([x, y]) => [m[0] * x + m[4], m[3] * y + m[5]])));
}

/** Forgets the outlines traced from `texture` (after its pixels changed), or from every texture. */
export function forgetTextureHulls(texture?: Texture): void {
  if (texture) traces.delete(texture);
  else traces = new WeakMap();
}

/**
 * An {@link Occluder} for a `Sprite`: hulls traced from its texture's alpha (see
 * {@link hullsFromTexture}), following the sprite. Made by {@link PenumbraLayer.addOccluder}.
 * It also follows the sprite's `anchor`, and its `texture`: a new texture (an `AnimatedSprite`'s
 * next frame) brings that texture's hulls, traced the first time it is shown and reused after.
 */
export class SpriteOccluder extends Occluder {
  declare readonly object: Sprite;
  private readonly options: SpriteHullsOptions;
  private readonly pixi: Renderer;
  private texture: Texture | null = null;
  private trace: Trace | null = null;
  private anchorX = NaN;
  private anchorY = NaN;

  /** @internal */
  constructor(sprite: Sprite, renderer: PenumbraRenderer, pixi: Renderer, options: SpriteHullsOptions, onDestroyed: (occluder: Occluder) => void) {
    super(sprite, renderer, [], onDestroyed);
    this.options = { ...options };
    this.pixi = pixi;
    this.refresh();
  }

  /** Traces the sprite's texture again, e.g. after new pixels were drawn into it. */
  retrace(): void {
    if (this.texture) forgetTextureHulls(this.texture);
    this.texture = null;
  }

  protected override refresh(): void {
    const sprite = this.object;
    const texture = sprite.texture;
    const { x, y } = sprite.anchor;
    if (texture === this.texture && x === this.anchorX && y === this.anchorY) return;
    if (texture !== this.texture) {
      this.trace = traceTexture(texture, this.options, this.pixi);
      this.texture = texture;
      this.anchorX = NaN;
    }
    const trace = this.trace!;
    const placement = texturePlacement(texture, trace, x, y);
    const bases = new Float64Array(6 * trace.outlines.length);
    for (let i = 0; i < trace.outlines.length; i++) bases.set(placement, 6 * i);
    if (Number.isNaN(this.anchorX)) this.setHulls(trace.outlines.map((outline) => new Hull(outline)), bases);
    else this.setBases(bases);
    this.anchorX = x;
    this.anchorY = y;
  }
}

/** Texture pixels → sprite-local units, `[a, b, c, d, tx, ty]`, as Pixi lays out a sprite's quad. */
function texturePlacement(texture: Texture, trace: Trace, anchorX: number, anchorY: number): Float64Array {
  const { orig, trim } = texture;
  const width = trim ? trim.width : orig.width;
  const height = trim ? trim.height : orig.height;
  return Float64Array.of(
    width / trace.width, 0, 0, height / trace.height,
    (trim ? trim.x : 0) - anchorX * orig.width, (trim ? trim.y : 0) - anchorY * orig.height,
  );
}

function traceTexture(texture: Texture, options: SpriteHullsOptions, renderer: Renderer | undefined): Trace {
  const { threshold, tolerance, maxPoints, minArea } = options;
  const key = `${threshold} ${tolerance} ${maxPoints} ${minArea}`;
  let byOptions = traces.get(texture);
  const cached = byOptions?.get(key);
  if (cached) return cached;
  const image = readTextureAlpha(texture, renderer);
  const hulls = hullsFromAlpha(image, { threshold, tolerance, maxPoints, minArea, anchor: [0, 0] });
  const trace = { width: image.width, height: image.height, outlines: hulls.map((hull) => hull.points) };
  if (!byOptions) traces.set(texture, (byOptions = new Map<string, Trace>()));
  byOptions.set(key, trace);
  return trace;
}

/** Whether `resource` can be handed to a 2D canvas's `drawImage`. */
function isDrawable(resource: unknown): resource is CanvasImageSource {
  if (typeof resource !== 'object' || resource === null) return false;
  for (const name of ['HTMLImageElement', 'HTMLCanvasElement', 'ImageBitmap', 'OffscreenCanvas', 'HTMLVideoElement', 'VideoFrame', 'SVGImageElement']) {
    const type = (globalThis as Record<string, unknown>)[name];
    if (typeof type === 'function' && resource instanceof type) return true;
  }
  return false;
}

/** The RGBA pixels of a texture's frame, top row first. */
function readTextureAlpha(texture: Texture, renderer: Renderer | undefined): AlphaImage {
  if (texture.rotate) throw new RangeError(`penumbra: hulls of a texture rotated in its atlas (rotate ${texture.rotate}) are not supported`);
  const source = texture.source;
  const resolution = source.resolution;
  const frame = texture.frame;
  const x = Math.round(frame.x * resolution), y = Math.round(frame.y * resolution);
  const width = Math.max(1, Math.round(frame.width * resolution));
  const height = Math.max(1, Math.round(frame.height * resolution));
  const resource: unknown = source.resource;
  if (isDrawable(resource)) {
    if (typeof HTMLImageElement !== 'undefined' && resource instanceof HTMLImageElement && !(resource.complete && resource.naturalWidth > 0)) {
      throw new TypeError('penumbra: the texture\'s image is not loaded yet: trace it once it is (await Assets.load)');
    }
    const canvas = DOMAdapter.get().createCanvas(width, height);
    const context = canvas.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D | null;
    if (context) {
      context.drawImage(resource, x, y, width, height, 0, 0, width, height);
      return context.getImageData(0, 0, width, height);
    }
  } else if (ArrayBuffer.isView(resource) && /^(rgba8|bgra8)unorm/.test(source.format)) {
    // A pixel buffer (BufferImageSource) of 8-bit RGBA or BGRA: alpha is the fourth byte either way.
    const bytes = new Uint8Array(resource.buffer, resource.byteOffset, resource.byteLength);
    const data = new Uint8ClampedArray(width * height * 4);
    for (let row = 0; row < height; row++) {
      const start = ((y + row) * source.pixelWidth + x) * 4;
      data.set(bytes.subarray(start, start + width * 4), row * width * 4);
    }
    return { data, width, height };
  }
  if (!renderer) {
    throw new TypeError(`penumbra: the pixels of texture ${texture.label ?? texture.uid} are only on the GPU: pass Pixi's renderer to read them back`);
  }
  // Extract binds the texture's framebuffer; the layer rebinds its target when it sees gpuReads change.
  gpuReads++;
  const { pixels, width: readWidth, height: readHeight } = renderer.extract.pixels(texture);
  return { data: pixels, width: readWidth, height: readHeight };
}
