import type { ShadowBins } from '../geometry/ShadowBins';
import type { ShadowGeometry } from '../geometry/ShadowGeometry';
import { BIN_COUNT, BIN_FLOATS, ENTRY_FLOATS, RECORD_FLOATS, RECORDS_PER_ROW, TEXTURE_WIDTH } from '../geometry/shadowLayout';

/** Texture units of the shadow textures; the light pass binds a light's cookie on unit 2. */
export const ShadowUnits = { records: 0, bins: 1, entries: 3, recordTags: 4 } as const;

/**
 * The GPU copy of the shadow data (see shadowLayout): the records of every hull and their tags
 * (uploaded by dirty rows: only when hulls change), and the frame's bins and entries (the rows the
 * frame used).
 */
export class ShadowTextures {
  readonly records: WebGLTexture;
  readonly recordTags: WebGLTexture;
  readonly bins: WebGLTexture;
  readonly entries: WebGLTexture;
  private recordRows = 0;
  private binRows = 0;
  private entryRows = 0;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.records = createDataTexture(gl);
    this.recordTags = createDataTexture(gl, TAG_FORMAT);
    this.bins = createDataTexture(gl);
    this.entries = createDataTexture(gl);
  }

  /** Uploads what changed; leaves the textures bound on their units (see {@link ShadowUnits}) and unit 0 active. */
  upload(geometry: ShadowGeometry, bins: ShadowBins): void {
    const gl = this.gl;
    const recordRows = geometry.records.length / (RECORDS_PER_ROW * RECORD_FLOATS);
    const resized = recordRows !== this.recordRows;
    this.recordRows = recordRows;
    gl.activeTexture(gl.TEXTURE0 + ShadowUnits.recordTags);
    gl.bindTexture(gl.TEXTURE_2D, this.recordTags);
    uploadRecordRows(gl, geometry, geometry.recordTags, RECORDS_PER_ROW, TAG_FORMAT, resized);
    gl.activeTexture(gl.TEXTURE0 + ShadowUnits.records);
    gl.bindTexture(gl.TEXTURE_2D, this.records);
    uploadRecordRows(gl, geometry, geometry.records, TEXTURE_WIDTH, RECORD_FORMAT, resized);
    gl.activeTexture(gl.TEXTURE0 + ShadowUnits.bins);
    gl.bindTexture(gl.TEXTURE_2D, this.bins);
    this.binRows = uploadUsed(gl, BIN_COUNT, bins.bins, bins.rowCount * BIN_COUNT * BIN_FLOATS, this.binRows);
    gl.activeTexture(gl.TEXTURE0 + ShadowUnits.entries);
    gl.bindTexture(gl.TEXTURE_2D, this.entries);
    this.entryRows = uploadUsed(gl, TEXTURE_WIDTH, bins.entries, bins.entryCount * ENTRY_FLOATS, this.entryRows);
    gl.activeTexture(gl.TEXTURE0);
  }

  dispose(): void {
    this.gl.deleteTexture(this.records);
    this.gl.deleteTexture(this.recordTags);
    this.gl.deleteTexture(this.bins);
    this.gl.deleteTexture(this.entries);
  }
}

/** A float texture's format: four floats a texel, or one. */
interface DataFormat {
  readonly channels: 1 | 4;
}
const RECORD_FORMAT: DataFormat = { channels: 4 };
const TAG_FORMAT: DataFormat = { channels: 1 };

function createDataTexture(gl: WebGL2RenderingContext, format: DataFormat = RECORD_FORMAT): WebGLTexture {
  const texture = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  allocate(gl, 1, 1, format);
  return texture;
}

/** (Re)allocates the bound RGBA32F (or R32F) texture. */
function allocate(gl: WebGL2RenderingContext, width: number, rows: number, format: DataFormat = RECORD_FORMAT): void {
  const [internal, layout] = format.channels === 4 ? [gl.RGBA32F, gl.RGBA] : [gl.R32F, gl.RED];
  gl.texImage2D(gl.TEXTURE_2D, 0, internal, width, Math.max(rows, 1), 0, layout, gl.FLOAT, null);
}

function uploadRows(gl: WebGL2RenderingContext, width: number, firstRow: number, rows: number, data: Float32Array, format: DataFormat = RECORD_FORMAT): void {
  const layout = format.channels === 4 ? gl.RGBA : gl.RED;
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, firstRow, width, rows, layout, gl.FLOAT, data, firstRow * width * format.channels);
}

/**
 * Uploads per-record data (`width` texels a row of records) to the bound texture: all of it when
 * the rows changed in number (reallocating), else the runs of dirty rows, one call per run.
 */
function uploadRecordRows(gl: WebGL2RenderingContext, geometry: ShadowGeometry, data: Float32Array, width: number, format: DataFormat, resized: boolean): void {
  const dirty = geometry.dirtyRows;
  if (resized) {
    allocate(gl, width, dirty.length, format);
    if (dirty.length > 0) uploadRows(gl, width, 0, dirty.length, data, format);
    return;
  }
  for (let row = 0; row < dirty.length; row++) {
    if (dirty[row] === 0) continue;
    const first = row;
    while (row + 1 < dirty.length && dirty[row + 1] !== 0) row++;
    uploadRows(gl, width, first, row + 1 - first, data, format);
  }
}

/**
 * Uploads the rows of the bound texture (`width` texels wide) that hold `data`'s first `floats`,
 * growing it to the array's whole rows when it no longer fits; returns its row count.
 */
function uploadUsed(gl: WebGL2RenderingContext, width: number, data: Float32Array, floats: number, rows: number): number {
  const rowFloats = width * 4;
  const used = Math.ceil(floats / rowFloats);
  if (used > rows) {
    rows = data.length / rowFloats;
    allocate(gl, width, rows);
  }
  if (used > 0) uploadRows(gl, width, 0, used, data);
  return rows;
}
