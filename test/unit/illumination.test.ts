import { afterAll, describe, expect, it } from 'vitest';
import { DiskVisibility, diskVisibleFraction } from '../../src/geometry/diskVisibility';
import { Hull, PointLight, ShadowType, Spotlight, TexturedLight, type Light } from '../../src/index';
import { IlluminationQuery, type Illumination, type IlluminationOptions } from '../../src/scene/illumination';
import { createRandom, randomScene } from '../reference/randomScenes';
import { SceneGeometry } from '../reference/sceneGeometry';
import { box, REFERENCE_SCENES, type Point, type ReferenceScene } from '../reference/scenes';
import { visibleFraction, type FractionOf } from '../reference/softShadowReference';
import { compareWithSampling, diskFraction, pointsOf } from './diskVisibilitySupport';

/**
 * The CPU light query behind `PenumbraRenderer.illuminationAt` and `isLit`, without GL:
 * - the disk visibility (src/geometry/diskVisibility.ts) against disk sampling, which shares no
 *   code with it (test/reference/softShadowReference.ts), on every reference scene and scenes made
 *   for each cut of its sweep, and against circular-cap areas of its own; the convex pieces'
 *   shortcut against the plain sweep;
 * - the query against the reference model (Σ falloff × visible fraction × colour × intensity) on
 *   the same scenes, and each rule of the renderer's model on its own: layers, ignored hulls,
 *   castsShadows, shadow colour and strength, Solid and Illuminated inside hulls, a light inside a
 *   hull, disabled lights and hulls, spotlight cones, textured lights' cookies, open polylines,
 *   ambient light; then the result's reuse, and isLit against illuminationAt.
 * The rendered lightmap itself is compared in test/gl/illumination.test.ts; test/accuracy/ holds
 * the denser sampling over random scenes and of the reference images.
 */

const figures: string[] = [];
afterAll(() => console.log(figures.join('\n')));

const RANDOM_SCENES = Array.from({ length: 150 }, (_, i) => randomScene(0x1000 + i, 80, 60));

describe('DiskVisibility', () => {
  /**
   * Disk samples of the sampling reference. The sunflower pattern's visible fraction errs by about
   * N^-3/4 (2.0e-3) per straight cut across the disk, and the visible part of a disk is cut by a
   * few (hull edges, rays past hull points): measured over the reference and random scenes, 1.4
   * N^-3/4 at worst and 0.1 N^-3/4 on average. The limits, 3 N^-3/4 at a point and 0.2 N^-3/4 on
   * average, leave room for more cuts. A closed form or a sign wrong fails both by far; a cut of
   * the sweep left out shows only where it splits a piece in front of the disk, which the scenes
   * below are made for. The same over 150 random scenes with denser sampling is
   * test/accuracy/diskVisibility.test.ts.
   */
  const SAMPLES = 4096;
  const SAMPLING_ERROR = SAMPLES ** -0.75;

  it(`matches disk sampling (${SAMPLES} points) on every reference scene, with and without convex hulls taken whole`, () => {
    const { worst, mean, evaluations, partial } = compareWithSampling(REFERENCE_SCENES, SAMPLES, 40);
    figures.push(`DiskVisibility vs disk sampling (N = ${SAMPLES}, N^-3/4 = ${SAMPLING_ERROR.toExponential(2)}): max ${worst.toExponential(2)}, mean ${mean.toExponential(2)} over ${evaluations} fractions (${partial} in penumbrae)`);
    expect(partial).toBeGreaterThan(300);
    expect(worst).toBeLessThan(3 * SAMPLING_ERROR);
    expect(mean).toBeLessThan(0.2 * SAMPLING_ERROR);
  });

  it('takes convex hulls whole as exactly as edge by edge, on every reference scene and 150 random scenes', () => {
    const { shortcutGap, evaluations } = compareWithSampling([...REFERENCE_SCENES, ...RANDOM_SCENES], 0, 40);
    expect(evaluations).toBeGreaterThan(10000);
    // Both ways are exact to rounding (seen: 2.4e-9, in pieces that graze an edge, where tan is steep).
    expect(shortcutGap).toBeLessThan(1e-7);
  });

  /**
   * Disks that edges cross, end in or cross each other in, so that every kind of cut of the sweep
   * (edge ends, rim crossings, crossings of two edges) splits a piece somewhere: random scenes meet
   * few of these where they matter. Seen from a grid of points in and around the disk, against
   * denser sampling (N^-3/4 = 6.9e-4): a cut left out costs a piece a sliver of a few degrees.
   */
  const CUT_SCENES = ([
    { name: 'an X of two fences crossing at the centre', polylines: [[[-4, -4], [4, 4]], [[-4, 4], [4, -4]]], hulls: [] },
    { name: 'a fence ending inside the disk', polylines: [[[-20, 1], [2, 1]]], hulls: [] },
    { name: 'a fence across the disk and a box it crosses there', polylines: [[[-12, -2], [12, 3]]], hulls: [box(-1, -8, 3, 7)] },
    { name: 'a triangle reaching into the disk', hulls: [[[2, 2], [9, -1], [9, 6]]] },
  ] satisfies Pick<ReferenceScene, 'name' | 'hulls' | 'polylines'>[]).map((scene): ReferenceScene => ({ ...scene, width: 0, height: 0, lights: [{ position: [0, 0], range: 1000, radius: 5 }] }));
  const DENSE_SAMPLES = 16384;

  for (const scene of CUT_SCENES) {
    it(`matches denser disk sampling (${DENSE_SAMPLES} points) where each cut matters: ${scene.name}`, () => {
      const geometry = new SceneGeometry(scene.hulls, scene.polylines);
      const sampled = visibleFraction(scene, { method: 'sampled', samples: DENSE_SAMPLES });
      const visibility = new DiskVisibility();
      let worst = 0, partial = 0;
      for (let x = -24.5; x <= 25; x += 3.5) {
        for (let y = -24.5; y <= 25; y += 3.5) {
          if (geometry.isInsideHull(x, y) || geometry.isNearOutline(x, y, 1e-6)) continue;
          const expected = sampled(x, y, scene.lights[0]);
          for (const shortcut of [true, false]) worst = Math.max(worst, Math.abs(diskFraction(visibility, scene, x, y, scene.lights[0], shortcut) - expected));
          if (expected > 0.01 && expected < 0.99) partial++;
        }
      }
      expect(partial).toBeGreaterThan(20);
      expect(worst).toBeLessThan(3 * DENSE_SAMPLES ** -0.75);
    });
  }

  /** Area of the part of a disk of radius r beyond a chord at distance h from its centre. */
  const capArea = (r: number, h: number) => r * r * Math.acos(h / r) - h * Math.sqrt(r * r - h * h);

  it('gives circular-cap areas: a long wall across the disk, seen from inside the disk and from beside it', () => {
    const r = 5, wall = (y: number) => ({ points: [-100, y, 100, y], closed: false });
    // From the centre's side of a wall 2 above it, the cap beyond the wall is hidden.
    for (const [px, py] of [[0, 0], [1, -3], [-2, 1]]) {
      expect(diskVisibleFraction(px, py, 0, 0, r, [wall(2)])).toBeCloseTo(1 - capArea(r, 2) / (Math.PI * r * r), 9);
      expect(diskVisibleFraction(px, py, 0, 0, r, [wall(-4.5)])).toBeCloseTo(1 - capArea(r, 4.5) / (Math.PI * r * r), 9);
    }
    // From beyond the wall only that cap is seen.
    expect(diskVisibleFraction(0, 30, 0, 0, r, [wall(2)])).toBeCloseTo(capArea(r, 2) / (Math.PI * r * r), 9);
    // A closed hull over the far half hides it from a point below: the half disk inside the hull too.
    expect(diskVisibleFraction(3, -20, 0, 0, r, [{ points: [-50, 0, 50, 0, 50, 50, -50, 50], closed: true }])).toBeCloseTo(0.5, 9);
  });

  it('is a segment test for radius 0, and 1 with nothing in the way', () => {
    const post = [{ points: box(10, -1, 2, 2).flat(), closed: true }];
    expect(diskVisibleFraction(0, 0, 20, 0, 0, post)).toBe(0);
    expect(diskVisibleFraction(0, 0, 20, 3, 0, post)).toBe(1);
    expect(diskVisibleFraction(0, 0, 20, 0, 4, [])).toBe(1);
    expect(diskVisibleFraction(0, 0, 20, 0, 4, [{ points: box(30, -1, 2, 2).flat(), closed: true }])).toBe(1);
  });
});

/** The scene's lights (Solid, as the reference's) and hulls as the library's objects. */
function objectsOf(scene: ReferenceScene): { lights: Light[]; hulls: Hull[] } {
  return {
    lights: scene.lights.map(({ position, range, radius, color, intensity }) => new PointLight({ position, range, radius, color, intensity, shadowType: ShadowType.Solid })),
    hulls: [...scene.hulls.map((points) => new Hull(points)), ...(scene.polylines ?? []).map((points) => new Hull(points, { closed: false }))],
  };
}

/** The reference model at a point: Σ falloff × visible fraction × colour × intensity, 0 inside a hull. */
function referenceAt(scene: ReferenceScene, geometry: SceneGeometry, fraction: FractionOf, px: number, py: number): number[] {
  const sum = [0, 0, 0];
  if (geometry.isInsideHull(px, py)) return sum;
  for (const light of scene.lights) {
    const { position: [lx, ly], range, color = [1, 1, 1], intensity = 1 } = light;
    const falloff = Math.max(0, 1 - Math.hypot(px - lx, py - ly) / range);
    if (falloff === 0) continue;
    const visible = fraction(px, py, light);
    for (let c = 0; c < 3; c++) sum[c] += falloff * visible * color[c] * intensity;
  }
  return sum;
}

const AMBIENT_OFF = Object.freeze([0, 0, 0] as const);

/** A query with fresh state, as a new renderer's first call. */
function illuminationAt(lights: readonly Light[], hulls: readonly Hull[], x: number, y: number, options: IlluminationOptions = {}, ambient: readonly [number, number, number] = AMBIENT_OFF): Illumination {
  return new IlluminationQuery().at(lights, hulls, ambient, x, y, options, undefined);
}

/** The red channel a lone white light gives (x, y). */
const redAt = (lights: readonly Light[], hulls: readonly Hull[], x: number, y: number) => illuminationAt(lights, hulls, x, y).color[0];

describe('IlluminationQuery against the reference model', () => {
  it('matches on every reference scene and 150 random scenes (within 1e-6)', () => {
    let worst = 0, worstParts = 0, points = 0;
    for (const scene of [...REFERENCE_SCENES, ...RANDOM_SCENES]) {
      const geometry = new SceneGeometry(scene.hulls, scene.polylines);
      const fraction = visibleFraction(scene);
      const { lights, hulls } = objectsOf(scene);
      const query = new IlluminationQuery();
      for (const [px, py] of pointsOf(scene, geometry, 150, 11)) {
        const expected = referenceAt(scene, geometry, fraction, px, py);
        const got = query.at(lights, hulls, AMBIENT_OFF, px, py, { perLight: true }, undefined);
        for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(got.color[c] - expected[c]));
        const parts = got.lights.reduce((sum, entry) => sum + entry.color[0], 0);
        worstParts = Math.max(worstParts, Math.abs(parts - got.color[0]));
        points++;
      }
    }
    figures.push(`illuminationAt vs the reference model: max difference ${worst.toExponential(2)} over ${points} points`);
    expect(worst).toBeLessThan(1e-6);
    // The parts add up to the whole, to rounding.
    expect(worstParts).toBeLessThan(5e-13);
  });
});

describe('IlluminationQuery: the rules of the renderer\'s model', () => {
  // A light left of two boxes, one per layer; points behind each.
  const LIGHT = { position: [20, 50] as Point, range: 200, radius: 4 };
  const behindWall: Point = [100, 30], behindCrate: Point = [100, 70], open: Point = [100, 50];
  const layered = () => ({ wall: new Hull(box(50, 20, 6, 26), { layers: 0b01 }), crate: new Hull(box(50, 54, 6, 26), { layers: 0b10 }) });
  const falloffAt = ([x, y]: Point, [lx, ly] = LIGHT.position, range = LIGHT.range) => Math.max(0, 1 - Math.hypot(x - lx, y - ly) / range);

  it('shadows a light only by hulls sharing a layer with its shadowLayers', () => {
    const { wall, crate } = layered();
    const at = (mask: number, point: Point) => redAt([new PointLight({ ...LIGHT, shadowLayers: mask })], [wall, crate], ...point);
    expect(at(0b01, behindWall)).toBe(0);
    expect(at(0b01, behindCrate)).toBeCloseTo(falloffAt(behindCrate), 9);
    expect(at(0b10, behindWall)).toBeCloseTo(falloffAt(behindWall), 9);
    expect(at(0b10, behindCrate)).toBe(0);
    expect(at(0b11, behindWall) + at(0b11, behindCrate)).toBe(0);
    expect(at(0, behindWall)).toBeCloseTo(falloffAt(behindWall), 9);
  });

  it('counts only the lights whose litLayers share a bit with the content layers asked for', () => {
    const warm = new PointLight({ ...LIGHT, color: [1, 0.5, 0.2], litLayers: 0b01 });
    const cold = new PointLight({ ...LIGHT, position: [30, 60], color: [0.2, 0.5, 1], litLayers: 0b10 });
    const point: Point = [80, 50];
    const both = illuminationAt([warm, cold], [], ...point);
    const warmOnly = illuminationAt([warm, cold], [], ...point, { layers: 0b01 });
    const coldOnly = illuminationAt([warm, cold], [], ...point, { layers: 0b10 });
    expect(warmOnly.lights.map((entry) => entry.light)).toEqual([warm]);
    expect(coldOnly.lights.map((entry) => entry.light)).toEqual([cold]);
    both.color.forEach((c, i) => expect(c).toBeCloseTo(warmOnly.color[i] + coldOnly.color[i], 12));
    expect(illuminationAt([warm, cold], [], ...point, { layers: 0 }).color).toEqual([0, 0, 0]);
    const query = new IlluminationQuery();
    expect(query.isLit([warm, cold], [], ...point, warmOnly.luminance - 1e-9, null, 0b01)).toBe(true);
    expect(query.isLit([warm, cold], [], ...point, warmOnly.luminance + 1e-9, null, 0b01)).toBe(false);
  });

  it('passes through ignored hulls, and through every hull without castsShadows', () => {
    const { wall, crate } = layered();
    const ignoring = new PointLight({ ...LIGHT, ignoredHulls: [wall] });
    expect(redAt([ignoring], [wall, crate], ...behindWall)).toBeCloseTo(falloffAt(behindWall), 9);
    expect(redAt([ignoring], [wall, crate], ...behindCrate)).toBe(0);
    ignoring.ignoredHulls.delete(wall);
    expect(redAt([ignoring], [wall, crate], ...behindWall)).toBe(0);
    const unshadowed = new PointLight({ ...LIGHT, castsShadows: false });
    expect(illuminationAt([unshadowed], [wall, crate], ...behindCrate).lights[0].visibility).toBe(1);
  });

  it('keeps 1 − strength × (1 − shadowColor) of the light in full shadow, and mixes by the visible fraction in the penumbra', () => {
    const { wall } = layered();
    const light = new PointLight({ ...LIGHT, color: [1, 0.8, 0.6], intensity: 1.5, shadowColor: [0.2, 0.5, 0.9], shadowStrength: 0.6 });
    const kept = [0.2, 0.5, 0.9].map((c) => 1 - 0.6 * (1 - c));
    const umbra = illuminationAt([light], [wall], ...behindWall);
    expect(umbra.lights[0].visibility).toBe(0);
    [1, 0.8, 0.6].forEach((c, i) => expect(umbra.color[i]).toBeCloseTo(falloffAt(behindWall) * 1.5 * c * kept[i], 9));
    // In the penumbra: v + (1 − v) × kept of the full light.
    const edge: Point = [100, 41.5];
    const penumbra = illuminationAt([light], [wall], ...edge);
    const v = penumbra.lights[0].visibility;
    expect(v).toBeGreaterThan(0.05);
    expect(v).toBeLessThan(0.95);
    [1, 0.8, 0.6].forEach((c, i) => expect(penumbra.color[i]).toBeCloseTo(falloffAt(edge) * 1.5 * c * (v + (1 - v) * kept[i]), 9));
    expect(penumbra.luminance).toBeCloseTo(0.2126 * penumbra.color[0] + 0.7152 * penumbra.color[1] + 0.0722 * penumbra.color[2], 12);
  });

  it('keeps a point inside a hull dark for a Solid light and lit for an Illuminated one', () => {
    const hull = new Hull(box(50, 40, 10, 20));
    const inside: Point = [55, 50];
    const solid = new PointLight({ ...LIGHT, shadowType: ShadowType.Solid });
    const illuminated = new PointLight({ ...LIGHT, shadowType: ShadowType.Illuminated });
    expect(redAt([solid], [hull], ...inside)).toBe(0);
    expect(redAt([illuminated], [hull], ...inside)).toBeCloseTo(falloffAt(inside), 9);
    // Behind the hull both are shadowed; an open polyline has no inside.
    expect(redAt([illuminated], [hull], 100, 50)).toBe(0);
    const fence = new Hull([[50, 40], [60, 40], [60, 60], [50, 60]], { closed: false });
    expect(redAt([solid], [fence], ...inside)).toBeGreaterThan(0);
  });

  it('hides the part of a light\'s disk inside a hull: all of it for a disk wholly inside, the rest still shining', () => {
    const hull = new Hull(box(10, 40, 20, 20), { layers: 0b01 });
    const trapped = new PointLight({ ...LIGHT });
    expect(illuminationAt([trapped], [hull], 40, 50).lights.map(({ visibility }) => visibility)).toEqual([0]);
    expect(redAt([trapped], [hull], 40, 50)).toBe(0);
    // The disk (x 16..24) reaching 2 units past the hull's right side (x = 22): that part shines,
    // a sliver of the disk between chords 0.5 and 1 of its radius.
    const halfIn = illuminationAt([trapped], [new Hull(box(10, 40, 12, 20))], 40, 50).lights[0].visibility;
    expect(halfIn).toBeCloseTo((Math.acos(0.5) - 0.5 * Math.sqrt(0.75)) / Math.PI, 3);
    // Not when the hull is in another layer, ignored, disabled or open, or the light casts no shadows.
    expect(redAt([new PointLight({ ...LIGHT, shadowLayers: 0b10 })], [hull], 40, 50)).toBeCloseTo(falloffAt([40, 50]), 9);
    expect(redAt([new PointLight({ ...LIGHT, ignoredHulls: [hull] })], [hull], 40, 50)).toBeCloseTo(falloffAt([40, 50]), 9);
    expect(redAt([new PointLight({ ...LIGHT, castsShadows: false })], [hull], 40, 50)).toBeCloseTo(falloffAt([40, 50]), 9);
    expect(redAt([trapped], [new Hull(box(10, 40, 20, 20), { enabled: false })], 40, 50)).toBeCloseTo(falloffAt([40, 50]), 9);
    // The polyline's open side (x = 10) lets the light out to the left.
    expect(redAt([trapped], [new Hull(box(10, 40, 20, 20), { closed: false })], 0, 50)).toBeGreaterThan(0);
  });

  it('skips disabled lights, lights of intensity or range 0, disabled and invalid hulls', () => {
    const { wall } = layered();
    expect(illuminationAt([new PointLight({ ...LIGHT, enabled: false })], [], ...open).lights).toEqual([]);
    expect(illuminationAt([new PointLight({ ...LIGHT, intensity: 0 })], [], ...open).lights).toEqual([]);
    expect(illuminationAt([new PointLight({ ...LIGHT, range: 0 })], [], ...open).lights).toEqual([]);
    wall.enabled = false;
    expect(redAt([new PointLight(LIGHT)], [wall], ...behindWall)).toBeCloseTo(falloffAt(behindWall), 9);
    const invalid = new Hull([[50, 20], [56, 40], [56, 20], [50, 40]]);
    expect(invalid.valid).toBe(false);
    expect(redAt([new PointLight(LIGHT)], [invalid], ...behindWall)).toBeCloseTo(falloffAt(behindWall), 9);
    // Beyond the range: nothing, and not listed.
    expect(illuminationAt([new PointLight({ ...LIGHT, range: 50 })], [], ...open).lights).toEqual([]);
  });

  it('applies a spotlight\'s cone: (1 − θ / half angle) ^ decay inside, 0 outside', () => {
    const spot = (coneDecay: number) => new Spotlight({ position: [0, 0], range: 100, radius: 0, rotation: Math.PI / 2, coneAngle: (2 * Math.PI) / 3, coneDecay });
    // 30° off the axis (+y) at distance 40, half angle 60°: 1 − ½.
    const point: Point = [40 * Math.sin(Math.PI / 6), 40 * Math.cos(Math.PI / 6)];
    expect(redAt([spot(1)], [], ...point)).toBeCloseTo(0.6 * 0.5, 9);
    expect(redAt([spot(2.5)], [], ...point)).toBeCloseTo(0.6 * 0.5 ** 2.5, 9);
    expect(redAt([spot(0)], [], ...point)).toBeCloseTo(0.6, 9);
    expect(illuminationAt([spot(1)], [], 40, -5).lights).toEqual([]); // 97° off: outside
    expect(illuminationAt([spot(1)], [], 0, 40).lights[0].strength).toBeCloseTo(0.6, 9); // on the axis
    // Shadows as a point light's.
    expect(redAt([spot(1)], [new Hull(box(-5, 10, 10, 4))], 0, 40)).toBe(0);
  });

  it('blocks light with open polylines from both sides, and lets it round their ends', () => {
    const fence = new Hull([[50, 30], [50, 70]], { closed: false });
    const light = new PointLight({ position: [20, 50], range: 200, radius: 0 });
    expect(redAt([light], [fence], 80, 50)).toBe(0);
    expect(redAt([light], [fence], 80, 100)).toBeGreaterThan(0);
    const beyond = new PointLight({ position: [80, 50], range: 200, radius: 0 });
    expect(redAt([beyond], [fence], 20, 50)).toBe(0);
    // A polyline is not closed: its last point does not join its first.
    const hook = new Hull([[50, 30], [70, 30], [70, 70], [50, 70]], { closed: false });
    expect(redAt([light], [hook], 60, 50)).toBeGreaterThan(0);
  });

  it('follows hulls placed by position, rotation and scale, and every change to them', () => {
    const light = new PointLight({ position: [20, 50], range: 200, radius: 2 });
    const hull = new Hull(box(0, 0, 12, 40), { position: [50, 40], origin: [6, 20], rotation: Math.PI / 2 });
    // Turned a quarter: 40 wide, 12 tall around (50, 40): it shadows (100, 35), not (100, 62).
    expect(redAt([light], [hull], 100, 35)).toBe(0);
    expect(redAt([light], [hull], 100, 62)).toBeCloseTo(falloffAt([100, 62], [20, 50]), 9);
    const query = new IlluminationQuery();
    const at = (x: number, y: number) => query.at([light], [hull], AMBIENT_OFF, x, y, {}, undefined).color[0];
    expect(at(100, 35)).toBe(0);
    hull.setPosition(50, 60);
    expect(at(100, 35)).toBeGreaterThan(0.4);
    expect(at(100, 62)).toBe(0);
    // 4 wide now: light passes below it.
    hull.scale = [1, 0.1];
    expect(at(100, 62)).toBeGreaterThan(0);
    hull.enabled = false;
    expect(at(100, 35)).toBeGreaterThan(0.4);
  });

  it('reads a textured light\'s cookie through the sampler at the quad\'s (u, v), 1 without one', () => {
    const texture = {} as WebGLTexture;
    // A 40 × 20 quad, pivot at its top-left corner, turned a quarter: +u runs along +y, +v along −x.
    const light = new TexturedLight({ texture, position: [50, 50], size: [40, 20], origin: [0, 0], rotation: Math.PI / 2, range: 30 });
    const seen: number[][] = [];
    const cookie = (from: TexturedLight, u: number, v: number) => {
      expect(from).toBe(light);
      seen.push([u, v]);
      return 0.25 + 0.5 * u;
    };
    const result = illuminationAt([light], [], 45, 80, { cookie });
    expect(seen[0][0]).toBeCloseTo(0.75, 6);
    expect(seen[0][1]).toBeCloseTo(0.25, 6);
    expect(result.color[0]).toBeCloseTo(0.25 + 0.5 * 0.75, 6);
    expect(result.lights[0].strength).toBeCloseTo(0.625, 6);
    expect(redAt([light], [], 45, 80)).toBe(1);
    // Outside the quad: nothing, and the sampler is not asked.
    seen.length = 0;
    expect(illuminationAt([light], [], 55, 80, { cookie }).lights).toEqual([]);
    expect(seen).toEqual([]);
  });

  it('adds the ambient colour unless told not to, and lists the lights unless told not to', () => {
    const ambient = [0.1, 0.2, 0.3] as const;
    const lights = [new PointLight({ ...LIGHT, color: [1, 0, 0] }), new PointLight({ position: [180, 50], range: 100, color: [0, 0, 1] })];
    const all = illuminationAt(lights, [], ...open, {}, ambient);
    expect(all.color[0]).toBeCloseTo(0.1 + falloffAt(open), 12);
    expect(all.color[1]).toBeCloseTo(0.2, 12);
    expect(all.color[2]).toBeCloseTo(0.3 + falloffAt(open, [180, 50], 100), 12);
    expect(all.lights.map((entry) => entry.light)).toEqual(lights);
    const lightsOnly = illuminationAt(lights, [], ...open, { includeAmbient: false, perLight: false }, ambient);
    expect(lightsOnly.color[1]).toBe(0);
    expect(lightsOnly.lights).toEqual([]);
    expect(lightsOnly.luminance).toBeCloseTo(all.luminance - (0.2126 * 0.1 + 0.7152 * 0.2 + 0.0722 * 0.3), 12);
  });

  it('reuses `out`: the same object, colour arrays and entries, the list cut to the lights listed and grown from the entries cut', () => {
    const lights = [new PointLight({ ...LIGHT }), new PointLight({ position: [60, 50], range: 30 })];
    const query = new IlluminationQuery();
    const out = query.at(lights, [], AMBIENT_OFF, 70, 50, {}, undefined);
    expect(out.lights.length).toBe(2);
    const [first, second] = out.lights, color = out.color;
    const again = query.at(lights, [], AMBIENT_OFF, 120, 50, {}, out);
    expect(again).toBe(out);
    expect(again.color).toBe(color);
    expect(again.lights).toEqual([first]);
    expect(again.lights[0]).toBe(first);
    expect(first.color[0]).toBeCloseTo(falloffAt([120, 50]), 12);
    query.at(lights, [], AMBIENT_OFF, 70, 50, {}, out);
    expect(out.lights[1]).toBe(second); // grown again from the entry cut
    expect(out.lights[1].light).toBe(lights[1]);
    expect(out.lights[1].color[0]).toBeCloseTo(falloffAt([70, 50], [60, 50], 30), 12);
  });
});

describe('isLit', () => {
  it('agrees with illuminationAt\'s luminance without ambient, at random points and thresholds of random scenes', () => {
    let decided = 0;
    const wrong: string[] = [];
    for (const scene of RANDOM_SCENES.slice(0, 60)) {
      const { lights, hulls } = objectsOf(scene);
      const random = createRandom(scene.lights.length * 7919 + scene.hulls.length);
      lights.forEach((light) => {
        if (random() < 0.3) light.castsShadows = false;
        if (random() < 0.3) light.shadowColor = [random(), random(), random()];
      });
      const query = new IlluminationQuery();
      for (let k = 0; k < 60; k++) {
        const x = random() * scene.width, y = random() * scene.height, threshold = random() * 0.6;
        const luminance = query.at(lights, hulls, [0.5, 0.5, 0.5], x, y, { includeAmbient: false, perLight: false }, undefined).luminance;
        if (Math.abs(luminance - threshold) < 1e-9) continue;
        if (query.isLit(lights, hulls, x, y, threshold, null) !== luminance > threshold) wrong.push(`${scene.name} (${x}, ${y}) ${luminance} vs ${threshold}`);
        decided++;
      }
    }
    expect(wrong).toEqual([]);
    expect(decided).toBeGreaterThan(3000);
  });

  it('counts a light whose centre is inside a hull as nothing, and shadowed light as what its shadow keeps', () => {
    const hull = new Hull(box(10, 40, 20, 20));
    const query = new IlluminationQuery();
    expect(query.isLit([new PointLight({ position: [20, 50], range: 100 })], [hull], 40, 50, 0.01, null)).toBe(false);
    const light = new PointLight({ position: [0, 50], range: 100, shadowStrength: 0.5 });
    // Behind the hull at falloff 0.6: half of it kept (0.3).
    expect(query.isLit([light], [hull], 40, 50, 0.29, null)).toBe(true);
    expect(query.isLit([light], [hull], 40, 50, 0.31, null)).toBe(false);
  });
});
