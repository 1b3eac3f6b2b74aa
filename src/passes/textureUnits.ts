import type { ShadowTextureUnits } from '../shadow/ShadowTextures';

/**
 * The texture unit of every sampler of every program: the one table the passes take their units
 * from. Each program's samplers are set to their units once, when it is linked (`createProgram`,
 * through `uniform1i`), and each pass binds its textures on them before it draws.
 *
 * A group holds the samplers one pass binds in one build; a program's samplers are the groups of
 * its pass and build, their units distinct (test/gl/gpuInterface.test.ts checks every program the
 * renderer links). Groups of different passes share units: the passes never bind both at once. A
 * frame runs in turn the shadow upload, the light pass, the blur, the hull mask, the composite and
 * the debug wireframes, each binding what it samples before it draws, so that the blur's source and
 * the composite's scene take unit 0 from the shadow records once the light pass has read them, and
 * the hull mask and debug passes bind the records again. The engine surface pass runs outside the
 * renderer's calls, around its own saved host state.
 */
export const TEXTURE_UNITS = {
  /** The light programs (LightPass), every build. */
  light: {
    /** The hulls' shadow records: programs with shadows. Bound by `ShadowTextures.upload` before each lightmap. */
    u_records: 0,
    /** The lights' shadow bins: programs with shadows. Bound with the records. */
    u_bins: 1,
    /** A textured light's cookie: its programs. Bound by `LightPass.render` for each textured light. */
    u_cookie: 2,
    /** The bins' entries: programs with shadows. Bound with the records. */
    u_entries: 3,
    /** The records' tags: programs with shadows. Bound with the records. */
    u_recordTags: 4,
    /** The tiles' masks of listed records: the listed programs. Bound with the records. */
    u_tileRecords: 7,
  },
  /** The light programs with normals: the surface, bound by `LightPass.begin` once a lightmap. */
  lightWithNormals: {
    /** The surface's normals. */
    u_normals: 5,
    /** The surface's material. */
    u_material: 6,
  },
  /** The lightmap blur (BlurPass), run after the light pass. */
  blur: {
    /** The target read along one axis: the lightmap, then the scratch target. Bound by `BlurPass.render` for each of its two draws. */
    u_source: 0,
  },
  /** The hull mask (HullMaskPass), with a lightmap smaller than the scene, run after the blur. */
  hullMask: {
    /** The shadow records, bound again by `HullMaskPass.render` when it draws. */
    u_records: 0,
  },
  /** The composite (CompositePass), every build; all its textures bound by `CompositePass.render`. */
  composite: {
    /** The host's scene colour. */
    u_scene: 0,
    /** The lightmap (its diffuse light with normals). */
    u_lightmap: 1,
  },
  /** The composite with normals. */
  compositeWithNormals: {
    /** The lightmap's highlights. */
    u_specular: 2,
    /** The surface's material, for the emission. */
    u_material: 3,
  },
  /** The composite upsampling aware of hull outlines (a lightmap smaller than the scene). */
  compositeEdgeAware: {
    /** The hull mask at the scene's resolution. */
    u_hullMask: 4,
    /** The hull mask at the lightmap's resolution. */
    u_lightmapHullMask: 5,
  },
  /** The debug records program (DebugPass), after the composite. */
  debug: {
    /** The shadow records, bound again by `DebugPass.render`. */
    u_records: 0,
  },
  /** The engine surface pass (SurfacePass), outside the renderer's calls; both bound by `SurfacePass.render` for each batch. */
  surface: {
    /** The sprite's colour texture, whose alpha is the coverage. */
    u_color: 0,
    /** The sprite's normal map. */
    u_normals: 1,
  },
} as const satisfies Record<string, Readonly<Record<string, number>>>;

/** The shadow textures' units, as `ShadowTextures` binds them: the light programs'. */
export const SHADOW_TEXTURE_UNITS: ShadowTextureUnits = {
  records: TEXTURE_UNITS.light.u_records, bins: TEXTURE_UNITS.light.u_bins,
  entries: TEXTURE_UNITS.light.u_entries, recordTags: TEXTURE_UNITS.light.u_recordTags,
  tileRecords: TEXTURE_UNITS.light.u_tileRecords,
};

/** How many units, from 0, the groups' samplers take: one past the highest unit. */
export function unitsSpanned(groups: readonly Readonly<Record<string, number>>[]): number {
  let highest = -1;
  for (const group of groups) for (const unit of Object.values(group)) highest = Math.max(highest, unit);
  return highest + 1;
}
