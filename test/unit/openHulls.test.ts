import { mat4 } from 'gl-matrix';
import { describe, expect, it } from 'vitest';
import { ShadowCache } from '../../src/shadow/ShadowCache';
import { ShadowGeometry } from '../../src/shadow/ShadowGeometry';
import { RECORD_FLOATS, RECORD_POINTS } from '../../src/shadow/shadowLayout';
import { Hull, PointLight } from '../../src/index';

/** The records the geometry writes for `hull` (placed alone), each as its points `[[x, y], …]`. */
function recordsOf(hull: Hull): [number, number][][] {
  const geometry = new ShadowGeometry();
  geometry.update([hull]);
  geometry.prepare(0);
  const records: [number, number][][] = [];
  for (let r = geometry.firstRecords[0]; r < geometry.firstRecords[0] + geometry.recordCounts[0]; r++) {
    const points: [number, number][] = [];
    for (let k = 0; k < RECORD_POINTS; k++) points.push([geometry.records[r * RECORD_FLOATS + 2 * k], geometry.records[r * RECORD_FLOATS + 2 * k + 1]]);
    records.push(points);
  }
  return records;
}

/** Twice the signed area of a polygon, in double precision from its (float32) points. */
function area2(points: readonly (readonly [number, number])[]): number {
  let sum = 0;
  for (let i = 0, j = points.length - 1; i < points.length; j = i++) sum += points[j][0] * points[i][1] - points[i][0] * points[j][1];
  return sum;
}

/** Largest distance of a box's points from the segment a–b's line, and their reach past its ends. */
function boxReach(points: readonly (readonly [number, number])[], a: readonly [number, number], b: readonly [number, number]) {
  const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
  const ux = (b[0] - a[0]) / length, uy = (b[1] - a[1]) / length;
  let side = 0, past = 0;
  for (const [x, y] of points) {
    const along = (x - a[0]) * ux + (y - a[1]) * uy;
    side = Math.max(side, Math.abs((x - a[0]) * -uy + (y - a[1]) * ux));
    past = Math.max(past, -along, along - length);
  }
  return { side, past };
}

describe('open hulls (polylines)', () => {
  it('is valid with two distinct points, has one edge fewer than points, and may cross itself', () => {
    const fence = new Hull([[0, 0], [10, 0]], { closed: false });
    expect(fence.closed).toBe(false);
    expect(fence.valid).toBe(true);
    expect(fence.edgeCount).toBe(1);
    expect(fence.convex).toBe(false);
    const bowTie = new Hull([[0, 0], [10, 10], [10, 0], [0, 10]], { closed: false });
    expect(bowTie.valid).toBe(true);
    expect(bowTie.edgeCount).toBe(3);
    // The same points closed cross themselves: an invalid polygon.
    expect(new Hull(bowTie.points).valid).toBe(false);
    expect(new Hull([[0, 0], [10, 0]]).closed).toBe(true);
  });

  it('drops repeated points and points on the way straight on, keeps a point where the line turns back', () => {
    expect(new Hull([[0, 0], [0, 0], [5, 0], [10, 0], [10, 5]], { closed: false }).edgeCount).toBe(2);
    expect(new Hull([[0, 0], [10, 0], [5, 0]], { closed: false }).edgeCount).toBe(2);
    expect(new Hull([[3, 3], [3, 3]], { closed: false }).valid).toBe(false);
    expect(new Hull([[3, 3]], { closed: false }).valid).toBe(false);
  });

  it('names the option when `closed` is not a boolean', () => {
    expect(() => new Hull([[0, 0], [1, 0]], { closed: 'no' as unknown as boolean })).toThrow(/^Hull\.closed must be true or false, got "no"$/);
  });

  it('gives each segment a box of positive area around it, thin, and not past its ends', () => {
    const points: [number, number][] = [[10, 10], [60, 20], [30, 50]];
    const records = recordsOf(new Hull(points, { closed: false }));
    expect(records).toHaveLength(2);
    records.forEach((box, i) => {
      expect(area2(box)).toBeGreaterThan(0);
      const { side, past } = boxReach(box, points[i], points[i + 1]);
      expect(side).toBeGreaterThan(5e-4);
      expect(side).toBeLessThan(2e-3);
      expect(past).toBeLessThan(1e-5);
    });
  });

  it('keeps the boxes open in float32 far from the origin, where 2^-10 is below float32 resolution', () => {
    const far = 3e5; // float32 steps of 1/32 here
    const records = recordsOf(new Hull([[0, 0], [17, 3]], { closed: false, position: [far, -far] }));
    const { side } = boxReach(records[0], [far, -far], [far + 17, -far + 3]);
    expect(area2(records[0])).toBeGreaterThan(0);
    // 16 float32 steps at this magnitude, give or take the rounding of each point.
    expect(side).toBeGreaterThan(far * 2 ** -19 * 0.75);
    expect(side).toBeLessThan(far * 2 ** -19 * 1.5);
  });

  it('draws a light inside a ring of fence, on a fence and inside a polygon, each shadowed by it', () => {
    const projection = mat4.ortho(mat4.create(), 0, 200, 200, 0, -1, 1);
    const light = new PointLight({ position: [100, 100], range: 50, radius: 5 });
    const drawn = (hull: Hull) => {
      const geometry = new ShadowGeometry(), plan = new ShadowCache();
      geometry.update([hull]);
      plan.build([light], [hull], geometry, projection, 200, 200);
      return plan.draws.slice(0, plan.drawCount).map((draw) => draw.hullCount);
    };
    const ring: [number, number][] = [[90, 95], [90, 90], [110, 90], [110, 110], [90, 110], [90, 105]];
    expect(drawn(new Hull(ring, { closed: false }))).toEqual([1]);
    expect(drawn(new Hull([[50, 100], [150, 100]], { closed: false }))).toEqual([1]);
    expect(drawn(new Hull(ring))).toEqual([1]);
  });
});
