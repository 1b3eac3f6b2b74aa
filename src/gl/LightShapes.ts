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
 * - the tile grid of `tileGrid`² tiles (see `LightTiles`) on attribute 0 of another: per tile four corners
 *   `(column, row, corner x, corner y)` as unsigned bytes, and two triangles of indices. The light
 *   vertex stage built with TILED places the tiles and collapses those of other classes.
 */
export class LightShapes {
  private readonly vertexArray: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;
  private readonly tileVertexArray: WebGLVertexArrayObject;
  private readonly tileBuffer: WebGLBuffer;
  private readonly tileIndexBuffer: WebGLBuffer;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly tileGrid: number) {
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
    gl.bufferData(gl.ARRAY_BUFFER, tileVertices(tileGrid), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 4, gl.UNSIGNED_BYTE, false, 0, 0);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.tileIndexBuffer);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, tileIndices(tileGrid), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
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

  /** Draws every tile of the grid using the current program (built with TILED). */
  drawTiles(): void {
    this.gl.bindVertexArray(this.tileVertexArray);
    this.gl.drawElements(this.gl.TRIANGLES, 6 * this.tileGrid * this.tileGrid, this.gl.UNSIGNED_SHORT, 0);
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

function tileVertices(grid: number): Uint8Array {
  const vertices = new Uint8Array(grid * grid * 16);
  let k = 0;
  for (let row = 0; row < grid; row++) {
    for (let column = 0; column < grid; column++) {
      for (let corner = 0; corner < 4; corner++) {
        vertices[k++] = column;
        vertices[k++] = row;
        vertices[k++] = corner & 1;
        vertices[k++] = corner >> 1;
      }
    }
  }
  return vertices;
}

function tileIndices(grid: number): Uint16Array {
  const indices = new Uint16Array(grid * grid * 6);
  for (let tile = 0, k = 0; tile < grid * grid; tile++) {
    const v = 4 * tile;
    indices.set([v, v + 1, v + 2, v + 2, v + 1, v + 3], k);
    k += 6;
  }
  return indices;
}
