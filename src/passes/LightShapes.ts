import { ROW_INDICES, TILE_COLUMNS, TILE_ROWS } from '../shadow/shadowLayout';

/**
 * Sides of the polygon drawn for a light's range disk. It is circumscribed, so it covers the whole
 * disk; with 16 sides it is 1.3% larger than the disk and 20% smaller than the quad.
 */
const DISK_SIDES = 16;

/**
 * The shapes a light is drawn with, no triangle fans among them (ANGLE's Metal backend rewrites
 * fans into index buffers on the CPU):
 * - in the unit square 0..1 of the light's quad (see `Light.writeQuad`), on attribute 0 of one
 *   vertex array: the quad as a TRIANGLE_STRIP and as a LINE_LOOP, and a polygon circumscribing
 *   the disk inscribed in the quad as TRIANGLES: where a light confined to its range adds anything;
 * - the tile grid's corner points `(i, j)` ((TILE_COLUMNS + 1) × (TILE_ROWS + 1), see `tileCorner`) on
 *   attribute 0 of another, with the lights' rectangles of tiles as indices (`LightTiles`
 *   `rectangles`: one slot of ROW_INDICES per filing row, uploaded by the rows that changed). The
 *   light vertex stage built with TILED places the points on the light's grid.
 */
export class LightShapes {
  private readonly vertexArray: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;
  private readonly tileVertexArray: WebGLVertexArrayObject;
  private readonly tileBuffer: WebGLBuffer;
  private readonly tileIndexBuffer: WebGLBuffer;
  /** Filing rows the index buffer has room for; -1 before the first upload. */
  private tileRows = -1;
  /**
   * A row's indices are copied here and uploaded through the view of the fewest UPLOAD_GRANULEs
   * that hold them: views made once (headless-gl's bufferSubData has no source offset and length,
   * and a view per upload would be heap each frame).
   */
  private readonly staging = new Uint16Array(ROW_INDICES);
  private readonly stagingViews = Array.from({ length: GRANULES_PER_ROW }, (_, k) => this.staging.subarray(0, (k + 1) * UPLOAD_GRANULE));

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.vertexArray = gl.createVertexArray()!;
    this.buffer = gl.createBuffer()!;
    gl.bindVertexArray(this.vertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, shapeVertices(), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    this.tileVertexArray = gl.createVertexArray()!;
    this.tileBuffer = gl.createBuffer()!;
    this.tileIndexBuffer = gl.createBuffer()!;
    gl.bindVertexArray(this.tileVertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.tileBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, tileCorners(), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.tileIndexBuffer);
    gl.bindVertexArray(null);
  }

  /**
   * Uploads the tile rectangles' indices (`rectangles`, ROW_INDICES per row, of which each row's
   * first `used[row]` count): all rows, reallocating, when their number changed, else the rows
   * marked in `dirty`. Leaves the tile vertex array bound.
   */
  uploadTileRectangles(dirty: Uint8Array, rectangles: Uint16Array, used: Int32Array): void {
    const gl = this.gl, rows = dirty.length, all = rows !== this.tileRows;
    gl.bindVertexArray(this.tileVertexArray);
    if (all) {
      this.tileRows = rows;
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, Math.max(rows, 1) * ROW_INDICES * 2, gl.DYNAMIC_DRAW);
    }
    for (let row = 0; row < rows; row++) {
      if ((!all && dirty[row] === 0) || used[row] === 0) continue;
      const count = used[row], slot = row * ROW_INDICES;
      for (let k = 0; k < count; k++) this.staging[k] = rectangles[slot + k];
      gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, slot * 2, this.stagingViews[Math.ceil(count / UPLOAD_GRANULE) - 1]);
    }
  }

  /** Fills the quad using the current program. */
  drawQuad(): void {
    this.gl.bindVertexArray(this.vertexArray);
    this.gl.drawArrays(this.gl.TRIANGLE_STRIP, QUAD_STRIP_FIRST, 4);
  }

  /** Outlines the quad using the current program. */
  outlineQuad(): void {
    this.gl.bindVertexArray(this.vertexArray);
    this.gl.drawArrays(this.gl.LINE_LOOP, QUAD_LOOP_FIRST, 4);
  }

  /** Fills the polygon around the range disk using the current program. */
  drawDisk(): void {
    this.gl.bindVertexArray(this.vertexArray);
    this.gl.drawArrays(this.gl.TRIANGLES, DISK_FIRST, 3 * (DISK_SIDES - 2));
  }

  /** Draws `count` indices of the tile rectangles from index `first` (see `LightTiles.writeLists`) using the current program (built with TILED). */
  drawTileRectangles(first: number, count: number): void {
    this.gl.bindVertexArray(this.tileVertexArray);
    this.gl.drawElements(this.gl.TRIANGLES, count, this.gl.UNSIGNED_SHORT, 2 * first);
  }

  dispose(): void {
    this.gl.deleteVertexArray(this.vertexArray);
    this.gl.deleteBuffer(this.buffer);
    this.gl.deleteVertexArray(this.tileVertexArray);
    this.gl.deleteBuffer(this.tileBuffer);
    this.gl.deleteBuffer(this.tileIndexBuffer);
  }
}

const QUAD_LOOP_FIRST = 0;
const QUAD_STRIP_FIRST = 4;
const DISK_FIRST = 8;

function shapeVertices(): Float32Array {
  // A regular polygon's sides are 1 / cos(π / n) times its vertices' distance closer to its centre.
  const outset = 1 / Math.cos(Math.PI / DISK_SIDES);
  const polygon = (vertex: number): number[] => {
    const angle = (2 * Math.PI * vertex) / DISK_SIDES;
    return [0.5 + 0.5 * outset * Math.cos(angle), 0.5 + 0.5 * outset * Math.sin(angle)];
  };
  const vertices: number[] = [0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 0, 1, 1, 1];
  for (let i = 1; i + 1 < DISK_SIDES; i++) vertices.push(...polygon(0), ...polygon(i), ...polygon(i + 1));
  return new Float32Array(vertices);
}

/** Indices uploaded per row are rounded up to a multiple of this (64 rectangles): the staging views' lengths. */
const UPLOAD_GRANULE = 384;
const GRANULES_PER_ROW = ROW_INDICES / UPLOAD_GRANULE;

/** The tile grid's corner points, row by row (see `tileCorner`). */
function tileCorners(): Float32Array {
  const points = new Float32Array(2 * (TILE_COLUMNS + 1) * (TILE_ROWS + 1));
  for (let j = 0, k = 0; j <= TILE_ROWS; j++) {
    for (let i = 0; i <= TILE_COLUMNS; i++) {
      points[k++] = i;
      points[k++] = j;
    }
  }
  return points;
}
