import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../shadow/ShadowCache';
import { RECORD_POINTS } from '../shadow/shadowLayout';
import { createPrograms, deletePrograms, type ProgramOf, type UniformDeclaration } from '../gl/program';
import type { LightShapes } from './LightShapes';
import { shaderSources } from './shaders';
import { TEXTURE_UNITS } from './textureUnits';

/** Vertices per record in the wireframe: each of its point slots starts a side drawn as a line. */
const RECORD_VERTICES = 2 * RECORD_POINTS;

/**
 * The uniforms but the sampler of the debug pass's programs: the light quads' (the light pass's
 * vertex stage) and the records' (shaders/records.vert.glsl), both with shaders/debug.frag.glsl.
 * `DebugPass` sets them through these names only.
 */
const DEBUG_UNIFORMS = {
  /** World to clip space. */
  u_viewProjection: { type: 'mat4' },
  /** The outlines' colour. */
  u_color: { type: 'vec4' },
  /** Light quads: the light's quad, a corner and the two edge vectors (Light.writeQuad). */
  u_quad: { type: 'vec2[3]' },
  /**
   * Light quads: the light pass's light, left unset (the outline ignores the varyings it feeds).
   */
  u_light: { type: 'vec3' },
} as const satisfies Record<string, UniformDeclaration>;

/** What the debug pass addresses in its programs. */
export const DEBUG_INTERFACE = { uniforms: DEBUG_UNIFORMS, samplers: TEXTURE_UNITS.debug };

/**
 * Debug pass: over the composited image, outlines each drawn light's quad (yellow) and the convex
 * records the hulls' shadows are computed from (magenta).
 */
export class DebugPass {
  private readonly quadProgram: ProgramOf<typeof DEBUG_INTERFACE>;
  private readonly recordsProgram: ProgramOf<typeof DEBUG_INTERFACE>;
  /** No attributes: the records' vertex stage fetches its points. */
  private readonly emptyVertexArray: WebGLVertexArrayObject;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly shapes: LightShapes) {
    const programs = createPrograms(gl, {
      quad: ['debug light quads', shaderSources.lightVertex, shaderSources.debugFragment],
      records: ['debug shadow records', shaderSources.recordOutlinesVertex, shaderSources.debugFragment],
    }, DEBUG_INTERFACE);
    this.quadProgram = programs.quad;
    this.recordsProgram = programs.records;
    // Made after the programs, which may fail: creating a vertex array cannot.
    this.emptyVertexArray = gl.createVertexArray()!;
  }

  /** Draws the outlines of the first `recordCount` records of the `records` texture and of the lights' quads. */
  render(draws: readonly LightDraw[], drawCount: number, records: WebGLTexture, recordCount: number, viewProjection: ReadonlyMat4): void {
    const gl = this.gl;
    gl.disable(gl.BLEND);
    gl.activeTexture(gl.TEXTURE0 + TEXTURE_UNITS.debug.u_records);
    gl.bindTexture(gl.TEXTURE_2D, records);
    gl.useProgram(this.recordsProgram.handle);
    gl.uniformMatrix4fv(this.recordsProgram.uniforms.u_viewProjection, false, viewProjection);
    gl.uniform4f(this.recordsProgram.uniforms.u_color, 1, 0, 1, 1);
    gl.bindVertexArray(this.emptyVertexArray);
    gl.drawArrays(gl.LINES, 0, RECORD_VERTICES * recordCount);
    gl.useProgram(this.quadProgram.handle);
    const quadUniforms = this.quadProgram.uniforms;
    gl.uniformMatrix4fv(quadUniforms.u_viewProjection, false, viewProjection);
    gl.uniform4f(quadUniforms.u_color, 1, 1, 0, 1);
    for (let i = 0; i < drawCount; i++) {
      gl.uniform2fv(quadUniforms.u_quad, draws[i].quad);
      this.shapes.outlineQuad();
    }
  }

  dispose(): void {
    deletePrograms(this.gl, [this.quadProgram, this.recordsProgram]);
    this.gl.deleteVertexArray(this.emptyVertexArray);
  }
}
