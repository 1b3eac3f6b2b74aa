import { SceneGeometry } from './sceneGeometry';
import { box, type Point, type ReferenceScene } from './scenes';
import { computeReference, diskSamples, DISK_SAMPLES, LIT, PENUMBRA, shareOfSamplesSeen, UMBRA, type ReferenceImage } from './softShadowReference';

/**
 * The ground truth for Occluded lights (`ShadowType.Occluded`), by disk sampling, with none of the
 * renderer's math. Pixel centres outside hulls are as in {@link computeReference}. A pixel centre
 * inside hulls (its holders) sees a disk point when their segment crosses no edge of a hull that
 * does not hold it and no edge of a holder that faces the pixel (the pixel strictly on the edge's
 * outer side): the segment leaves each holder once, and a facing edge is where it would enter one
 * again.
 *
 * Accuracy: the sampling's, about 2e-3 of full light for 4,096 samples (see DISK_SAMPLES).
 */
export function computeOccludedReference(scene: ReferenceScene, samples = DISK_SAMPLES): ReferenceImage {
  const reference = computeReference(scene);
  const { width, height } = scene;
  const lightSamples = scene.lights.map((light) => diskSamples(light.position[0], light.position[1], light.radius, samples));
  const outlines = scene.hulls.map((hull) => Float64Array.from(hull.flat()));
  const geometry = new SceneGeometry(scene.hulls);
  const edges = new Float64Array(4 * scene.hulls.reduce((sum, hull) => sum + hull.length, 0));
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const px = x + 0.5, py = y + 0.5, pixel = y * width + x;
      if (!geometry.isInsideHull(px, py)) continue;
      const edgeFloats = writeEdgesSeenFromInside(outlines, px, py, edges);
      let all = true, none = true;
      for (let c = 0; c < 3; c++) reference.light[pixel * 3 + c] = 0;
      scene.lights.forEach((light, l) => {
        const falloff = Math.max(0, 1 - Math.hypot(px - light.position[0], py - light.position[1]) / light.range);
        if (falloff === 0) return;
        const fraction = shareOfSamplesSeen(px, py, lightSamples[l], edges, edgeFloats);
        reference.visibility[l][pixel] = fraction;
        if (fraction !== 1) all = false;
        if (fraction !== 0) none = false;
        const color = light.color ?? [1, 1, 1], intensity = light.intensity ?? 1;
        for (let c = 0; c < 3; c++) reference.light[pixel * 3 + c] += falloff * fraction * color[c] * intensity;
      });
      reference.shade[pixel] = all ? LIT : none ? UMBRA : PENUMBRA;
    }
  }
  return reference;
}

/**
 * Writes every edge of the hulls that do not hold (px, py) and the edges of those that do facing
 * it into `edges`; returns the floats written.
 */
export function writeEdgesSeenFromInside(outlines: readonly Float64Array[], px: number, py: number, edges: Float64Array): number {
  let floats = 0;
  outlines.forEach((outline) => {
    const count = outline.length / 2;
    const winding = Math.sign(signedArea(outline)), holds = contains(outline, px, py);
    for (let i = 0; i < count; i++) {
      const j = (i + 1) % count;
      const ax = outline[2 * i], ay = outline[2 * i + 1], bx = outline[2 * j], by = outline[2 * j + 1];
      // The cross product's sign times the winding's is negative on the outer side.
      const outer = ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) * winding < 0;
      if (holds && !outer) continue;
      edges.set([ax, ay, bx, by], floats);
      floats += 4;
    }
  });
  return floats;
}

/** Whether (px, py) lies inside `outline` (even-odd). */
function contains(outline: Float64Array, px: number, py: number): boolean {
  let inside = false;
  const count = outline.length / 2;
  for (let i = 0, j = count - 1; i < count; j = i++) {
    const ax = outline[2 * i], ay = outline[2 * i + 1], bx = outline[2 * j], by = outline[2 * j + 1];
    if ((ay > py) !== (by > py) && px < ax + ((py - ay) * (bx - ax)) / (by - ay)) inside = !inside;
  }
  return inside;
}

function signedArea(outline: Float64Array): number {
  let twice = 0;
  const count = outline.length / 2;
  for (let i = 0, j = count - 1; i < count; j = i++) twice += outline[2 * j] * outline[2 * i + 1] - outline[2 * i] * outline[2 * j + 1];
  return twice / 2;
}

/** A U-shaped outline opening towards −y (in the scenes' y-down rows: upwards): arms `arm` wide, `depth` deep from the top. */
export function uShape(x: number, y: number, width: number, height: number, arm: number, depth: number): Point[] {
  return [
    [x, y], [x + arm, y], [x + arm, y + depth], [x + width - arm, y + depth], [x + width - arm, y],
    [x + width, y], [x + width, y + height], [x, y + height],
  ];
}

const WIDTH = 160, HEIGHT = 120;
const scene = (name: string, lights: ReferenceScene['lights'], hulls: ReferenceScene['hulls']): ReferenceScene => ({ name, width: WIDTH, height: HEIGHT, lights, hulls, shadowType: 'occluded' });

/** Scenes of Occluded lights, each with hull pixels that are lit and (but two) some that are not. */
export const OCCLUDED_SCENES: ReferenceScene[] = [
  scene('a crate behind a wall is dark where the wall\'s shadow falls on it', [{ position: [30, 60], range: 160, radius: 6 }],
    [box(60, 40, 8, 36), box(100, 34, 24, 24), box(100, 84, 16, 16)]),
  scene('a U-shaped building shades its far arm from a light beside it', [{ position: [22, 44], range: 170, radius: 5 }],
    [uShape(56, 30, 70, 56, 14, 32)]),
  scene('a U-shaped building lit into its yard shades nothing of itself from there', [{ position: [91, 40], range: 120, radius: 4 }],
    [uShape(56, 30, 70, 56, 14, 32)]),
  scene('a convex hull never shades itself, and a hard light gives hard edges on the hull behind', [{ position: [20, 100], range: 200, radius: 0 }],
    [[[50, 70], [70, 62], [84, 74], [78, 94], [56, 96]], box(100, 20, 40, 60)]),
  scene('a torch whose disk reaches into an L-shaped hull lights the hull from the part of the disk inside it', [{ position: [66, 47], range: 110, radius: 9 }],
    [[[40, 30], [56, 30], [56, 54], [110, 54], [110, 70], [40, 70]]]),
  scene('two lights on both sides of a row of crates', [{ position: [20, 30], range: 150, radius: 4, color: [1, 0.6, 0.3] }, { position: [140, 100], range: 150, radius: 7, color: [0.3, 0.6, 1] }],
    [box(50, 50, 14, 14), box(72, 56, 14, 14), box(94, 62, 14, 14), uShape(40, 82, 40, 26, 10, 14)]),
];

/** A regular hexagon around (cx, cy) of circumradius r, turned by `turn` radians. */
export function hexagon(cx: number, cy: number, r: number, turn = 0): Point[] {
  return Array.from({ length: 6 }, (_, i) => [cx + r * Math.cos(turn + (i * Math.PI) / 3), cy + r * Math.sin(turn + (i * Math.PI) / 3)] as Point);
}

/**
 * Occluded scenes whose hulls overlap: a pixel inside several is lit as from inside all of them,
 * whatever their order (each scene also lists its hulls in reverse).
 */
export const OVERLAPPING_OCCLUDED_SCENES: ReferenceScene[] = [
  scene('two overlapping convex hexagons', [{ position: [24, 58], range: 170, radius: 6 }],
    [hexagon(70, 60, 24, 0.2), hexagon(96, 64, 26, 0.5)]),
  scene('a convex hexagon over the far arm of a U-shaped building', [{ position: [22, 44], range: 170, radius: 5 }],
    [uShape(56, 30, 70, 56, 14, 32), hexagon(118, 50, 18, 0.3)]),
  scene('two overlapping U-shaped buildings, one turned over', [{ position: [20, 100], range: 190, radius: 7 }],
    [uShape(40, 24, 70, 56, 14, 32), uShape(70, 46, 66, 50, 12, 30).map(([x, y]) => [x, 142 - y] as Point)]),
].flatMap((forward) => [forward, { ...forward, name: `${forward.name} (listed in reverse)`, hulls: [...forward.hulls].reverse() }]);
