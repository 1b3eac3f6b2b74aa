import type { Falloff } from '../scene/falloff';
import type { UniformDeclaration } from '../gl/program';
import { LISTED_RECORDS } from '../shadow/shadowLayout';

/**
 * The light passes' codes for a light's distance falloff (see `Falloff`), which
 * shaders/chunks/light-common.glsl compares its varying with, reaching it as defines
 * ({@link LIGHT_DEFINES}).
 */
export const FALLOFF_CODES = { linear: 0, smooth: 1, inverseSquare: 2 } as const satisfies Record<Falloff, number>;

/** The falloff codes as `#define`s. */
export const LIGHT_DEFINES: Readonly<Record<string, number>> = {
  FALLOFF_LINEAR: FALLOFF_CODES.linear, FALLOFF_SMOOTH: FALLOFF_CODES.smooth, FALLOFF_INVERSE_SQUARE: FALLOFF_CODES.inverseSquare,
};

/**
 * Every uniform of the light programs but the samplers (see `TEXTURE_UNITS.light`), with its GLSL
 * type and what it holds; which a program has depends on its light kind and build (with shadows or
 * not, tiled, with normals). `LightPass` sets them through these names only. A directional light's
 * programs hold something else in some slots, as said there: the same slots, so that the shadow
 * chunk reads one set of uniforms.
 */
export const LIGHT_UNIFORMS = {
  /** World to clip space. */
  u_viewProjection: { type: 'mat4' },
  /** The light's quad: a corner and the two edge vectors (Light.writeQuad). */
  u_quad: { type: 'vec2[3]' },
  /**
   * Tiled programs: the tile grid's corner (least x and y), a tile's width and height
   * (LightDraw.tileFrame).
   */
  u_tiles: { type: 'vec4' },
  /**
   * Colour × intensity; for the dark tiles, times the fraction of each channel the shadows keep.
   */
  u_lightColor: { type: 'vec3' },
  /** Position xy, range; for a directional light: position xy and range 1, unused (no falloff). */
  u_light: { type: 'vec3' },
  /**
   * The curve's code (FALLOFF_CODES), the inverse-square core in ranges; for a directional light:
   * unused (no falloff).
   */
  u_falloff: { type: 'vec2' },
  /**
   * Programs with shadows: position xy, disk radius, row of the light's shadow bins; for a
   * directional light: the unit direction the light travels (xy), the sine of its angular radius,
   * its row of strips.
   */
  u_shadow: { type: 'vec4' },
  /** Programs with shadows: how the light treats the inside of hulls (SHADOW_TYPE_CODES). */
  u_shadowType: { type: 'float' },
  /** Programs with shadows: the fraction of each channel a pixel in full shadow keeps. */
  u_shadowKept: { type: 'vec3' },
  /**
   * Programs with shadows: the disk the bins were filed for, centre xy and radius, and a distance
   * bucket's width (LightDraw.binning); for a directional light: its strips (DirectionalStrips):
   * the least coordinate across the travel, a strip's width, where the first bucket starts along
   * it, a bucket's width.
   */
  u_binning: { type: 'vec4' },
  /**
   * With normals: 1 / lightmap width, 1 / lightmap height, 1 when the surface's row 0 is the top of
   * the view.
   */
  u_surfaceFrame: { type: 'vec3' },
  /**
   * With normals: position xy and height, w 0; for a directional light: the unit vector towards the
   * light (xyz), w 1.
   */
  u_towardsLight: { type: 'vec4' },
  /** The listed programs: the light's listed records, nearest first (LightDraw.listedRecords; see `TileRecordLists`). */
  u_listedRecords: { type: `int[${LISTED_RECORDS}]` },
  /** Spotlights: the cone's axis, a unit vector. */
  u_direction: { type: 'vec2' },
  /** Spotlights: half the cone's angle. */
  u_coneHalfAngle: { type: 'float' },
  /** Spotlights: the exponent of the falloff across the cone. */
  u_coneDecay: { type: 'float' },
} as const satisfies Record<string, UniformDeclaration>;
