import { POINT_FLOATS, POINT_ROW, type ShadowGeometry } from '../geometry/ShadowGeometry';
import { CASTER_ROW, type FramePlan } from '../geometry/FramePlan';

/** Width of the hull-points texture, in points: one row per block of point capacity. */
const POINTS_TEXTURE_WIDTH = POINT_ROW;

/**
 * The shared GPU copy of the hull geometry: the point records (as a vertex buffer for the hull
 * pass and as an RGBA32F texture the shadow-mask pass fetches edges from), and the frame's lists:
 * triangle indices for the hull pass, shadow casters (an R32F texture) for the shadow quads. Uploads only the
 * runs of dirty point rows unless the capacity changed: one call pair per run rather than one span
 * from the first to the last dirty row, so two hulls moving far apart in the arrays do not upload
 * everything between them.
 *
 * Shadow quads have no vertex attributes: the six vertices of caster `i` of a light find it from
 * `gl_VertexID` in the casters texture, so per light the CPU writes and uploads 4 bytes per caster.
 * Not instanced: SwiftShader runs each instance as a draw of its own, about 10 µs each (measured
 * at 20,000 small quads: 216 ms instanced, 27 ms as one draw of triangles).
 */
export class GeometryBuffers {
  /** A vertex array with no attributes, for the shadow quads. */
  readonly casterVertexArray: WebGLVertexArrayObject;
  readonly hullVertexArray: WebGLVertexArrayObject;
  readonly pointsTexture: WebGLTexture;
  readonly castersTexture: WebGLTexture;
  private readonly pointBuffer: WebGLBuffer;
  private readonly indexBuffer: WebGLBuffer;
  private pointCapacity = 0;
  private indexCapacity = 0;
  private casterCapacity = 0;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.pointBuffer = gl.createBuffer()!;
    this.indexBuffer = gl.createBuffer()!;
    this.pointsTexture = gl.createTexture()!;
    this.castersTexture = gl.createTexture()!;
    this.casterVertexArray = gl.createVertexArray()!;
    this.hullVertexArray = gl.createVertexArray()!;
    gl.bindVertexArray(this.hullVertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.pointBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, POINT_FLOATS * 4, 0);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
    gl.bindVertexArray(null);
  }

  /** Uploads what changed in `geometry` and the frame's lists. Changes buffer, VAO and texture bindings. */
  upload(geometry: ShadowGeometry, plan: FramePlan): void {
    const gl = this.gl;
    const capacity = geometry.points.length / POINT_FLOATS;
    if (capacity !== this.pointCapacity) {
      this.pointCapacity = capacity;
      this.allocate(geometry);
    } else {
      this.uploadDirtyRows(geometry);
    }
    // The index buffer is element state of the hull vertex array: bound through it, never through the host's.
    gl.bindVertexArray(this.hullVertexArray);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
    if (plan.indexCount > this.indexCapacity) {
      this.indexCapacity = plan.indices.length;
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, plan.indices.byteLength, gl.DYNAMIC_DRAW);
    }
    if (plan.indexCount > 0) gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 0, plan.indices, 0, plan.indexCount);
    this.uploadCasters(plan);
  }

  /** Uploads the rows of the casters texture that hold the frame's casters, reallocating it when the plan's array grew. */
  private uploadCasters(plan: FramePlan): void {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.castersTexture);
    if (plan.casters.length !== this.casterCapacity) {
      this.casterCapacity = plan.casters.length;
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, CASTER_ROW, this.casterCapacity / CASTER_ROW, 0, gl.RED, gl.FLOAT, null);
    }
    const rows = Math.ceil(plan.casterCount / CASTER_ROW);
    if (rows > 0) gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, CASTER_ROW, rows, gl.RED, gl.FLOAT, plan.casters, 0);
  }

  private allocate(geometry: ShadowGeometry): void {
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.pointBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, geometry.points, gl.DYNAMIC_DRAW);
    const rows = this.pointCapacity / POINTS_TEXTURE_WIDTH;
    gl.bindTexture(gl.TEXTURE_2D, this.pointsTexture);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, POINTS_TEXTURE_WIDTH, Math.max(rows, 1), 0, gl.RGBA, gl.FLOAT, null);
    if (rows > 0) this.uploadPointRows(geometry, 0, rows);
  }

  private uploadDirtyRows(geometry: ShadowGeometry): void {
    const dirty = geometry.dirtyRows;
    for (let row = 0; row < dirty.length; row++) {
      if (dirty[row] === 0) continue;
      const first = row;
      while (row + 1 < dirty.length && dirty[row + 1] !== 0) row++;
      this.uploadPoints(geometry, first, row + 1 - first);
    }
  }

  /** Uploads `rows` whole rows of point records from `firstRow` to the vertex buffer and the texture. */
  private uploadPoints(geometry: ShadowGeometry, firstRow: number, rows: number): void {
    const gl = this.gl;
    const rowFloats = POINTS_TEXTURE_WIDTH * POINT_FLOATS;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.pointBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, firstRow * rowFloats * 4, geometry.points, firstRow * rowFloats, rows * rowFloats);
    gl.bindTexture(gl.TEXTURE_2D, this.pointsTexture);
    this.uploadPointRows(geometry, firstRow, rows);
  }

  /** Uploads whole texture rows; the points array holds whole rows (see POINT_ROW). */
  private uploadPointRows(geometry: ShadowGeometry, firstRow: number, rows: number): void {
    const gl = this.gl;
    const rowFloats = POINTS_TEXTURE_WIDTH * POINT_FLOATS;
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, firstRow, POINTS_TEXTURE_WIDTH, rows, gl.RGBA, gl.FLOAT, geometry.points, firstRow * rowFloats);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteBuffer(this.pointBuffer);
    gl.deleteBuffer(this.indexBuffer);
    gl.deleteTexture(this.pointsTexture);
    gl.deleteTexture(this.castersTexture);
    gl.deleteVertexArray(this.casterVertexArray);
    gl.deleteVertexArray(this.hullVertexArray);
  }
}
