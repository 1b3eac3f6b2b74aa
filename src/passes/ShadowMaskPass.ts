import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../geometry/FramePlan';
import { createProgram, type Program } from '../gl/program';
import { RenderTarget } from '../gl/RenderTarget';
import type { GeometryBuffers } from './GeometryBuffers';
import { shaderSources } from './shaders';

/**
 * How far the far corners of a shadow quad are pushed: many times the light's bounds diagonal, so
 * that even when the two tangents of a long edge diverge widely the quad's far side stays outside
 * the scissor rectangle.
 */
export function projectionLength(bounds: Float64Array): number {
  const width = bounds[2] - bounds[0], height = bounds[3] - bounds[1];
  // Not Math.hypot: it is variadic and allocates.
  return 64 * Math.sqrt(width * width + height * height);
}

/** The cleared mask: no part of the disk hidden. */
const NOTHING_HIDDEN = new Float32Array(4);

/** Texture unit the shadow-mask pass reads hull points from. */
const POINTS_UNIT = 0;

/**
 * Shadow mask pass: per light, writes into its own RGBA8 target how much of the light disk the
 * hulls in range hide from each pixel (see shadow-mask.frag.glsl), then lets the hull pass mark
 * the hulls' insides. Light-facing edges are culled by the rasterizer.
 */
export class ShadowMaskPass {
  readonly target: RenderTarget;
  private readonly program: Program;
  private readonly lightPosition = new Float32Array(2);
  private readonly lightRadius = new Float32Array(1);
  private readonly projectionLength = new Float32Array(1);

  constructor(private readonly gl: WebGL2RenderingContext, width: number, height: number) {
    this.program = createProgram(gl, 'shadow mask', shaderSources.shadowMaskVertex, shaderSources.shadowMaskFragment);
    this.target = new RenderTarget(gl, { format: 'rgba8' }, width, height);
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
    const uniforms = this.program.uniforms;
    this.target.bind();
    gl.clearBufferfv(gl.COLOR, 0, NOTHING_HIDDEN);
    gl.useProgram(this.program.handle);
    gl.uniformMatrix4fv(uniforms.u_viewProjection, false, viewProjection);
    gl.uniformMatrix4fv(uniforms.u_clipToWorld, false, clipToWorld);
    gl.uniform2f(uniforms.u_targetSize, this.target.width, this.target.height);
    // Through reused typed arrays: doubles passed to a GL call one by one are boxed on the heap.
    // (One array per uniform: headless-gl lacks the srcOffset/srcLength overloads.)
    this.lightPosition[0] = draw.light.position[0];
    this.lightPosition[1] = draw.light.position[1];
    this.lightRadius[0] = draw.light.radius;
    this.projectionLength[0] = projectionLength(draw.bounds);
    gl.uniform2fv(uniforms.u_lightPosition, this.lightPosition);
    gl.uniform1fv(uniforms.u_lightRadius, this.lightRadius);
    gl.uniform1fv(uniforms.u_projectionLength, this.projectionLength);
    gl.uniform1i(uniforms.u_hullPoints, POINTS_UNIT);
    gl.activeTexture(gl.TEXTURE0 + POINTS_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, buffers.pointsTexture);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.MAX);
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.BACK);
    // Edges facing away from the light give clockwise quads in world space (y up).
    gl.frontFace(mirrored ? gl.CCW : gl.CW);
    buffers.bindEdges(draw);
    gl.drawArraysInstanced(gl.TRIANGLE_FAN, 0, 4, draw.edgeCount);
    gl.disable(gl.CULL_FACE);
  }

  dispose(): void {
    this.gl.deleteProgram(this.program.handle);
    this.target.dispose();
  }
}
