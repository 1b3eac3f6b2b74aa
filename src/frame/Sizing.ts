import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import { assertFinite, describeValue } from '../util/validate';

/**
 * The size of the renderer's targets, the largest the context allows, the lightmap's share of it
 * (`lightmapScale`), and the view-projection, whose default (pixel space of the targets, origin
 * top-left, y down) follows the size. A side is 0 while a renderer made on a lost context without
 * it waits for the restore; the identity stands in for the default view until then.
 */
export class Sizing {
  /** World → clip; the default one while no other was assigned. */
  readonly viewProjection = mat4.create();
  private customViewProjection = false;
  private _width: number;
  private _height: number;
  /** The largest target side the context allows (MAX_TEXTURE_SIZE and MAX_RENDERBUFFER_SIZE); read again on restore. */
  private maxSize: number;

  /** The lightmap's side over the targets', in (0, 1]. */
  readonly lightmapScale: number;

  /** Checks the options' sides (a side not given is the drawing buffer's, or waits on a lost context), then the scale. */
  constructor(gl: WebGL2RenderingContext, width: number | undefined, height: number | undefined, lightmapScale: number) {
    this.maxSize = maxTargetSize(gl);
    // A lost context's drawing buffer is 0 × 0: a side left to it waits for the restore (0 until then).
    const lost = gl.isContextLost();
    this._width = width === undefined && lost ? 0 : this.checkSize('PenumbraRenderer.width', width ?? gl.drawingBufferWidth);
    this._height = height === undefined && lost ? 0 : this.checkSize('PenumbraRenderer.height', height ?? gl.drawingBufferHeight);
    if (typeof lightmapScale !== 'number' || !(lightmapScale > 0 && lightmapScale <= 1)) {
      throw new RangeError(`PenumbraRenderer.lightmapScale must be in (0, 1], got ${lightmapScale}`);
    }
    this.lightmapScale = lightmapScale;
    this.updateDefaultViewProjection();
  }

  get width(): number {
    return this._width;
  }
  get height(): number {
    return this._height;
  }
  get lightmapWidth(): number {
    return Math.max(1, Math.round(this._width * this.lightmapScale));
  }
  get lightmapHeight(): number {
    return Math.max(1, Math.round(this._height * this.lightmapScale));
  }

  /**
   * Whether the composite upsamples the lightmap aware of hull outlines: when it is smaller than
   * the scene (`lightmapScale` below 1), through the hull masks.
   */
  get edgeAware(): boolean {
    return this.lightmapScale < 1;
  }

  /** `value`, checked as a side of the targets: a positive integer within the context's limit. */
  checkSize(name: string, value: number): number {
    if (!Number.isInteger(value) || value <= 0) throw new RangeError(`${name} must be a positive integer, got ${describeValue(value)}`);
    if (value > this.maxSize) {
      throw new RangeError(`${name} ${value} exceeds this context's largest texture size ${this.maxSize} (MAX_TEXTURE_SIZE / MAX_RENDERBUFFER_SIZE)`);
    }
    return value;
  }

  setSize(width: number, height: number): void {
    this._width = width;
    this._height = height;
    if (!this.customViewProjection) this.updateDefaultViewProjection();
  }

  /** Takes `value` as the view-projection after checking it, or goes back to the default for `null`. */
  setViewProjection(value: ReadonlyMat4 | null): void {
    if (value == null) {
      this.customViewProjection = false;
      this.updateDefaultViewProjection();
      return;
    }
    if (value.length !== 16) throw new RangeError(`PenumbraRenderer.viewProjection must have 16 elements, got ${value.length}`);
    for (let i = 0; i < 16; i++) assertFinite(`PenumbraRenderer.viewProjection[${i}]`, value[i]);
    mat4.copy(this.viewProjection, value);
    this.customViewProjection = true;
  }

  /** On a restored context: reads its limit again, and gives a side still 0 the drawing buffer's. */
  adoptRestoredContext(gl: WebGL2RenderingContext): void {
    this.maxSize = maxTargetSize(gl);
    if (this._width !== 0 && this._height !== 0) return;
    this.setSize(this._width || this.checkSize('PenumbraRenderer.width', gl.drawingBufferWidth),
      this._height || this.checkSize('PenumbraRenderer.height', gl.drawingBufferHeight));
  }

  private updateDefaultViewProjection(): void {
    if (this._width === 0 || this._height === 0) return;
    mat4.ortho(this.viewProjection, 0, this._width, this._height, 0, -1, 1);
  }
}

/** The largest side of a target the context can allocate: its texture and its depth/stencil renderbuffer. */
function maxTargetSize(gl: WebGL2RenderingContext): number {
  // A lost context answers null: no limit is known until it is back.
  const textureSize = (gl.getParameter(gl.MAX_TEXTURE_SIZE) as number | null) ?? Infinity;
  const renderbufferSize = (gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number | null) ?? Infinity;
  return Math.min(textureSize, renderbufferSize);
}
