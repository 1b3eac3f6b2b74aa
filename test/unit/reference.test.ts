import { afterAll, describe, expect, it } from 'vitest';
import { ExactVisibility } from '../reference/exactVisibility';
import { randomScene } from '../reference/randomScenes';
import { SceneGeometry } from '../reference/sceneGeometry';
import { REFERENCE_SCENES, box, type Point, type ReferenceScene } from '../reference/scenes';
import { computeReference, LIT, PENUMBRA, UMBRA, type ReferenceImage } from '../reference/softShadowReference';

/**
 * The CPU references the renderer is tested against (test/gl/reference.test.ts,
 * test/gl/randomScenes.test.ts): the exact one must be right, or those tests prove nothing.
 * Three independent checks:
 * - cases whose visible fraction has a closed form of its own (areas of circular caps);
 * - the exact closed forms against Gauss–Legendre quadrature of the same integrand, on every
 *   reference scene and some random ones;
 * - the exact reference against the disk-sampling one (SPEC §6 stated as plainly as possible) on
 *   the same scenes: this one shares no code with the exact integral but the segment tests.
 */

/** Area of the part of a disk of radius r beyond a line at signed distance h from its centre (h < 0: the larger part). */
const capArea = (r: number, h: number) => r * r * Math.acos(h / r) - h * Math.sqrt(r * r - h * h);

/** A pixel at the origin looking at a disk of radius 4 centred 20 to its right. */
const P: Point = [0, 0], C: Point = [20, 0], R = 4;
/** Area of that disk seen from P at angles above β (the line through P at angle β passes 20 sin β from C). */
const areaAbove = (beta: number) => capArea(R, 20 * Math.sin(beta));
/** A hull hiding from P exactly the directions in [from, to]: its long sides lie on those rays, between distances 8 and 9. */
const wedge = (from: number, to: number, near = 8, far = 9): Point[] => [
  [near * Math.cos(from), near * Math.sin(from)], [far * Math.cos(from), far * Math.sin(from)],
  [far * Math.cos(to), far * Math.sin(to)], [near * Math.cos(to), near * Math.sin(to)],
];

const ANALYTIC_CASES: { name: string; hulls: Point[][]; pixel?: Point; centre?: Point; radius?: number; expected: number }[] = [
  { name: 'no hull in the way', hulls: [box(0, 10, 20, 2)], expected: 1 },
  { name: 'the half of the disk below the axis hidden by a post between', hulls: [box(8, -10, 1, 10)], expected: 0.5 },
  {
    // The post's corner is on the ray at β: everything below it is hidden, the cap above is seen.
    name: 'a cap seen past a post corner', hulls: [[[8, 8 * Math.tan(0.075) - 10], [9, 8 * Math.tan(0.075) - 10], [9, 8 * Math.tan(0.075)], [8, 8 * Math.tan(0.075)]]],
    expected: areaAbove(0.075) / (Math.PI * R * R),
  },
  { name: 'a disk half inside a hull, nothing between', hulls: [box(20, -10, 10, 20)], expected: 0.5 },
  {
    name: 'two posts hiding overlapping slices (the union is hidden)', hulls: [wedge(-0.1, 0.05), wedge(0, 0.12, 12, 13)],
    expected: 1 - (areaAbove(-0.1) - areaAbove(0.12)) / (Math.PI * R * R),
  },
  {
    name: 'two posts hiding separate slices', hulls: [wedge(-0.15, -0.05, 12, 13), wedge(0.02, 0.1)],
    expected: 1 - (areaAbove(-0.15) - areaAbove(-0.05) + areaAbove(0.02) - areaAbove(0.1)) / (Math.PI * R * R),
  },
  {
    // From inside the disk, a wall 1 from the centre hides the cap beyond it and all behind it.
    name: 'a wall through the disk, seen from inside it', pixel: [0, 0], centre: [1, 0], radius: 3, hulls: [box(2, -10, 0.5, 20)],
    expected: 1 - capArea(3, 1) / (Math.PI * 9),
  },
  { name: 'hard light, post between', radius: 0, hulls: [box(8, -1, 1, 2)], expected: 0 },
  { name: 'hard light, post beside the segment', radius: 0, hulls: [box(8, 1, 1, 2)], expected: 1 },
];

/** The sampling reference of one pixel: a one-pixel scene whose pixel centre is `pixel`. */
function sampledFraction(hulls: Point[][], [px, py]: Point, centre: Point, radius: number, samples: number): number {
  const shift = (p: Point): Point => [p[0] - px + 0.5, p[1] - py + 0.5];
  const scene: ReferenceScene = {
    name: 'one pixel', width: 1, height: 1, hulls: hulls.map((h) => h.map(shift)),
    lights: [{ position: shift(centre), range: 1000, radius }],
  };
  return computeReference(scene, { method: 'sampled', samples }).visibility[0][0];
}

describe('exact visible fraction, cases with a closed form', () => {
  for (const { name, hulls, pixel = P, centre = C, radius = R, expected } of ANALYTIC_CASES) {
    it(name, () => {
      const geometry = new SceneGeometry(hulls);
      // Rounding only: every piece is integrated in closed form.
      const exact = new ExactVisibility(geometry).fraction(...pixel, ...centre, radius);
      expect(Math.abs(exact - expected)).toBeLessThan(1e-12);
      // Gauss–Legendre on the same pieces: smooth integrands, converged to rounding at 16 nodes.
      const quadrature = new ExactVisibility(geometry, { method: 'quadrature', nodes: 16 }).fraction(...pixel, ...centre, radius);
      expect(Math.abs(quadrature - expected)).toBeLessThan(1e-9);
      // The sunflower pattern errs by about N^-3/4 for a disk cut by straight lines: 2.4e-4 at 65536 samples.
      expect(Math.abs(sampledFraction(hulls, pixel, centre, radius, 65536) - expected)).toBeLessThan(1e-3);
    });
  }
});

/** Largest and mean |a − b| of the per-light visibilities over the pixels both computed that are not ambiguous. */
function difference(a: ReferenceImage, b: ReferenceImage): { max: number; mean: number; pixels: number } {
  let max = 0, sum = 0, pixels = 0;
  a.visibility.forEach((visibility, l) => {
    for (let i = 0; i < visibility.length; i++) {
      if (!a.inRange[i] || !b.inRange[i] || a.ambiguous[i]) continue;
      const d = Math.abs(visibility[i] - b.visibility[l][i]);
      max = Math.max(max, d);
      sum += d;
      pixels++;
    }
  });
  return { max, mean: pixels ? sum / pixels : 0, pixels };
}

/** Every fixed reference scene, and random scenes (overlapping hulls, tile rows, disks overlapping hulls). */
const SCENES: readonly ReferenceScene[] = [
  ...REFERENCE_SCENES,
  ...Array.from({ length: 12 }, (_, i) => randomScene(0x5eed + i, 80, 60)),
];

describe('exact reference against quadrature and against disk sampling', () => {
  const worst = { quadrature: 0, samplingMax: 0, samplingMean: 0 };
  afterAll(() => {
    console.log(`exact reference vs quadrature: max ${worst.quadrature.toExponential(1)}; `
      + `vs disk sampling: max ${worst.samplingMax.toExponential(1)}, largest scene mean ${worst.samplingMean.toExponential(1)}`);
  });

  for (const scene of SCENES) {
    it(scene.name, () => {
      const exact = computeReference(scene);
      // Quadrature of the same integrand: the pieces next to a hull edge that runs from near the
      // pixel into the disk are sharply peaked (1 / cos² of the angle to the edge), and 64 nodes
      // are needed there to reach rounding; the visibilities are stored as float32 (6e-8).
      const quadrature = computeReference(scene, { method: 'quadrature', nodes: 64, step: 3 });
      const byQuadrature = difference(exact, quadrature);
      expect(byQuadrature.pixels).toBeGreaterThan(0);
      expect(byQuadrature.max).toBeLessThan(1e-6);
      // Disk sampling (16384 sunflower points, every fifth pixel each way): its own error is about
      // N^-3/4 = 7e-4 per straight cut across the disk, up to 1.3e-3 measured where several hulls
      // cut it; over a scene's pixels it averages at most 1.4e-4 (where a disk overlaps a hull,
      // every pixel in range is in penumbra).
      const sampled = computeReference(scene, { method: 'sampled', samples: 16384, step: 5 });
      const bySampling = difference(exact, sampled);
      worst.quadrature = Math.max(worst.quadrature, byQuadrature.max);
      worst.samplingMax = Math.max(worst.samplingMax, bySampling.max);
      worst.samplingMean = Math.max(worst.samplingMean, bySampling.mean);
      expect(bySampling.max).toBeLessThan(1.5e-3);
      expect(bySampling.mean).toBeLessThan(2e-4);
    });
  }
});

describe('reference image', () => {
  it('keeps hull insides dark, also where a disk overlaps the hull, and adds lights up', () => {
    const scene: ReferenceScene = {
      name: 'two lights, one disk half inside a crate', width: 40, height: 20, hulls: [box(20, 0, 10, 10)],
      lights: [{ position: [20, 15], range: 30, radius: 8 }, { position: [5, 5], range: 20, radius: 0, color: [0, 1, 0] }],
    };
    const reference = computeReference(scene);
    const at = (x: number, y: number) => y * scene.width + x;
    // Pixel (22, 8) is inside the crate and sees the part of the first disk inside it without crossing an edge.
    expect(reference.visibility[0][at(22, 8)]).toBe(0);
    expect(reference.shade[at(22, 8)]).toBe(UMBRA);
    expect(Array.from(reference.light.subarray(at(22, 8) * 3, at(22, 8) * 3 + 3))).toEqual([0, 0, 0]);
    // Next to the first light, left of the crate: both lights reach it, the first in part.
    const pixel = at(12, 12);
    const falloff0 = 1 - Math.hypot(12.5 - 20, 12.5 - 15) / 30, falloff1 = 1 - Math.hypot(12.5 - 5, 12.5 - 5) / 20;
    expect(reference.visibility[0][pixel]).toBeGreaterThan(0.5);
    expect(reference.visibility[0][pixel]).toBeLessThan(1);
    expect(reference.visibility[1][pixel]).toBe(1);
    expect(reference.shade[pixel]).toBe(PENUMBRA);
    expect(reference.light[pixel * 3]).toBeCloseTo(falloff0 * reference.visibility[0][pixel], 6);
    expect(reference.light[pixel * 3 + 1]).toBeCloseTo(falloff0 * reference.visibility[0][pixel] + falloff1, 6);
    // The part of the first disk inside the crate is hidden from every pixel outside it.
    expect(Math.max(...reference.visibility[0])).toBeLessThan(1);
    expect(reference.shade.includes(LIT)).toBe(false);
  });

  it('marks pixel centres on a hull outline and on a hard shadow edge as ambiguous', () => {
    const scene: ReferenceScene = {
      name: 'outline through pixel centres', width: 20, height: 20, hulls: [box(5.5, 5.5, 4, 4)],
      lights: [{ position: [0.5, 0.5], range: 40, radius: 0 }],
    };
    const reference = computeReference(scene);
    expect(reference.ambiguous[5 * 20 + 7]).toBe(1); // on the top edge
    expect(reference.ambiguous[12 * 20 + 12]).toBe(1); // on the diagonal through the corner (5.5, 5.5)
    expect(reference.ambiguous[12 * 20 + 13]).toBe(0);
  });
});
