import { describe, expect, it } from 'vitest';
import { isInsidePolygon, isSimplePolygon, segmentsIntersect, signedArea2, simplifyPolygon, triangulate } from '../../src/geometry/polygon';
import { Hull } from '../../src/index';

/** A seeded generator of floats in [0, 1) (mulberry32), so a failure reproduces. */
function random(seed: number): () => number {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * The definition of a simple polygon, checked pair by pair: at least 3 points, non-zero area,
 * edges that are not neighbours share no point, and neighbours share only their common end point.
 */
function isSimpleByDefinition(c: number[]): boolean {
  const n = c.length >> 1;
  if (n < 3 || signedArea2(c) === 0) return false;
  const edge = (i: number) => [c[2 * i], c[2 * i + 1], c[2 * ((i + 1) % n)], c[2 * ((i + 1) % n) + 1]] as const;
  for (let i = 0; i < n; i++) {
    for (let j = i + 1; j < n; j++) {
      const [ax, ay, bx, by] = edge(i), [cx, cy, dx, dy] = edge(j);
      if (j === i + 1 || (i === 0 && j === n - 1)) {
        // Neighbours: the far end of one must not lie on the other, nor may they fold back onto each other.
        const [px, py, sx, sy, qx, qy] = j === i + 1 ? [ax, ay, bx, by, dx, dy] : [cx, cy, ax, ay, bx, by];
        const cross = (sx - px) * (qy - py) - (sy - py) * (qx - px);
        const dot = (px - sx) * (qx - sx) + (py - sy) * (qy - sy);
        if ((px === qx && py === qy) || (cross === 0 && dot > 0)) return false;
      } else if (segmentsIntersect(ax, ay, bx, by, cx, cy, dx, dy)) return false;
    }
  }
  return true;
}

/** A star of `count` points at radii 1–4 rounded to whole numbers; with a chance of a third, two points swapped. */
function roundedStar(count: number, next: () => number): number[] {
  const coords: number[] = [];
  for (let i = 0; i < count; i++) {
    const angle = (2 * Math.PI * (i + next() * 0.8)) / count, radius = 1 + Math.floor(next() * 4);
    coords.push(Math.round(radius * Math.cos(angle)), Math.round(radius * Math.sin(angle)));
  }
  if (next() < 1 / 3) {
    const i = Math.floor(next() * count), j = Math.floor(next() * count);
    [coords[2 * i], coords[2 * i + 1], coords[2 * j], coords[2 * j + 1]] = [coords[2 * j], coords[2 * j + 1], coords[2 * i], coords[2 * i + 1]];
  }
  return coords;
}

/** A star-shaped polygon of `count` points at random radii around the origin: simple, concave, counter-clockwise. */
function star(count: number, next: () => number): number[] {
  const coords: number[] = [];
  for (let i = 0; i < count; i++) {
    const angle = (2 * Math.PI * i) / count, radius = 50 + 50 * next();
    coords.push(radius * Math.cos(angle), radius * Math.sin(angle));
  }
  return coords;
}

/** A comb of `teeth` long notches cut down from its top edge: half its points are reflex, and its ears are long slivers. */
function comb(teeth: number): number[] {
  const width = 2 * teeth + 2;
  const coords = [0, 0, width, 0, width, 100];
  for (let i = teeth - 1; i >= 0; i--) coords.push(2 * i + 2, 100, 2 * i + 2, 1, 2 * i + 1, 1, 2 * i + 1, 100);
  coords.push(0, 100);
  return coords;
}

/** Checks that `triangles` tile the counter-clockwise polygon `coords`: n − 2 triangles, each turning left, inside, summing to its area. */
function expectTriangulation(coords: number[], triangles: number[]): void {
  const n = coords.length >> 1;
  expect(triangles.length).toBe(3 * (n - 2));
  let area = 0;
  const wrong: string[] = [];
  for (let t = 0; t < triangles.length; t += 3) {
    const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
    const triangle = [coords[2 * a], coords[2 * a + 1], coords[2 * b], coords[2 * b + 1], coords[2 * c], coords[2 * c + 1]];
    const twice = signedArea2(triangle);
    if (!(twice > 0)) wrong.push(`triangle ${t / 3} turns right or is flat`);
    area += twice;
    const centroid = [(triangle[0] + triangle[2] + triangle[4]) / 3, (triangle[1] + triangle[3] + triangle[5]) / 3];
    if (!isInsidePolygon(coords, centroid)) wrong.push(`triangle ${t / 3} lies outside`);
  }
  expect(wrong).toEqual([]);
  expect(area).toBeCloseTo(signedArea2(coords), 6);
}

describe('polygon validity and triangulation at scale', () => {
  // Points on a small grid: touching vertices, collinear overlaps and folds back are common. Up to
  // 8 points isSimplePolygon tests pairs, from 9 on it sweeps: both ranges are checked, the larger
  // with stars rounded to the grid (random points that many are almost never simple), two of their
  // points swapped one time in three.
  it.each([
    { points: '3–8', fewest: 3, most: 8, seed: 14 },
    { points: '9–14', fewest: 9, most: 14, seed: 15 },
  ])('agrees with the pairwise definition of a simple polygon on small random outlines of $points points', ({ fewest, most, seed }) => {
    const next = random(seed);
    let simple = 0;
    for (let trial = 0; trial < 3000; trial++) {
      const count = fewest + Math.floor(next() * (most - fewest + 1));
      const coords = count <= 8 ? Array.from({ length: 2 * count }, () => Math.floor(next() * 5)) : roundedStar(count, next);
      const expected = isSimpleByDefinition(coords);
      if (isSimplePolygon(coords) !== expected) throw new Error(`isSimplePolygon(${JSON.stringify(coords)}) should be ${expected}`);
      if (expected) simple++;
    }
    expect(simple).toBeGreaterThan(300);
  });

  it('rejects an outline that folds back along itself', () => {
    // A square with a spike: (10, 5) → (15, 5) → (12, 5) → (10, 6) runs back along its own edge.
    expect(isSimplePolygon([0, 0, 10, 0, 10, 5, 15, 5, 12, 5, 10, 6, 10, 10, 0, 10])).toBe(false);
  });

  it('triangulates random concave polygons into triangles that tile them', () => {
    const next = random(7);
    for (let trial = 0; trial < 200; trial++) {
      const coords = simplifyPolygon(star(4 + Math.floor(next() * 60), next));
      expectTriangulation(coords, triangulate(coords));
    }
    const teeth = simplifyPolygon(comb(40));
    expect(isSimplePolygon(teeth)).toBe(true);
    expectTriangulation(teeth, triangulate(teeth));
  });

  it('removes long runs of collinear points in one pass', () => {
    const side = Array.from({ length: 5000 }, (_, i) => [i, 0]).flat();
    const square = [...side, 5000, 0, 5000, 5000, 0, 5000];
    expect(simplifyPolygon(square)).toEqual([0, 0, 5000, 0, 5000, 5000, 0, 5000]);
  });

  // What these cost is measured by `npm run bench:hulls`, not here.
  it.each([
    ['a 20,000-point star', () => star(20_000, random(3))],
    ['a comb of 5,000 teeth (20,000 points)', () => comb(5_000)],
  ])('validates and triangulates %s into triangles of its area', (_name, make) => {
    const coords = make();
    expect(new Hull(Array.from({ length: coords.length >> 1 }, (_, i) => [coords[2 * i], coords[2 * i + 1]] as [number, number])).valid).toBe(true);
    const outline = simplifyPolygon(coords), triangles = triangulate(outline);
    expect(triangles.length).toBe(3 * ((outline.length >> 1) - 2));
    let area = 0, flipped = 0;
    for (let t = 0; t < triangles.length; t += 3) {
      const twice = signedArea2([0, 1, 2].flatMap((k) => [outline[2 * triangles[t + k]], outline[2 * triangles[t + k] + 1]]));
      if (!(twice > 0)) flipped++;
      area += twice;
    }
    expect(flipped, 'triangles that turn right or are flat').toBe(0);
    expect(area / signedArea2(outline)).toBeCloseTo(1, 9);
  });
});
