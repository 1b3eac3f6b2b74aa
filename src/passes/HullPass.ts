import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../geometry/FramePlan';
import { createProgram, type Program } from '../gl/program';
import { ShadowType } from '../scene/lights';
import type { GeometryBuffers } from './GeometryBuffers';
import { shaderSources } from './shaders';

/**
 * Hull pass: draws the hulls in range into the bound shadow mask. A Solid light marks their
 * insides fully hidden; an Illuminated light clears the mask there so the hulls are lit.
 */
export class HullPass {
  private readonly program: Program;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = createProgram(gl, 'hull', shaderSources.hullVertex, shaderSources.hullFragment);
  }

  /** Once a frame, before the lights: sets the view-projection (a program keeps its uniforms). */
  beginFrame(viewProjection: ReadonlyMat4): void {
    this.gl.useProgram(this.program.handle);
    this.gl.uniformMatrix4fv(this.program.uniforms.u_viewProjection, false, viewProjection);
  }

  render(draw: LightDraw, buffers: GeometryBuffers): void {
    const gl = this.gl;
    const uniforms = this.program.uniforms;
    gl.useProgram(this.program.handle);
    if (draw.light.shadowType === ShadowType.Solid) {
      gl.enable(gl.BLEND);
      gl.blendEquation(gl.MAX);
      gl.uniform4f(uniforms.u_maskValue, 1, 0, 0, 0);
    } else {
      gl.disable(gl.BLEND);
      gl.uniform4f(uniforms.u_maskValue, 0, 0, 0, 0);
    }
    gl.bindVertexArray(buffers.hullVertexArray);
    gl.drawElements(gl.TRIANGLES, draw.triangleIndexCount, gl.UNSIGNED_INT, draw.triangleIndexOffset * 4);
  }

  dispose(): void {
    this.gl.deleteProgram(this.program.handle);
  }
}
