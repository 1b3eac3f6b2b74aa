import type { BenchLight } from './library';

const VERTEX = `#version 300 es
layout(location = 0) in vec2 a_corner;
uniform vec4 u_rect; // centre xy, half size zw, in clip space
void main() { gl_Position = vec4(u_rect.xy + (a_corner * 2.0 - 1.0) * u_rect.zw, 0.0, 1.0); }`;
const FRAGMENT = `#version 300 es
precision mediump float;
uniform vec3 u_color;
out vec4 o_color;
void main() { o_color = vec4(u_color, 1.0); }`;

/**
 * The fill-rate floor: every light drawn as a plain additive quad of its range into an RGBA16F
 * target of the lightmap's size, with a trivial shader and no shadows. What no lighting renderer
 * with these lights can beat on this machine.
 */
export class FillFloor {
  private readonly program: WebGLProgram;
  private readonly framebuffer: WebGLFramebuffer;
  private readonly texture: WebGLTexture;
  private readonly vertexArray: WebGLVertexArrayObject;
  private readonly corners: WebGLBuffer;
  private readonly rect: WebGLUniformLocation;
  private readonly color: WebGLUniformLocation;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly width: number, private readonly height: number) {
    gl.getExtension('EXT_color_buffer_float');
    this.program = link(gl);
    this.rect = gl.getUniformLocation(this.program, 'u_rect')!;
    this.color = gl.getUniformLocation(this.program, 'u_color')!;
    this.texture = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA16F, width, height, 0, gl.RGBA, gl.HALF_FLOAT, null);
    this.framebuffer = gl.createFramebuffer()!;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.texture, 0);
    this.vertexArray = gl.createVertexArray()!;
    gl.bindVertexArray(this.vertexArray);
    this.corners = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.corners);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  /** Draws the lights; the world is the target's pixel space (origin top-left, y down). */
  render(lights: readonly BenchLight[]): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.viewport(0, 0, this.width, this.height);
    gl.clearColor(0.05, 0.05, 0.05, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.useProgram(this.program);
    gl.bindVertexArray(this.vertexArray);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE);
    for (const light of lights) {
      const [x, y] = light.position;
      // A directional light covers the whole target.
      if (light.kind === 'directional') gl.uniform4f(this.rect, 0, 0, 1, 1);
      else gl.uniform4f(this.rect, x / this.width * 2 - 1, 1 - y / this.height * 2, light.range / this.width * 2, light.range / this.height * 2);
      gl.uniform3f(this.color, light.color[0], light.color[1], light.color[2]);
      gl.drawArrays(gl.TRIANGLE_FAN, 0, 4);
    }
    gl.disable(gl.BLEND);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteProgram(this.program);
    gl.deleteFramebuffer(this.framebuffer);
    gl.deleteTexture(this.texture);
    gl.deleteVertexArray(this.vertexArray);
    gl.deleteBuffer(this.corners);
  }
}

function link(gl: WebGL2RenderingContext): WebGLProgram {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, VERTEX], [gl.FRAGMENT_SHADER, FRAGMENT]] as const) {
    const shader = gl.createShader(type)!;
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`fill floor: ${gl.getProgramInfoLog(program)}`);
  return program;
}
