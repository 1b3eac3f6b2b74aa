import type { ShadowBins } from './ShadowBins';
import type { ShadowGeometry } from './ShadowGeometry';
import { BIN_COUNT, RECORDS_PER_ROW, TEXTURE_WIDTH } from './shadowLayout';
import type { TileRecordLists } from './TileRecordLists';

/** The texture units the shadow textures are bound on (the light pass's table gives them). */
export interface ShadowTextureUnits {
  readonly records: number;
  readonly bins: number;
  readonly entries: number;
  readonly recordTags: number;
  readonly tileRecords: number;
}

/**
 * The GPU copy of the shadow data (see shadowLayout): the records of every hull and their tags, and
 * the lights' bins, entries and tile records, each uploaded by the rows written since the last
 * upload (records when hulls change, the others when lights are filed or classified anew), or
 * whole when it grew.
 */
export class ShadowTextures {
  private readonly recordData: DataTexture;
  private readonly recordTagData: DataTexture;
  private readonly binData: DataTexture;
  private readonly entryData: DataTexture;
  private readonly tileRecordData: DataTexture;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly units: ShadowTextureUnits) {
    this.recordData = new DataTexture(gl, TEXTURE_WIDTH, 'rgba32f');
    this.recordTagData = new DataTexture(gl, RECORDS_PER_ROW, 'r32f');
    this.binData = new DataTexture(gl, BIN_COUNT, 'rgba32f');
    this.entryData = new DataTexture(gl, TEXTURE_WIDTH, 'rgba32f');
    this.tileRecordData = new DataTexture(gl, TEXTURE_WIDTH, 'rg16ui');
  }

  get records(): WebGLTexture {
    return this.recordData.texture;
  }

  /** Uploads what changed; leaves the textures bound on their units (`units`) and unit 0 active. */
  upload(geometry: ShadowGeometry, bins: ShadowBins, lists: TileRecordLists): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + this.units.recordTags);
    this.recordTagData.upload(geometry.dirtyRows, geometry.recordTags);
    gl.activeTexture(gl.TEXTURE0 + this.units.records);
    this.recordData.upload(geometry.dirtyRows, geometry.records);
    gl.activeTexture(gl.TEXTURE0 + this.units.bins);
    this.binData.upload(bins.dirtyBinRows, bins.bins);
    gl.activeTexture(gl.TEXTURE0 + this.units.entries);
    this.entryData.upload(bins.dirtyEntryRows, bins.entries);
    gl.activeTexture(gl.TEXTURE0 + this.units.tileRecords);
    this.tileRecordData.upload(lists.dirtyTextureRows, lists.maskHalves);
    gl.activeTexture(gl.TEXTURE0);
  }

  dispose(): void {
    this.recordData.dispose();
    this.recordTagData.dispose();
    this.binData.dispose();
    this.entryData.dispose();
    this.tileRecordData.dispose();
  }
}

/** A data texture's format: its texels' channels and type. */
type DataFormat = 'rgba32f' | 'r32f' | 'rg16ui';

/** Per format: values per texel, internal format, format and type (as GL enum names). */
const FORMATS = {
  rgba32f: { channels: 4, internalFormat: 'RGBA32F', layout: 'RGBA', type: 'FLOAT' },
  r32f: { channels: 1, internalFormat: 'R32F', layout: 'RED', type: 'FLOAT' },
  // 32-bit words as their two halves: headless-gl uploads no Uint32Array, and WebGL takes a
  // Uint16Array for UNSIGNED_SHORT only.
  rg16ui: { channels: 2, internalFormat: 'RG16UI', layout: 'RG_INTEGER', type: 'UNSIGNED_SHORT' },
} as const satisfies Record<DataFormat, { channels: number; internalFormat: keyof WebGL2RenderingContext; layout: keyof WebGL2RenderingContext; type: keyof WebGL2RenderingContext }>;

/** A nearest-filtered texture `width` texels wide of one of the data formats, a copy of the rows of an array. */
class DataTexture {
  readonly texture: WebGLTexture;
  private rows = -1;
  private readonly channels: number;
  private readonly internalFormat: number;
  private readonly layout: number;
  private readonly type: number;
  /**
   * Per row, a view of the array from that row on, made once per array: texSubImage2D's source
   * offset would do without views, but headless-gl ignores it (it uploads from the array's start).
   */
  private views: (Float32Array | Uint16Array)[] = [];
  private viewed: Float32Array | Uint16Array | null = null;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly width: number, format: DataFormat) {
    const { channels, internalFormat, layout, type } = FORMATS[format];
    this.channels = channels;
    this.internalFormat = gl[internalFormat];
    this.layout = gl[layout];
    this.type = gl[type];
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
  upload(dirty: Uint8Array, data: Float32Array | Uint16Array): void {
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
    gl.texImage2D(gl.TEXTURE_2D, 0, this.internalFormat, this.width, Math.max(rows, 1), 0, this.layout, this.type, null);
  }

  private uploadRows(data: Float32Array | Uint16Array, firstRow: number, rows: number): void {
    const gl = this.gl;
    if (this.viewed !== data) {
      this.viewed = data;
      this.views = [];
    }
    const view = this.views[firstRow] ??= data.subarray(firstRow * this.width * this.channels);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, firstRow, this.width, rows, this.layout, this.type, view);
  }
}
