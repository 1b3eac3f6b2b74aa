import { mat4 } from 'gl-matrix';

/** Smallest and largest zoom (CSS pixels per world unit) the view allows. */
const MIN_ZOOM = 0.05;
const MAX_ZOOM = 20;

/**
 * The playground's 2D view: the world point at the centre of the canvas's free part (left of
 * `insetRight`, which the panel covers) and a zoom in CSS pixels per world unit. It yields the
 * renderer's `viewProjection`, so lights and hulls stay in world units.
 */
export class Camera {
  readonly center: [number, number] = [0, 0];
  zoom = 1;
  /** Canvas size in CSS pixels. */
  width = 1;
  height = 1;
  /** CSS pixels on the canvas's right that the panel covers: the view centres on the rest. */
  insetRight = 0;
  private readonly matrix = mat4.create();

  /** World → clip for the current view, y down (reused matrix: copy it to keep it). */
  viewProjection(): mat4 {
    const m = this.matrix;
    mat4.identity(m);
    m[0] = (2 * this.zoom) / this.width;
    m[5] = (-2 * this.zoom) / this.height;
    m[12] = -this.center[0] * m[0] + (2 * this.anchorX()) / this.width - 1;
    m[13] = -this.center[1] * m[5];
    return m;
  }

  /** The world point under a canvas point (CSS pixels), written into `out`. */
  screenToWorld(x: number, y: number, out: [number, number]): [number, number] {
    out[0] = this.center[0] + (x - this.anchorX()) / this.zoom;
    out[1] = this.center[1] + (y - this.height / 2) / this.zoom;
    return out;
  }

  /** The canvas point (CSS pixels) of a world point, written into `out`. */
  worldToScreen(x: number, y: number, out: [number, number]): [number, number] {
    out[0] = (x - this.center[0]) * this.zoom + this.anchorX();
    out[1] = (y - this.center[1]) * this.zoom + this.height / 2;
    return out;
  }

  /** Where on the canvas (CSS x) `center` is drawn: the middle of the part the panel leaves free. */
  private anchorX(): number {
    return Math.max(0, this.width - this.insetRight) / 2;
  }

  /** Moves the view by a distance in CSS pixels. */
  panBy(dx: number, dy: number): void {
    this.center[0] -= dx / this.zoom;
    this.center[1] -= dy / this.zoom;
  }

  /** Multiplies the zoom by `factor`, keeping the world point under canvas point (x, y) in place. */
  zoomAt(x: number, y: number, factor: number): void {
    const zoom = Math.min(MAX_ZOOM, Math.max(MIN_ZOOM, this.zoom * factor));
    const wx = this.center[0] + (x - this.anchorX()) / this.zoom;
    const wy = this.center[1] + (y - this.height / 2) / this.zoom;
    this.zoom = zoom;
    this.center[0] = wx - (x - this.anchorX()) / zoom;
    this.center[1] = wy - (y - this.height / 2) / zoom;
  }

  /** The visible world rectangle `[minX, minY, maxX, maxY]`, written into `out`. */
  visibleWorld(out: Float32Array): Float32Array {
    const left = this.anchorX() / this.zoom, right = (this.width - this.anchorX()) / this.zoom, halfHeight = this.height / 2 / this.zoom;
    out[0] = this.center[0] - left;
    out[1] = this.center[1] - halfHeight;
    out[2] = this.center[0] + right;
    out[3] = this.center[1] + halfHeight;
    return out;
  }
}
