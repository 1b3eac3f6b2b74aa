import type { ShadowBins } from './ShadowBins';
import type { ShadowGeometry } from './ShadowGeometry';
import { BIN_COUNT, RECORDS_PER_ROW, TEXTURE_WIDTH } from './shadowLayout';

/** The texture units the shadow textures are bound on (the light pass's table gives them). */
export interface ShadowTextureUnits {
  readonly records: number;
  readonly bins: number;
  readonly entries: number;
  readonly recordTags: number;
}

/**
 * The GPU copy of the shadow data (see shadowLayout): the records of every hull and their tags, and
 * the lights' bins and entries, each uploaded by the rows written since the last upload (records
 * when hulls change, bins and entries when lights are filed anew), or whole when it grew.
 */
export class ShadowTextures {
  private readonly recordData: DataTexture;
  private readonly recordTagData: DataTexture;
  private readonly binData: DataTexture;
  private readonly entryData: DataTexture;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly units: ShadowTextureUnits) {
    this.recordData = new DataTexture(gl, TEXTURE_WIDTH, 4);
    this.recordTagData = new DataTexture(gl, RECORDS_PER_ROW, 1);
    this.binData = new DataTexture(gl, BIN_COUNT, 4);
    this.entryData = new DataTexture(gl, TEXTURE_WIDTH, 4);
  }

  get records(): WebGLTexture {
    return this.recordData.texture;
  }

  /** Uploads what changed; leaves the textures bound on their units (`units`) and unit 0 active. */
  upload(geometry: ShadowGeometry, bins: ShadowBins): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + this.units.recordTags);
    this.recordTagData.upload(geometry.dirtyRows, geometry.recordTags);
    gl.activeTexture(gl.TEXTURE0 + this.units.records);
    this.recordData.upload(geometry.dirtyRows, geometry.records);
    gl.activeTexture(gl.TEXTURE0 + this.units.bins);
    this.binData.upload(bins.dirtyBinRows, bins.bins);
    gl.activeTexture(gl.TEXTURE0 + this.units.entries);
    this.entryData.upload(bins.dirtyEntryRows, bins.entries);
    gl.activeTexture(gl.TEXTURE0);
  }

  dispose(): void {
    this.recordData.dispose();
    this.recordTagData.dispose();
    this.binData.dispose();
    this.entryData.dispose();
  }
}

/** Floats per texel (RGBA32F, R32F). */
type Channels = 1 | 4;

/** A nearest-filtered RGBA32F or R32F texture `width` texels wide, a copy of the rows of an array. */
class DataTexture {
  readonly texture: WebGLTexture;
  private rows = -1;
  /**
   * Per row, a view of the array from that row on, made once per array: texSubImage2D's source
   * offset would do without views, but headless-gl ignores it (it uploads from the array's start).
   */
  private views: Float32Array[] = [];
  private viewed: Float32Array | null = null;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly width: number, private readonly channels: Channels) {
    this.texture = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    this.allocate(1);
  }

  /**
   * Binds the texture on the active unit and uploads `data` (one row per entry of `dirty`): all of
   * it, reallocating, when its rows changed in number, else the runs of dirty rows, one call each.
   */
  upload(dirty: Uint8Array, data: Float32Array): void {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    if (dirty.length !== this.rows) {
      this.rows = dirty.length;
      this.allocate(this.rows);
      if (this.rows > 0) this.uploadRows(data, 0, this.rows);
      return;
    }
    for (let row = 0; row < dirty.length; row++) {
      if (dirty[row] === 0) continue;
      const first = row;
      while (row + 1 < dirty.length && dirty[row + 1] !== 0) row++;
      this.uploadRows(data, first, row + 1 - first);
    }
  }

  dispose(): void {
    this.gl.deleteTexture(this.texture);
  }

  private allocate(rows: number): void {
    const gl = this.gl;
    gl.texImage2D(gl.TEXTURE_2D, 0, this.internalFormat(), this.width, Math.max(rows, 1), 0, this.layout(), gl.FLOAT, null);
  }

  private internalFormat(): number {
    return this.channels === 4 ? this.gl.RGBA32F : this.gl.R32F;
  }

  private layout(): number {
    return this.channels === 4 ? this.gl.RGBA : this.gl.RED;
  }

  private uploadRows(data: Float32Array, firstRow: number, rows: number): void {
    const gl = this.gl;
    if (this.viewed !== data) {
      this.viewed = data;
      this.views = [];
    }
    const view = this.views[firstRow] ??= data.subarray(firstRow * this.width * this.channels);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, firstRow, this.width, rows, this.layout(), gl.FLOAT, view);
  }
}
