import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../geometry/FramePlan';
import { createProgram, type Program } from '../gl/program';
import { RenderTarget } from '../gl/RenderTarget';
import { CASTER_VERTICES, CasterUniforms } from './CasterUniforms';
import type { GeometryBuffers } from './GeometryBuffers';
import { shaderSources } from './shaders';

/** The cleared mask: no part of the disk hidden. */
const NOTHING_HIDDEN = new Float32Array(4);

/**
 * Shadow mask pass: per light, writes into its own RGBA8 target how much of the light disk the
 * hulls in range hide from each pixel (see shadow-mask.frag.glsl), then lets the hull pass mark
 * the hulls' insides. Each shadow caster is one quad (shadow-mask.vert.glsl); light-facing edges
 * are culled by the rasterizer.
 */
export class ShadowMaskPass {
  readonly target: RenderTarget;
  /** For whole convex hulls' regions, and for edge quads: two programs rather than a branch per fragment, which cost SwiftShader 30%. */
  private readonly hullProgram: Program;
  private readonly edgesProgram: Program;
  private readonly casterUniforms: CasterUniforms;

  constructor(private readonly gl: WebGL2RenderingContext, width: number, height: number) {
    this.hullProgram = createProgram(gl, 'shadow mask of hulls', shaderSources.shadowMaskVertex, shaderSources.shadowHullFragment);
    this.edgesProgram = createProgram(gl, 'shadow mask of edges', shaderSources.shadowMaskVertex, shaderSources.shadowEdgesFragment);
    this.target = new RenderTarget(gl, { format: 'rgba8' }, width, height);
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
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.MAX);
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.BACK);
    // Casters the light must draw give clockwise quads in world space (y up).
    gl.frontFace(mirrored ? gl.CCW : gl.CW);
    gl.bindVertexArray(buffers.casterVertexArray);
    const edgeCasters = draw.casterCount - draw.hullCasterCount;
    if (draw.hullCasterCount > 0) this.drawCasters(this.hullProgram, draw, buffers, viewProjection, clipToWorld, 0, draw.hullCasterCount);
    if (edgeCasters > 0) this.drawCasters(this.edgesProgram, draw, buffers, viewProjection, clipToWorld, draw.hullCasterCount, edgeCasters);
    gl.disable(gl.CULL_FACE);
  }

  /** Draws `count` of `draw`'s casters from its `first` on with `program`. */
  private drawCasters(program: Program, draw: LightDraw, buffers: GeometryBuffers, viewProjection: ReadonlyMat4, clipToWorld: ReadonlyMat4, first: number, count: number): void {
    const gl = this.gl;
    gl.useProgram(program.handle);
    gl.uniformMatrix4fv(program.uniforms.u_clipToWorld, false, clipToWorld);
    gl.uniform2f(program.uniforms.u_targetSize, this.target.width, this.target.height);
    this.casterUniforms.set(program, draw, buffers, viewProjection);
    gl.drawArrays(gl.TRIANGLES, first * CASTER_VERTICES, count * CASTER_VERTICES);
  }

  dispose(): void {
    this.gl.deleteProgram(this.hullProgram.handle);
    this.gl.deleteProgram(this.edgesProgram.handle);
    this.target.dispose();
  }
}
