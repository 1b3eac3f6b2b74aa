import { readFileSync } from 'node:fs';
import { expect } from 'vitest';
import { readScene, SceneFormatError, type SceneDocument } from '../../src/index';
import { REFERENCE_SCENES } from '../reference/scenes';

/** The error `readScene` throws for `input`, failing the test unless it is a `SceneFormatError`. */
export function errorOf(input: unknown): SceneFormatError {
  try {
    readScene(input);
  } catch (error) {
    expect(error).toBeInstanceOf(SceneFormatError);
    return error as SceneFormatError;
  }
  throw new Error('readScene accepted a bad scene');
}

/** The worked example of docs/scene-format.md, as parsed JSON. */
export function docsExample(): unknown {
  const text = readFileSync(new URL('../../docs/scene-format.md', import.meta.url), 'utf8');
  return JSON.parse(/```json\n([\s\S]*?)```/.exec(text)![1]);
}

/** The reference scenes (test/reference/scenes.ts) as minimal scene files: convex, concave and round hulls. */
export function referenceDocuments(): unknown[] {
  return REFERENCE_SCENES.map((scene) => ({
    format: 'penumbra-scene', version: 1,
    hulls: scene.hulls.map((points) => ({ points })),
    lights: scene.lights.map((light) => ({ kind: 'point', ...light })),
  }));
}

/** A complete scene with every kind of light and every field set away from its default. */
export function fullScene(): SceneDocument {
  return {
    format: 'penumbra-scene',
    version: 3,
    ambient: [0.1, 0.2, 0.3],
    camera: { center: [120, -40], zoom: 1.5 },
    look: { exposure: 1.25, toneMapping: 'aces', dithering: 'noise', lightmapBlur: 3.5 },
    app: {},
    hulls: [
      { points: [[0, 0], [40, 0], [40, 30], [0, 30]], position: [200, 100], origin: [20, 15], rotation: 0.3, scale: [1, -2], enabled: true, closed: true, layers: 1 },
      { points: [[0, 0], [60, 0], [60, 20], [20, 20], [20, 60], [0, 60]], position: [400, 300], origin: [0, 0], rotation: 0, scale: [1, 1], enabled: false, closed: true, layers: 6 },
      { points: [[0, 0], [30, 10], [60, 0]], position: [100, 400], origin: [0, 0], rotation: 0, scale: [1, 1], enabled: true, closed: false, layers: 0xffffffff },
    ],
    lights: [
      {
        kind: 'point', position: [10, 20], range: 300, radius: 12, color: [1, 0.8, 0.6], intensity: 1.5, rotation: 0,
        origin: [0.5, 0.5], shadowType: 'solid', enabled: true, castsShadows: false, ignoredHulls: [1],
        shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, falloff: 'linear', height: null,
      },
      {
        kind: 'spot', position: [50, 60], range: 250, radius: 4, color: [0.5, 0.5, 1], intensity: 1, rotation: 1.2,
        origin: [0.5, 0.5], shadowType: 'illuminated', enabled: false, castsShadows: true, ignoredHulls: [],
        shadowLayers: 2, shadowColor: [0.2, 0.3, 0.6], shadowStrength: 0.75, litLayers: 6, falloff: 'smooth', height: 40, coneAngle: 0.9, coneDecay: 2,
      },
      {
        kind: 'textured', position: [70, 80], range: 200, radius: 8, color: [1, 0.6, 0.2], intensity: 2, rotation: -0.4,
        origin: [0.25, 0.75], shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [0, 1],
        shadowLayers: 0, shadowColor: [1, 1, 1], shadowStrength: 0, litLayers: 0, falloff: 'inverseSquare', height: null, cookie: 'flame', size: [160, 120],
      },
      {
        kind: 'directional', color: [1, 0.95, 0.8], intensity: 0.7, rotation: 2.1, shadowType: 'occluded', enabled: true,
        castsShadows: true, ignoredHulls: [2], shadowLayers: 5, shadowColor: [0.1, 0.1, 0.2], shadowStrength: 0.9, litLayers: 1, angularSize: 0.2, elevation: 0.6,
      },
    ],
  };
}
