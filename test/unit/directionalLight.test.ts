import { afterAll, describe, expect, it } from 'vitest';
import { DirectionalLight, Hull, ShadowType } from '../../src/index';
import { IlluminationQuery } from '../../src/scene/illumination';
import { computeDirectionalReference } from '../reference/directionalReference';
import { box, type Point } from '../reference/scenes';
import { messageOf } from './thrown';

/**
 * The directional light: its class, `illuminationAt` for it (src/scene/illumination.ts) and the
 * reference that samples its disk at infinity (test/reference/directionalReference.ts) against the
 * closed form for a half-plane wall, and isLit. illuminationAt against that reference on scenes of
 * every rule (layers, ignored hulls, Occluded, hulls far upstream) is
 * test/accuracy/directionalLight.test.ts.
 */

const figures: string[] = [];
afterAll(() => console.log(figures.join('\n')));

describe('DirectionalLight', () => {
  it('has the sun as its default and no position, range or bounds', () => {
    const light = new DirectionalLight();
    expect(light.kind).toBe('directional');
    expect(light.angularSize).toBe(0.0093);
    expect(light).toMatchObject({ rotation: 0, intensity: 1, color: [1, 1, 1], shadowType: ShadowType.Illuminated, castsShadows: true, enabled: true });
    expect(light.reach()).toBe(Infinity);
    expect(light.isConfinedToRangeDisk()).toBe(false);
    const overcast = new DirectionalLight({ rotation: 2, angularSize: Math.PI / 2, shadowType: ShadowType.Occluded, shadowLayers: 4 });
    expect(overcast).toMatchObject({ rotation: 2, angularSize: Math.PI / 2, shadowType: ShadowType.Occluded, shadowLayers: 4 });
    overcast.angularSize = 0;
    expect(overcast.angularSize).toBe(0);
  });

  it('checks angularSize (0..π/2) and the inherited options, naming DirectionalLight and the value', () => {
    const cases: [unknown, ErrorConstructor, string][] = [
      [-0.5, RangeError, 'DirectionalLight.angularSize must not be negative, got -0.5'],
      [2, RangeError, 'DirectionalLight.angularSize must be at most π/2, got 2'],
      [NaN, RangeError, 'DirectionalLight.angularSize must be a finite number, got NaN'],
      [Infinity, RangeError, 'DirectionalLight.angularSize must be a finite number, got Infinity'],
      ['0.1', TypeError, 'DirectionalLight.angularSize must be a finite number, got "0.1"'],
    ];
    for (const [value, type, message] of cases) {
      expect(messageOf(() => new DirectionalLight({ angularSize: value as number }), type)).toBe(message);
      const light = new DirectionalLight({ angularSize: 0.2 });
      expect(messageOf(() => { light.angularSize = value as number; }, type)).toBe(message);
      expect(light.angularSize).toBe(0.2);
    }
    expect(messageOf(() => new DirectionalLight({ rotation: NaN }), RangeError)).toBe('DirectionalLight.rotation must be a finite number, got NaN');
    expect(messageOf(() => new DirectionalLight({ intensity: -1 }), RangeError)).toBe('DirectionalLight.intensity must not be negative, got -1');
    expect(messageOf(() => new DirectionalLight({ shadowLayers: 0.5 }), RangeError))
      .toBe('DirectionalLight.shadowLayers must be an integer from 0 to 0xffffffff (a bit mask), got 0.5');
    expect(messageOf(() => new DirectionalLight(null as unknown as object), TypeError)).toBe('DirectionalLight options must be an object, got null');
  });
});

/** The area fraction of the unit disk below the chord at height t ∈ [−1, 1] (clamped outside). */
function belowChord(t: number): number {
  const c = Math.max(-1, Math.min(1, t));
  return 0.5 + (Math.asin(c) + c * Math.sqrt(1 - c * c)) / Math.PI;
}

describe('a half-plane wall: the reference and illuminationAt against the closed form', () => {
  // The light travels along +x (rotation 0), so u = (−1, 0) points at it. A wall along x = −10
  // runs from its end at y = e up to e − 50,000 (beyond any ray here). From p = (100.5, 0.5) the
  // ray at angle θ off u (towards −y for θ > 0) passes x = −10 at 0.5 − 110.5 tan θ: it is blocked
  // for θ ≥ φ, where it grazes the wall's end (tan φ = (0.5 − e) / 110.5). The part of the disk
  // seen lies below the chord at height sin φ / sin α: v = G(sin φ / sin α).
  const px = 100.5, py = 0.5;
  const wallEndingAt = (end: number): Point[] => [[-10, end], [-10, end - 50_000]];
  const query = new IlluminationQuery();
  for (const angularSize of [Math.PI / 2, 0.6, 0.05]) {
    it(`angularSize ${angularSize.toFixed(3)}`, () => {
      const alpha = angularSize / 2, light = new DirectionalLight({ angularSize });
      let worstReference = 0, worstQuery = 0;
      for (const share of [-0.98, -0.7, -0.4, -0.1, 0, 0.2, 0.5, 0.8, 0.97]) {
        // Hulls keep float32 world points: the end as stored sets the exact angle.
        const end = Math.fround(py - (px + 10) * Math.tan(share * alpha)), wall = wallEndingAt(end);
        const expected = belowChord(Math.sin(Math.atan((py - end) / (px + 10))) / Math.sin(alpha));
        // One row of pixels: the last one's centre is p.
        const reference = computeDirectionalReference({
          name: 'half-plane', width: 101, height: 1, light: { rotation: 0, angularSize }, shadowType: 'solid', hulls: [], polylines: [wall],
        });
        worstReference = Math.max(worstReference, Math.abs(reference.visibility[0][100] - expected));
        const seen = query.at([light], [new Hull(wall, { closed: false })], [0, 0, 0], px, py, {}, undefined).lights[0].visibility;
        worstQuery = Math.max(worstQuery, Math.abs(seen - expected));
      }
      figures.push(`half-plane wall, angularSize ${angularSize.toFixed(3)}: reference within ${worstReference.toExponential(1)}, illuminationAt within ${worstQuery.toExponential(1)} of G(sin φ / sin α)`);
      // The sunflower's error for a disk cut by a line: about N^-3/4 (2e-3 at 4,096 samples).
      expect(worstReference).toBeLessThan(3e-3);
      expect(worstQuery).toBeLessThan(1e-9);
    });
  }
});

describe('isLit for a directional light', () => {
  it('agrees with illuminationAt', () => {
    // A wall under a low sun: lit, shadowed and penumbra points, Illuminated inside the wall.
    const hulls = [new Hull(box(50, 20, 8, 50))];
    const lights = [new DirectionalLight({ rotation: 0.25, angularSize: 0.15, color: [1, 0.9, 0.7], intensity: 1.3, shadowType: ShadowType.Illuminated })];
    const query = new IlluminationQuery();
    let shadowed = 0;
    for (let y = 0.5; y < 120; y += 3) {
      for (let x = 0.5; x < 160; x += 3) {
        const luminance = query.at(lights, hulls, [0, 0, 0], x, y, {}, undefined).luminance;
        if (luminance < 0.5) shadowed++;
        for (const threshold of [0.2, 0.5, 0.9]) expect(query.isLit(lights, hulls, x, y, threshold, null)).toBe(luminance > threshold);
      }
    }
    expect(shadowed).toBeGreaterThan(50);
  });
});
