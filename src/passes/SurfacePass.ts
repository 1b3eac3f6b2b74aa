import { SURFACE_GLSL } from './shaders';
import type { SurfaceTextures } from './surfaceLayout';
import { HostState } from '../gl/HostState';
import { createProgram, type ProgramOf, type UniformDeclaration } from '../gl/program';
import { RenderTarget } from '../gl/RenderTarget';
import { TEXTURE_UNITS, unitsSpanned } from './textureUnits';

/**
 * One sprite of an engine's display list for the surface pass: a quad, the textures it is drawn
 * from, its turn and its material. The engines fill one scratch object per pass and hand it to
 * {@link SurfacePass.add}, which copies it.
 */
interface SurfaceQuad {
  /** The texture the sprite's colour is drawn from: its alpha is the coverage. */
  color: WebGLTexture | null;
  /** The sprite's normal map, laid out as `color`; null for a sprite without one, which erases what it covers. */
  normals: WebGLTexture | null;
  /** Corners in target units (y down from the top of the target): top-left, top-right, bottom-left, bottom-right of the image. */
  readonly corners: Float32Array;
  /** Texture coordinates of the same corners. */
  readonly uvs: Float32Array;
  /** The sprite's linear map from image axes to world axes, `[a, b, c, d]` as x' = a·x + c·y, y' = b·x + d·y. */
  readonly worldFromImage: Float32Array;
  /** Green points up the image (OpenGL-style maps) rather than down (DirectX-style). */
  greenUp: boolean;
  specular: number;
  shininess: number;
  emissive: number;
  /** The sprite's alpha, multiplying its texture's. */
  alpha: number;
}

/** Sets the quad's texture coordinates to the rectangle from (u0, v0) at its top-left corner to (u1, v1) at its bottom-right. */
export function setQuadUvs(quad: SurfaceQuad, u0: number, v0: number, u1: number, v1: number): void {
  const uvs = quad.uvs;
  uvs[0] = u0; uvs[1] = v0;
  uvs[2] = u1; uvs[3] = v0;
  uvs[4] = u0; uvs[5] = v1;
  uvs[6] = u1; uvs[7] = v1;
}

/** Sets the quad's image → world map to a rotation after a scale (negative for a flip) of each image axis. */
export function setWorldFromImage(quad: SurfaceQuad, rotation: number, scaleX: number, scaleY: number): void {
  const cos = Math.cos(rotation), sin = Math.sin(rotation), w = quad.worldFromImage;
  w[0] = cos * scaleX;
  w[1] = sin * scaleX;
  w[2] = -sin * scaleY;
  w[3] = cos * scaleY;
}

/** Copies a material's values into the quad. */
export function setQuadMaterial(quad: SurfaceQuad, material: Readonly<Pick<SurfaceQuad, 'greenUp' | 'specular' | 'shininess' | 'emissive'>>): void {
  quad.greenUp = material.greenUp;
  quad.specular = material.specular;
  quad.shininess = material.shininess;
  quad.emissive = material.emissive;
}

/** A zeroed {@link SurfaceQuad}, to fill. */
export function createSurfaceQuad(): SurfaceQuad {
  return {
    color: null, normals: null, corners: new Float32Array(8), uvs: new Float32Array(8), worldFromImage: Float32Array.of(1, 0, 0, 1),
    greenUp: true, specular: 0, shininess: 1, emissive: 0, alpha: 1,
  };
}

/** Floats per quad in the instance buffer: corners 8, uvs 8, worldFromImage 4, material 4, greenUp 1. */
const STRIDE = 25;
/** Sizes of the attributes at locations 0, 1, …, and their offsets (floats) in an instance. */
const ATTRIBUTE_SIZES = Int32Array.of(4, 4, 4, 4, 4, 4, 1);
const ATTRIBUTE_OFFSETS = Int32Array.of(0, 4, 8, 12, 16, 20, 24);
const { u_color: COLOR_UNIT, u_normals: NORMAL_UNIT } = TEXTURE_UNITS.surface;

/** The surface program's uniforms but its samplers (VERTEX and FRAGMENT below), which `SurfacePass` sets through these names only. */
const SURFACE_UNIFORMS = {
  /** 2 / width, 2 / height (target units), and 1, or -1 for a target drawn upside down. */
  u_frame: { type: 'vec3' },
  /** Whether the batch's sprites have no normal map: they write their coverage only, to erase. */
  u_erase: { type: 'bool' },
} as const satisfies Record<string, UniformDeclaration>;

/** What the surface pass addresses in its program. */
export const SURFACE_INTERFACE = { uniforms: SURFACE_UNIFORMS, samplers: TEXTURE_UNITS.surface };

const VERTEX = `#version 300 es
layout(location = 0) in vec4 a_corners01;
layout(location = 1) in vec4 a_corners23;
layout(location = 2) in vec4 a_uvs01;
layout(location = 3) in vec4 a_uvs23;
layout(location = 4) in vec4 a_worldFromImage;
layout(location = 5) in vec4 a_material;
layout(location = 6) in float a_greenUp;
// 2 / width, 2 / height (target units), and 1, or -1 for a target drawn upside down (its top in row 0).
uniform vec3 u_frame;
out vec2 v_uv;
// Per sprite, the same at its four corners: smooth varyings of a constant (no flat varyings, which
// ANGLE's Metal backend emulates at a cost per draw).
out vec4 v_worldFromImage;
out vec4 v_material;
out float v_greenUp;
void main() {
  // A strip of the quad's corners: top-left, top-right, bottom-left, bottom-right.
  int corner = gl_VertexID;
  vec2 p = corner == 0 ? a_corners01.xy : corner == 1 ? a_corners01.zw : corner == 2 ? a_corners23.xy : a_corners23.zw;
  v_uv = corner == 0 ? a_uvs01.xy : corner == 1 ? a_uvs01.zw : corner == 2 ? a_uvs23.xy : a_uvs23.zw;
  v_worldFromImage = a_worldFromImage;
  v_material = a_material;
  v_greenUp = a_greenUp;
  gl_Position = vec4(p.x * u_frame.x - 1.0, (1.0 - p.y * u_frame.y) * u_frame.z, 0.0, 1.0);
}
`;

const FRAGMENT = `#version 300 es
precision highp float;
${SURFACE_GLSL}
uniform sampler2D u_color;
uniform sampler2D u_normals;
// Drawing sprites without a normal map: they write their coverage only, blended to erase what they cover.
uniform bool u_erase;
in vec2 v_uv;
in vec4 v_worldFromImage;
in vec4 v_material;
in float v_greenUp;
layout(location = 0) out vec4 o_normal;
layout(location = 1) out vec4 o_material;
void main() {
  float coverage = texture(u_color, v_uv).a * v_material.w;
  if (u_erase) {
    o_normal = vec4(coverage);
    o_material = vec4(coverage);
    return;
  }
  vec3 normal = penumbraWorldNormal(texture(u_normals, v_uv).rgb, mat2(v_worldFromImage), v_greenUp > 0.5);
  o_normal = penumbraEncodeNormal(normal, coverage);
  o_material = penumbraEncodeMaterial(v_material.x, v_material.y, v_material.z, coverage);
}
`;

/**
 * The normal pass of an engine integration: the sprites of a display list drawn, in its order,
 * from their normal maps into a normal and a material texture with the encodings of
 * docs/normal-maps.md, for `drawInPlace(layers, surfaces)`. Sprites with a normal map write their
 * normal turned to world axes and their material, premultiplied by their coverage (texture alpha ×
 * alpha); sprites without one, once one with a normal map was drawn, erase what they cover by their
 * coverage, so that they are lit as without normals where they are on top.
 *
 * Each frame: {@link SurfacePass.begin}, {@link SurfacePass.add} per sprite, then
 * {@link SurfacePass.render}. Its GL objects (program, buffer, vertex array, targets) are made on the
 * first frame that has a normal-mapped sprite; the instance array grows (doubling) only past the
 * most sprites seen; the targets are resized only when the viewport's size changes.
 *
 * Context loss, as the core renderer: while `gl.isContextLost()` is true (also in the window before
 * the `webglcontextlost` event) {@link SurfacePass.render} draws nothing and returns null; the lost
 * event drops the GL objects, which were the lost context's, and the first frame with a
 * normal-mapped sprite after the restore makes them again. The engines restore their own textures.
 */
export class SurfacePass {
  private program: ProgramOf<typeof SURFACE_INTERFACE> | null = null;
  private buffer: WebGLBuffer | null = null;
  private vertexArray: WebGLVertexArrayObject | null = null;
  private target: RenderTarget | null = null;
  private readonly hostState: HostState;
  private instances = new Float32Array(64 * STRIDE);
  /** Batches: runs of quads drawn from the same textures, erasing or not. */
  private batchStarts = new Int32Array(16);
  private batchColors: (WebGLTexture | null)[] = [];
  private batchNormals: (WebGLTexture | null)[] = [];
  private count = 0;
  private batches = 0;
  /** Whether a quad with a normal map was added this frame: without one, nothing needs drawing. */
  private hasNormals = false;
  private readonly surfaces: SurfaceTextures = { normals: null!, material: null, flipY: false };
  private readonly frame = new Float32Array(3);
  private readonly canvas: EventTarget | null;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.hostState = new HostState(gl, unitsSpanned([TEXTURE_UNITS.surface]));
    const canvas = (gl as { canvas?: unknown }).canvas as EventTarget | undefined;
    this.canvas = canvas && typeof canvas.addEventListener === 'function' ? canvas : null;
    this.canvas?.addEventListener('webglcontextlost', this.onContextLost);
  }

  /** Starts a frame's list of quads. */
  begin(): void {
    this.count = 0;
    this.batches = 0;
    this.hasNormals = false;
  }

  /** Adds a quad, copied from `quad`: a sprite without a normal map is skipped until one with a normal map was added. */
  add(quad: SurfaceQuad): void {
    const erase = quad.normals === null;
    if (erase && !this.hasNormals) return;
    this.hasNormals = true;
    if (this.batches === 0 || this.batchColors[this.batches - 1] !== quad.color || this.batchNormals[this.batches - 1] !== quad.normals) {
      this.startBatch(quad.color, quad.normals);
    }
    if ((this.count + 1) * STRIDE > this.instances.length) {
      const grown = new Float32Array(this.instances.length * 2);
      grown.set(this.instances);
      this.instances = grown;
    }
    const out = this.instances, o = this.count * STRIDE;
    out.set(quad.corners, o);
    out.set(quad.uvs, o + 8);
    out.set(quad.worldFromImage, o + 16);
    out[o + 20] = quad.specular;
    out[o + 21] = quad.shininess;
    out[o + 22] = quad.emissive;
    out[o + 23] = quad.alpha;
    out[o + 24] = quad.greenUp ? 1 : 0;
    this.count++;
  }

  /**
   * Draws the quads added since {@link SurfacePass.begin} into the pass's normal and material
   * textures, `pixelWidth` × `pixelHeight` pixels covering a target of `width` × `height` units, in
   * the same rows as the host's target (`flipY`: the host draws it upside down). Leaves the context
   * state as it was. Returns the textures for `drawInPlace`, or null when no quad had a normal map:
   * then the frame is lit as without normals, and nothing was drawn.
   */
  render(width: number, height: number, pixelWidth: number, pixelHeight: number, flipY: boolean): SurfaceTextures | null {
    const gl = this.gl;
    if (!this.hasNormals || gl.isContextLost()) return null;
    const host = this.hostState;
    host.save();
    try {
      host.prepareForRenderer();
      const target = this.prepare(pixelWidth, pixelHeight);
      const program = this.program!;
      target.bind();
      gl.clearBufferfv(gl.COLOR, 0, CLEAR);
      gl.clearBufferfv(gl.COLOR, 1, CLEAR);
      gl.useProgram(program.handle);
      this.frame[0] = 2 / width;
      this.frame[1] = 2 / height;
      this.frame[2] = flipY ? -1 : 1;
      gl.uniform3fv(program.uniforms.u_frame, this.frame);
      gl.bindVertexArray(this.vertexArray);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
      gl.bufferData(gl.ARRAY_BUFFER, this.instances, gl.STREAM_DRAW, 0, this.count * STRIDE);
      gl.enable(gl.BLEND);
      gl.blendEquation(gl.FUNC_ADD);
      for (let i = 0; i < this.batches; i++) {
        const start = this.batchStarts[i];
        const end = i + 1 < this.batches ? this.batchStarts[i + 1] : this.count;
        const normals = this.batchNormals[i];
        // Premultiplied "over" for normals; an eraser keeps dst × (1 − coverage) in every channel.
        if (normals) gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
        else gl.blendFunc(gl.ZERO, gl.ONE_MINUS_SRC_ALPHA);
        gl.uniform1i(program.uniforms.u_erase, normals ? 0 : 1);
        gl.activeTexture(gl.TEXTURE0 + COLOR_UNIT);
        gl.bindTexture(gl.TEXTURE_2D, this.batchColors[i]);
        gl.activeTexture(gl.TEXTURE0 + NORMAL_UNIT);
        gl.bindTexture(gl.TEXTURE_2D, normals);
        // WebGL2 has no base instance: the attributes start at the batch's first quad instead.
        for (let location = 0; location < ATTRIBUTE_SIZES.length; location++) {
          gl.vertexAttribPointer(location, ATTRIBUTE_SIZES[location], gl.FLOAT, false, STRIDE * 4, (start * STRIDE + ATTRIBUTE_OFFSETS[location]) * 4);
        }
        gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, end - start);
      }
    } finally {
      host.restore();
    }
    const surfaces = this.surfaces;
    surfaces.normals = this.target!.textures[0];
    surfaces.material = this.target!.textures[1];
    // Drawn in the host target's rows: its row 0 is the host's row 0.
    surfaces.flipY = false;
    return surfaces;
  }

  /** Frees the GL objects; safe to call twice, and while the context is lost. */
  dispose(): void {
    this.canvas?.removeEventListener('webglcontextlost', this.onContextLost);
    const gl = this.gl;
    if (!gl.isContextLost()) {
      if (this.program) gl.deleteProgram(this.program.handle);
      gl.deleteBuffer(this.buffer);
      gl.deleteVertexArray(this.vertexArray);
      this.target?.dispose();
    }
    this.forgetObjects();
  }

  /** The lost context took the GL objects with it: forget them, to be made again on the restored context. */
  private readonly onContextLost = (): void => {
    this.forgetObjects();
  };

  private forgetObjects(): void {
    this.program = null;
    this.buffer = null;
    this.vertexArray = null;
    this.target = null;
    // The last frame's batches name textures of the lost context.
    this.begin();
    this.batchColors.length = this.batchNormals.length = 0;
  }

  private startBatch(color: WebGLTexture | null, normals: WebGLTexture | null): void {
    if (this.batches === this.batchStarts.length) {
      const grown = new Int32Array(this.batchStarts.length * 2);
      grown.set(this.batchStarts);
      this.batchStarts = grown;
    }
    this.batchStarts[this.batches] = this.count;
    this.batchColors[this.batches] = color;
    this.batchNormals[this.batches] = normals;
    this.batches++;
  }

  /** The GL objects, made on first use, and the target at the viewport's size. Inside the saved host state. */
  private prepare(width: number, height: number): RenderTarget {
    const gl = this.gl;
    if (!this.program) {
      this.program = createProgram(gl, 'engine surface', VERTEX, FRAGMENT, SURFACE_INTERFACE);
      this.buffer = gl.createBuffer();
      this.vertexArray = gl.createVertexArray();
      gl.bindVertexArray(this.vertexArray);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
      for (let location = 0; location < ATTRIBUTE_SIZES.length; location++) {
        gl.enableVertexAttribArray(location);
        gl.vertexAttribDivisor(location, 1);
      }
    }
    // Linear: the light passes read the normals at the lightmap's resolution, filtered.
    if (!this.target) this.target = new RenderTarget(gl, { format: 'rgba8', linear: true, colorAttachments: 2 }, width, height);
    else this.target.resize(width, height);
    return this.target;
  }
}

const CLEAR = new Float32Array(4);
