import { createProgram, type Program } from '../gl/program';
import { DITHERING_CODES, TONE_MAPPING_CODES, type Dithering, type ToneMapping } from './compositeLayout';
import type { Surface } from './LightPass';
import { shaderSources } from './shaders';

const SCENE_UNIT = 0;
const LIGHTMAP_UNIT = 1;
/** With normals: the highlights and the material (for the emission). */
const SPECULAR_UNIT = 2;
const MATERIAL_UNIT = 3;

/** How the composite turns scene × lightmap into output colour: see `PenumbraRenderer.exposure` and the next two. */
export interface CompositeLook {
  readonly exposure: number;
  readonly toneMapping: ToneMapping;
  readonly dithering: Dithering;
}

/**
 * Composite pass: writes scene × lightmap × exposure, tone-mapped and dithered, with one
 * full-screen triangle into the bound framebuffer. With normals (a program of its own):
 * (scene × (lightmap + emissive) + highlights) × exposure.
 */
export class CompositePass {
  private readonly program: Program;
  private readonly emptyVertexArray: WebGLVertexArrayObject;
  /** Through a reused array, as the light pass's uniforms: a double passed alone may be boxed. */
  private readonly exposure = new Float32Array(1);

  /** @param normals - whether the renderer has normals (the highlights and the emission). */
  constructor(private readonly gl: WebGL2RenderingContext, private readonly normals: boolean) {
    this.program = normals
      ? createProgram(gl, 'composite with normals', shaderSources.fullscreenVertex, shaderSources.compositeFragmentWithNormals)
      : createProgram(gl, 'composite', shaderSources.fullscreenVertex, shaderSources.compositeFragment);
    this.emptyVertexArray = gl.createVertexArray()!;
  }

  /**
   * @param lightmap - the light pass's target: its first attachment, and with normals its highlights.
   * @param surface - with normals, where the material is; ignored without.
   */
  render(scene: WebGLTexture, lightmap: readonly WebGLTexture[], look: CompositeLook, surface: Surface): void {
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
    gl.bindTexture(gl.TEXTURE_2D, lightmap[0]);
    if (this.normals) this.bindSurface(lightmap[1], surface);
    gl.bindVertexArray(this.emptyVertexArray);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  private bindSurface(specular: WebGLTexture, surface: Surface): void {
    const gl = this.gl;
    const uniforms = this.program.uniforms;
    gl.uniform1i(uniforms.u_specular, SPECULAR_UNIT);
    gl.uniform1i(uniforms.u_material, MATERIAL_UNIT);
    gl.uniform1i(uniforms.u_flipSurface, surface.flipY ? 1 : 0);
    gl.activeTexture(gl.TEXTURE0 + SPECULAR_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, specular);
    gl.activeTexture(gl.TEXTURE0 + MATERIAL_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, surface.material);
  }

  dispose(): void {
    this.gl.deleteProgram(this.program.handle);
    this.gl.deleteVertexArray(this.emptyVertexArray);
  }
}
