import { describe, expect, it } from 'vitest';
import { isConvexPolygon, isInsidePolygon, isSimplePolygon, signedArea2, simplifyPolygon, triangulate } from '../../src/geometry/polygon';
import { Hull } from '../../src/index';

const square = [0, 0, 10, 0, 10, 10, 0, 10];

describe('polygon winding and validity', () => {
  it('measures the signed area: positive counter-clockwise (y up), negative clockwise', () => {
    expect(signedArea2(square)).toBe(200);
    expect(signedArea2([0, 0, 0, 10, 10, 10, 10, 0])).toBe(-200);
  });

  it('accepts convex and concave simple polygons', () => {
    expect(isSimplePolygon(square)).toBe(true);
    expect(isSimplePolygon([0, 0, 30, 0, 30, 10, 10, 10, 10, 30, 0, 30])).toBe(true); // L
  });

  it('rejects self-intersecting, zero-area and too short outlines', () => {
    expect(isSimplePolygon([0, 0, 10, 10, 10, 0, 0, 10])).toBe(false); // bow tie
    expect(isSimplePolygon([0, 0, 5, 5, 10, 10])).toBe(false); // collinear: zero area
    expect(isSimplePolygon([0, 0, 10, 0])).toBe(false);
  });

  it('rejects edges that touch without crossing', () => {
    // The vertex (5, 0) of the inner notch lies on the bottom edge.
    expect(isSimplePolygon([0, 0, 10, 0, 10, 10, 5, 0, 0, 10])).toBe(false);
  });

  it('removes duplicate and collinear points without changing the outline', () => {
    expect(simplifyPolygon([0, 0, 0, 0, 5, 0, 10, 0, 10, 10, 0, 10])).toEqual(square);
  });

  it('triangulates a concave polygon into triangles covering its area', () => {
    const l = [0, 0, 30, 0, 30, 10, 10, 10, 10, 30, 0, 30];
    const triangles = triangulate(l);
    expect(triangles.length).toBe((6 - 2) * 3);
    let area = 0;
    for (let t = 0; t < triangles.length; t += 3) {
      const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
      area += signedArea2([l[2 * a], l[2 * a + 1], l[2 * b], l[2 * b + 1], l[2 * c], l[2 * c + 1]]);
    }
    expect(area).toBe(signedArea2(l));
  });

  it('tests points against a concave outline', () => {
    const l = [0, 0, 30, 0, 30, 10, 10, 10, 10, 30, 0, 30];
    expect(isInsidePolygon(l, [5, 25])).toBe(true);
    expect(isInsidePolygon(l, [20, 20])).toBe(false); // in the notch
  });
});

describe('Hull validity', () => {
  it('is valid for either winding and stores counter-clockwise points', () => {
    for (const points of [[[0, 0], [10, 0], [10, 10]], [[0, 0], [10, 10], [10, 0]]] as [number, number][][]) {
      const hull = new Hull(points);
      expect(hull.valid).toBe(true);
      hull.updateWorld();
      expect(signedArea2(hull.worldPoints)).toBeGreaterThan(0);
    }
  });

  it('drops duplicate and collinear points', () => {
    const hull = new Hull([[0, 0], [0, 0], [5, 0], [10, 0], [10, 10], [0, 10]]);
    expect(hull.valid).toBe(true);
    expect(hull.edgeCount).toBe(4);
  });

  it('is invalid, never throwing, for fewer than 3 points, crossing edges, zero area or zero scale', () => {
    expect(new Hull([]).valid).toBe(false);
    expect(new Hull([[0, 0], [1, 1]]).valid).toBe(false);
    expect(new Hull([[0, 0], [10, 10], [10, 0], [0, 10]]).valid).toBe(false);
    expect(new Hull([[0, 0], [5, 5], [10, 10]]).valid).toBe(false);
    expect(new Hull([[0, 0], [1, 1], [1, 1]]).valid).toBe(false);
    expect(new Hull([[0, 0], [10, 0], [10, 10]], { scale: [0, 1] }).valid).toBe(false);
  });

  it('becomes valid again when its points are fixed', () => {
    const hull = new Hull([[0, 0], [10, 10], [10, 0], [0, 10]]);
    expect(hull.valid).toBe(false);
    hull.points = [[0, 0], [10, 0], [10, 10], [0, 10]];
    expect(hull.valid).toBe(true);
  });
});

describe('convexity', () => {
  it('tells convex counter-clockwise polygons from concave ones', () => {
    expect(isConvexPolygon([0, 0, 10, 0, 10, 10, 0, 10])).toBe(true);
    expect(isConvexPolygon([0, 0, 10, 0, 5, 3, 10, 10, 0, 10])).toBe(false);
  });

  it('holds for a hull given clockwise, mirrored, or invalid', () => {
    const hull = new Hull([[0, 10], [10, 10], [10, 0], [0, 0]]);
    expect(hull.convex).toBe(true);
    hull.scale = [-1, 1];
    expect(hull.convex).toBe(true);
    hull.points = [[0, 0], [10, 0], [5, 3], [10, 10], [0, 10]];
    expect(hull.convex).toBe(false);
    hull.points = [[0, 0], [10, 10], [10, 0], [0, 10]];
    expect(hull.convex).toBe(false);
  });
});
