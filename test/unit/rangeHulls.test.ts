/**
 * RangeHulls against the obvious reference: the farthest point of a range along a direction,
 * found by scanning the range.
 */
import { describe, expect, it } from 'vitest';
import { RangeHulls } from '../../src/geometry/rangeHulls';
import { createRandom } from '../reference/randomScenes';

/** The largest x · dx + y · dy over the `count` indices from `from` on, wrapping, by a scan. */
function farthestValue(xs: Float64Array, ys: Float64Array, from: number, count: number, dx: number, dy: number): number {
  let best = -Infinity;
  for (let k = 0; k < count; k++) {
    const i = (from + k) % xs.length;
    best = Math.max(best, xs[i] * dx + ys[i] * dy);
  }
  return best;
}

describe('RangeHulls', () => {
  it('finds the farthest point of any range, wrapping or not, along any direction', () => {
    const random = createRandom(17);
    for (const n of [1, 2, 7, 8, 9, 16, 17, 100, 1000]) {
      // Half-integer points: a random walk (an outline's kind of sequence) and scattered ones, with repeats.
      const xs = new Float64Array(n), ys = new Float64Array(n);
      for (let i = 0; i < n; i++) {
        const walk = i > 0 && i % 3 !== 0;
        xs[i] = walk ? xs[i - 1] + Math.round(2 * random() - 1) / 2 : Math.round(40 * random()) / 2;
        ys[i] = walk ? ys[i - 1] + Math.round(2 * random() - 1) / 2 : Math.round(40 * random()) / 2;
      }
      const hulls = new RangeHulls(xs, ys, n);
      for (let q = 0; q < 400; q++) {
        const from = Math.floor(random() * n), count = 1 + Math.floor(random() * n);
        const [dx, dy] = q % 4 === 0 ? [[1, 0], [-1, 0], [0, 1], [0, -1]][q % 16 / 4] : [2 * random() - 1, 2 * random() - 1];
        const found = hulls.farthest(from, count, dx, dy);
        expect((found - from + n) % n, `index ${found} outside ${from} + ${count}`).toBeLessThan(count);
        expect(xs[found] * dx + ys[found] * dy).toBe(farthestValue(xs, ys, from, count, dx, dy));
      }
    }
  });

  it('gives the convex hull of all the points, counter-clockwise (y up), without collinear points', () => {
    const xs = Float64Array.from([0, 1, 2, 2, 2, 1, 0, 0, 1, 1.5]), ys = Float64Array.from([0, 0, 0, 1, 2, 2, 2, 1, 1, 0.5]);
    const hull = new RangeHulls(xs, ys, xs.length).hull();
    expect(hull.map((i) => [xs[i], ys[i]])).toEqual([[0, 0], [2, 0], [2, 2], [0, 2]]);
  });
});
