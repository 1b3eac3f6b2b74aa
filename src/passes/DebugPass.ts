import type { ReadonlyMat4 } from 'gl-matrix';
import { ANY_SIZE_CLASS, type LightDraw } from '../geometry/FramePlan';
import { createProgram, type Program } from '../gl/program';
import type { LightShapes } from '../gl/LightShapes';
import { CasterUniforms } from './CasterUniforms';
import type { GeometryBuffers } from './GeometryBuffers';
import { shaderSources } from './shaders';

/** Vertices per caster in the wireframe: its quad's four sides as lines. */
const OUTLINE_VERTICES = 8;

/**
 * Debug pass: over the composited image, outlines each drawn light's quad (yellow) and draws its
 * shadow casters' quads as wireframe (magenta), cut at the light's scissor rectangle.
 */
export class DebugPass {
  private readonly quadProgram: Program;
  private readonly shadowProgram: Program;
  private readonly casterUniforms: CasterUniforms;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly shapes: LightShapes) {
    this.quadProgram = createProgram(gl, 'debug light quads', shaderSources.lightVertex, shaderSources.debugFragment);
    this.shadowProgram = createProgram(gl, 'debug shadow geometry', shaderSources.shadowMaskVertex[ANY_SIZE_CLASS], shaderSources.debugFragment);
    this.casterUniforms = new CasterUniforms(gl);
    gl.useProgram(this.shadowProgram.handle);
    this.casterUniforms.setSamplerUnits(this.shadowProgram);
  }

  /**
   * @param toTarget scale from lightmap pixels to the bound target's pixels, for the scissor.
   */
  render(draws: readonly LightDraw[], drawCount: number, buffers: GeometryBuffers, viewProjection: ReadonlyMat4, toTargetX: number, toTargetY: number, offsetX: number, offsetY: number): void {
    const gl = this.gl;
    gl.disable(gl.BLEND);
    gl.enable(gl.SCISSOR_TEST);
    for (let i = 0; i < drawCount; i++) {
      const draw = draws[i];
      const s = draw.scissor;
      gl.scissor(offsetX + Math.floor(s[0] * toTargetX), offsetY + Math.floor(s[1] * toTargetY), Math.ceil(s[2] * toTargetX), Math.ceil(s[3] * toTargetY));
      gl.useProgram(this.shadowProgram.handle);
      this.casterUniforms.bindTextures(buffers);
      this.casterUniforms.setFrame(this.shadowProgram, viewProjection);
      this.casterUniforms.setLight(this.shadowProgram, draw);
      gl.uniform1i(this.shadowProgram.uniforms.u_outline, 1);
      gl.uniform4f(this.shadowProgram.uniforms.u_color, 1, 0, 1, 1);
      gl.bindVertexArray(buffers.casterVertexArray);
      // Each caster's quad as its four sides: an edge's quad shows the edge, the rays from its ends
      // and the far side; a hull's region its nearest line, the two inner tangents and the reach.
      gl.drawArrays(gl.LINES, 0, OUTLINE_VERTICES * draw.casterCount);
      gl.useProgram(this.quadProgram.handle);
      const quadUniforms = this.quadProgram.uniforms;
      gl.uniformMatrix4fv(quadUniforms.u_viewProjection, false, viewProjection);
      gl.uniform2fv(quadUniforms.u_quad, draw.quad);
      gl.uniform4f(quadUniforms.u_color, 1, 1, 0, 1);
      this.shapes.drawQuad(gl.LINE_LOOP);
    }
  }

  dispose(): void {
    this.gl.deleteProgram(this.quadProgram.handle);
    this.gl.deleteProgram(this.shadowProgram.handle);
  }
}
