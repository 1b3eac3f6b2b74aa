import { mat4 } from 'gl-matrix';
import { describe, expect, it } from 'vitest';
import { FramePlan, sizeClassOf } from '../../src/geometry/FramePlan';
import { ShadowGeometry } from '../../src/geometry/ShadowGeometry';
import { Hull, PointLight, TexturedLight, type Light } from '../../src/index';

const WIDTH = 200, HEIGHT = 100;
const pixelSpace = mat4.ortho(mat4.create(), 0, WIDTH, HEIGHT, 0, -1, 1);

function plan(lights: Light[], hulls: Hull[]): FramePlan {
  const geometry = new ShadowGeometry();
  geometry.update(hulls);
  const framePlan = new FramePlan();
  framePlan.build(lights, hulls, geometry, pixelSpace, WIDTH, HEIGHT);
  return framePlan;
}

/** The scissor `[x, y, w, h]` covers `[x0, y0, x1, y1]` and exceeds it by at most one pixel per side. */
function expectScissorAround(scissor: Int32Array, [x0, y0, x1, y1]: number[]): void {
  const [x, y, w, h] = scissor;
  expect(x).toBeLessThanOrEqual(x0);
  expect(x).toBeGreaterThanOrEqual(x0 - 1);
  expect(y).toBeLessThanOrEqual(y0);
  expect(y).toBeGreaterThanOrEqual(y0 - 1);
  expect(x + w).toBeGreaterThanOrEqual(x1);
  expect(x + w).toBeLessThanOrEqual(x1 + 1);
  expect(y + h).toBeGreaterThanOrEqual(y1);
  expect(y + h).toBeLessThanOrEqual(y1 + 1);
}

const drawnLights = (framePlan: FramePlan) => framePlan.draws.slice(0, framePlan.drawCount).map((d) => d.light);

describe('FramePlan culling', () => {
  it('draws an on-screen light with a scissor around its range, clamped to the target', () => {
    const light = new PointLight({ position: [50, 50], range: 20 });
    const framePlan = plan([light], []);
    expect(drawnLights(framePlan)).toEqual([light]);
    // World y down → GL window y up: rows 30..70 from the top are 30..70 from the bottom of 100.
    // Rounding is outward, so float noise in the projection may widen the box by one pixel.
    expectScissorAround(framePlan.draws[0].scissor, [30, 30, 70, 70]);
    const edge = plan([new PointLight({ position: [5, 5], range: 20 })], []);
    expectScissorAround(edge.draws[0].scissor, [0, 75, 25, 100]);
  });

  it('skips lights that are off screen, disabled, of zero intensity or range', () => {
    const lights = [
      new PointLight({ position: [-50, 50], range: 20 }),
      new PointLight({ position: [100, 200], range: 50 }),
      new PointLight({ position: [50, 50], enabled: false }),
      new PointLight({ position: [50, 50], intensity: 0 }),
      new PointLight({ position: [50, 50], range: 0 }),
    ];
    expect(plan(lights, []).drawCount).toBe(0);
  });

  it('skips a light whose centre is inside a hull, unless it ignores that hull', () => {
    const housing = new Hull([[40, 40], [60, 40], [60, 60], [40, 60]]);
    const inside = new PointLight({ position: [50, 50], range: 30 });
    expect(plan([inside], [housing]).drawCount).toBe(0);
    inside.ignoredHulls.add(housing);
    const framePlan = plan([inside], [housing]);
    expect(drawnLights(framePlan)).toEqual([inside]);
    expect(framePlan.draws[0].hullCount).toBe(0);
  });

  it('does not skip a light in a concave hull’s notch or inside a disabled or invalid hull', () => {
    const u = new Hull([[0, 0], [30, 0], [30, 30], [20, 30], [20, 10], [10, 10], [10, 30], [0, 30]]);
    const notchLight = new PointLight({ position: [15, 20], range: 30 });
    expect(plan([notchLight], [u]).drawCount).toBe(1);
    const disabled = new Hull([[40, 40], [60, 40], [60, 60], [40, 60]], { enabled: false });
    const invalid = new Hull([[40, 40], [60, 60], [60, 40], [40, 60]]);
    expect(plan([new PointLight({ position: [50, 50], range: 30 })], [disabled, invalid]).drawCount).toBe(1);
  });

  it('lists only hulls within the light’s range, and none for a light that casts no shadows', () => {
    const near = new Hull([[60, 45], [70, 45], [70, 55], [60, 55]]);
    const far = new Hull([[180, 45], [190, 45], [190, 55], [180, 55]]);
    const light = new PointLight({ position: [50, 50], range: 30 });
    expect(plan([light], [near, far]).draws[0].hullCount).toBe(1);
    light.castsShadows = false;
    expect(plan([light], [near, far]).draws[0].hullCount).toBe(0);
  });
});

describe('FramePlan shadow casters', () => {
  const casters = (framePlan: FramePlan) => {
    const draw = framePlan.draws[0];
    return Array.from(framePlan.casters.subarray(draw.casterOffset, draw.casterOffset + draw.casterCount));
  };

  it('makes a convex hull clear of the light disk one caster, numbered -1 - its first point', () => {
    const far = new Hull([[80, 40], [90, 40], [90, 50], [80, 50]]);
    expect(casters(plan([new PointLight({ position: [30, 45], range: 100, radius: 10 })], [far]))).toEqual([-1]);
  });

  it('puts convex regions first, then concave ones, then their cavities, then the edges of hulls near the disk', () => {
    const u = new Hull([[80, 30], [100, 30], [100, 60], [80, 60], [80, 55], [95, 55], [95, 35], [80, 35]]);
    const near = new Hull([[40, 40], [50, 40], [50, 50], [40, 50]]);
    const far = new Hull([[80, 70], [90, 70], [90, 80], [80, 80]]);
    const light = new PointLight({ position: [30, 45], range: 100, radius: 10 });
    const framePlan = plan([light], [u, near, far]);
    // Points: u 0–7, near 8–11, far 12–15.
    expect(casters(framePlan)).toEqual([-13, -1, -1, 8, 9, 10, 11]);
    // Runs: convex regions, concave regions, cavities, edges; each of up to 4 points, up to 8, any size.
    expect(Array.from(framePlan.draws[0].runEnds)).toEqual([1, 1, 1, 1, 2, 2, 2, 3, 3, 7, 7, 7]);
    expect(framePlan.draws[0].regionCasterCount).toBe(2);
    light.radius = 1;
    expect(casters(plan([light], [near]))).toEqual([-1]);
  });

  it('sorts the hulls of each kind by size class: up to 4 points, up to 8, more', () => {
    expect([3, 4, 5, 8, 9, 100].map(sizeClassOf)).toEqual([0, 0, 1, 1, 2, 2]);
    const light = new PointLight({ position: [0, 0], range: 200, radius: 5 });
    const polygon = (count: number, x: number, y: number) => new Hull(Array.from({ length: count }, (_, i): [number, number] =>
      [x + 10 * Math.cos((2 * Math.PI * i) / count), y + 10 * Math.sin((2 * Math.PI * i) / count)]));
    const round = polygon(9, 100, 0), nearRound = polygon(10, 12, 0), square = polygon(4, 0, 100), hexagon = polygon(6, 100, 100);
    const framePlan = plan([light], [round, nearRound, square, hexagon]);
    // Points: round 0–8, nearRound 9–18, square 19–22, hexagon 23–28.
    expect(casters(framePlan)).toEqual([-20, -24, -1, ...Array.from({ length: 10 }, (_, i) => 9 + i)]);
    expect(Array.from(framePlan.draws[0].runEnds)).toEqual([1, 2, 3, 3, 3, 3, 3, 3, 3, 3, 3, 13]);
  });

  it('makes a hull near the disk one caster while its region opens at most 78° either side', () => {
    const light = new PointLight({ position: [40, 60], range: 100, radius: 10 });
    const box = (x: number) => new Hull([[x, 50], [x + 10, 50], [x + 10, 70], [x, 70]]);
    // Tangents through the near corners lean 33.7° off 33.7° (67° each side), then 39.8° off 39.8° (80°).
    expect(casters(plan([light], [box(55)]))).toEqual([-1]);
    expect(casters(plan([light], [box(52)]))).toEqual([0, 1, 2, 3]);
  });

  it('writes each light its reach: the range, or the farthest corner of a textured quad', () => {
    const framePlan = plan([new PointLight({ position: [50, 50], range: 40 })], []);
    expect(framePlan.draws[0].reach).toBe(40);
    // The plan never reads the cookie texture itself.
    const cookie = new TexturedLight({ position: [50, 50], range: 10, size: [40, 20], origin: [0, 0.5], texture: {} as WebGLTexture });
    expect(plan([cookie], []).draws[0].reach).toBeCloseTo(Math.sqrt(40 * 40 + 10 * 10), 9);
  });
});
