/**
 * A unit square 0..1 as four corners in fan order (usable as TRIANGLE_FAN and as LINE_LOOP),
 * on attribute 0 of its own vertex array.
 */
export class UnitQuad {
  readonly vertexArray: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.vertexArray = gl.createVertexArray()!;
    this.buffer = gl.createBuffer()!;
    gl.bindVertexArray(this.vertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
  }

  /** Draws the quad with `mode` (TRIANGLE_FAN or LINE_LOOP) using the current program. */
  draw(mode: number): void {
    this.gl.bindVertexArray(this.vertexArray);
    this.gl.drawArrays(mode, 0, 4);
  }

  dispose(): void {
    this.gl.deleteVertexArray(this.vertexArray);
    this.gl.deleteBuffer(this.buffer);
  }
}
