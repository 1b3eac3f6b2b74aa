import { describe, expect, it } from 'vitest';
import { signedArea2 } from '../../src/geometry/polygon';
import { Hull } from '../../src/index';

/** World points as `[x, y]` pairs, rounded to 1e-9 to compare away float noise. */
function worldPoints(hull: Hull): [number, number][] {
  hull.updateWorld();
  const out: [number, number][] = [];
  for (let i = 0; i < hull.edgeCount; i++) {
    out.push([Math.round(hull.worldPoints[2 * i] * 1e6) / 1e6, Math.round(hull.worldPoints[2 * i + 1] * 1e6) / 1e6]);
  }
  return out;
}

/** Same polygon regardless of the starting point. */
function sameCycle(a: [number, number][], b: [number, number][]): boolean {
  if (a.length !== b.length) return false;
  const key = (p: [number, number]) => `${p[0]},${p[1]}`;
  const start = b.findIndex((p) => key(p) === key(a[0]));
  return start >= 0 && a.every((p, i) => key(p) === key(b[(start + i) % b.length]));
}

const triangle: [number, number][] = [[0, 0], [4, 0], [0, 2]];

describe('Hull transforms', () => {
  it('places local points by position', () => {
    const hull = new Hull(triangle, { position: [10, 20] });
    expect(sameCycle(worldPoints(hull), [[10, 20], [14, 20], [10, 22]])).toBe(true);
  });

  it('rotates and scales around the origin, then moves the origin to position', () => {
    const hull = new Hull(triangle, { origin: [4, 0], rotation: Math.PI / 2, scale: 2, position: [100, 100] });
    // (0,0) → (-4,0) from the origin → ×2 (-8,0) → rotated +90° (0,-8) → (100, 92); (4,0) → (100,100); (0,2) → (-8,4) → (-4,-8) → (96,92).
    expect(sameCycle(worldPoints(hull), [[100, 92], [100, 100], [96, 92]])).toBe(true);
    expect(hull.worldBounds).toEqual(Float64Array.of(96, 92, 100, 100));
  });

  it('scales along the local axes before it rotates, as documented', () => {
    const hull = new Hull([[0, 0], [1, 0], [0, 1]], { scale: [2, 1], rotation: Math.PI / 2 });
    // (1, 0) → ×[2, 1] (2, 0) → turned +90° (0, 2); rotated first it would end at (0, 1).
    const world = worldPoints(hull).map(([x, y]) => [Math.round(x * 1e9) / 1e9 + 0, Math.round(y * 1e9) / 1e9 + 0]);
    expect(sameCycle(world as [number, number][], [[0, 0], [0, 2], [-1, 0]])).toBe(true);
  });

  it('mirrors with a negative scale and keeps counter-clockwise order', () => {
    const hull = new Hull(triangle, { scale: [-1, 1] });
    const points = worldPoints(hull);
    expect(sameCycle(points, [[0, 0], [0, 2], [-4, 0]])).toBe(true);
    expect(signedArea2(hull.worldPoints)).toBeGreaterThan(0);
    hull.scale = [-1, -1]; // two mirrors: a half turn, still counter-clockwise
    expect(sameCycle(worldPoints(hull), [[0, 0], [-4, 0], [0, -2]])).toBe(true);
    expect(signedArea2(hull.worldPoints)).toBeGreaterThan(0);
  });

  // Triangle winding is free (the hull pass does not cull), so areas are compared unsigned.
  it('keeps its triangulation covering the hull when mirrored', () => {
    const hull = new Hull([[0, 0], [30, 0], [30, 10], [10, 10], [10, 30], [0, 30]], { scale: [1, -1] });
    hull.updateWorld();
    const w = hull.worldPoints;
    const t = hull.worldTriangles;
    let area = 0;
    for (let k = 0; k < t.length; k += 3) {
      area += Math.abs(signedArea2([w[2 * t[k]], w[2 * t[k] + 1], w[2 * t[k + 1]], w[2 * t[k + 1] + 1], w[2 * t[k + 2]], w[2 * t[k + 2] + 1]]));
    }
    expect(area).toBeCloseTo(signedArea2(w), 6);
  });
});

describe('Hull dirty tracking', () => {
  it('bumps version on every change', () => {
    const hull = new Hull(triangle);
    const changes: ((h: Hull) => void)[] = [
      (h) => { h.position = [1, 2]; }, (h) => h.setPosition(3, 4), (h) => { h.origin = [1, 1]; },
      (h) => { h.rotation = 1; }, (h) => { h.scale = 2; }, (h) => { h.enabled = false; }, (h) => { h.points = triangle; },
    ];
    for (const change of changes) {
      const before = hull.version;
      change(hull);
      expect(hull.version).toBeGreaterThan(before);
    }
  });

  it('does not count setting a position, rotation, enabled or layers to the value it has as a change', () => {
    const hull = new Hull(triangle, { position: [3, 4], rotation: 1, layers: 2 });
    const before = hull.version;
    hull.position = [3, 4];
    hull.setPosition(3, 4);
    hull.rotation = 1;
    hull.enabled = true;
    hull.layers = 2;
    expect(hull.version).toBe(before);
    // Still validated.
    expect(() => hull.setPosition(NaN, 4)).toThrow(/Hull\.position/);
    expect(() => { hull.rotation = Infinity; }).toThrow(/Hull\.rotation/);
  });

  it('recomputes world points only when changed', () => {
    const hull = new Hull(triangle);
    expect(hull.updateWorld()).toBe(true);
    expect(hull.updateWorld()).toBe(false);
    hull.rotation = 0.5;
    expect(hull.updateWorld()).toBe(true);
    expect(hull.updateWorld()).toBe(false);
  });
});
