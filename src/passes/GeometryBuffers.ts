import { POINT_ROW, SHADOW_VERTEX_FLOATS, VERTICES_PER_EDGE, type ShadowGeometry } from '../geometry/ShadowGeometry';
import type { FramePlan } from '../geometry/FramePlan';

/** Width of the hull-points texture, in points: one row per block of point capacity. */
const POINTS_TEXTURE_WIDTH = POINT_ROW;

/**
 * The shared GPU copy of the hull geometry: edge quads, hull points (as a vertex buffer for the
 * hull pass and as a texture for the shadow-mask pass) and the frame's index lists. Uploads only
 * the dirty point range unless the layout changed.
 */
export class GeometryBuffers {
  readonly edgeVertexArray: WebGLVertexArrayObject;
  readonly hullVertexArray: WebGLVertexArrayObject;
  readonly pointsTexture: WebGLTexture;
  private readonly edgeBuffer: WebGLBuffer;
  private readonly pointBuffer: WebGLBuffer;
  private readonly indexBuffer: WebGLBuffer;
  private pointCapacity = 0;
  private indexCapacity = 0;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.edgeBuffer = gl.createBuffer()!;
    this.pointBuffer = gl.createBuffer()!;
    this.indexBuffer = gl.createBuffer()!;
    this.pointsTexture = gl.createTexture()!;
    this.edgeVertexArray = gl.createVertexArray()!;
    gl.bindVertexArray(this.edgeVertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.edgeBuffer);
    const stride = SHADOW_VERTEX_FLOATS * 4;
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 4, gl.FLOAT, false, stride, 0);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribPointer(1, 2, gl.FLOAT, false, stride, 16);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribPointer(2, 2, gl.FLOAT, false, stride, 24);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
    this.hullVertexArray = gl.createVertexArray()!;
    gl.bindVertexArray(this.hullVertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.pointBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 8, 0);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
    gl.bindVertexArray(null);
  }

  /** Uploads what changed in `geometry` and the frame's index lists. Changes buffer, VAO and texture bindings. */
  upload(geometry: ShadowGeometry, plan: FramePlan): void {
    const gl = this.gl;
    const capacity = geometry.points.length >> 1;
    if (capacity !== this.pointCapacity) {
      this.pointCapacity = capacity;
      this.allocate(geometry);
    } else if (geometry.dirtyEnd > geometry.dirtyFirst) {
      this.uploadPoints(geometry, geometry.dirtyFirst, geometry.dirtyEnd);
    }
    gl.bindVertexArray(this.edgeVertexArray);
    if (plan.indexCount > this.indexCapacity) {
      this.indexCapacity = plan.indices.length;
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, plan.indices.byteLength, gl.DYNAMIC_DRAW);
    }
    if (plan.indexCount > 0) gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 0, plan.indices, 0, plan.indexCount);
  }

  private allocate(geometry: ShadowGeometry): void {
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.edgeBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, geometry.edgeVertices, gl.DYNAMIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.pointBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, geometry.points, gl.DYNAMIC_DRAW);
    const rows = this.pointCapacity / POINTS_TEXTURE_WIDTH;
    gl.bindTexture(gl.TEXTURE_2D, this.pointsTexture);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RG32F, POINTS_TEXTURE_WIDTH, Math.max(rows, 1), 0, gl.RG, gl.FLOAT, null);
    if (rows > 0) this.uploadPointRows(geometry, 0, rows);
  }

  private uploadPoints(geometry: ShadowGeometry, first: number, end: number): void {
    const gl = this.gl;
    const edgeFloats = VERTICES_PER_EDGE * SHADOW_VERTEX_FLOATS;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.edgeBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, first * edgeFloats * 4, geometry.edgeVertices, first * edgeFloats, (end - first) * edgeFloats);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.pointBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, first * 8, geometry.points, first * 2, (end - first) * 2);
    const firstRow = Math.floor(first / POINTS_TEXTURE_WIDTH);
    const endRow = Math.ceil(end / POINTS_TEXTURE_WIDTH);
    gl.bindTexture(gl.TEXTURE_2D, this.pointsTexture);
    this.uploadPointRows(geometry, firstRow, endRow - firstRow);
  }

  /** Uploads whole texture rows; the points array holds whole rows (see POINT_ROW). */
  private uploadPointRows(geometry: ShadowGeometry, firstRow: number, rows: number): void {
    const gl = this.gl;
    const rowFloats = POINTS_TEXTURE_WIDTH * 2;
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, firstRow, POINTS_TEXTURE_WIDTH, rows, gl.RG, gl.FLOAT, geometry.points, firstRow * rowFloats);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteBuffer(this.edgeBuffer);
    gl.deleteBuffer(this.pointBuffer);
    gl.deleteBuffer(this.indexBuffer);
    gl.deleteTexture(this.pointsTexture);
    gl.deleteVertexArray(this.edgeVertexArray);
    gl.deleteVertexArray(this.hullVertexArray);
  }
}
