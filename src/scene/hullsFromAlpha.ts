import { alphaOutlines } from '../geometry/alphaOutlines';
import { Hull } from './Hull';
import { assertBoolean, assertFinite, assertNonNegative, assertOptions, describeValue, frozenVec2, type Vec2Like } from '../util/validate';

/**
 * An image's pixels as RGBA bytes, row after row from the top: a browser's `ImageData`, or raw
 * RGBA in Node (a decoded PNG, a `Buffer`). `data` holds exactly `width × height × 4` bytes.
 */
export interface AlphaImage {
  /** RGBA bytes, 4 per pixel; only every fourth (alpha) is read. */
  readonly data: Uint8ClampedArray | Uint8Array;
  /** Width in pixels. */
  readonly width: number;
  /** Height in pixels. */
  readonly height: number;
}

/**
 * Options of {@link hullsFromAlpha}; every field has the default shown. The placement fields are
 * a sprite's: a hull follows a sprite drawn from the same image when it gets the sprite's
 * `position`, `rotation` and `scale` (world units per pixel), and `anchor` is the sprite's
 * anchor (Pixi) or origin (Phaser). The vectors take `[x, y]` or `{ x, y }` ({@link Vec2Like}):
 * a Pixi sprite's `anchor`, `position` and `scale` as they are.
 */
export interface HullsFromAlphaOptions {
  /** A pixel is solid when its alpha is ≥ this (0–255). Default `128`. */
  threshold?: number;
  /**
   * Largest distance, in pixels, between a hull's outline and the traced outline of the solid
   * pixels (Douglas–Peucker). `0` keeps every corner of the trace. Default `1`.
   */
  tolerance?: number;
  /**
   * Most points per hull, an integer ≥ 3 or `Infinity`: an outline with more is simplified with a
   * larger tolerance until it fits. Only the points where a hull meets another hull split from the
   * same island are never dropped, and can exceed it. Default `64`.
   */
  maxPoints?: number;
  /** Islands (4-connected solid pixels) of fewer pixels than this are dropped: specks, noise. Default `0`. */
  minArea?: number;
  /**
   * The pivot as a fraction of the image's size: `[0, 0]` its top-left corner, `[0.5, 0.5]` its
   * centre. Each hull's `origin` is this point in pixels. Default `[0.5, 0.5]`.
   */
  anchor?: Vec2Like;
  /** World position of the anchor. Default `[0, 0]`. */
  position?: Vec2Like;
  /** Rotation in radians around the anchor (positive turns +x towards +y). Default `0`. */
  rotation?: number;
  /** World units per pixel, one factor or `[sx, sy]`; a negative factor mirrors around the anchor. Default `1`. */
  scale?: number | Vec2Like;
  /**
   * Mirror the image left–right within its own bounds before placing it (Phaser's `flipX`: the
   * anchor stays where it is in the frame). For Pixi's mirroring (a negative scale) use `scale`.
   * Default `false`.
   */
  flipX?: boolean;
  /** Mirror the image top–bottom within its own bounds, as {@link HullsFromAlphaOptions.flipX}. Default `false`. */
  flipY?: boolean;
}

const NAME = 'hullsFromAlpha';
/** The options {@link hullsFromAlpha} takes; any other key is an error (see {@link assertOptions}). */
const OPTION_KEYS: readonly string[] = Object.keys({
  threshold: true, tolerance: true, maxPoints: true, minArea: true, anchor: true, position: true, rotation: true, scale: true, flipX: true, flipY: true,
} satisfies Record<keyof HullsFromAlphaOptions, true>);

/**
 * Hulls that cast the shadow of an image's opaque pixels: the pixels with alpha ≥ `threshold`,
 * traced by marching squares and simplified to `tolerance` pixels, one hull per island, islands
 * with holes split into several hulls that meet exactly along the cuts (hulls are simple polygons
 * without holes). Pure: runs in Node on raw RGBA as in a browser on `ImageData`.
 *
 * Each hull's points are in pixels, y down (flips applied), and its `origin`, `position`,
 * `rotation` and `scale` come from the options, so moving, turning or scaling every hull as the
 * sprite moves keeps them on it. Unsimplified (`tolerance: 0`), a hull holds exactly the centres
 * of its solid pixels; simplified, its outline stays within `tolerance` pixels of that trace.
 *
 * @example
 * ```ts
 * const image = context.getImageData(0, 0, canvas.width, canvas.height);
 * const hulls = hullsFromAlpha(image, { position: [400, 300], scale: 2, tolerance: 1.5 });
 * for (const hull of hulls) renderer.addHull(hull);
 * ```
 * @throws TypeError or RangeError naming the field when the image or an option is malformed.
 */
export function hullsFromAlpha(image: AlphaImage, options: HullsFromAlphaOptions = {}): Hull[] {
  const { data, width, height } = checkImage(image);
  assertOptions(NAME, options, OPTION_KEYS);
  const {
    threshold = 128, tolerance = 1, maxPoints = 64, minArea = 0, anchor = [0.5, 0.5], position = [0, 0], rotation = 0,
    scale = 1, flipX = false, flipY = false,
  } = options;
  assertNonNegative(`${NAME} options.threshold`, threshold);
  if (threshold > 255) throw new RangeError(`${NAME} options.threshold must be at most 255, got ${threshold}`);
  assertNonNegative(`${NAME} options.tolerance`, tolerance);
  checkMaxPoints(maxPoints);
  assertNonNegative(`${NAME} options.minArea`, minArea);
  const [ax, ay] = frozenVec2(`${NAME} options.anchor`, anchor);
  const placement = {
    position: frozenVec2(`${NAME} options.position`, position),
    rotation: assertFinite(`${NAME} options.rotation`, rotation),
    scale: typeof scale === 'number' ? [assertFinite(`${NAME} options.scale`, scale), scale] as const : frozenVec2(`${NAME} options.scale`, scale),
    origin: [ax * width, ay * height] as const,
  };
  assertBoolean(`${NAME} options.flipX`, flipX);
  assertBoolean(`${NAME} options.flipY`, flipY);

  const outlines = alphaOutlines(data, width, height, threshold, { tolerance, maxPoints, minArea });
  return outlines.map((outline) => {
    const coords = new Float64Array(outline.length);
    for (let i = 0; i < outline.length; i += 2) {
      coords[i] = flipX ? width - outline[i] : outline[i];
      coords[i + 1] = flipY ? height - outline[i + 1] : outline[i + 1];
    }
    return Hull.fromCoords(coords, placement);
  });
}

function checkImage(image: AlphaImage): AlphaImage {
  if (typeof image !== 'object' || image === null) throw new TypeError(`${NAME} image must be an ImageData or { data, width, height }, got ${describeValue(image)}`);
  const { data, width, height } = image;
  for (const [field, value] of [['width', width], ['height', height]] as const) {
    if (typeof value !== 'number') throw new TypeError(`${NAME} image.${field} must be a non-negative integer, got ${describeValue(value)}`);
    if (!Number.isInteger(value) || value < 0) throw new RangeError(`${NAME} image.${field} must be a non-negative integer, got ${describeValue(value)}`);
  }
  if (!(data instanceof Uint8ClampedArray || data instanceof Uint8Array)) {
    throw new TypeError(`${NAME} image.data must be a Uint8ClampedArray or Uint8Array of RGBA bytes, got ${describeValue(data)}`);
  }
  if (data.length !== width * height * 4) {
    throw new RangeError(`${NAME} image.data must hold width × height × 4 = ${width * height * 4} bytes, got ${data.length}`);
  }
  return image;
}

function checkMaxPoints(value: number): void {
  if (typeof value !== 'number') throw new TypeError(`${NAME} options.maxPoints must be an integer ≥ 3 or Infinity, got ${describeValue(value)}`);
  if (value !== Infinity && !(Number.isInteger(value) && value >= 3)) {
    throw new RangeError(`${NAME} options.maxPoints must be an integer ≥ 3 or Infinity, got ${describeValue(value)}`);
  }
}
