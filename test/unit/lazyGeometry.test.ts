import { mat4 } from 'gl-matrix';
import { describe, expect, it, vi } from 'vitest';
import { ShadowCache } from '../../src/shadow/ShadowCache';
import { ShadowGeometry } from '../../src/shadow/ShadowGeometry';
import { RECORD_FLOATS, RECORDS_PER_ROW } from '../../src/shadow/shadowLayout';
import { Hull, PointLight, type Light } from '../../src/index';

const WIDTH = 400, HEIGHT = 200;
const pixelSpace = mat4.ortho(mat4.create(), 0, WIDTH, HEIGHT, 0, -1, 1);

/** A renderer's per-frame CPU work: geometry update, then the plan. */
function frame(geometry: ShadowGeometry, plan: ShadowCache, lights: Light[], hulls: Hull[]): void {
  geometry.update(hulls);
  plan.build(lights, hulls, geometry, pixelSpace, WIDTH, HEIGHT);
}

/** The world points the geometry holds for the (convex, at most 8-point) hull at `index`: its one record. */
function storedPoints(geometry: ShadowGeometry, index: number): number[] {
  const record = geometry.firstRecords[index];
  return Array.from(geometry.records.subarray(record * RECORD_FLOATS, record * RECORD_FLOATS + 2 * geometry.recordPointCounts[record]));
}

/** The exact world points of a hull's current placement, from a fresh copy. */
function exactPoints(hull: Hull): number[] {
  const copy = new Hull(hull.points, { position: hull.position, origin: hull.origin, rotation: hull.rotation, scale: hull.scale });
  copy.updateWorld();
  return Array.from(copy.worldPoints);
}

const square = (x: number, y: number) => new Hull([[-5, -5], [5, -5], [5, 5], [-5, 5]], { position: [x, y] });

describe('Lazy hull geometry', () => {
  it('does not transform a hull no light reaches, and has it exact the frame it comes into range', () => {
    const light = new PointLight({ position: [50, 100], range: 40 });
    const near = square(60, 100), far = square(350, 100);
    const hulls = [near, far];
    const geometry = new ShadowGeometry(), plan = new ShadowCache();
    const transform = vi.spyOn(far, 'updateWorld');
    for (let f = 0; f < 3; f++) {
      far.setPosition(350, 100 + f);
      far.rotation = f;
      frame(geometry, plan, [light], hulls);
    }
    expect(transform).not.toHaveBeenCalled();
    expect(plan.draws[0].hullCount).toBe(1);
    far.setPosition(80, 100);
    frame(geometry, plan, [light], hulls);
    expect(plan.draws[0].hullCount).toBe(2);
    expect(storedPoints(geometry, 1)).toEqual(exactPoints(far));
  });

  it('marks dirty only the record rows of hulls written this frame', () => {
    // Enough hulls to fill several rows; the light reaches only the first.
    const hulls = Array.from({ length: 3 * RECORDS_PER_ROW }, (_, i) => square(i === 0 ? 60 : 10_000 + i * 20, 100));
    const light = new PointLight({ position: [50, 100], range: 40 });
    const geometry = new ShadowGeometry(), plan = new ShadowCache();
    frame(geometry, plan, [light], hulls);
    expect(Array.from(geometry.dirtyRows)).toEqual([1, 0, 0]);
    frame(geometry, plan, [light], hulls);
    expect(Array.from(geometry.dirtyRows)).toEqual([0, 0, 0]);
    hulls[hulls.length - 1].setPosition(70, 100);
    frame(geometry, plan, [light], hulls);
    expect(Array.from(geometry.dirtyRows)).toEqual([0, 0, 1]);
  });

  it('brings every change to every light the next frame, also to a light whose centre a hull held', () => {
    const housing = square(300, 100);
    const inside = new PointLight({ position: [300, 100], range: 40 });
    const outside = new PointLight({ position: [50, 100], range: 40 });
    const hulls = [housing];
    const geometry = new ShadowGeometry(), plan = new ShadowCache();
    frame(geometry, plan, [inside, outside], hulls);
    expect(plan.draws.slice(0, plan.drawCount).map((d) => [d.light, d.hullCount])).toEqual([[inside, 1], [outside, 0]]);
    // The hull moves out from over the first light into the other light's range.
    housing.setPosition(70, 100);
    frame(geometry, plan, [inside, outside], hulls);
    expect(plan.draws.slice(0, plan.drawCount).map((d) => [d.light, d.hullCount])).toEqual([[inside, 0], [outside, 1]]);
    expect(storedPoints(geometry, 0)).toEqual(exactPoints(housing));
    // Turned, mirrored and moved back over the first light in one frame: exact at once.
    housing.rotation = 0.7;
    housing.scale = [2, -1];
    housing.setPosition(300, 100);
    frame(geometry, plan, [inside, outside], hulls);
    expect(plan.draws.slice(0, plan.drawCount).map((d) => [d.light, d.hullCount])).toEqual([[inside, 1], [outside, 0]]);
    expect(storedPoints(geometry, 0)).toEqual(exactPoints(housing));
  });

  it('keeps coarse bounds around the exact world bounds under any placement', () => {
    const hull = new Hull([[0, 0], [30, 4], [12, 20], [5, 9]]);
    for (const [origin, rotation, scale] of [[[0, 0], 0, 1], [[40, -10], 2.1, [3, -0.5]], [[10, 10], -0.4, -2]] as const) {
      hull.origin = origin;
      hull.rotation = rotation;
      hull.scale = scale;
      hull.setPosition(17, -3);
      hull.updateWorld();
      hull.updateCoarseBounds();
      const w = hull.worldBounds, c = hull.coarseBounds;
      expect(c[0] <= w[0] && c[1] <= w[1] && c[2] >= w[2] && c[3] >= w[3]).toBe(true);
    }
  });
});
