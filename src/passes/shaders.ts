import blurFragment from '../../shaders/blur.frag.glsl?raw';
import compositeFragment from '../../shaders/composite.frag.glsl?raw';
import debugFragment from '../../shaders/debug.frag.glsl?raw';
import fullscreenVertex from '../../shaders/fullscreen.vert.glsl?raw';
import lightCommon from '../../shaders/chunks/light-common.glsl?raw';
import lightDirectionalFragment from '../../shaders/light-directional.frag.glsl?raw';
import lightPointFragment from '../../shaders/light-point.frag.glsl?raw';
import lightSpotFragment from '../../shaders/light-spot.frag.glsl?raw';
import lightTexturedFragment from '../../shaders/light-textured.frag.glsl?raw';
import lightVertex from '../../shaders/light.vert.glsl?raw';
import recordsVertex from '../../shaders/records.vert.glsl?raw';
import shadowBehind from '../../shaders/chunks/shadow-behind.glsl?raw';
import shadowQuadrature from '../../shaders/chunks/shadow-quadrature.glsl?raw';
import shadowVisibility from '../../shaders/chunks/shadow-visibility.glsl?raw';
import surface from '../../shaders/surface.glsl?raw';
import { SHADOW_DEFINES } from '../shadow/shadowLayout';
import { COMPOSITE_DEFINES } from './compositeLayout';
import { MAX_BLUR_RADIUS } from '../scene/look';
import { LIGHT_DEFINES } from './lightLayout';
import { SURFACE_DEFINES } from './surfaceLayout';
import { resolveIncludes, withDefines } from '../gl/program';

const chunks = { 'light-common': lightCommon, 'shadow-visibility': shadowVisibility, 'shadow-behind': shadowBehind, 'shadow-quadrature': shadowQuadrature };

/** Resolves includes until none is left: chunks include chunks (light-common → shadow-visibility → shadow-behind, shadow-quadrature). */
function resolveChunks(source: string): string {
  for (let resolved = resolveIncludes(source, chunks); ; source = resolved, resolved = resolveIncludes(source, chunks)) {
    if (resolved === source) return resolved;
  }
}

/** The stages of a light pass (see the chunk light-common). */
export interface LightStages {
  vertex: string;
  /** The vertex stage that draws the tile grid of a light's classes (`TILED`). */
  tiledVertex: string;
  /** For a light with no hull in range. */
  unshadowed: string;
  /** For a light with hulls in range (`SHADOWED`): the general exact program. */
  shadowed: string;
  /** For the general tiles of a light whose records reaching into its disk are one convex hull's (`SHADOWED`, `CLOSED_SHADOW`): no quadrature. */
  closed: string;
  /** For the tiles of a light with hulls whose records all lie in front of the disk (`SHADOWED`, `LEAN_SHADOW`). */
  lean: string;
  /** For the lean tiles whose records are listed per tile (`SHADOWED`, `LEAN_SHADOW`, `LISTED_TILES`). */
  listed: string;
  /** For an Illuminated light's tiles that are dark but inside hulls (`SHADOWED`, `HELD_SHADOW`). */
  held: string;
}

/** The defines of the light passes of a renderer with normals. */
const NORMALS_DEFINES = { NORMALS: '', ...SURFACE_DEFINES };

/**
 * A light pass's stages from its fragment source (one of `shaderSources.light*Fragment`), for a
 * renderer with or without normals.
 */
export function lightStages(fragment: string, normals: boolean): LightStages {
  const resolved = normals ? withDefines(fragment, NORMALS_DEFINES) : fragment;
  return {
    vertex: lightVertex,
    tiledVertex: withDefines(lightVertex, { TILED: '' }),
    unshadowed: resolved,
    shadowed: withDefines(resolved, { SHADOWED: '', ...SHADOW_DEFINES }),
    closed: withDefines(resolved, { SHADOWED: '', CLOSED_SHADOW: '', ...SHADOW_DEFINES }),
    lean: withDefines(resolved, { SHADOWED: '', LEAN_SHADOW: '', ...SHADOW_DEFINES }),
    listed: withDefines(resolved, { SHADOWED: '', LEAN_SHADOW: '', LISTED_TILES: '', ...SHADOW_DEFINES }),
    held: withDefines(resolved, { SHADOWED: '', HELD_SHADOW: '', ...SHADOW_DEFINES }),
  };
}

/**
 * The composite's fragment stage for a renderer with or without normals, upsampling a smaller
 * lightmap bilinearly or aware of hull outlines (`edgeAware`, see the shader).
 */
export function compositeStage(normals: boolean, edgeAware: boolean): string {
  return withDefines(compositeFragment, { ...COMPOSITE_DEFINES, ...(normals ? NORMALS_DEFINES : {}), ...(edgeAware ? { EDGE_AWARE: '' } : {}) });
}

function lightFragment(source: string): string {
  return withDefines(resolveChunks(source), LIGHT_DEFINES);
}

/**
 * The GLSL sources, inlined at build time, with their chunks resolved. The calls are marked pure so
 * that a bundle which never constructs a renderer (only the scene format or the model classes)
 * drops this object and every shader string with it.
 */
export const shaderSources = {
  blurFragment: /* @__PURE__ */ withDefines(blurFragment, { MAX_BLUR_RADIUS }),
  debugFragment,
  /** The shadow records as outlines (the debug wireframe). */
  recordOutlinesVertex: /* @__PURE__ */ withDefines(recordsVertex, SHADOW_DEFINES),
  /** The shadow records as filled triangles (the hull mask). */
  filledRecordsVertex: /* @__PURE__ */ withDefines(recordsVertex, { ...SHADOW_DEFINES, FILLED: '' }),
  fullscreenVertex,
  lightVertex,
  lightPointFragment: /* @__PURE__ */ lightFragment(lightPointFragment),
  lightSpotFragment: /* @__PURE__ */ lightFragment(lightSpotFragment),
  lightTexturedFragment: /* @__PURE__ */ lightFragment(lightTexturedFragment),
  lightDirectionalFragment: /* @__PURE__ */ lightFragment(lightDirectionalFragment),
};

/** The hosts' surface helpers (docs/normal-maps.md): GLSL ES 3.00 functions to paste after a fragment shader's `#version` line. */
export const SURFACE_GLSL: string = /* @__PURE__ */ withDefines(surface, SURFACE_DEFINES);
