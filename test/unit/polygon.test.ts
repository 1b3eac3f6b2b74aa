import { describe, expect, it } from 'vitest';
import { orient2d } from '../../src/geometry/orient2d';
import { isConvexPolygon, isInsidePolygon, isSimplePolygon, signedArea2, simplifyPolygon, triangulate } from '../../src/geometry/polygon';
import { Hull } from '../../src/index';
import { createRandom } from '../reference/randomScenes';

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

/**
 * The exact reference: a finite double is an integer times a power of two, read from its bits;
 * scaled to the smallest power among them, an orientation's doubles are integers, and the
 * determinant is computed exactly in BigInt.
 */
const bitsView = new DataView(new ArrayBuffer(8));
function exactParts(value: number): [bigint, number] {
  const view = bitsView;
  view.setFloat64(0, value);
  const bits = view.getBigUint64(0);
  const exponent = Number((bits >> 52n) & 0x7ffn), fraction = bits & ((1n << 52n) - 1n);
  const integer = exponent === 0 ? fraction : fraction | (1n << 52n);
  return [bits >> 63n ? -integer : integer, Math.max(exponent, 1) - 1075];
}

/** Doubles as integers scaled to one power of two: their exact values, in proportion. */
function exactIntegers(values: readonly number[]): bigint[] {
  const parts = values.map(exactParts);
  const least = Math.min(...parts.map(([, power]) => power));
  return parts.map(([integer, power]) => integer << BigInt(power - least));
}

/** The sign of (b − a) × (c − a) for exact points `[x, y]`. */
function exactSign(a: readonly bigint[], b: readonly bigint[], c: readonly bigint[]): number {
  const determinant = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return determinant > 0n ? 1 : determinant < 0n ? -1 : 0;
}

/**
 * The sign of (b − a) × (c − a), exactly: from the doubles when the determinant is more than 1e-10
 * of its terms' size (its rounding error is below 1e-15 of that), else in BigInt.
 */
function exactOrientation(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  const left = (bx - ax) * (cy - ay), right = (by - ay) * (cx - ax);
  if (Math.abs(left - right) > 1e-10 * (Math.abs(left) + Math.abs(right))) return Math.sign(left - right);
  const [eax, eay, ebx, eby, ecx, ecy] = exactIntegers([ax, ay, bx, by, cx, cy]);
  return exactSign([eax, eay], [ebx, eby], [ecx, ecy]);
}

type Point = readonly number[];

/** Whether the closed segments a–b and c–d share a point, exactly. */
function exactSegmentsMeet(a: Point, b: Point, c: Point, d: Point): boolean {
  const orientation = (p: Point, q: Point, r: Point) => exactOrientation(p[0], p[1], q[0], q[1], r[0], r[1]);
  const o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  const within = (p: Point, q: Point, r: Point) =>
    Math.min(p[0], q[0]) <= r[0] && r[0] <= Math.max(p[0], q[0]) && Math.min(p[1], q[1]) <= r[1] && r[1] <= Math.max(p[1], q[1]);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 === 0 && within(a, b, c)) || (o2 === 0 && within(a, b, d)) || (o3 === 0 && within(c, d, a)) || (o4 === 0 && within(c, d, b));
}

/** Simple polygon, exactly, by every pair of edges: neighbours meet only at their shared point, others nowhere. */
function exactlySimple(points: ReadonlyArray<Point>): boolean {
  const n = points.length;
  for (let i = 0; i < n; i++) {
    const a = points[i], b = points[(i + 1) % n];
    for (let j = i + 1; j < n; j++) {
      const c = points[j], d = points[(j + 1) % n];
      if (j === i + 1 || (i === 0 && j === n - 1)) {
        // Neighbours share one point; they meet elsewhere only by folding back along each other
        // (collinear, the other two points on one side: each coordinate difference has one sign).
        const [shared, p, q] = j === i + 1 ? [b, a, d] : [a, b, c];
        if (exactOrientation(shared[0], shared[1], p[0], p[1], q[0], q[1]) === 0
          && [0, 1].every((k) => Math.sign(p[k] - shared[k]) * Math.sign(q[k] - shared[k]) >= 0)) return false;
      } else if (exactSegmentsMeet(a, b, c, d)) return false;
    }
  }
  return true;
}

/**
 * A U (outer 30 × 30, arms 10 wide) whose arm tips lie on one line, scaled, turned and moved into
 * the world at random, in doubles as a host computes them.
 */
function worldU(random: () => number): number[][] {
  const u = [[0, 0], [30, 0], [30, 30], [20, 30], [20, 10], [10, 10], [10, 30], [0, 30]];
  const angle = random() * 2 * Math.PI, scale = 0.5 + 4 * random();
  const px = 4000 * random() - 2000, py = 4000 * random() - 2000, cos = Math.cos(angle), sin = Math.sin(angle);
  return u.map(([x, y]) => [px + scale * (x * cos - y * sin), py + scale * (x * sin + y * cos)]);
}

describe('exact orientation', () => {
  it('gives orient2d the exact sign on nearly collinear triples, where the plain determinant fails', () => {
    const naive = (ax: number, ay: number, bx: number, by: number, cx: number, cy: number) =>
      Math.sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
    const wrong: number[][] = [];
    let naiveWrong = 0, checked = 0;
    // Shewchuk's grid: points a few ulps around (0.5, 0.5) against the line through (12, 12) and (24, 24).
    for (let i = 0; i < 64; i++) {
      for (let j = 0; j < 64; j++) {
        const x = 0.5 + i * 2 ** -53, y = 0.5 + j * 2 ** -53;
        const exact = exactOrientation(x, y, 12, 12, 24, 24);
        if (Math.sign(orient2d(x, y, 12, 12, 24, 24)) !== exact) wrong.push([x, y, 12, 12, 24, 24]);
        naiveWrong += naive(x, y, 12, 12, 24, 24) !== exact ? 1 : 0;
        checked++;
      }
    }
    // Random lines far from the origin, the third point on the line rounded and nudged by ulps.
    const random = createRandom(11);
    for (let k = 0; k < 20000; k++) {
      const ax = 1e4 * (random() - 0.5), ay = 1e4 * (random() - 0.5), bx = ax + 100 * (random() - 0.5), by = ay + 100 * (random() - 0.5);
      const t = 3 * random() - 1, nudge = Math.floor(5 * random()) - 2;
      const cx = ax + t * (bx - ax), cy = ay + t * (by - ay) + nudge * Number.EPSILON * Math.abs(ay);
      const exact = exactOrientation(ax, ay, bx, by, cx, cy);
      for (const [p, q, r] of [[[ax, ay], [bx, by], [cx, cy]], [[bx, by], [cx, cy], [ax, ay]], [[cx, cy], [bx, by], [ax, ay]]]) {
        if (Math.sign(orient2d(p[0], p[1], q[0], q[1], r[0], r[1])) !== exactOrientation(p[0], p[1], q[0], q[1], r[0], r[1])) wrong.push([...p, ...q, ...r]);
      }
      naiveWrong += naive(ax, ay, bx, by, cx, cy) !== exact ? 1 : 0;
      checked++;
    }
    expect(wrong).toEqual([]);
    // The cases are hard: the plain determinant gets a good share of them wrong.
    expect(naiveWrong).toBeGreaterThan(checked / 20);
  });

  it('is exactly 0 on exactly collinear points and antisymmetric', () => {
    expect(orient2d(0, 0, 1, 1, 2, 2)).toBe(0);
    expect(orient2d(1e140, 1e140, -1e140, -1e140, 3, 3)).toBe(0);
    expect(orient2d(0.1, 0.1, 0.3, 0.3, 1e-140, 1e-140)).toBe(0);
    expect(Math.sign(orient2d(0, 0, 1, 0, 0, 1))).toBe(1);
    expect(Math.sign(orient2d(0, 0, 0, 1, 1, 0))).toBe(-1);
  });
});

describe('exact decisions on nearly collinear edges', () => {
  it('accepts a U whose arm tips lie on one line at any rotation in world coordinates, as exact arithmetic does', () => {
    const random = createRandom(2024);
    for (let k = 0; k < 20000; k++) {
      const points = worldU(random), coords = points.flat();
      const simple = exactlySimple(points);
      if (isSimplePolygon(coords) !== simple || new Hull(points).valid !== simple) {
        expect.fail(`isSimplePolygon and Hull.valid must be ${simple} for ${JSON.stringify(points)}`);
      }
      // The triangulation: n − 2 triangles, each turning counter-clockwise, exactly.
      const ccw = signedArea2(coords) > 0 ? coords : points.slice().reverse().flat();
      const triangles = triangulate(ccw);
      expect(triangles).toHaveLength(3 * (points.length - 2));
      for (let t = 0; t < triangles.length; t += 3) {
        const [a, b, c] = [2 * triangles[t], 2 * triangles[t + 1], 2 * triangles[t + 2]];
        if (exactOrientation(ccw[a], ccw[a + 1], ccw[b], ccw[b + 1], ccw[c], ccw[c + 1]) !== 1) expect.fail(`triangle ${t / 3} of ${JSON.stringify(ccw)} does not turn left`);
      }
    }
  });

  it('tests points on and next to a turned outline as exact arithmetic does', () => {
    const random = createRandom(5);
    for (let k = 0; k < 2000; k++) {
      const points = worldU(random), coords = points.flat(), n = points.length;
      // A point on the line of an edge (rounded), nudged by an ulp or two across it.
      const e = Math.floor(random() * n), [ax, ay] = points[e], [bx, by] = points[(e + 1) % n], t = random();
      const x = ax + t * (bx - ax), y = ay + t * (by - ay) + (Math.floor(5 * random()) - 2) * Number.EPSILON * Math.abs(ay);
      // Even-odd by exact arithmetic: an edge crossing the point's row counts when the point lies left of it.
      let inside = false;
      for (let i = 0, j = n - 1; i < n; j = i++) {
        const [xi, yi] = points[i], [xj, yj] = points[j];
        if ((yi > y) === (yj > y)) continue;
        const [lowX, lowY, highX, highY] = yi < yj ? [xi, yi, xj, yj] : [xj, yj, xi, yi];
        if (exactOrientation(lowX, lowY, highX, highY, x, y) > 0) inside = !inside;
      }
      expect(isInsidePolygon(coords, [x, y]), `(${x}, ${y}) in ${JSON.stringify(points)}`).toBe(inside);
    }
  });
});
