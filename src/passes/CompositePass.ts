import { createProgram, type Program } from '../gl/program';
import { DITHERING_CODES, TONE_MAPPING_CODES, type Dithering, type ToneMapping } from './compositeLayout';
import { shaderSources } from './shaders';

const SCENE_UNIT = 0;
const LIGHTMAP_UNIT = 1;

/** How the composite turns scene × lightmap into output colour: see `PenumbraRenderer.exposure` and the next two. */
export interface CompositeLook {
  readonly exposure: number;
  readonly toneMapping: ToneMapping;
  readonly dithering: Dithering;
}

/**
 * Composite pass: writes scene × lightmap × exposure, tone-mapped and dithered, with one
 * full-screen triangle into the bound framebuffer.
 */
export class CompositePass {
  private readonly program: Program;
  private readonly emptyVertexArray: WebGLVertexArrayObject;
  /** Through a reused array, as the light pass's uniforms: a double passed alone may be boxed. */
  private readonly exposure = new Float32Array(1);

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = createProgram(gl, 'composite', shaderSources.fullscreenVertex, shaderSources.compositeFragment);
    this.emptyVertexArray = gl.createVertexArray()!;
  }

  render(scene: WebGLTexture, lightmap: WebGLTexture, look: CompositeLook): void {
    const gl = this.gl;
    const uniforms = this.program.uniforms;
    gl.disable(gl.BLEND);
    gl.disable(gl.SCISSOR_TEST);
    gl.useProgram(this.program.handle);
    gl.uniform1i(uniforms.u_scene, SCENE_UNIT);
    gl.uniform1i(uniforms.u_lightmap, LIGHTMAP_UNIT);
    this.exposure[0] = look.exposure;
    gl.uniform1fv(uniforms.u_exposure, this.exposure);
    gl.uniform1i(uniforms.u_toneMapping, TONE_MAPPING_CODES[look.toneMapping]);
    gl.uniform1i(uniforms.u_dithering, DITHERING_CODES[look.dithering]);
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
