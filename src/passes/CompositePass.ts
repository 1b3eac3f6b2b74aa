import { createProgram, type Program } from '../gl/program';
import { shaderSources } from './shaders';

const SCENE_UNIT = 0;
const LIGHTMAP_UNIT = 1;

/** Composite pass: writes scene × lightmap with one full-screen triangle into the bound framebuffer. */
export class CompositePass {
  private readonly program: Program;
  private readonly emptyVertexArray: WebGLVertexArrayObject;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = createProgram(gl, 'composite', shaderSources.fullscreenVertex, shaderSources.compositeFragment);
    this.emptyVertexArray = gl.createVertexArray()!;
  }

  render(scene: WebGLTexture, lightmap: WebGLTexture): void {
    const gl = this.gl;
    gl.disable(gl.BLEND);
    gl.disable(gl.SCISSOR_TEST);
    gl.useProgram(this.program.handle);
    gl.uniform1i(this.program.uniforms.u_scene, SCENE_UNIT);
    gl.uniform1i(this.program.uniforms.u_lightmap, LIGHTMAP_UNIT);
    gl.activeTexture(gl.TEXTURE0 + SCENE_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, scene);
    gl.activeTexture(gl.TEXTURE0 + LIGHTMAP_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, lightmap);
    gl.bindVertexArray(this.emptyVertexArray);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  dispose(): void {
    this.gl.deleteProgram(this.program.handle);
    this.gl.deleteVertexArray(this.emptyVertexArray);
  }
}
