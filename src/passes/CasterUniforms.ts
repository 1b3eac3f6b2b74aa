import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../geometry/FramePlan';
import type { Program } from '../gl/program';
import type { GeometryBuffers } from './GeometryBuffers';

/** Vertices per shadow caster: its quad as two triangles (see shadow-mask.vert.glsl). */
export const CASTER_VERTICES = 6;

/** Texture units of the hull points and casters: no other pass of the light loop binds them. */
const POINTS_UNIT = 0;
const CASTERS_UNIT = 3;

/**
 * How far the far corners of an edge's shadow quad are pushed, in light bounds diagonals: far enough
 * that even when the two tangents of a long edge diverge widely the quad's far side stays outside
 * the scissor rectangle.
 */
const PROJECTION_DIAGONALS = 64;

/**
 * Sets the textures and uniforms of shadow-mask.vert.glsl: for the shadow-mask pass and the debug
 * wireframe, whose programs share that vertex stage. What does not change between lights is set
 * once a frame.
 */
export class CasterUniforms {
  // Through reused typed arrays: doubles passed to a GL call one by one are boxed on the heap.
  // (One array per uniform: headless-gl lacks the srcOffset/srcLength overloads.)
  private readonly lightPosition = new Float32Array(2);
  private readonly lightRadius = new Float32Array(1);
  private readonly lightReach = new Float32Array(1);
  private readonly projectionLength = new Float32Array(1);

  constructor(private readonly gl: WebGL2RenderingContext) {}

  /** Binds the hull points and casters textures to their units; leaves unit 0 active. */
  bindTextures(buffers: GeometryBuffers): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + CASTERS_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, buffers.castersTexture);
    gl.activeTexture(gl.TEXTURE0 + POINTS_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, buffers.pointsTexture);
  }

  /** Points the samplers of `program` (in use) at the texture units; once, when it is linked: a program keeps its uniforms. */
  setSamplerUnits(program: Program): void {
    this.gl.uniform1i(program.uniforms.u_hullPoints, POINTS_UNIT);
    this.gl.uniform1i(program.uniforms.u_casters, CASTERS_UNIT);
  }

  /** Sets the frame's uniforms of `program`, which must be in use. */
  setFrame(program: Program, viewProjection: ReadonlyMat4): void {
    this.gl.uniformMatrix4fv(program.uniforms.u_viewProjection, false, viewProjection);
  }

  /** Sets the uniforms of `program` (in use) for `draw`'s light. */
  setLight(program: Program, draw: LightDraw): void {
    const gl = this.gl;
    const uniforms = program.uniforms;
    this.lightPosition[0] = draw.light.position[0];
    this.lightPosition[1] = draw.light.position[1];
    this.lightRadius[0] = draw.light.radius;
    this.lightReach[0] = draw.reach;
    // Computed in place: a double returned by a function that is not inlined is boxed on the heap.
    const bounds = draw.bounds;
    const width = bounds[2] - bounds[0], height = bounds[3] - bounds[1];
    this.projectionLength[0] = PROJECTION_DIAGONALS * Math.sqrt(width * width + height * height);
    gl.uniform2fv(uniforms.u_lightPosition, this.lightPosition);
    gl.uniform1fv(uniforms.u_lightRadius, this.lightRadius);
    gl.uniform1fv(uniforms.u_lightReach, this.lightReach);
    gl.uniform1fv(uniforms.u_projectionLength, this.projectionLength);
    gl.uniform1i(uniforms.u_firstCaster, draw.casterOffset);
  }
}
