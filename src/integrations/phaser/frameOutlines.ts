import type Phaser from 'phaser';
import { hullsFromAlpha, type AlphaImage } from '../../index';

/** How an image's alpha is traced: the fields of `HullsFromAlphaOptions` that shape the outlines. */
interface TraceOptions {
  threshold?: number;
  tolerance?: number;
  maxPoints?: number;
  minArea?: number;
}

/** A traced outline: points in pixels of the traced image, y down. */
export type Outline = ReadonlyArray<readonly [number, number]>;

/** Outlines per frame object, then per trace options: a frame's pixels are read once for each. */
const cache = new WeakMap<Phaser.Textures.Frame, Map<string, readonly Outline[]>>();

/**
 * The outlines of a texture frame's opaque pixels, in pixels of the frame's cut (its rectangle in
 * the source image, `cutWidth × cutHeight`), cached per frame object and trace options.
 * @throws TypeError when the frame's pixels cannot be read (no image or canvas behind it, or a
 * cross-origin image).
 */
export function frameOutlines(frame: Phaser.Textures.Frame, options: TraceOptions): readonly Outline[] {
  const key = `${options.threshold}/${options.tolerance}/${options.maxPoints}/${options.minArea}`;
  let byOptions = cache.get(frame);
  if (!byOptions) cache.set(frame, byOptions = new Map<string, readonly Outline[]>());
  let outlines = byOptions.get(key);
  if (!outlines) byOptions.set(key, outlines = traceImage(readFramePixels(frame), options));
  return outlines;
}

/** Drops the cached outlines of a frame, e.g. after its canvas was redrawn. */
export function forgetFrameOutlines(frame: Phaser.Textures.Frame): void {
  cache.delete(frame);
}

/** The outlines of an image's opaque pixels (see `hullsFromAlpha`), not placed. */
export function traceImage(image: AlphaImage, options: TraceOptions): readonly Outline[] {
  const { threshold, tolerance, maxPoints, minArea } = options;
  return Object.freeze(hullsFromAlpha(image, { threshold, tolerance, maxPoints, minArea, anchor: [0, 0] }).map((hull) => hull.points));
}

/**
 * The RGBA pixels of a frame's cut from its source image, upright: an atlas packer may store a
 * frame turned 90° clockwise (`frame.rotated`), `cutHeight` wide and `cutWidth` tall.
 */
function readFramePixels(frame: Phaser.Textures.Frame): AlphaImage {
  const named = `frame ${JSON.stringify(frame.name)} of texture ${JSON.stringify(frame.texture.key)}`;
  const source: unknown = frame.source.image;
  if (!(source instanceof HTMLImageElement || source instanceof HTMLCanvasElement || source instanceof HTMLVideoElement
    || (typeof ImageBitmap !== 'undefined' && source instanceof ImageBitmap))) {
    throw new TypeError(`penumbra: the pixels of ${named} cannot be read (its source is not an image or a canvas, e.g. a DynamicTexture or raw data): give options.image`);
  }
  const width = frame.cutWidth, height = frame.cutHeight;
  if (width === 0 || height === 0) return { data: new Uint8ClampedArray(0), width, height };
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const context = canvas.getContext('2d', { willReadFrequently: true });
  if (!context) throw new TypeError(`penumbra: no 2D canvas to read the pixels of ${named}`);
  if (frame.rotated) {
    // Stored pixel (sx, sy) is upright pixel (sy, height − sx): map the stored rectangle onto the canvas.
    context.setTransform(0, -1, 1, 0, 0, height);
    context.drawImage(source, frame.cutX, frame.cutY, height, width, 0, 0, height, width);
  } else {
    context.drawImage(source, frame.cutX, frame.cutY, width, height, 0, 0, width, height);
  }
  try {
    return context.getImageData(0, 0, width, height);
  } catch (error) {
    throw new TypeError(`penumbra: the pixels of ${named} cannot be read (${String(error)}; a cross-origin image needs CORS): give options.image`, { cause: error });
  }
}
