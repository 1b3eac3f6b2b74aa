import { hullsFromAlpha } from 'penumbra-gl';
import type { Playground } from './Playground';

/** Images are traced at most this many pixels on their longer side (larger ones are scaled down first). */
const MAX_TRACE_SIZE = 512;
/** A pixel is solid from this alpha (hullsFromAlpha's default). */
const THRESHOLD = 128;
/** The traced image's longer side is its own size in world units, kept within these fractions of the view's shorter side. */
const FIT_MIN = 0.15;
const FIT_MAX = 0.5;

/**
 * Turns an image file into hulls that cast its opaque pixels' shadow (`hullsFromAlpha`), placed
 * with the image's centre at a world point and sized to fit the view, with the image itself drawn
 * under them. Failures (not an image, nothing opaque) become `status` and a message, never a throw.
 */
export class ImageTracer {
  /** Largest distance in image pixels between a hull's outline and the traced one. */
  private _tolerance = 1;
  /** What the last trace did, for the panel. */
  status = 'none yet';
  private readonly view = new Float32Array(4);

  constructor(private readonly playground: Playground, private readonly showError: (message: string) => void) {}

  get tolerance(): number {
    return this._tolerance;
  }
  set tolerance(value: number) {
    if (typeof value !== 'number' || !Number.isFinite(value) || value < 0) throw new RangeError(`image tolerance must be a finite number ≥ 0, got ${value}`);
    this._tolerance = value;
  }

  /** Traces `file` and adds its hulls centred on world point (x, y). Resolves once done, whatever happened. */
  async trace(file: File, x: number, y: number): Promise<void> {
    this.status = `tracing ${file.name}…`;
    try {
      const { canvas, naturalSize } = await decode(file);
      const { width, height } = canvas;
      const pixels = canvas.getContext('2d', { willReadFrequently: true })!.getImageData(0, 0, width, height);
      const scale = this.fitSize(naturalSize) / Math.max(width, height);
      const hulls = hullsFromAlpha(pixels, { threshold: THRESHOLD, tolerance: this._tolerance, position: [x, y], scale });
      if (hulls.length === 0) throw new Error(`it has no opaque pixels (alpha ≥ ${THRESHOLD}) to cast a shadow`);
      this.playground.addTracedImage(hulls, canvas, width, height);
      this.playground.renderer.debug = true;
      const points = hulls.reduce((sum, hull) => sum + hull.points.length, 0);
      this.status = `${file.name}: ${hulls.length} hull${hulls.length === 1 ? '' : 's'}, ${points} points`;
    } catch (error) {
      this.status = `${file.name}: not traced`;
      this.showError(`Could not trace ${file.name}: ${(error as Error).message}`);
    }
  }

  /**
   * The world length of the image's longer side: its own size in pixels (one unit per pixel),
   * brought within {@link FIT_MIN}–{@link FIT_MAX} of the view's shorter side.
   */
  private fitSize(naturalSize: number): number {
    const [x0, y0, x1, y1] = this.playground.camera.visibleWorld(this.view);
    const view = Math.min(x1 - x0, y1 - y0);
    return Math.min(FIT_MAX * view, Math.max(FIT_MIN * view, naturalSize));
  }
}

/**
 * The file's pixels on a canvas, scaled down to at most {@link MAX_TRACE_SIZE} pixels a side, and
 * the file's own longer side; rejects with a readable message if it is no image.
 */
async function decode(file: File): Promise<{ canvas: HTMLCanvasElement; naturalSize: number }> {
  let bitmap: ImageBitmap;
  try {
    bitmap = await createImageBitmap(file);
  } catch {
    throw new Error(`it is not an image this browser can read (type ${file.type || 'unknown'})`);
  }
  const fit = Math.min(1, MAX_TRACE_SIZE / Math.max(bitmap.width, bitmap.height));
  const canvas = document.createElement('canvas');
  canvas.width = Math.max(1, Math.round(bitmap.width * fit));
  canvas.height = Math.max(1, Math.round(bitmap.height * fit));
  canvas.getContext('2d', { willReadFrequently: true })!.drawImage(bitmap, 0, 0, canvas.width, canvas.height);
  const naturalSize = Math.max(bitmap.width, bitmap.height);
  bitmap.close();
  return { canvas, naturalSize };
}
