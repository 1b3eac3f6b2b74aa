import type { ReadonlyMat4 } from 'gl-matrix';
import { ANY_SIZE_CLASS, CASTER_RUN_COUNT, CasterKind, kindOfRun, sizeClassOfRun, VARYING_POINT_COUNTS, type LightDraw } from '../geometry/FramePlan';
import type { LightShapes } from '../gl/LightShapes';
import { createProgram, type Program } from '../gl/program';
import { RenderTarget } from '../gl/RenderTarget';
import { CASTER_VERTICES, CasterUniforms } from './CasterUniforms';
import type { GeometryBuffers } from './GeometryBuffers';
import { shaderSources } from './shaders';

/** The cleared mask: no part of the disk hidden. */
const NOTHING_HIDDEN = new Float32Array(4);
/**
 * The cleared depth: the range cut-out and the umbrae are drawn nearer, and the other shadow quads
 * behind them fail the depth test.
 */
const FARTHEST = 1;

/** What the vertex stage draws for a whole-hull caster (`u_shape` in shadow-mask.vert.glsl); edges ignore it. */
const CasterShape = { Region: 0, Umbra: 1, Bounds: 2 } as const;

/** The fragment stage of each kind of caster, one build per size class, and its quads' shape. */
const KIND_STAGES: Record<CasterKind, { name: string; fragment: readonly string[]; shape: number }> = {
  [CasterKind.ConvexHull]: { name: 'convex hulls', fragment: shaderSources.shadowHullFragment, shape: CasterShape.Region },
  [CasterKind.ConcaveHull]: { name: 'concave hulls', fragment: shaderSources.shadowConcaveFragment, shape: CasterShape.Region },
  [CasterKind.ConcaveCavities]: { name: 'cavities', fragment: shaderSources.shadowCavityFragment, shape: CasterShape.Bounds },
  [CasterKind.Edges]: { name: 'edges', fragment: shaderSources.shadowEdgesFragment, shape: CasterShape.Region },
};

/**
 * Shadow mask pass: per light, writes into its own RGBA8 target how much of the light disk the
 * hulls in range hide from each pixel (see the chunk shadow-common), then lets the hull pass mark
 * the hulls' insides. Each shadow caster is one quad (shadow-mask.vert.glsl); light-facing edges
 * are culled by the rasterizer. The umbrae of the whole-hull casters are drawn first, cheaply and
 * with depth, so that the costly shadow fragments behind them (of any caster) are skipped by the
 * early depth test. Before them, for a light confined to its range, so is the part of its quad
 * outside the range, where the light adds nothing: an eighth of the shadow fragments of the bench's
 * S3 fell there.
 */
export class ShadowMaskPass {
  readonly target: RenderTarget;
  private readonly rangeCutoutProgram: Program;
  private readonly umbraProgram: Program;
  /** Per run of casters (see `CASTER_RUN_COUNT`): the program that computes the hidden part of the disk per pixel. */
  private readonly shadingPrograms: readonly Program[];
  private readonly casterUniforms: CasterUniforms;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly shapes: LightShapes, width: number, height: number) {
    this.casterUniforms = new CasterUniforms(gl);
    // Depth only: the colour it would write is masked off.
    this.rangeCutoutProgram = createProgram(gl, 'shadow mask: range cut-out', shaderSources.rangeCutoutVertex, shaderSources.shadowUmbraFragment);
    const vertex = shaderSources.shadowMaskVertex;
    this.umbraProgram = this.createShadowProgram('umbrae', vertex[ANY_SIZE_CLASS], shaderSources.shadowUmbraFragment, CasterShape.Umbra);
    const shading: Program[] = [];
    for (let run = 0; run < CASTER_RUN_COUNT; run++) {
      const { name, fragment, shape } = KIND_STAGES[kindOfRun(run)];
      const sizeClass = sizeClassOfRun(run);
      const size = sizeClass < ANY_SIZE_CLASS ? `of up to ${VARYING_POINT_COUNTS[sizeClass]} points` : 'of any size';
      shading.push(this.createShadowProgram(`${name} ${size}`, vertex[sizeClass], fragment[sizeClass], shape));
    }
    this.shadingPrograms = shading;
    this.target = new RenderTarget(gl, { format: 'rgba8', depthStencil: true }, width, height);
  }

  /** Links a program of the pass and sets what never changes: its caster shape and sampler units. */
  private createShadowProgram(name: string, vertexSource: string, fragmentSource: string, shape: number): Program {
    const program = createProgram(this.gl, `shadow mask of ${name}`, vertexSource, fragmentSource);
    this.gl.useProgram(program.handle);
    this.gl.uniform1i(program.uniforms.u_shape, shape);
    this.casterUniforms.setSamplerUnits(program);
    return program;
  }

  resize(width: number, height: number): void {
    this.target.resize(width, height);
  }

  /**
   * Once a frame, before the lights: binds the geometry textures and sets what every light shares.
   * The light loop's other passes leave those texture units and the face culling settings alone.
   * @param mirrored whether the view-projection flips orientation (decides which faces are light-facing).
   */
  beginFrame(buffers: GeometryBuffers, viewProjection: ReadonlyMat4, mirrored: boolean): void {
    const gl = this.gl;
    gl.cullFace(gl.BACK);
    // Casters the light must draw give clockwise quads in world space (y up).
    gl.frontFace(mirrored ? gl.CCW : gl.CW);
    this.casterUniforms.bindTextures(buffers);
    gl.useProgram(this.rangeCutoutProgram.handle);
    gl.uniformMatrix4fv(this.rangeCutoutProgram.uniforms.u_viewProjection, false, viewProjection);
    gl.useProgram(this.umbraProgram.handle);
    this.casterUniforms.setFrame(this.umbraProgram, viewProjection);
    // Indexed: a for-of allocates an iterator every frame.
    const shading = this.shadingPrograms;
    for (let i = 0; i < shading.length; i++) {
      const program = shading[i];
      gl.useProgram(program.handle);
      this.casterUniforms.setFrame(program, viewProjection);
    }
  }

  /** Clears the mask inside the current scissor and draws the shadows of `draw`'s hulls. */
  render(draw: LightDraw, buffers: GeometryBuffers): void {
    const gl = this.gl;
    this.target.bind();
    gl.clearBufferfv(gl.COLOR, 0, NOTHING_HIDDEN);
    // Clears obey the write masks: the last light left depth writes off.
    gl.depthMask(true);
    gl.clearBufferfi(gl.DEPTH_STENCIL, 0, FARTHEST, 0);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    if (draw.light.isConfinedToRangeDisk()) this.cutOutsideRange(draw);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.MAX);
    gl.enable(gl.CULL_FACE);
    gl.bindVertexArray(buffers.casterVertexArray);
    const regions = draw.regionCasterCount;
    if (regions > 0) this.drawCasters(this.umbraProgram, draw, 0, regions);
    gl.depthMask(false);
    const ends = draw.runEnds;
    for (let run = 0, start = 0; run < CASTER_RUN_COUNT; start = ends[run++]) {
      if (ends[run] > start) this.drawCasters(this.shadingPrograms[run], draw, start, ends[run] - start);
    }
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
  }

  /** Writes the nearest depth over the light's quad outside its range disk. */
  private cutOutsideRange(draw: LightDraw): void {
    const gl = this.gl;
    gl.useProgram(this.rangeCutoutProgram.handle);
    gl.uniform2fv(this.rangeCutoutProgram.uniforms.u_quad, draw.quad);
    gl.colorMask(false, false, false, false);
    this.shapes.drawOutsideDisk();
    gl.colorMask(true, true, true, true);
  }

  /** Draws `count` of `draw`'s casters from its `first` on with `program`. */
  private drawCasters(program: Program, draw: LightDraw, first: number, count: number): void {
    const gl = this.gl;
    gl.useProgram(program.handle);
    this.casterUniforms.setLight(program, draw);
    gl.drawArrays(gl.TRIANGLES, first * CASTER_VERTICES, count * CASTER_VERTICES);
  }

  dispose(): void {
    this.gl.deleteProgram(this.rangeCutoutProgram.handle);
    this.gl.deleteProgram(this.umbraProgram.handle);
    for (const program of this.shadingPrograms) this.gl.deleteProgram(program.handle);
    this.target.dispose();
  }
}
