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
  /** For whole convex hulls' regions, and for edge quads: two programs rather than a branch per fragment, which cost SwiftShader 30%. */
  private readonly hullProgram: Program;
  private readonly umbraProgram: Program;
  private readonly edgesProgram: Program;
  private readonly casterUniforms: CasterUniforms;

  constructor(private readonly gl: WebGL2RenderingContext, width: number, height: number) {
    this.hullProgram = createProgram(gl, 'shadow mask of hulls', shaderSources.shadowMaskVertex, shaderSources.shadowHullFragment);
    this.umbraProgram = createProgram(gl, 'shadow mask of umbrae', shaderSources.shadowMaskVertex, shaderSources.shadowUmbraFragment);
    this.edgesProgram = createProgram(gl, 'shadow mask of edges', shaderSources.shadowMaskVertex, shaderSources.shadowEdgesFragment);
    this.target = new RenderTarget(gl, { format: 'rgba8', depthStencil: true }, width, height);
    this.casterUniforms = new CasterUniforms(gl);
  }

  resize(width: number, height: number): void {
    this.target.resize(width, height);
  }

  /**
   * Clears the mask inside the current scissor and draws the shadows of `draw`'s hulls.
   * @param mirrored whether `viewProjection` flips orientation (decides which faces are light-facing).
   */
  render(draw: LightDraw, buffers: GeometryBuffers, viewProjection: ReadonlyMat4, clipToWorld: ReadonlyMat4, mirrored: boolean): void {
    const gl = this.gl;
    this.target.bind();
    gl.clearBufferfv(gl.COLOR, 0, NOTHING_HIDDEN);
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
    const hullCasters = draw.hullCasterCount, edgeCasters = draw.casterCount - hullCasters;
    if (hullCasters > 0) {
      gl.depthMask(true);
      this.useCasterProgram(this.umbraProgram, draw, buffers, viewProjection, true);
      this.drawCasters(0, hullCasters);
      gl.depthMask(false);
      this.useShadingProgram(this.hullProgram, draw, buffers, viewProjection, clipToWorld);
      this.drawCasters(0, hullCasters);
    }
    if (edgeCasters > 0) {
      gl.depthMask(false);
      this.useShadingProgram(this.edgesProgram, draw, buffers, viewProjection, clipToWorld);
      this.drawCasters(hullCasters, edgeCasters);
    }
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
  }

  private useCasterProgram(program: Program, draw: LightDraw, buffers: GeometryBuffers, viewProjection: ReadonlyMat4, umbra: boolean): void {
    this.gl.useProgram(program.handle);
    this.gl.uniform1i(program.uniforms.u_umbra, umbra ? 1 : 0);
    this.casterUniforms.set(program, draw, buffers, viewProjection);
  }

  /** Uses a program that computes the hidden part of the disk per pixel (it turns fragments back into world points). */
  private useShadingProgram(program: Program, draw: LightDraw, buffers: GeometryBuffers, viewProjection: ReadonlyMat4, clipToWorld: ReadonlyMat4): void {
    this.useCasterProgram(program, draw, buffers, viewProjection, false);
    this.gl.uniformMatrix4fv(program.uniforms.u_clipToWorld, false, clipToWorld);
    this.gl.uniform2f(program.uniforms.u_targetSize, this.target.width, this.target.height);
  }

  /** Draws `count` casters of the light from its `first` on. */
  private drawCasters(first: number, count: number): void {
    this.gl.drawArrays(this.gl.TRIANGLES, first * CASTER_VERTICES, count * CASTER_VERTICES);
  }

  dispose(): void {
    this.gl.deleteProgram(this.hullProgram.handle);
    this.gl.deleteProgram(this.umbraProgram.handle);
    this.gl.deleteProgram(this.edgesProgram.handle);
    this.target.dispose();
  }
}
