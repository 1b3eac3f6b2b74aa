/** Side of the tiled normal map, in pixels (texels map 1:1 onto the world). */
const TILE = 64;
/** The floor's material: specular on, as a shiny sprite has it. */
const SPECULAR = 0.5, SHININESS = 32;

const VERTEX = `#version 300 es
void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}`;

/** The host's fragment shader of a normal-mapped sprite: colour, normal and material at locations 0, 1, 2 through SURFACE_GLSL. */
function fragment(surfaceGlsl: string): string {
  return `#version 300 es
precision highp float;
${surfaceGlsl}
uniform sampler2D u_normalMap;
uniform mat2 u_worldFromImage;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_material;
void main() {
  vec3 texel = texture(u_normalMap, gl_FragCoord.xy / ${TILE.toFixed(1)}).rgb;
  o_color = vec4(1.0);
  o_normal = penumbraEncodeNormal(penumbraWorldNormal(texel, u_worldFromImage, true), 1.0);
  o_material = penumbraEncodeMaterial(${SPECULAR.toFixed(1)}, ${SHININESS.toFixed(1)}, 0.0, 1.0);
}`;
}

/**
 * The normal-mapped scenes' floor: one full-screen triangle, white as the plain scenes' clear, whose
 * every pixel samples a tiled normal map (a field of round bumps, RGBA8, linear, repeated) and
 * writes its world normal and a shiny material, unblended, as an opaque sprite of a host would.
 * Draw it while a renderer made with `normals: true` has its scene target bound (after beginDraw()).
 */
export class SurfaceFloor {
  private readonly program: WebGLProgram;
  private readonly normalMap: WebGLTexture;
  private readonly worldFromImage: WebGLUniformLocation | null;

  constructor(private readonly gl: WebGL2RenderingContext, surfaceGlsl: string) {
    this.program = link(gl, VERTEX, fragment(surfaceGlsl));
    gl.useProgram(this.program);
    gl.uniform1i(gl.getUniformLocation(this.program, 'u_normalMap'), 0);
    this.worldFromImage = gl.getUniformLocation(this.program, 'u_worldFromImage');
    // A sprite turned by 0.5 rad: the helpers' inverse-transpose path runs as for any rotated sprite.
    const cos = Math.cos(0.5), sin = Math.sin(0.5);
    gl.uniformMatrix2fv(this.worldFromImage, false, [cos, sin, -sin, cos]);
    gl.useProgram(null);
    this.normalMap = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, this.normalMap);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, TILE, TILE, 0, gl.RGBA, gl.UNSIGNED_BYTE, bumps());
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  /** Draws the floor into the bound framebuffer (all three attachments). */
  render(): void {
    const gl = this.gl;
    gl.disable(gl.BLEND);
    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(this.program);
    gl.bindVertexArray(null);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.normalMap);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  dispose(): void {
    this.gl.deleteProgram(this.program);
    this.gl.deleteTexture(this.normalMap);
  }
}

/** A tile of four round bumps (a height field's normals, OpenGL style: green up the image), as RGBA8 bytes. */
function bumps(): Uint8Array {
  const bytes = new Uint8Array(TILE * TILE * 4);
  const cell = TILE / 2, radius = cell * 0.45;
  for (let y = 0; y < TILE; y++) {
    for (let x = 0; x < TILE; x++) {
      // Offset from the centre of this pixel's cell; the bump's slope grows towards its rim.
      const dx = ((x + 0.5) % cell) - cell / 2, dy = ((y + 0.5) % cell) - cell / 2;
      const inside = Math.hypot(dx, dy) < radius;
      // Image y points down; green up is −y.
      const nx = inside ? dx / radius : 0, ny = inside ? -dy / radius : 0;
      const length = Math.hypot(nx, ny, 1);
      const i = (y * TILE + x) * 4;
      bytes[i] = Math.round((nx / length * 0.5 + 0.5) * 255);
      bytes[i + 1] = Math.round((ny / length * 0.5 + 0.5) * 255);
      bytes[i + 2] = Math.round((1 / length * 0.5 + 0.5) * 255);
      bytes[i + 3] = 255;
    }
  }
  return bytes;
}

function link(gl: WebGL2RenderingContext, vertex: string, fragmentSource: string): WebGLProgram {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vertex], [gl.FRAGMENT_SHADER, fragmentSource]] as const) {
    const shader = gl.createShader(type)!;
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`bench surface floor: ${gl.getShaderInfoLog(shader)}`);
    gl.attachShader(program, shader);
    gl.deleteShader(shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`bench surface floor: ${gl.getProgramInfoLog(program)}`);
  return program;
}
