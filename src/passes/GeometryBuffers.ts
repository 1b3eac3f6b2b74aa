import { POINT_FLOATS, POINT_ROW, type ShadowGeometry } from '../geometry/ShadowGeometry';
import type { FramePlan, LightDraw } from '../geometry/FramePlan';

/** Width of the hull-points texture, in points: one row per block of point capacity. */
const POINTS_TEXTURE_WIDTH = POINT_ROW;

/**
 * The shared GPU copy of the hull geometry: the point records (as a vertex buffer for the hull
 * pass and as an RGBA32F texture the shadow-mask pass fetches edges from), and the frame's lists:
 * triangle indices for the hull pass, edge numbers for the instanced shadow quads. Uploads only the
 * runs of dirty point rows unless the capacity changed: one call pair per run rather than one span
 * from the first to the last dirty row, so two hulls moving far apart in the arrays do not upload
 * everything between them.
 *
 * Shadow quads are instanced (one instance per edge, its corners from `gl_VertexID`): per light the
 * CPU writes and uploads 4 bytes per edge, where four vertices and six indices per edge took 24
 * bytes of indices per light plus 128 bytes of vertices per edge.
 */
export class GeometryBuffers {
  private readonly edgeVertexArray: WebGLVertexArrayObject;
  readonly hullVertexArray: WebGLVertexArrayObject;
  readonly pointsTexture: WebGLTexture;
  private readonly pointBuffer: WebGLBuffer;
  private readonly indexBuffer: WebGLBuffer;
  private readonly edgeBuffer: WebGLBuffer;
  private pointCapacity = 0;
  private indexCapacity = 0;
  private edgeCapacity = 0;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.pointBuffer = gl.createBuffer()!;
    this.indexBuffer = gl.createBuffer()!;
    this.edgeBuffer = gl.createBuffer()!;
    this.pointsTexture = gl.createTexture()!;
    this.edgeVertexArray = gl.createVertexArray()!;
    gl.bindVertexArray(this.edgeVertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.edgeBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribIPointer(0, 1, gl.UNSIGNED_INT, 0, 0);
    gl.vertexAttribDivisor(0, 1);
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
    gl.bindBuffer(gl.ARRAY_BUFFER, this.edgeBuffer);
    if (plan.edgeCount > this.edgeCapacity) {
      this.edgeCapacity = plan.edges.length;
      gl.bufferData(gl.ARRAY_BUFFER, plan.edges.byteLength, gl.DYNAMIC_DRAW);
    }
    if (plan.edgeCount > 0) gl.bufferSubData(gl.ARRAY_BUFFER, 0, plan.edges, 0, plan.edgeCount);
  }

  /**
   * Binds the edge vertex array with its instance attribute pointing at `draw`'s edges (WebGL2 has
   * no base instance), for `drawArraysInstanced(mode, 0, 4, draw.edgeCount)`.
   */
  bindEdges(draw: LightDraw): void {
    const gl = this.gl;
    gl.bindVertexArray(this.edgeVertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.edgeBuffer);
    gl.vertexAttribIPointer(0, 1, gl.UNSIGNED_INT, 0, draw.edgeOffset * 4);
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
    gl.deleteBuffer(this.edgeBuffer);
    gl.deleteTexture(this.pointsTexture);
    gl.deleteVertexArray(this.edgeVertexArray);
    gl.deleteVertexArray(this.hullVertexArray);
  }
}
