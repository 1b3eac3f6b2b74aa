import type { Light, PenumbraRenderer } from '../../src/index';
import type { Illumination, IlluminationOptions } from '../../src/scene/illumination';
import { renderLightmap, type Lightmap } from '../gl/lightmap';
import { SceneGeometry } from './sceneGeometry';
import type { Point, ReferenceScene } from './scenes';
import { HARD_EDGE_BAND, OUTLINE_BAND } from './softShadowReference';

/**
 * `renderer.illuminationAt` against the lightmap the same renderer renders, at pixel centres.
 * Plain WebGL2 and no test framework: used by the headless-gl test (test/gl/illumination.test.ts)
 * and, on Chromium's own JS and WebGL, by the reference page (test/browser/reference-page).
 */

/**
 * Largest difference allowed in a channel, in units of full light. The render and the query share
 * the light model; what is left is the GPU's rounding (float32 math, a half-float lightmap with
 * steps of about 5e-4 near 1): at most about 5e-3 on headless-gl, and up to about 0.017 on
 * Chromium's SwiftShader, where the lightmap is that far from the exact CPU reference itself at a
 * few penumbra pixels (test/browser/reference.test.ts shows the same maxima).
 */
export const MAX_DIFFERENCE = 0.02;

/** What a comparison leaves out, besides pixels no light reaches. */
export interface Exclusions {
  /** Hull outlines (world points) and open polylines. */
  geometry: SceneGeometry;
  /** Centres of the radius-0 lights (hard shadow edges). */
  hardCentres: readonly Point[];
  /** Any other pixel centre to leave out. */
  other?: (x: number, y: number) => boolean;
}

/** The result of one comparison. */
export interface IlluminationComparison {
  /** Pixel centres compared that some light reaches (every unambiguous pixel is compared). */
  points: number;
  /** Largest difference in a channel over every pixel compared. */
  max: number;
  /** 99th percentile, over the points some light reaches, of each point's largest channel difference. */
  p99: number;
  /** Where `max` is, with both values. */
  worst: string;
}

/**
 * Compares `illuminationAt` with the lightmap at every pixel centre that is not ambiguous (see
 * {@link isAmbiguous}); the lightmap must be the renderer's, rendered since its last change.
 */
export function compareWithLightmap(
  renderer: PenumbraRenderer, lightmap: Lightmap, exclusions: Exclusions, options: IlluminationOptions = {},
): IlluminationComparison {
  const out: Illumination = { color: [0, 0, 0], luminance: 0, lights: [] };
  const litDifferences: number[] = [];
  let max = 0, worst = '';
  for (let y = 0; y < lightmap.height; y++) {
    for (let x = 0; x < lightmap.width; x++) {
      const px = x + 0.5, py = y + 0.5;
      if (isAmbiguous(exclusions, px, py)) continue;
      const result = renderer.illuminationAt(px, py, options, out);
      const rendered = lightmap.at(x, y);
      let pointMax = 0;
      for (let c = 0; c < 3; c++) pointMax = Math.max(pointMax, Math.abs(result.color[c] - rendered[c]));
      // Every pixel is compared (a light wrongly left out shows as a difference); those some light reaches are counted.
      if (result.lights.length > 0) litDifferences.push(pointMax);
      if (pointMax > max) {
        max = pointMax;
        worst = `at (${px}, ${py}): ${result.color.map((v) => v.toFixed(4))} vs ${rendered.map((v) => v.toFixed(4))}`;
      }
    }
  }
  return { points: litDifferences.length, max, p99: percentile(litDifferences, 0.99), worst };
}

/**
 * Renders the lightmap of `renderer`, which holds `scene` as `createSceneRenderer` or `setScene`
 * (./buildScene.ts) build it, on `gl` (its context, of the scene's size), and compares
 * `illuminationAt` with it, per light (`perLight: true`, so the points some light reaches are
 * known). `glError` is the context's error after the render and read-back.
 */
export function compareReferenceScene(
  gl: WebGL2RenderingContext, renderer: PenumbraRenderer, scene: ReferenceScene,
): IlluminationComparison & { glError: number } {
  const lightmap = renderLightmap(gl, renderer, scene.width, scene.height);
  const glError = gl.getError();
  return { ...compareWithLightmap(renderer, lightmap, sceneExclusions(scene, renderer.lights), { perLight: true }), glError };
}

/** The exclusions of a scene built from `scene` (its hulls and polylines) with `lights`. */
export function sceneExclusions(scene: ReferenceScene, lights: readonly Light[]): Exclusions {
  return { geometry: new SceneGeometry(scene.hulls, scene.polylines), hardCentres: hardCentres(lights) };
}

export const hardCentres = (lights: readonly Light[]): Point[] => lights.filter((light) => light.radius === 0).map((light) => [light.position[0], light.position[1]]);

/**
 * Left out, as the reference tests leave them out: pixel centres within 1/16 pixel of a hull
 * outline or of a hard shadow's edge, where the rasterizer's snapping decides
 * (test/reference/softShadowReference), and whatever `other` leaves out.
 */
function isAmbiguous({ geometry, hardCentres, other }: Exclusions, x: number, y: number): boolean {
  if (geometry.isNearOutline(x, y, OUTLINE_BAND)) return true;
  for (const [lx, ly] of hardCentres) if (nearHardEdge(geometry, x, y, lx, ly)) return true;
  return other?.(x, y) ?? false;
}

/** Whether (x, y) lies within HARD_EDGE_BAND of a ray from (lx, ly) through a hull point between them (as the reference's test). */
function nearHardEdge(geometry: SceneGeometry, x: number, y: number, lx: number, ly: number): boolean {
  const v = geometry.vertices;
  const dx = x - lx, dy = y - ly, length2 = dx * dx + dy * dy;
  for (let i = 0; i < v.length; i += 2) {
    const vx = v[i] - lx, vy = v[i + 1] - ly, along = vx * dx + vy * dy;
    if (along <= 0 || along > length2) continue;
    if (Math.abs(vx * dy - vy * dx) < HARD_EDGE_BAND * Math.hypot(vx, vy)) return true;
  }
  return false;
}

/** The `q` quantile of `values` (nearest rank); 0 for none. Sorts `values`. */
function percentile(values: number[], q: number): number {
  if (values.length === 0) return 0;
  values.sort((a, b) => a - b);
  return values[Math.min(values.length - 1, Math.ceil(q * values.length) - 1)];
}
