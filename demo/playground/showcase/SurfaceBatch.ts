import type { mat4 } from 'gl-matrix';
import { SURFACE_GLSL } from 'penumbra-gl';
import type { SurfaceImage } from './surfaceImage';
import { createTexture, linkProgram } from '../textures';

/**
 * Draws textured quads with normal maps into the renderer's scene target: colour at location 0,
 * the world normal at 1 and the material at 2, premultiplied by coverage (docs/normal-maps.md),
 * through the package's `SURFACE_GLSL` helpers. A quad is a sprite (rotated, its normals turned
 * with it) or a shadow decal (darkens the colour, leaves the normal and material as they are).
 */

const VERTEX_SHADER = `#version 300 es
in vec2 a_position;
in vec2 a_uv;
in vec4 a_params;
uniform mat4 u_viewProjection;
out vec2 v_uv;
out vec4 v_params;
void main() {
  v_uv = a_uv;
  v_params = a_params;
  gl_Position = u_viewProjection * vec4(a_position, 0.0, 1.0);
}`;

const FRAGMENT_SHADER = `#version 300 es
precision highp float;
${SURFACE_GLSL}
in vec2 v_uv;
// cos and sin of the sprite's rotation, its opacity, and 1 for a shadow decal.
in vec4 v_params;
uniform sampler2D u_albedo;
uniform sampler2D u_normal;
uniform sampler2D u_material;
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outMaterial;
void main() {
  vec4 albedo = texture(u_albedo, v_uv);
  float coverage = albedo.a * v_params.z;
  if (v_params.w > 0.5) {
    // Blended ONE, ONE_MINUS_SRC_ALPHA: the colour darkens by the coverage, the zeros keep the rest.
    outColor = vec4(0.0, 0.0, 0.0, coverage);
    outNormal = vec4(0.0);
    outMaterial = vec4(0.0);
    return;
  }
  vec4 material = texture(u_material, v_uv);
  mat2 worldFromImage = mat2(v_params.x, v_params.y, -v_params.y, v_params.x);
  vec3 normal = penumbraWorldNormal(texture(u_normal, v_uv).rgb, worldFromImage, true);
  outColor = vec4(albedo.rgb * coverage, coverage);
  outNormal = penumbraEncodeNormal(normal, coverage);
  outMaterial = penumbraEncodeMaterial(material.r, exp2(material.g * 11.0), material.b, coverage);
}`;

/** Floats per vertex: position (2), uv (2), params (4). */
const FLOATS = 8;

/** The three textures of a {@link SurfaceImage}. */
export interface SurfaceTextures {
  albedo: WebGLTexture;
  normal: WebGLTexture;
  material: WebGLTexture;
  width: number;
  height: number;
}

export class SurfaceBatch {
  private readonly program: WebGLProgram;
  private readonly viewProjectionLocation: WebGLUniformLocation;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;
  private vertices = new Float32Array(6 * FLOATS * 512);
  private count = 0;
  private readonly owned: WebGLTexture[] = [];

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = linkProgram(gl, 'showcase', VERTEX_SHADER, FRAGMENT_SHADER);
    this.viewProjectionLocation = gl.getUniformLocation(this.program, 'u_viewProjection')!;
    gl.useProgram(this.program);
    ['u_albedo', 'u_normal', 'u_material'].forEach((name, unit) => gl.uniform1i(gl.getUniformLocation(this.program, name), unit));
    gl.useProgram(null);
    this.vao = gl.createVertexArray()!;
    this.buffer = gl.createBuffer()!;
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    const attributes: [string, number, number][] = [['a_position', 2, 0], ['a_uv', 2, 2], ['a_params', 4, 4]];
    for (const [name, size, offset] of attributes) {
      const location = gl.getAttribLocation(this.program, name);
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, gl.FLOAT, false, FLOATS * 4, offset * 4);
    }
    gl.bindVertexArray(null);
  }

  /** Uploads a surface image's three images as mipmapped textures, repeating or clamped. */
  upload(image: SurfaceImage, repeat: boolean): SurfaceTextures {
    const gl = this.gl;
    const make = (pixels: Uint8Array) => {
      const texture = createTexture(gl, { width: image.width, height: image.height, pixels }, repeat);
      this.owned.push(texture);
      return texture;
    };
    return { albedo: make(image.albedo), normal: make(image.normal), material: make(image.material), width: image.width, height: image.height };
  }

  /** Starts drawing into the bound framebuffer (the renderer's scene target, between beginDraw and draw). */
  begin(viewProjection: mat4): void {
    const gl = this.gl;
    gl.useProgram(this.program);
    gl.uniformMatrix4fv(this.viewProjectionLocation, false, viewProjection);
    gl.bindVertexArray(this.vao);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
  }

  /** Ends drawing: what {@link begin} changed is back to WebGL's defaults. */
  end(): void {
    const gl = this.gl;
    gl.disable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ZERO);
    gl.bindVertexArray(null);
    for (let unit = 2; unit >= 0; unit--) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
  }

  /**
   * A quad from corner (x, y) along world axes a and b (the image's x and y), with uv from (u, v)
   * spanning (du, dv); `cos`, `sin`: the rotation its normals turn by; `opacity`; `decal`: a shadow.
   */
  quad(x: number, y: number, ax: number, ay: number, bx: number, by: number, u: number, v: number, du: number, dv: number,
    cos: number, sin: number, opacity = 1, decal = false): void {
    const d = decal ? 1 : 0;
    this.vertex(x, y, u, v, cos, sin, opacity, d);
    this.vertex(x + ax, y + ay, u + du, v, cos, sin, opacity, d);
    this.vertex(x + ax + bx, y + ay + by, u + du, v + dv, cos, sin, opacity, d);
    this.vertex(x, y, u, v, cos, sin, opacity, d);
    this.vertex(x + ax + bx, y + ay + by, u + du, v + dv, cos, sin, opacity, d);
    this.vertex(x + bx, y + by, u, v + dv, cos, sin, opacity, d);
  }

  /** Draws the quads pushed since the last flush with a set of textures. */
  flush(textures: SurfaceTextures): void {
    if (this.count === 0) return;
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, this.vertices, gl.STREAM_DRAW, 0, this.count * FLOATS);
    [textures.albedo, textures.normal, textures.material].forEach((texture, unit) => {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, texture);
    });
    gl.drawArrays(gl.TRIANGLES, 0, this.count);
    this.count = 0;
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteProgram(this.program);
    gl.deleteVertexArray(this.vao);
    gl.deleteBuffer(this.buffer);
    for (const texture of this.owned) gl.deleteTexture(texture);
    this.owned.length = 0;
  }

  private vertex(x: number, y: number, u: number, v: number, cos: number, sin: number, opacity: number, decal: number): void {
    if ((this.count + 1) * FLOATS > this.vertices.length) {
      const grown = new Float32Array(this.vertices.length * 2);
      grown.set(this.vertices);
      this.vertices = grown;
    }
    const o = this.count * FLOATS, vertices = this.vertices;
    vertices[o] = x;
    vertices[o + 1] = y;
    vertices[o + 2] = u;
    vertices[o + 3] = v;
    vertices[o + 4] = cos;
    vertices[o + 5] = sin;
    vertices[o + 6] = opacity;
    vertices[o + 7] = decal;
    this.count++;
  }
}
