import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../geometry/FramePlan';
import { createProgram, type Program } from '../gl/program';
import { RenderTarget } from '../gl/RenderTarget';
import { CASTER_VERTICES, CasterUniforms } from './CasterUniforms';
import type { GeometryBuffers } from './GeometryBuffers';
import { shaderSources } from './shaders';

/** The cleared mask: no part of the disk hidden. */
const NOTHING_HIDDEN = new Float32Array(4);
/** The cleared depth: umbrae are drawn nearer, and the other shadow quads behind them fail the depth test. */
const FARTHEST = 1;

/**
 * Shadow mask pass: per light, writes into its own RGBA8 target how much of the light disk the
 * hulls in range hide from each pixel (see shadow-mask.frag.glsl), then lets the hull pass mark
 * the hulls' insides. Each shadow caster is one quad (shadow-mask.vert.glsl); light-facing edges
 * are culled by the rasterizer. The umbrae of the whole-hull casters are drawn first, cheaply and
 * with depth, so that the costly shadow fragments behind them (of any caster) are skipped by the
 * early depth test.
 */
export class ShadowMaskPass {
  readonly target: RenderTarget;
  /**
   * For the regions of convex and of concave hulls, and for edge quads: a program each rather than a
   * branch per fragment, which cost SwiftShader 30% (it runs both sides).
   */
  private readonly hullProgram: Program;
  private readonly concaveProgram: Program;
  private readonly umbraProgram: Program;
  private readonly edgesProgram: Program;
  private readonly programs: readonly Program[];
  /** The programs that compute the hidden part of the disk per pixel (all but the umbra's). */
  private readonly shadingPrograms: readonly Program[];
  private readonly casterUniforms: CasterUniforms;

  constructor(private readonly gl: WebGL2RenderingContext, width: number, height: number) {
    this.hullProgram = createProgram(gl, 'shadow mask of hulls', shaderSources.shadowMaskVertex, shaderSources.shadowHullFragment);
    this.umbraProgram = createProgram(gl, 'shadow mask of umbrae', shaderSources.shadowMaskVertex, shaderSources.shadowUmbraFragment);
    this.concaveProgram = createProgram(gl, 'shadow mask of concave hulls', shaderSources.shadowMaskVertex, shaderSources.shadowConcaveFragment);
    this.edgesProgram = createProgram(gl, 'shadow mask of edges', shaderSources.shadowMaskVertex, shaderSources.shadowEdgesFragment);
    this.shadingPrograms = [this.hullProgram, this.concaveProgram, this.edgesProgram];
    this.programs = [this.umbraProgram, ...this.shadingPrograms];
    this.target = new RenderTarget(gl, { format: 'rgba8', depthStencil: true }, width, height);
    this.casterUniforms = new CasterUniforms(gl);
  }

  resize(width: number, height: number): void {
    this.target.resize(width, height);
  }

  /**
   * Once a frame, before the lights: binds the geometry textures and sets what every light shares.
   * The light loop's other passes leave those texture units alone.
   */
  beginFrame(buffers: GeometryBuffers, viewProjection: ReadonlyMat4, clipToWorld: ReadonlyMat4): void {
    const gl = this.gl;
    this.casterUniforms.bindTextures(buffers);
    gl.useProgram(this.umbraProgram.handle);
    this.casterUniforms.setFrame(this.umbraProgram, viewProjection);
    gl.uniform1i(this.umbraProgram.uniforms.u_umbra, 1);
    // Indexed: a for-of allocates an iterator every frame.
    const shading = this.shadingPrograms;
    for (let i = 0; i < shading.length; i++) {
      const program = shading[i];
      gl.useProgram(program.handle);
      this.casterUniforms.setFrame(program, viewProjection);
      gl.uniform1i(program.uniforms.u_umbra, 0);
      gl.uniformMatrix4fv(program.uniforms.u_clipToWorld, false, clipToWorld);
      gl.uniform2f(program.uniforms.u_targetSize, this.target.width, this.target.height);
    }
  }

  /**
   * Clears the mask inside the current scissor and draws the shadows of `draw`'s hulls.
   * @param mirrored whether the view-projection flips orientation (decides which faces are light-facing).
   */
  render(draw: LightDraw, buffers: GeometryBuffers, mirrored: boolean): void {
    const gl = this.gl;
    this.target.bind();
    gl.clearBufferfv(gl.COLOR, 0, NOTHING_HIDDEN);
    // Clears obey the write masks: the last light left depth writes off.
    gl.depthMask(true);
    gl.clearBufferfi(gl.DEPTH_STENCIL, 0, FARTHEST, 0);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.MAX);
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.BACK);
    // Casters the light must draw give clockwise quads in world space (y up).
    gl.frontFace(mirrored ? gl.CCW : gl.CW);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.bindVertexArray(buffers.casterVertexArray);
    const convex = draw.convexCasterCount, hulls = draw.hullCasterCount, all = draw.casterCount;
    if (hulls > 0) this.drawCasters(this.umbraProgram, draw, 0, hulls);
    gl.depthMask(false);
    if (convex > 0) this.drawCasters(this.hullProgram, draw, 0, convex);
    if (hulls > convex) this.drawCasters(this.concaveProgram, draw, convex, hulls - convex);
    if (all > hulls) this.drawCasters(this.edgesProgram, draw, hulls, all - hulls);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
  }

  /** Draws `count` of `draw`'s casters from its `first` on with `program`. */
  private drawCasters(program: Program, draw: LightDraw, first: number, count: number): void {
    const gl = this.gl;
    gl.useProgram(program.handle);
    this.casterUniforms.setLight(program, draw);
    gl.drawArrays(gl.TRIANGLES, first * CASTER_VERTICES, count * CASTER_VERTICES);
  }

  dispose(): void {
    for (const program of this.programs) this.gl.deleteProgram(program.handle);
    this.target.dispose();
  }
}
