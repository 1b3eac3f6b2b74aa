import type { mat4 } from 'gl-matrix';
import type { Hull } from 'penumbra-gl';
import { hullLocalToWorld, hullWorldPoint } from './hullShape';
import { createTexture, drawBarrel, drawFloorTiles, drawStone, drawWalker, linkProgram } from './textures';

const VERTEX_SHADER = `#version 300 es
in vec2 a_position;
in vec2 a_uv;
uniform mat4 u_viewProjection;
out vec2 v_uv;
void main() {
  v_uv = a_uv;
  gl_Position = u_viewProjection * vec4(a_position, 0.0, 1.0);
}`;

const FRAGMENT_SHADER = `#version 300 es
precision mediump float;
in vec2 v_uv;
uniform sampler2D u_texture;
// With a renderer made with { normals: true }, the scene target also has a normal and a material
// attachment: zeros there (coverage 0) light these pixels as without normals. Without, they are dropped.
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outMaterial;
void main() {
  outColor = texture(u_texture, v_uv);
  outNormal = vec4(0.0);
  outMaterial = vec4(0.0);
}`;

/** World units per repetition of the floor and stone textures. */
const FLOOR_TILE = 256;
const STONE_TILE = 128;
/** Width in world units of the stone line an open hull is drawn as. */
const OPEN_HULL_WIDTH = 6;
/** Floats per vertex: position (2), uv (2). */
const FLOATS = 4;

const SPRITE_KINDS = ['barrel', 'walker'] as const;

/** A sprite drawn over the floor: texture, centre, size and heading. */
export interface Sprite {
  texture: 'walker' | 'barrel';
  x: number;
  y: number;
  size: number;
  rotation: number;
}

/**
 * An image traced into hulls, drawn as a quad over the hulls' local space (`width` × `height`
 * pixels from local (0, 0)) placed like the first of its hulls still in the scene.
 */
export interface ImageSprite {
  texture: WebGLTexture;
  hulls: readonly Hull[];
  width: number;
  height: number;
}

/**
 * The game-like scene under the lights, drawn with plain WebGL2 in world space: a tiled floor,
 * the closed hulls' tops in stone (any simple or even invalid polygon, via a stencil even-odd fill,
 * so no triangulation is needed) and the open hulls as stone lines (they have no inside), then
 * sprites and traced images. The renderer lights whatever this draws.
 */
export class SceneArt {
  private readonly program: WebGLProgram;
  private readonly viewProjectionLocation: WebGLUniformLocation;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;
  private vertices = new Float32Array(6 * FLOATS * 256);
  private count = 0;
  private readonly textures: Record<'floor' | 'stone' | 'walker' | 'barrel', WebGLTexture>;
  private readonly point: [number, number] = [0, 0];
  private readonly first: [number, number] = [0, 0];
  private readonly previous: [number, number] = [0, 0];

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = linkProgram(gl, 'scene', VERTEX_SHADER, FRAGMENT_SHADER);
    this.viewProjectionLocation = gl.getUniformLocation(this.program, 'u_viewProjection')!;
    this.vao = gl.createVertexArray()!;
    this.buffer = gl.createBuffer()!;
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    const position = gl.getAttribLocation(this.program, 'a_position');
    const uv = gl.getAttribLocation(this.program, 'a_uv');
    gl.enableVertexAttribArray(position);
    gl.vertexAttribPointer(position, 2, gl.FLOAT, false, FLOATS * 4, 0);
    gl.enableVertexAttribArray(uv);
    gl.vertexAttribPointer(uv, 2, gl.FLOAT, false, FLOATS * 4, 8);
    gl.bindVertexArray(null);
    this.textures = {
      floor: createTexture(gl, drawFloorTiles(), true),
      stone: createTexture(gl, drawStone(), true),
      walker: createTexture(gl, drawWalker(), false),
      barrel: createTexture(gl, drawBarrel(), false),
    };
  }

  /**
   * Draws the scene into the bound framebuffer, which must have a stencil buffer (the renderer's
   * scene target has one and clears it in `beginDraw`). `view` is the visible world rectangle.
   * `floor`: false to draw over a floor already drawn (the showcase's).
   */
  draw(viewProjection: mat4, view: Float32Array, hulls: readonly Hull[], sprites: readonly Sprite[], images: readonly ImageSprite[] = [], floor = true): void {
    const gl = this.gl;
    gl.useProgram(this.program);
    gl.uniformMatrix4fv(this.viewProjectionLocation, false, viewProjection);
    gl.bindVertexArray(this.vao);
    gl.activeTexture(gl.TEXTURE0);

    if (floor) {
      this.pushWorldRect(view, FLOOR_TILE);
      this.flush(this.textures.floor);
    }

    // Hull tops: every hull's triangle fan inverts the stencil (even-odd), then one stone quad
    // over the view is drawn where the stencil is odd.
    gl.enable(gl.STENCIL_TEST);
    gl.stencilMask(0xff);
    gl.stencilFunc(gl.ALWAYS, 0, 0xff);
    gl.stencilOp(gl.KEEP, gl.KEEP, gl.INVERT);
    gl.colorMask(false, false, false, false);
    for (const hull of hulls) if (hull.enabled && hull.closed) this.pushFan(hull);
    this.flush(this.textures.stone);
    gl.colorMask(true, true, true, true);
    gl.stencilFunc(gl.NOTEQUAL, 0, 0xff);
    gl.stencilOp(gl.KEEP, gl.KEEP, gl.KEEP);
    this.pushWorldRect(view, STONE_TILE);
    this.flush(this.textures.stone);
    gl.disable(gl.STENCIL_TEST);
    for (const hull of hulls) if (hull.enabled && !hull.closed) this.pushLine(hull);
    this.flush(this.textures.stone);

    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    for (const kind of SPRITE_KINDS) {
      for (const sprite of sprites) if (sprite.texture === kind) this.pushSprite(sprite);
      this.flush(this.textures[kind]);
    }
    for (const image of images) {
      const hull = image.hulls.find((candidate) => hulls.includes(candidate));
      if (!hull) continue;
      this.pushImage(hull, image.width, image.height);
      this.flush(image.texture);
    }
    gl.disable(gl.BLEND);
    gl.bindVertexArray(null);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteProgram(this.program);
    gl.deleteVertexArray(this.vao);
    gl.deleteBuffer(this.buffer);
    for (const texture of Object.values(this.textures)) gl.deleteTexture(texture);
  }

  private pushWorldRect(view: Float32Array, tile: number): void {
    const [x0, y0, x1, y1] = view;
    this.pushQuad(x0, y0, x1 - x0, 0, 0, y1 - y0, x0 / tile, y0 / tile, (x1 - x0) / tile, (y1 - y0) / tile);
  }

  private pushSprite(sprite: Sprite): void {
    const cos = Math.cos(sprite.rotation) * sprite.size, sin = Math.sin(sprite.rotation) * sprite.size;
    const x = sprite.x - (cos - sin) / 2, y = sprite.y - (sin + cos) / 2;
    this.pushQuad(x, y, cos, sin, -sin, cos, 0, 0, 1, 1);
  }

  /** The rectangle [0, width] × [0, height] of a hull's local space, placed as the hull is. */
  private pushImage(hull: Hull, width: number, height: number): void {
    const [x, y] = hullLocalToWorld(hull, 0, 0, this.first);
    const [rx, ry] = hullLocalToWorld(hull, width, 0, this.previous);
    const [bx, by] = hullLocalToWorld(hull, 0, height, this.point);
    this.pushQuad(x, y, rx - x, ry - y, bx - x, by - y, 0, 0, 1, 1);
  }

  /** A parallelogram from corner (x, y) along axes a and b, with uv from (u, v) spanning (du, dv). */
  private pushQuad(x: number, y: number, ax: number, ay: number, bx: number, by: number, u: number, v: number, du: number, dv: number): void {
    this.pushVertex(x, y, u, v);
    this.pushVertex(x + ax, y + ay, u + du, v);
    this.pushVertex(x + ax + bx, y + ay + by, u + du, v + dv);
    this.pushVertex(x, y, u, v);
    this.pushVertex(x + ax + bx, y + ay + by, u + du, v + dv);
    this.pushVertex(x + bx, y + by, u, v + dv);
  }

  private pushFan(hull: Hull): void {
    const n = hull.points.length;
    if (n < 3) return;
    const first = hullWorldPoint(hull, 0, this.first);
    const previous = hullWorldPoint(hull, 1, this.previous);
    for (let i = 2; i < n; i++) {
      const point = hullWorldPoint(hull, i, this.point);
      this.pushVertex(first[0], first[1], 0, 0);
      this.pushVertex(previous[0], previous[1], 0, 0);
      this.pushVertex(point[0], point[1], 0, 0);
      previous[0] = point[0];
      previous[1] = point[1];
    }
  }

  /**
   * An open hull's segments as quads {@link OPEN_HULL_WIDTH} wide, each reaching half the width
   * past its ends so that consecutive ones overlap at their shared point (no notch at a bend).
   * Opaque, so the overlaps need no stencil.
   */
  private pushLine(hull: Hull): void {
    const n = hull.points.length;
    if (n < 2) return;
    const half = OPEN_HULL_WIDTH / 2;
    const previous = hullWorldPoint(hull, 0, this.previous);
    for (let i = 1; i < n; i++) {
      const point = hullWorldPoint(hull, i, this.point);
      const length = Math.hypot(point[0] - previous[0], point[1] - previous[1]);
      if (length > 0) {
        // Unit vectors along the segment and across it.
        const ux = (point[0] - previous[0]) / length, uy = (point[1] - previous[1]) / length;
        const x = previous[0] - ux * half + uy * half, y = previous[1] - uy * half - ux * half;
        const along = length + OPEN_HULL_WIDTH;
        this.pushQuad(x, y, ux * along, uy * along, -uy * OPEN_HULL_WIDTH, ux * OPEN_HULL_WIDTH, 0, 0, along / STONE_TILE, OPEN_HULL_WIDTH / STONE_TILE);
      }
      previous[0] = point[0];
      previous[1] = point[1];
    }
  }

  private pushVertex(x: number, y: number, u: number, v: number): void {
    if ((this.count + 1) * FLOATS > this.vertices.length) {
      const grown = new Float32Array(this.vertices.length * 2);
      grown.set(this.vertices);
      this.vertices = grown;
    }
    const offset = this.count * FLOATS;
    this.vertices[offset] = x;
    this.vertices[offset + 1] = y;
    this.vertices[offset + 2] = u;
    this.vertices[offset + 3] = v;
    this.count++;
  }

  private flush(texture: WebGLTexture): void {
    if (this.count === 0) return;
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, this.vertices, gl.STREAM_DRAW, 0, this.count * FLOATS);
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.drawArrays(gl.TRIANGLES, 0, this.count);
    this.count = 0;
  }
}
