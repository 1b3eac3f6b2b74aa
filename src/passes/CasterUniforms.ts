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
 * Sets the textures and uniforms of shadow-mask.vert.glsl: for the shadow-mask pass and the debug
 * wireframe, whose programs share that vertex stage. What does not change between lights is set
 * once a frame.
 */
export class CasterUniforms {
  // Through a reused typed array: doubles passed to a GL call one by one are boxed on the heap.
  private readonly light = new Float32Array(4);

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
    const light = this.light;
    light[0] = draw.light.position[0];
    light[1] = draw.light.position[1];
    light[2] = draw.light.radius;
    light[3] = draw.reach;
    this.gl.uniform4fv(program.uniforms.u_light, light);
    this.gl.uniform1i(program.uniforms.u_firstCaster, draw.casterOffset);
  }
}
