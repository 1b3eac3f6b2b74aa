import type { Falloff } from '../scene/falloff';

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
 * Every uniform of the light programs but the samplers, with what it holds; which a program has
 * depends on its light kind and build (shadowed or not, tiled, with normals).
 */
export const LIGHT_UNIFORMS = {
  u_viewProjection: 'world to clip space',
  u_surfaceFrame: 'with normals: 1 / lightmap width, 1 / lightmap height, 1 when the surface\'s row 0 is the top of the view',
  u_quad: 'the light\'s quad: a corner and the two edge vectors (Light.writeQuad)',
  u_tiles: 'tiled programs: the tile grid\'s corner (least x and y), a tile\'s width and height (LightDraw.tileFrame)',
  u_lightColor: 'colour × intensity (times the shadow\'s kept fraction for dark tiles)',
  u_light: 'position xy, range',
  u_falloff: 'the curve\'s code (FALLOFF_CODES), the inverse-square core in ranges',
  u_towardsLight: 'with normals: a positional light\'s position xy and height (w 0), a directional light\'s unit vector towards it (w 1)',
  u_shadow: 'shadowed programs: position xy, disk radius, row of the light\'s shadow bins',
  u_shadowType: 'shadowed programs: how the light treats the inside of hulls (SHADOW_TYPE_CODES)',
  u_shadowKept: 'shadowed programs: the fraction of each channel a pixel in full shadow keeps',
  u_binning: 'shadowed programs: how the bins were filed (LightDraw.binning), or a directional light\'s strips',
  u_direction: 'spotlights: the cone\'s axis, a unit vector',
  u_coneHalfAngle: 'spotlights: half the cone\'s angle',
  u_coneDecay: 'spotlights: the exponent of the falloff across the cone',
} as const;
