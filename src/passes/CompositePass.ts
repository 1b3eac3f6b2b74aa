import { createProgram, type ProgramOf, type UniformDeclaration } from '../gl/program';
import { DITHERING_CODES, TONE_MAPPING_CODES } from './compositeLayout';
import type { Dithering, ToneMapping } from '../scene/look';
import type { Surface } from './LightPass';
import type { HullMaskPass } from './HullMaskPass';
import { compositeStage, shaderSources } from './shaders';
import { TEXTURE_UNITS } from './textureUnits';

const { composite: units, compositeWithNormals: normalsUnits, compositeEdgeAware: edgeAwareUnits } = TEXTURE_UNITS;

/** The composite's uniforms but the samplers (shaders/composite.frag.glsl), which `CompositePass` sets through these names only. */
const COMPOSITE_UNIFORMS = {
  /** The factor of the lit colour before tone mapping. */
  u_exposure: { type: 'float' },
  /** The curve's code (TONE_MAPPING_CODES). */
  u_toneMapping: { type: 'int' },
  /** The dithering's code (DITHERING_CODES). */
  u_dithering: { type: 'int' },
  /** With normals: whether the material's row 0 is the top of the view. */
  u_flipSurface: { type: 'bool' },
} as const satisfies Record<string, UniformDeclaration>;

/** What the composite addresses in its program: its uniforms and the samplers of every build. */
export const COMPOSITE_INTERFACE = { uniforms: COMPOSITE_UNIFORMS, samplers: { ...units, ...normalsUnits, ...edgeAwareUnits } };

/** How the composite turns scene × lightmap into output colour: see `PenumbraRenderer.exposure` and the next two. */
export interface CompositeLook {
  readonly exposure: number;
  readonly toneMapping: ToneMapping;
  readonly dithering: Dithering;
}

/**
 * Composite pass: writes scene × lightmap × exposure, tone-mapped and dithered, with one
 * full-screen triangle into the bound framebuffer. With normals (a program of its own):
 * (scene × (lightmap + emissive) + highlights) × exposure. With a lightmap smaller than the scene
 * (a program of its own), the lightmap is upsampled aware of hull outlines, through the hull masks.
 */
export class CompositePass {
  private readonly program: ProgramOf<typeof COMPOSITE_INTERFACE>;
  private readonly emptyVertexArray: WebGLVertexArrayObject;
  /** Through a reused array, as the light pass's uniforms: a double passed alone may be boxed. */
  private readonly exposure = new Float32Array(1);

  /**
   * @param normals - whether the renderer has normals (the highlights and the emission).
   * @param edgeAware - whether the lightmap is upsampled aware of hull outlines (`render` then takes the hull masks).
   */
  constructor(private readonly gl: WebGL2RenderingContext, private readonly normals: boolean, edgeAware: boolean) {
    const name = `composite${normals ? ' with normals' : ''}${edgeAware ? ', edge-aware upsampling' : ''}`;
    this.program = createProgram(gl, name, shaderSources.fullscreenVertex, compositeStage(normals, edgeAware), COMPOSITE_INTERFACE);
    this.emptyVertexArray = gl.createVertexArray()!;
  }

  /**
   * @param lightmap - the light pass's target: its first attachment, and with normals its highlights.
   * @param surface - with normals, where the material is; ignored without.
   * @param hullMasks - upsampling aware of hull edges, this frame's masks; ignored otherwise.
   */
  render(scene: WebGLTexture, lightmap: readonly WebGLTexture[], look: CompositeLook, surface: Surface, hullMasks: HullMaskPass | null): void {
    const gl = this.gl;
    const uniforms = this.program.uniforms;
    gl.disable(gl.BLEND);
    gl.useProgram(this.program.handle);
    this.exposure[0] = look.exposure;
    gl.uniform1fv(uniforms.u_exposure, this.exposure);
    gl.uniform1i(uniforms.u_toneMapping, TONE_MAPPING_CODES[look.toneMapping]);
    gl.uniform1i(uniforms.u_dithering, DITHERING_CODES[look.dithering]);
    this.bind(units.u_scene, scene);
    this.bind(units.u_lightmap, lightmap[0]);
    if (this.normals) {
      gl.uniform1i(uniforms.u_flipSurface, surface.flipY ? 1 : 0);
      this.bind(normalsUnits.u_specular, lightmap[1]);
      this.bind(normalsUnits.u_material, surface.material);
    }
    if (hullMasks) {
      this.bind(edgeAwareUnits.u_hullMask, hullMasks.scene.texture);
      this.bind(edgeAwareUnits.u_lightmapHullMask, hullMasks.lightmap.texture);
    }
    gl.bindVertexArray(this.emptyVertexArray);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  private bind(unit: number, texture: WebGLTexture): void {
    this.gl.activeTexture(this.gl.TEXTURE0 + unit);
    this.gl.bindTexture(this.gl.TEXTURE_2D, texture);
  }

  dispose(): void {
    this.gl.deleteProgram(this.program.handle);
    this.gl.deleteVertexArray(this.emptyVertexArray);
  }
}
