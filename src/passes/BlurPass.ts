import { createProgram, type ProgramOf, type UniformDeclaration } from '../gl/program';
import { RenderTarget, type TargetFormat } from '../gl/RenderTarget';
import { MAX_BLUR_RADIUS, MIN_BLUR_RADIUS } from '../scene/look';
import { shaderSources } from './shaders';
import { TEXTURE_UNITS } from './textureUnits';

const SOURCE_UNIT = TEXTURE_UNITS.blur.u_source;

/** The blur's uniforms but its sampler (shaders/blur.frag.glsl), which `BlurPass` sets through these names only. */
const BLUR_UNIFORMS = {
  /** One texel along the draw's axis, in texture coordinates. */
  u_step: { type: 'vec2' },
  /** The taps on each side, ≤ MAX_BLUR_RADIUS. */
  u_radius: { type: 'int' },
  /** The weight of the taps at ±k, summing to 1 over the taps. */
  u_weights: { type: `float[${MAX_BLUR_RADIUS + 1}]` },
} as const satisfies Record<string, UniformDeclaration>;

/** What the blur addresses in its program. */
export const BLUR_INTERFACE = { uniforms: BLUR_UNIFORMS, samplers: TEXTURE_UNITS.blur };

type BlurProgram = ProgramOf<typeof BLUR_INTERFACE>;

/**
 * Lightmap blur: a Gaussian of standard deviation radius / 2, cut at ±radius texels and
 * normalised, run across the lightmap into a scratch target and back down into the lightmap. Its
 * program, vertex array and scratch target are made the first time a blur runs (none while the
 * blur is off: no compile at start-up), and the scratch target follows the lightmap's size.
 */
export class BlurPass {
  private program: BlurProgram | null = null;
  private emptyVertexArray: WebGLVertexArrayObject | null = null;
  private scratch: RenderTarget | null = null;
  private readonly weights = new Float32Array(MAX_BLUR_RADIUS + 1);
  private readonly step = new Float32Array(2);
  private weightsRadius = -1;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly format: TargetFormat) {}

  /**
   * Blurs the first attachment of `lightmap` in place by `radius` texels (≤ {@link MAX_BLUR_RADIUS});
   * leaves blending off. A radius below {@link MIN_BLUR_RADIUS} (the renderer's blur
   * times a `lightmapScale` below 1 may be one) is the identity: it does nothing.
   */
  render(lightmap: RenderTarget, radius: number): void {
    if (!(radius >= MIN_BLUR_RADIUS)) return;
    const gl = this.gl;
    const taps = Math.min(MAX_BLUR_RADIUS, Math.ceil(radius));
    const program = (this.program ??= createProgram(gl, 'lightmap blur', shaderSources.fullscreenVertex, shaderSources.blurFragment, BLUR_INTERFACE));
    this.emptyVertexArray ??= gl.createVertexArray();
    this.scratch ??= new RenderTarget(gl, { format: this.format }, lightmap.width, lightmap.height);
    this.scratch.resize(lightmap.width, lightmap.height);
    this.updateWeights(radius);
    const uniforms = program.uniforms;
    gl.disable(gl.BLEND);
    gl.useProgram(program.handle);
    gl.uniform1i(uniforms.u_radius, taps);
    gl.uniform1fv(uniforms.u_weights, this.weights);
    gl.bindVertexArray(this.emptyVertexArray);
    gl.activeTexture(gl.TEXTURE0 + SOURCE_UNIT);
    this.pass(program, lightmap, this.scratch, 1 / lightmap.width, 0);
    this.pass(program, this.scratch, lightmap, 0, 1 / lightmap.height);
  }

  private pass(program: BlurProgram, from: RenderTarget, to: RenderTarget, stepX: number, stepY: number): void {
    const gl = this.gl;
    to.bindFirst();
    gl.bindTexture(gl.TEXTURE_2D, from.texture);
    this.step[0] = stepX;
    this.step[1] = stepY;
    gl.uniform2fv(program.uniforms.u_step, this.step);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  /** Gaussian weights for taps 0..⌈radius⌉, σ = radius / 2, normalised over both sides; recomputed only when the radius changes. */
  private updateWeights(radius: number): void {
    if (radius === this.weightsRadius) return;
    this.weightsRadius = radius;
    const taps = Math.min(MAX_BLUR_RADIUS, Math.ceil(radius));
    const sigma = radius / 2;
    let sum = 0;
    this.weights.fill(0);
    for (let k = 0; k <= taps; k++) {
      this.weights[k] = Math.exp(-(k * k) / (2 * sigma * sigma));
      sum += k === 0 ? this.weights[k] : 2 * this.weights[k];
    }
    for (let k = 0; k <= taps; k++) this.weights[k] /= sum;
  }

  dispose(): void {
    if (this.program) this.gl.deleteProgram(this.program.handle);
    if (this.emptyVertexArray) this.gl.deleteVertexArray(this.emptyVertexArray);
    this.scratch?.dispose();
  }
}
