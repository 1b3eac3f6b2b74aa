import compositeFragment from '../../shaders/composite.frag.glsl?raw';
import debugFragment from '../../shaders/debug.frag.glsl?raw';
import fullscreenVertex from '../../shaders/fullscreen.vert.glsl?raw';
import hullFragment from '../../shaders/hull.frag.glsl?raw';
import hullVertex from '../../shaders/hull.vert.glsl?raw';
import lightCommon from '../../shaders/chunks/light-common.glsl?raw';
import lightPointFragment from '../../shaders/light-point.frag.glsl?raw';
import lightSpotFragment from '../../shaders/light-spot.frag.glsl?raw';
import lightTexturedFragment from '../../shaders/light-textured.frag.glsl?raw';
import lightVertex from '../../shaders/light.vert.glsl?raw';
import shadowCommon from '../../shaders/chunks/shadow-common.glsl?raw';
import shadowCavityFragment from '../../shaders/shadow-cavity.frag.glsl?raw';
import shadowEdgesFragment from '../../shaders/shadow-edges.frag.glsl?raw';
import shadowHullFragment from '../../shaders/shadow-hull.frag.glsl?raw';
import shadowMaskVertex from '../../shaders/shadow-mask.vert.glsl?raw';
import shadowUmbraFragment from '../../shaders/shadow-umbra.frag.glsl?raw';
import { VARYING_POINT_COUNTS } from '../geometry/FramePlan';
import { resolveIncludes, withDefines } from '../gl/program';

const chunks = { 'light-common': lightCommon, 'shadow-common': shadowCommon };

/**
 * A shadow-mask stage built once per size class (see `VARYING_POINT_COUNTS`): with the hull's points
 * in `VARYING_POINTS` varyings, then, for hulls of any size, read from the points texture. Both
 * stages of a program must be of the same class.
 */
function shadowStage(source: string, defines: Readonly<Record<string, string>> = {}): readonly string[] {
  const resolved = resolveIncludes(source, chunks);
  return [...VARYING_POINT_COUNTS.map((count) => withDefines(resolved, { ...defines, VARYING_POINTS: count })), withDefines(resolved, defines)];
}

/** A light pass's fragment stage for a light without a shadow mask, and with one (`SHADOWED`). */
function lightStage(source: string): { unshadowed: string; shadowed: string } {
  const resolved = resolveIncludes(source, chunks);
  return { unshadowed: resolved, shadowed: withDefines(resolved, { SHADOWED: '' }) };
}

/** The GLSL sources, inlined at build time, with their chunks resolved. */
export const shaderSources = {
  compositeFragment,
  debugFragment,
  fullscreenVertex,
  hullFragment,
  hullVertex,
  lightVertex,
  lightPointFragment: lightStage(lightPointFragment),
  lightSpotFragment: lightStage(lightSpotFragment),
  lightTexturedFragment: lightStage(lightTexturedFragment),
  rangeCutoutVertex: withDefines(lightVertex, { NEAREST_DEPTH: '' }),
  shadowCavityFragment: shadowStage(shadowCavityFragment),
  shadowConcaveFragment: shadowStage(shadowHullFragment, { CONCAVE_HULL: '' }),
  shadowEdgesFragment: shadowStage(shadowEdgesFragment),
  shadowHullFragment: shadowStage(shadowHullFragment),
  shadowMaskVertex: shadowStage(shadowMaskVertex),
  shadowUmbraFragment,
};
