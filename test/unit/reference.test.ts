import { describe, expect, it } from 'vitest';
import { box, type Point, type ReferenceScene } from '../reference/scenes';
import { computeReference, LIT, PENUMBRA, UMBRA, visibleFraction, type ReferenceOptions } from '../reference/softShadowReference';

/**
 * The CPU references the renderer is tested against (test/gl/reference.test.ts,
 * test/gl/randomScenes.test.ts): the exact one must be right, or those tests prove nothing. Here,
 * cases whose visible fraction has a closed form of its own (areas of circular caps), for the exact
 * reference and for disk sampling, and the reference image's own rules. The exact reference
 * against disk sampling on every reference scene and random ones is test/accuracy/reference.test.ts;
 * the exact fraction (the CPU light query's) against disk sampling at random points is
 * test/unit/illumination.test.ts.
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

/** The fraction at one pixel centre, by `method` (see ReferenceOptions). */
function fractionAt(hulls: Point[][], pixel: Point, centre: Point, radius: number, options: Omit<ReferenceOptions, 'step'>): number {
  const scene: ReferenceScene = { name: 'one pixel', width: 1, height: 1, hulls, lights: [{ position: centre, range: 1000, radius }] };
  return visibleFraction(scene, options)(...pixel, scene.lights[0]);
}

describe('exact visible fraction, cases with a closed form', () => {
  for (const { name, hulls, pixel = P, centre = C, radius = R, expected } of ANALYTIC_CASES) {
    it(name, () => {
      // Rounding only: every piece is integrated in closed form.
      expect(Math.abs(fractionAt(hulls, pixel, centre, radius, { method: 'exact' }) - expected)).toBeLessThan(1e-12);
      // The sunflower pattern errs by about N^-3/4 for a disk cut by straight lines: 2.4e-4 at 65536 samples.
      expect(Math.abs(fractionAt(hulls, pixel, centre, radius, { method: 'sampled', samples: 65536 }) - expected)).toBeLessThan(1e-3);
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
