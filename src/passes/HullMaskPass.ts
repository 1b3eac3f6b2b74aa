import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import { createProgram, type ProgramOf, type UniformDeclaration } from '../gl/program';
import { RenderTarget } from '../gl/RenderTarget';
import { shaderSources } from './shaders';
import { TEXTURE_UNITS } from './textureUnits';

/** Vertices per record: its convex quad as two triangles. */
const RECORD_VERTICES = 6;
/** Clear value of the masks: outside every hull. */
const OUTSIDE = new Float32Array(4);

/**
 * The hull mask program's uniforms but its sampler (shaders/records.vert.glsl, filled, with
 * shaders/debug.frag.glsl), which `HullMaskPass` sets through these names only.
 */
const HULL_MASK_UNIFORMS = {
  /** World to clip space. */
  u_viewProjection: { type: 'mat4' },
  /** The mask inside a hull: 1. */
  u_color: { type: 'vec4' },
} as const satisfies Record<string, UniformDeclaration>;

/** What the hull mask pass addresses in its program. */
export const HULL_MASK_INTERFACE = { uniforms: HULL_MASK_UNIFORMS, samplers: TEXTURE_UNITS.hullMask };

/**
 * Hull mask pass, for a lightmap smaller than the scene: draws the shadow records, 1 inside a hull
 * and 0 elsewhere, once at the scene's resolution and once at the lightmap's (where each texel
 * holds whether the light pass's sample point, the texel centre, lies in a hull). The composite reads
 * both to upsample the lightmap without smearing it across hull outlines (shaders/composite.frag.glsl).
 *
 * The mask holds every record the frame's records texture holds: those of hulls some light had in
 * range (the only ones that can make the lightmap jump), and possibly stale or disabled ones
 * elsewhere, where the lightmap is smooth and a mask only narrows the interpolation to one side.
 */
export class HullMaskPass {
  /** The mask at the scene's resolution. */
  readonly scene: RenderTarget;
  /** The mask at the lightmap's resolution. */
  readonly lightmap: RenderTarget;
  private readonly targets: readonly RenderTarget[];
  private readonly program: ProgramOf<typeof HULL_MASK_INTERFACE>;
  /** No attributes: the vertex stage fetches the records' points. */
  private readonly emptyVertexArray: WebGLVertexArrayObject;
  /** What the masks hold: the records' version and the view they were drawn for; null when they hold nothing yet (or were resized). */
  private drawnRecordsVersion: number | null = null;
  private readonly drawnView = mat4.create();

  /** Frees what it made before throwing when a part cannot be made. */
  constructor(private readonly gl: WebGL2RenderingContext, width: number, height: number, lightmapWidth: number, lightmapHeight: number) {
    const made: { dispose(): void }[] = [];
    try {
      this.program = createProgram(gl, 'hull mask', shaderSources.filledRecordsVertex, shaderSources.debugFragment, HULL_MASK_INTERFACE);
      made.push({ dispose: () => gl.deleteProgram(this.program.handle) });
      this.scene = new RenderTarget(gl, { format: 'r8' }, width, height);
      made.push(this.scene);
      // Filtered, the composite finds in one read whether the four texels around a pixel agree.
      this.lightmap = new RenderTarget(gl, { format: 'r8', linear: true }, lightmapWidth, lightmapHeight);
      this.targets = [this.scene, this.lightmap];
    } catch (error) {
      for (const resource of made) resource.dispose();
      throw error;
    }
    this.emptyVertexArray = gl.createVertexArray()!;
    gl.useProgram(this.program.handle);
    gl.uniform4f(this.program.uniforms.u_color, 1, 1, 1, 1);
  }

  resize(width: number, height: number, lightmapWidth: number, lightmapHeight: number): void {
    this.scene.resize(width, height);
    this.lightmap.resize(lightmapWidth, lightmapHeight);
    this.drawnRecordsVersion = null;
  }

  /**
   * Draws the first `recordCount` records of `records` (`recordsVersion`, as
   * `ShadowGeometry.recordsVersion` counts them) into both masks, unless they hold those records in
   * this view already. Leaves the lightmap's mask bound when it draws.
   */
  render(records: WebGLTexture, recordCount: number, recordsVersion: number, viewProjection: ReadonlyMat4): void {
    if (recordsVersion === this.drawnRecordsVersion && mat4.exactEquals(viewProjection, this.drawnView)) return;
    this.drawnRecordsVersion = recordsVersion;
    mat4.copy(this.drawnView, viewProjection);
    const gl = this.gl;
    gl.disable(gl.BLEND);
    gl.activeTexture(gl.TEXTURE0 + TEXTURE_UNITS.hullMask.u_records);
    gl.bindTexture(gl.TEXTURE_2D, records);
    gl.useProgram(this.program.handle);
    gl.uniformMatrix4fv(this.program.uniforms.u_viewProjection, false, viewProjection);
    gl.bindVertexArray(this.emptyVertexArray);
    for (let i = 0; i < this.targets.length; i++) {
      this.targets[i].bind();
      gl.clearBufferfv(gl.COLOR, 0, OUTSIDE);
      gl.drawArrays(gl.TRIANGLES, 0, RECORD_VERTICES * recordCount);
    }
  }

  dispose(): void {
    this.gl.deleteProgram(this.program.handle);
    this.gl.deleteVertexArray(this.emptyVertexArray);
    this.scene.dispose();
    this.lightmap.dispose();
  }
}
