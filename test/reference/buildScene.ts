import { DirectionalLight, Hull, PenumbraRenderer, PointLight, ShadowType } from '../../src/index';
import type { DirectionalReferenceScene } from './directionalReference';
import type { Point, ReferenceScene } from './scenes';

/**
 * A renderer set up for a reference scene: ambient black and the scene's shadow type (Solid by
 * default), so the lightmap is exactly Σ falloff × visible fraction × colour × intensity over the
 * lights everywhere, hull interiors included (the reference keeps them dark, as Solid does, or lit
 * where the light reaches them, as Occluded does). Shared by the headless-gl
 * tests and the Chromium page.
 */
export function createSceneRenderer(gl: WebGL2RenderingContext, scene: ReferenceScene): PenumbraRenderer {
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], width: scene.width, height: scene.height });
  setScene(renderer, scene);
  return renderer;
}

/**
 * Replaces every light and hull of `renderer` with the scene's (new objects each time), so one
 * renderer can render many scenes of its size in turn.
 */
export function setScene(renderer: PenumbraRenderer, scene: ReferenceScene): void {
  for (const light of [...renderer.lights]) renderer.removeLight(light);
  for (const hull of [...renderer.hulls]) renderer.removeHull(hull);
  const shadowType = SHADOW_TYPES[scene.shadowType ?? 'solid'];
  for (const { position, range, radius, color, intensity } of scene.lights) {
    renderer.addLight(new PointLight({ position, range, radius, color, intensity, shadowType }));
  }
  for (const points of scene.hulls) renderer.addHull(new Hull(points));
  for (const points of scene.polylines ?? []) renderer.addHull(new Hull(points, { closed: false }));
}

const SHADOW_TYPES = { solid: ShadowType.Solid, illuminated: ShadowType.Illuminated, occluded: ShadowType.Occluded } as const;

/**
 * A renderer set up for a directional reference scene: ambient black, the scene's sun and shadow
 * type, each hull placed at its centre, so its coarse bounds (around its position) are as tight as
 * its points': the search for hulls upstream, not a loose box, must find the far ones.
 */
export function createDirectionalSceneRenderer(gl: WebGL2RenderingContext, scene: DirectionalReferenceScene): PenumbraRenderer {
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], width: scene.width, height: scene.height });
  for (const points of scene.hulls) renderer.addHull(centredHull(points));
  for (const points of scene.polylines ?? []) renderer.addHull(new Hull(points, { closed: false }));
  const { rotation, angularSize, color, intensity } = scene.light;
  renderer.addLight(new DirectionalLight({ rotation, angularSize, color, intensity, shadowType: SHADOW_TYPES[scene.shadowType] }));
  return renderer;
}

function centredHull(points: readonly Point[]): Hull {
  const cx = points.reduce((sum, p) => sum + p[0], 0) / points.length, cy = points.reduce((sum, p) => sum + p[1], 0) / points.length;
  return new Hull(points.map(([x, y]): Point => [x - cx, y - cy]), { position: [cx, cy] });
}

/** Lightmap texels (RGBA, rows bottom-up as GL reads them) → RGB rows top-down as the world is laid out. */
export function lightmapToWorldRows(texels: ArrayLike<number>, width: number, height: number): Float32Array {
  const rgb = new Float32Array(width * height * 3);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const texel = ((height - 1 - y) * width + x) * 4;
      const pixel = (y * width + x) * 3;
      rgb[pixel] = texels[texel];
      rgb[pixel + 1] = texels[texel + 1];
      rgb[pixel + 2] = texels[texel + 2];
    }
  }
  return rgb;
}
