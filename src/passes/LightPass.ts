import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../shadow/ShadowCache';
import { createPrograms, deletePrograms, type ProgramOf, type ProgramSources } from '../gl/program';
import { RenderTarget, type TargetFormat } from '../gl/RenderTarget';
import type { LightShapes } from './LightShapes';
import { SHADOW_TYPE_CODES, TILE_CLASSES } from '../shadow/shadowLayout';
import { FALLOFF_CODES, LIGHT_UNIFORMS } from './lightLayout';
import { DirectionalLight } from '../scene/DirectionalLight';
import type { LightKind } from '../scene/Light';
import { Spotlight } from '../scene/Spotlight';
import { TexturedLight } from '../scene/TexturedLight';
import { lightStages, shaderSources, type LightStages } from './shaders';
import { TEXTURE_UNITS } from './textureUnits';

/** What the light pass addresses in its programs: the uniforms of its table and the samplers of every build. */
export const LIGHT_INTERFACE = { uniforms: LIGHT_UNIFORMS, samplers: { ...TEXTURE_UNITS.light, ...TEXTURE_UNITS.lightWithNormals } };

type LightProgram = ProgramOf<typeof LIGHT_INTERFACE>;

/** The textures a light pass with normals reads the surface from (see `PenumbraRenderer.drawInPlace`). */
export interface Surface {
  normals: WebGLTexture;
  material: WebGLTexture;
  /** Whether the textures' row 0 is the top of the view. */
  flipY: boolean;
}

/**
 * Light pass: owns the lightmap (RGBA16F where the context can render to it, so overlapping lights
 * go above 1), clears it to the ambient colour, and adds each light weighted by the visible
 * fraction of its disk: one fragment per light pixel. A light with no hull in range is drawn as the
 * polygon around its range disk when confined to it, else as its quad, with the plain program. A
 * point light, spotlight or textured light with hulls in range is drawn as the tiles of its grid
 * (see `LightTiles`): the lit tiles with the plain program, the dark ones with the plain program in
 * the colour its shadows keep (not at all when they keep none), the others with an exact program,
 * which computes the visible fraction from the shadow textures (see the chunk shadow-visibility):
 * the lean one where every record that hides anything lies in front of the disk (reading the
 * tile's records instead of its bin where they are listed, `TileRecordLists`), else the general
 * one; an Illuminated light's dark tiles with hulls in them with the held program (lit inside
 * hulls). A directional light with hulls is drawn as its quad with an exact program: the lean one
 * (from a disk at infinity every record is in front) but for an Occluded light (the holder pass).
 *
 * With normals the lightmap has a second attachment for the highlights, and the programs weight
 * each light by the surface's normal and material (docs/normal-maps.md); without, neither exists.
 *
 * A kind of light's programs are made when a light of that kind is first prepared
 * ({@link LightPass.prepare}): a renderer of point lights compiles none of the others.
 */
export class LightPass {
  readonly lightmap: RenderTarget;
  /**
   * Per kind of light, its programs: for a light with no hull in range (its shape), and for one
   * with some: its lit and dark tiles (plain), its held tiles, its lean tiles (lean exact; a
   * directional light's quad), its listed tiles (lean, reading their tile's records), its other tiles (general exact, in closed form when no pixel can see
   * several hulls past; an Occluded directional light's quad).
   */
  private readonly programs: Partial<Record<LightKind, LightPrograms>> = {};
  /** Every program made so far: the frame's uniforms and `dispose` go through it. */
  private readonly programList: LightProgram[] = [];
  private readonly clearValue = new Float32Array(4);
  // Uniform values go through reused typed arrays: doubles passed to a GL call one by one are boxed
  // on the heap. (One array per uniform: headless-gl lacks the srcOffset/srcLength overloads.)
  private readonly lightColor = new Float32Array(3);
  private readonly lightPositionAndRange = new Float32Array(3);
  private readonly shadow = new Float32Array(4);
  private readonly shadowKept = new Float32Array(3);
  private readonly binning = new Float32Array(4);
  private readonly falloff = new Float32Array(2);
  private readonly direction = new Float32Array(2);
  private readonly coneHalfAngle = new Float32Array(1);
  private readonly coneDecay = new Float32Array(1);
  private readonly towardsLight = new Float32Array(4);
  private readonly darkColor = new Float32Array(3);
  private readonly surfaceFrame = new Float32Array(3);
  private readonly clearZero = new Float32Array(4);

  /**
   * Throws when the lightmap cannot be made.
   * @param normals - whether to light through a surface's normals (programs and lightmap of a renderer with normals).
   */
  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly shapes: LightShapes, format: TargetFormat, width: number, height: number,
    private readonly normals: boolean,
  ) {
    this.lightmap = new RenderTarget(gl, { format, linear: true, colorAttachments: normals ? 2 : 1 }, width, height);
  }

  /** Whether the programs of `kind` are made. */
  prepared(kind: LightKind): boolean {
    return this.programs[kind] !== undefined;
  }

  /**
   * Makes the programs of `kind` unless they are made (when the pass is built, for the scene's
   * lights, and when a light of a new kind is added); {@link LightPass.begin} sets each frame's
   * uniforms on every program made. Changes the bound program.
   * @throws Error, having freed what it made, when a program cannot be made (or the context is lost).
   */
  prepare(kind: LightKind): void {
    if (this.programs[kind] !== undefined) return;
    const [name, fragment] = KIND_SOURCES[kind];
    const made = createPrograms(this.gl, sourcesOf(kind, name, lightStages(shaderSources[fragment], this.normals)), LIGHT_INTERFACE);
    this.programs[kind] = {
      unshadowed: made[`${kind} unshadowed`], plainTiles: made[`${kind} plain tiles`] ?? null, heldTiles: made[`${kind} held tiles`] ?? null,
      lean: made[`${kind} lean`], listed: made[`${kind} listed`] ?? null, closed: made[`${kind} closed`] ?? null, shadowed: made[`${kind} shadowed`],
    };
    this.programList.push(...Object.values(made));
  }

  resize(width: number, height: number): void {
    this.lightmap.resize(width, height);
  }

  /**
   * Once a frame, before the lights: sets the view-projection, binds the lightmap and clears it to
   * the ambient colour (alpha 1) and its highlights to 0, binds the surface with normals, and sets
   * additive blending. The shadow textures must be bound on their units (`ShadowTextures.upload`).
   * @param surface - with normals, the surface to light through; ignored without.
   */
  begin(ambient: readonly [number, number, number], viewProjection: ReadonlyMat4, surface: Surface): void {
    const gl = this.gl;
    if (this.normals) this.bindSurface(surface);
    // Indexed: a for-of allocates an iterator every frame.
    const programs = this.programList;
    for (let i = 0; i < programs.length; i++) {
      gl.useProgram(programs[i].handle);
      gl.uniformMatrix4fv(programs[i].uniforms.u_viewProjection, false, viewProjection);
      if (this.normals) gl.uniform3fv(programs[i].uniforms.u_surfaceFrame, this.surfaceFrame);
    }
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.FUNC_ADD);
    gl.blendFunc(gl.ONE, gl.ONE);
    this.lightmap.bind();
    const clear = this.clearValue;
    clear[0] = ambient[0];
    clear[1] = ambient[1];
    clear[2] = ambient[2];
    clear[3] = 1;
    // clearBufferfv leaves the clear colour alone, so the host's need not be saved.
    gl.clearBufferfv(gl.COLOR, 0, clear);
    if (this.normals) gl.clearBufferfv(gl.COLOR, 1, this.clearZero);
  }

  /** Binds the surface's textures on their units and fills the surface frame uniform's array. */
  private bindSurface(surface: Surface): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + TEXTURE_UNITS.lightWithNormals.u_normals);
    gl.bindTexture(gl.TEXTURE_2D, surface.normals);
    gl.activeTexture(gl.TEXTURE0 + TEXTURE_UNITS.lightWithNormals.u_material);
    gl.bindTexture(gl.TEXTURE_2D, surface.material);
    gl.activeTexture(gl.TEXTURE0);
    this.surfaceFrame[0] = 1 / this.lightmap.width;
    this.surfaceFrame[1] = 1 / this.lightmap.height;
    this.surfaceFrame[2] = surface.flipY ? 1 : 0;
  }

  /** Adds one light into the lightmap, shadowed by the hulls in its bins when it has any in range. */
  render(draw: LightDraw): void {
    const gl = this.gl;
    const light = draw.light;
    const programs = this.programs[light.kind];
    // Unprepared only for a light that reached the scene without addLight (or as the context was
    // being lost, until the rebuild): not drawn rather than a frame that throws.
    if (programs === undefined) return;
    this.writeLightUniforms(draw);
    if (light instanceof TexturedLight) {
      gl.activeTexture(gl.TEXTURE0 + TEXTURE_UNITS.light.u_cookie);
      gl.bindTexture(gl.TEXTURE_2D, light.texture);
    }
    if (draw.hullCount === 0) {
      this.setUniforms(programs.unshadowed, draw, this.lightColor);
      if (light.isConfinedToRangeDisk()) this.shapes.drawDisk();
      else this.shapes.drawQuad();
    } else if (programs.plainTiles === null) {
      this.setUniforms(light.shadowType === 'occluded' ? programs.shadowed : programs.lean, draw, this.lightColor);
      this.shapes.drawQuad();
    } else {
      const counts = draw.tileCounts, kept = this.shadowKept, dark = this.darkColor;
      if (counts[TILE_CLASSES.lit] > 0) this.drawTiles(programs.plainTiles, draw, TILE_CLASSES.lit, this.lightColor);
      if (counts[TILE_CLASSES.dark] > 0 && (kept[0] > 0 || kept[1] > 0 || kept[2] > 0)) {
        for (let c = 0; c < 3; c++) dark[c] = this.lightColor[c] * kept[c];
        this.drawTiles(programs.plainTiles, draw, TILE_CLASSES.dark, dark);
      }
      if (counts[TILE_CLASSES.held] > 0 && programs.heldTiles !== null) this.drawTiles(programs.heldTiles, draw, TILE_CLASSES.held, this.lightColor);
      if (counts[TILE_CLASSES.lean] > 0) this.drawTiles(programs.lean, draw, TILE_CLASSES.lean, this.lightColor);
      if (counts[TILE_CLASSES.listed] > 0 && programs.listed !== null) {
        gl.useProgram(programs.listed.handle);
        gl.uniform1iv(programs.listed.uniforms.u_listedRecords, draw.listedRecords);
        this.drawTiles(programs.listed, draw, TILE_CLASSES.listed, this.lightColor);
      }
      if (counts[TILE_CLASSES.exact] > 0) this.drawTiles(draw.closedForm && programs.closed !== null ? programs.closed : programs.shadowed, draw, TILE_CLASSES.exact, this.lightColor);
    }
  }

  /** Draws the light's tiles of class `tileClass` with `program` in `color`. */
  private drawTiles(program: LightProgram, draw: LightDraw, tileClass: number, color: Float32Array): void {
    this.setUniforms(program, draw, color);
    this.gl.uniform4fv(program.uniforms.u_tiles, draw.tileFrame);
    this.shapes.drawTileRectangles(draw.tileLists[2 * tileClass], draw.tileLists[2 * tileClass + 1]);
  }

  /** Makes `program` current and sets its uniforms from the arrays `writeLightUniforms` filled, the light's colour as `color`. */
  private setUniforms(program: LightProgram, draw: LightDraw, color: Float32Array): void {
    const gl = this.gl;
    const light = draw.light;
    const uniforms = program.uniforms;
    gl.useProgram(program.handle);
    gl.uniform2fv(uniforms.u_quad, draw.quad);
    gl.uniform3fv(uniforms.u_lightColor, color);
    gl.uniform3fv(uniforms.u_light, this.lightPositionAndRange);
    if (uniforms.u_shadow) {
      gl.uniform4fv(uniforms.u_shadow, this.shadow);
      gl.uniform1f(uniforms.u_shadowType, SHADOW_TYPE_CODES[light.shadowType]);
      gl.uniform3fv(uniforms.u_shadowKept, this.shadowKept);
    }
    if (uniforms.u_binning) gl.uniform4fv(uniforms.u_binning, this.binning);
    if (uniforms.u_falloff) gl.uniform2fv(uniforms.u_falloff, this.falloff);
    if (uniforms.u_towardsLight) gl.uniform4fv(uniforms.u_towardsLight, this.towardsLight);
    if (light instanceof Spotlight) {
      gl.uniform2fv(uniforms.u_direction, this.direction);
      gl.uniform1fv(uniforms.u_coneHalfAngle, this.coneHalfAngle);
      gl.uniform1fv(uniforms.u_coneDecay, this.coneDecay);
    }
  }

  /** Copies the light's colour, position, range and shadow values into the uniform arrays. */
  private writeLightUniforms(draw: LightDraw): void {
    const light = draw.light;
    light.writeEmittedColor(this.lightColor);
    this.lightPositionAndRange[0] = light.position[0];
    this.lightPositionAndRange[1] = light.position[1];
    this.lightPositionAndRange[2] = light.range;
    this.shadow[0] = light.position[0];
    this.shadow[1] = light.position[1];
    this.shadow[2] = light.radius;
    this.shadow[3] = draw.binRow;
    this.binning.set(draw.binning);
    light.writeShadowKept(this.shadowKept);
    this.falloff[0] = FALLOFF_CODES[light.falloff];
    light.writeInverseSquareCore(this.falloff, 1);
    this.towardsLight[0] = light.position[0];
    this.towardsLight[1] = light.position[1];
    this.towardsLight[2] = light.height;
    this.towardsLight[3] = 0;
    if (light instanceof DirectionalLight) this.writeDirectionalUniforms(draw, light);
    if (light instanceof Spotlight) {
      this.direction[0] = Math.cos(light.rotation);
      this.direction[1] = Math.sin(light.rotation);
      this.coneHalfAngle[0] = light.coneAngle / 2;
      this.coneDecay[0] = light.coneDecay;
    }
  }

  /**
   * A directional light's values in place of a position and range: the direction it travels and
   * sin α for the disk (see the chunk shadow-visibility), its strips, and a unit range (it has no
   * falloff; the pass ignores the distance).
   */
  private writeDirectionalUniforms(draw: LightDraw, light: DirectionalLight): void {
    const strips = draw.strips;
    this.lightPositionAndRange[2] = 1;
    this.shadow[0] = strips.travelX;
    this.shadow[1] = strips.travelY;
    this.shadow[2] = Math.sin(light.angularSize / 2);
    this.binning[0] = strips.perpBase;
    this.binning[1] = strips.width;
    this.binning[2] = strips.alongBase;
    this.binning[3] = strips.bucketWidth;
    const cosElevation = Math.cos(light.elevation);
    this.towardsLight[0] = -strips.travelX * cosElevation;
    this.towardsLight[1] = -strips.travelY * cosElevation;
    this.towardsLight[2] = Math.sin(light.elevation);
    this.towardsLight[3] = 1;
  }

  dispose(): void {
    deletePrograms(this.gl, this.programList);
    this.lightmap.dispose();
  }
}

/** Per kind of light, the name its programs' errors give and its fragment stage in `shaderSources`. */
const KIND_SOURCES: Readonly<Record<LightKind, readonly [string, 'lightPointFragment' | 'lightSpotFragment' | 'lightTexturedFragment' | 'lightDirectionalFragment']>> = {
  point: ['point light', 'lightPointFragment'],
  spot: ['spotlight', 'lightSpotFragment'],
  textured: ['textured light', 'lightTexturedFragment'],
  directional: ['directional light', 'lightDirectionalFragment'],
};

/** A kind of light's programs (see `LightPass.programs`); a directional light has no tiles. */
interface LightPrograms {
  unshadowed: LightProgram;
  plainTiles: LightProgram | null;
  heldTiles: LightProgram | null;
  lean: LightProgram;
  listed: LightProgram | null;
  closed: LightProgram | null;
  shadowed: LightProgram;
}

/** The sources of a kind's programs, keyed `<kind> unshadowed`, `<kind> plain tiles`, `<kind> held tiles`, `<kind> listed` and `<kind> closed` (but for a directional light), `<kind> lean` and `<kind> shadowed`. */
function sourcesOf(kind: LightKind, name: string, stages: LightStages): Record<string, ProgramSources> {
  if (kind === 'directional') {
    return {
      [`${kind} unshadowed`]: [name, stages.vertex, stages.unshadowed],
      [`${kind} lean`]: [`${name} with shadows, lean`, stages.vertex, stages.lean],
      [`${kind} shadowed`]: [`${name} with shadows`, stages.vertex, stages.shadowed],
    };
  }
  return {
    [`${kind} unshadowed`]: [name, stages.vertex, stages.unshadowed],
    [`${kind} plain tiles`]: [`${name}'s plain tiles`, stages.tiledVertex, stages.unshadowed],
    [`${kind} held tiles`]: [`${name}'s held tiles`, stages.tiledVertex, stages.held],
    [`${kind} lean`]: [`${name}'s lean exact tiles`, stages.tiledVertex, stages.lean],
    [`${kind} listed`]: [`${name}'s listed lean tiles`, stages.tiledVertex, stages.listed],
    [`${kind} closed`]: [`${name}'s general tiles in closed form`, stages.tiledVertex, stages.closed],
    [`${kind} shadowed`]: [`${name} with shadows`, stages.tiledVertex, stages.shadowed],
  };
}
