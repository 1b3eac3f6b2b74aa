import { DiskVisibility } from '../../src/geometry/diskVisibility';
import { createRandom } from '../reference/randomScenes';
import { SceneGeometry } from '../reference/sceneGeometry';
import type { Point, ReferenceLight, ReferenceScene } from '../reference/scenes';
import { visibleFraction } from '../reference/softShadowReference';

/** Random points of a scene, each at least `clearance` from every outline (where a rounding could flip a side). */
export function pointsOf(scene: ReferenceScene, geometry: SceneGeometry, count: number, seed: number, clearance = 1e-6): Point[] {
  const random = createRandom(seed);
  const points: Point[] = [];
  while (points.length < count) {
    const point: Point = [random() * scene.width, random() * scene.height];
    if (!geometry.isNearOutline(point[0], point[1], clearance)) points.push(point);
  }
  return points;
}

/** Whether a polygon (either winding) turns the same way at every point. */
function isConvex(points: readonly Point[]): boolean {
  const turns = points.map((a, i) => {
    const b = points[(i + 1) % points.length], c = points[(i + 2) % points.length];
    return Math.sign((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]));
  });
  return turns.every((turn) => turn >= 0) || turns.every((turn) => turn <= 0);
}

/** The fraction DiskVisibility gives at (px, py) for the light, with convex hulls taken whole by the shortcut or as edges. */
export function diskFraction(visibility: DiskVisibility, scene: ReferenceScene, px: number, py: number, { position: [cx, cy], radius }: ReferenceLight, shortcut: boolean): number {
  visibility.begin(px, py, cx, cy, radius);
  for (const hull of scene.hulls) visibility.addOutline(hull.flat(), hull.length, true, shortcut && isConvex(hull));
  // Without the shortcut, a polyline goes in as its edges one by one.
  for (const line of scene.polylines ?? []) {
    if (shortcut) visibility.addOutline(line.flat(), line.length, false);
    else for (let i = 0; i + 1 < line.length; i++) visibility.addEdge(...line[i], ...line[i + 1]);
  }
  return visibility.fraction();
}

/** What {@link compareWithSampling} found. */
export interface SamplingComparison {
  /** Largest |DiskVisibility − sampled| over both ways of adding hulls, and the mean without the shortcut. */
  worst: number;
  mean: number;
  evaluations: number;
  /** Fractions the sampling puts strictly inside (0.01, 0.99). */
  partial: number;
  /** Largest difference between the shortcut and the plain sweep. */
  shortcutGap: number;
}

/**
 * DiskVisibility, with and without the convex pieces' shortcut, against disk sampling with
 * `samples` sunflower points (no sampling at all when 0: then only the shortcut's gap is found), at
 * `points` random points of each scene outside its hulls, for each of its lights.
 */
export function compareWithSampling(scenes: readonly ReferenceScene[], samples: number, points: number): SamplingComparison {
  let worst = 0, sum = 0, evaluations = 0, partial = 0, shortcutGap = 0;
  const visibility = new DiskVisibility();
  for (const scene of scenes) {
    const geometry = new SceneGeometry(scene.hulls, scene.polylines);
    const sampled = samples > 0 ? visibleFraction(scene, { method: 'sampled', samples }) : undefined;
    for (const [px, py] of pointsOf(scene, geometry, points, 7)) {
      if (geometry.isInsideHull(px, py)) continue;
      for (const light of scene.lights) {
        const taken = diskFraction(visibility, scene, px, py, light, true), plain = diskFraction(visibility, scene, px, py, light, false);
        shortcutGap = Math.max(shortcutGap, Math.abs(taken - plain));
        evaluations++;
        if (!sampled) continue;
        const expected = sampled(px, py, light);
        worst = Math.max(worst, Math.abs(taken - expected), Math.abs(plain - expected));
        sum += Math.abs(plain - expected);
        if (expected > 0.01 && expected < 0.99) partial++;
      }
    }
  }
  return { worst, mean: sum / evaluations, evaluations, partial, shortcutGap };
}
