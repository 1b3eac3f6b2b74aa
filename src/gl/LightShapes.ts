/**
 * Sides of the polygon drawn for a light's range disk. It is circumscribed, so it covers the whole
 * disk; with 16 sides it is 1.3% larger than the disk and 20% smaller than the quad.
 */
const DISK_SIDES = 16;

/**
 * The shapes a light is drawn with, in the unit square 0..1 of its quad (see `Light.writeQuad`), on
 * attribute 0 of one vertex array:
 * - the quad itself, its four corners in fan order (a TRIANGLE_FAN or a LINE_LOOP);
 * - a polygon circumscribing the disk inscribed in the quad (a TRIANGLE_FAN): where a light
 *   confined to its range adds anything.
 */
export class LightShapes {
  private readonly vertexArray: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.vertexArray = gl.createVertexArray()!;
    this.buffer = gl.createBuffer()!;
    gl.bindVertexArray(this.vertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, shapeVertices(), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
  }

  /** Draws the quad with `mode` (TRIANGLE_FAN or LINE_LOOP) using the current program. */
  drawQuad(mode: number): void {
    this.gl.bindVertexArray(this.vertexArray);
    this.gl.drawArrays(mode, 0, QUAD_VERTICES);
  }

  /** Fills the polygon around the range disk using the current program. */
  drawDisk(): void {
    this.gl.bindVertexArray(this.vertexArray);
    this.gl.drawArrays(this.gl.TRIANGLE_FAN, QUAD_VERTICES, DISK_SIDES);
  }

  dispose(): void {
    this.gl.deleteVertexArray(this.vertexArray);
    this.gl.deleteBuffer(this.buffer);
  }
}

const QUAD_VERTICES = 4;

function shapeVertices(): Float32Array {
  // A regular polygon's sides are 1 / cos(π / n) times its vertices' distance closer to its centre.
  const outset = 1 / Math.cos(Math.PI / DISK_SIDES);
  const polygon = (radius: number, vertex: number): [number, number] => {
    const angle = (2 * Math.PI * vertex) / DISK_SIDES;
    return [0.5 + radius * outset * Math.cos(angle), 0.5 + radius * outset * Math.sin(angle)];
  };
  const vertices: number[] = [0, 0, 1, 0, 1, 1, 0, 1];
  for (let i = 0; i < DISK_SIDES; i++) vertices.push(...polygon(0.5, i));
  return new Float32Array(vertices);
}
