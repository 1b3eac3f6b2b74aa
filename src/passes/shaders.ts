import compositeFragment from '../../shaders/composite.frag.glsl?raw';
import debugFragment from '../../shaders/debug.frag.glsl?raw';
import debugRecordsVertex from '../../shaders/debug-records.vert.glsl?raw';
import fullscreenVertex from '../../shaders/fullscreen.vert.glsl?raw';
import lightCommon from '../../shaders/chunks/light-common.glsl?raw';
import lightPointFragment from '../../shaders/light-point.frag.glsl?raw';
import lightSpotFragment from '../../shaders/light-spot.frag.glsl?raw';
import lightTexturedFragment from '../../shaders/light-textured.frag.glsl?raw';
import lightVertex from '../../shaders/light.vert.glsl?raw';
import shadowVisibility from '../../shaders/chunks/shadow-visibility.glsl?raw';
import { SHADOW_DEFINES } from '../geometry/shadowLayout';
import { resolveIncludes, withDefines } from '../gl/program';

/** Chunks may include chunks: light-common includes shadow-visibility. */
function resolveChunks(source: string): string {
  const chunks = { 'light-common': lightCommon, 'shadow-visibility': shadowVisibility };
  return resolveIncludes(resolveIncludes(source, chunks), chunks);
}

/** A light pass's fragment stage for a light with no hull in range, and with some (`SHADOWED`). */
function lightStage(source: string): { unshadowed: string; shadowed: string } {
  const resolved = resolveChunks(source);
  return { unshadowed: resolved, shadowed: withDefines(resolved, { SHADOWED: '', ...SHADOW_DEFINES }) };
}

/** The GLSL sources, inlined at build time, with their chunks resolved. */
export const shaderSources = {
  compositeFragment,
  debugFragment,
  debugRecordsVertex: withDefines(debugRecordsVertex, SHADOW_DEFINES),
  fullscreenVertex,
  lightVertex,
  lightPointFragment: lightStage(lightPointFragment),
  lightSpotFragment: lightStage(lightSpotFragment),
  lightTexturedFragment: lightStage(lightTexturedFragment),
};
