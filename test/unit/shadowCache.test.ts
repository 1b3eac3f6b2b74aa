import { mat4 } from 'gl-matrix';
import { describe, expect, it, vi } from 'vitest';
import { ShadowCache } from '../../src/shadow/ShadowCache';
import { signedArea2 } from '../../src/geometry/polygon';
import { BIN_COUNT, BIN_FLOATS, ENTRY_FLOATS, ENTRY_MAX_RECORDS, MOVING_LIST, RECORD_FLOATS, STILL_LIST } from '../../src/shadow/shadowLayout';
import { ShadowGeometry } from '../../src/shadow/ShadowGeometry';
import { Hull, PointLight, TexturedLight, type Light } from '../../src/index';

const WIDTH = 200, HEIGHT = 100;
const pixelSpace = mat4.ortho(mat4.create(), 0, WIDTH, HEIGHT, 0, -1, 1);

function plan(lights: Light[], hulls: Hull[]): ShadowCache {
  const geometry = new ShadowGeometry();
  geometry.update(hulls);
  const shadowCache = new ShadowCache();
  shadowCache.build(lights, hulls, geometry, pixelSpace, WIDTH, HEIGHT);
  return shadowCache;
}

const drawnLights = (shadowCache: ShadowCache) => shadowCache.draws.slice(0, shadowCache.drawCount).map((d) => d.light);

describe('ShadowCache culling', () => {
  it('draws a light whose quad reaches into the target by any part of a pixel, and only such a light', () => {
    const light = new PointLight({ position: [50, 50], range: 20 });
    expect(drawnLights(plan([light], []))).toEqual([light]);
    const corner = new PointLight({ position: [5, 5], range: 20 });
    expect(drawnLights(plan([corner], []))).toEqual([corner]);
    // Quads from x = -40.5 to -0.5 and from -39.5 to 0.5: only the second covers part of pixel column 0.
    expect(plan([new PointLight({ position: [-20.5, 50], range: 20 })], []).drawCount).toBe(0);
    expect(plan([new PointLight({ position: [-19.5, 50], range: 20 })], []).drawCount).toBe(1);
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

  it('draws a light whose centre is inside a hull, shadowed by it unless it ignores it', () => {
    const housing = new Hull([[40, 40], [60, 40], [60, 60], [40, 60]]);
    const inside = new PointLight({ position: [50, 50], range: 30 });
    const held = plan([inside], [housing]);
    expect(drawnLights(held)).toEqual([inside]);
    expect(held.draws[0].hullCount).toBe(1);
    inside.ignoredHulls.add(housing);
    const shadowCache = plan([inside], [housing]);
    expect(drawnLights(shadowCache)).toEqual([inside]);
    expect(shadowCache.draws[0].hullCount).toBe(0);
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

/** The entries of bin `bin` of the draw's light, its still hulls' list then its moving list's, each nearest first (as the shader walks them). */
function entriesOfBin(shadowCache: ShadowCache, draw: ShadowCache['draws'][number], bin: number): number[] {
  const bins = shadowCache.bins.bins, b = (draw.binRow * BIN_COUNT + bin) * BIN_FLOATS;
  const out: number[] = [];
  for (const list of [STILL_LIST, MOVING_LIST]) for (let e = bins[b + list]; e < bins[b + list] + bins[b + list + 1]; e++) out.push(e);
  return out;
}

/** The entries of bin `bin` of the first draw's light: `[first record, record count, circle x, y, radius, fan (1 or 0)]` each. */
function binEntries(shadowCache: ShadowCache, bin: number): number[][] {
  const entries = shadowCache.bins.entries;
  const out: number[][] = [];
  for (const e of entriesOfBin(shadowCache, shadowCache.draws[0], bin)) {
    const code = entries[e * ENTRY_FLOATS], records = Math.floor(code / 2);
    out.push([Math.floor(records / ENTRY_MAX_RECORDS), (records % ENTRY_MAX_RECORDS) + 1, ...entries.subarray(e * ENTRY_FLOATS + 1, e * ENTRY_FLOATS + 4), code % 2]);
  }
  return out;
}

/**
 * The bins' pseudo-angle of the direction (x, y), not zero, in [0, 4) (shadowLayout.ts defines it):
 * where the ray meets the diamond |x| + |y| = 1, as the distance walked along its sides
 * counter-clockwise from (1, 0), one per side (0 along +x, 1 along +y, 2 along −x, 3 along −y).
 * Here the quarter comes from atan2, the place along that quarter's side from the direction turned
 * back into the first quarter.
 */
function diamondAngle(x: number, y: number): number {
  const quarter = Math.floor((((Math.atan2(y, x) / (Math.PI / 2)) % 4) + 4) % 4);
  // (x, y) turned clockwise by `quarter` quarter turns: u, v ≥ 0 (up to rounding at the sides).
  const [u, v] = [[x, y], [y, -x], [-x, -y], [-y, x]][quarter];
  const angle = quarter + v / (Math.abs(u) + Math.abs(v));
  return angle < 0 ? angle + 4 : angle >= 4 ? angle - 4 : angle;
}

/** The bin of the direction from the light at `from` to `to`. */
function binOf(from: readonly [number, number], to: readonly [number, number]): number {
  return Math.floor(diamondAngle(to[0] - from[0], to[1] - from[1]) * (BIN_COUNT / 4));
}

/** The bins of the directions `degrees` off +x from `centre`. */
function binAt(centre: readonly [number, number], degrees: number): number {
  return binOf(centre, [centre[0] + Math.cos((degrees * Math.PI) / 180), centre[1] + Math.sin((degrees * Math.PI) / 180)]);
}

describe('ShadowCache shadow bins', () => {
  const box = (x: number, y: number, w = 10, h = 10) => new Hull([[x, y], [x + w, y], [x + w, y + h], [x, y + h]]);
  const light = (position: [number, number], radius: number) => new PointLight({ position, range: 160, radius });

  it('files a hull in the bins of its direction only', () => {
    const centre: [number, number] = [30, 45];
    const shadowCache = plan([light(centre, 2)], [box(80, 40)]);
    expect(binEntries(shadowCache, binAt(centre, 0)).map(([record, count]) => [record, count])).toEqual([[0, 1]]);
    for (const degrees of [60, 90, 180, 270]) expect(binEntries(shadowCache, binAt(centre, degrees))).toEqual([]);
  });

  it('widens a hull\'s bins by the angle the disk subtends from it (its penumbrae), and no further than twice that', () => {
    const centre: [number, number] = [0, 50];
    // The hull's circle (radius 7.1 at 55) spans ±7.4°; a disk of radius 20 at 47.9 adds 24.7°.
    const shadowCache = plan([light(centre, 20)], [box(50, 45)]);
    const filedAt = (degrees: number) => binEntries(shadowCache, binAt(centre, degrees)).length;
    for (const degrees of [0, 30, -30]) expect(filedAt(degrees)).toBe(1);
    for (const degrees of [80, -80, 180]) expect(filedAt(degrees)).toBe(0);
  });

  it('files a hull in every bin its shadow directions cross, and in few more, in every direction (diagonals too)', () => {
    // The directions a hull's circle (ρ at distance d) can shade lie within asin(ρ / d) + asin(r / (d − ρ))
    // of its own (ShadowBins). The bins must hold them all; the bound's slack (the asin and tan
    // bounds, the margin) may add a little, not the factor two that a width added to the pseudo-angle
    // gives on diagonals, where it grows half as fast as the angle.
    let seed = 7;
    const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    let filed = 0, needed = 0;
    for (let trial = 0; trial < 200; trial++) {
      const centre: [number, number] = [100, 50];
      const angle = random() * 2 * Math.PI, distance = 25 + random() * 50, size = 2 + random() * 6;
      const x = centre[0] + distance * Math.cos(angle) - size / 2, y = centre[1] + distance * Math.sin(angle) - size / 2;
      const radius = random() * 10;
      const shadowCache = plan([light(centre, radius)], [box(x, y, size, size)]);
      const bins = Array.from({ length: BIN_COUNT }, (_, bin) => binEntries(shadowCache, bin));
      const [, , hx, hy, hullRadius] = bins.find((entries) => entries.length > 0)![0];
      const d = Math.hypot(hx - centre[0], hy - centre[1]), direction = Math.atan2(hy - centre[1], hx - centre[0]);
      const halfWidth = Math.asin(hullRadius / d) + Math.asin(radius / (d - hullRadius));
      const binsWithin = (width: number) => {
        const within = new Set<number>();
        for (let k = -500; k <= 500; k++) within.add(binAt(centre, ((direction + (k / 500) * width) * 180) / Math.PI));
        return within;
      };
      const must = binsWithin(halfWidth), may = binsWithin(halfWidth * 1.1 + 0.01);
      for (let bin = 0; bin < BIN_COUNT; bin++) {
        const isFiled = bins[bin].length > 0;
        if (must.has(bin)) expect(isFiled, `trial ${trial}: bin ${bin} must hold the hull`).toBe(true);
        if (isFiled) expect(may.has(bin), `trial ${trial}: bin ${bin} is beyond the hull's directions`).toBe(true);
        filed += isFiled ? 1 : 0;
      }
      needed += must.size;
    }
    expect(filed / needed).toBeLessThan(1.2);
  });

  it('lists each bin nearest first with a circle around each hull, and files a hull that reaches into the disk in every bin, first', () => {
    const centre: [number, number] = [50, 50];
    const shadowCache = plan([light(centre, 5)], [box(120, 45), box(90, 45), box(53, 40, 10, 20)]);
    const listed = binEntries(shadowCache, binAt(centre, 0));
    expect(listed.map(([record]) => record)).toEqual([2, 1, 0]);
    expect(listed[1].slice(2, 5)).toEqual([95, 50, Math.fround(Math.hypot(5, 5))]);
    // Distance buckets of 160 / 32 = 5 units.
    expect(shadowCache.draws[0].binning[3]).toBe(5);
    for (let bin = 0; bin < BIN_COUNT; bin++) expect(binEntries(shadowCache, bin)[0].slice(0, 2)).toEqual([2, 1]);
  });

  it('makes a concave hull its triangles and a convex hull of more than 4 points a fan of records', () => {
    const u = new Hull([[80, 30], [100, 30], [100, 60], [80, 60], [80, 55], [95, 55], [95, 35], [80, 35]]);
    const round = new Hull(Array.from({ length: 16 }, (_, i): [number, number] => [150 + 10 * Math.cos((Math.PI * i) / 8), 50 + 10 * Math.sin((Math.PI * i) / 8)]));
    const geometry = new ShadowGeometry();
    geometry.update([u, round]);
    geometry.prepare(0);
    geometry.prepare(1);
    expect(Array.from(geometry.recordCounts.subarray(0, 2))).toEqual([6, 7]);
    // Records of a fan: points 0–3, then 0, 3, 4, 5, and so on to 0, 13, 14, 15; every record has positive area.
    expect(Array.from(geometry.recordPointCounts.subarray(6, 13))).toEqual([4, 4, 4, 4, 4, 4, 4]);
    for (let record = 0; record < 13; record++) {
      const count = geometry.recordPointCounts[record];
      const points = geometry.records.subarray(record * RECORD_FLOATS, record * RECORD_FLOATS + 2 * count);
      expect(signedArea2(points)).toBeGreaterThan(0);
    }
    // Only the convex hull's entry is marked a fan (the shader then drops its inner diagonals).
    const centre: [number, number] = [120, 45];
    const shadowCache = plan([light(centre, 2)], [u, round]);
    expect(binEntries(shadowCache, binAt(centre, 180)).map(([record, count, , , , fan]) => [record, count, fan])).toEqual([[0, 6, 0]]);
    expect(binEntries(shadowCache, binAt(centre, 0)).map(([record, count, , , , fan]) => [record, count, fan])).toEqual([[6, 7, 1]]);
  });

  it('writes each light its reach: the range, or the farthest corner of a textured quad', () => {
    const shadowCache = plan([new PointLight({ position: [50, 50], range: 40 })], []);
    expect(shadowCache.draws[0].reach).toBe(40);
    // The plan never reads the cookie texture itself.
    const cookie = new TexturedLight({ position: [50, 50], range: 10, size: [40, 20], origin: [0, 0.5], texture: {} as WebGLTexture });
    expect(plan([cookie], []).draws[0].reach).toBeCloseTo(Math.sqrt(40 * 40 + 10 * 10), 9);
  });
});

describe('ShadowCache filings kept from frame to frame', () => {
  /** Per drawn light: its hull count, bucket width and, per bin, its entries in both lists sorted (a kept filing may order a distance bucket differently). */
  function filings(shadowCache: ShadowCache): Map<Light, string> {
    const entries = shadowCache.bins.entries;
    const out = new Map<Light, string>();
    for (let d = 0; d < shadowCache.drawCount; d++) {
      const draw = shadowCache.draws[d];
      const perBin: string[] = [`hulls ${draw.hullCount}, buckets ${draw.binning[3]}`];
      for (let bin = 0; draw.hullCount > 0 && bin < BIN_COUNT; bin++) {
        const listed = entriesOfBin(shadowCache, draw, bin).map((e) => entries.subarray(e * ENTRY_FLOATS, (e + 1) * ENTRY_FLOATS).join(' '));
        perBin.push(listed.sort().join(', '));
      }
      out.set(draw.light, perBin.join('\n'));
    }
    return out;
  }

  /** A square hull with corners (x, y) and (x + size, y + size), its points around its position (as hulls' coarse bounds expect). */
  const square = (x: number, y: number, size: number) => {
    const h = size / 2;
    return new Hull([[-h, -h], [h, -h], [h, h], [-h, h]], { position: [x + h, y + h] });
  };

  /** A hull (by index) that can shade a light, and the circle around its world points. */
  interface ShadingCircle { index: number; hx: number; hy: number; rho: number }

  /** The circles of the hulls that can shade `light`: enabled, valid, in its shadow layers, not ignored. */
  function shadingCircles(light: Light, hulls: Hull[]): ShadingCircle[] {
    const circles: ShadingCircle[] = [];
    hulls.forEach((hull, index) => {
      if (!hull.enabled || !hull.valid || (hull.layers & light.shadowLayers) === 0 || light.ignoredHulls.has(hull)) return;
      const c = Math.cos(hull.rotation), s = Math.sin(hull.rotation);
      const points = hull.points.map(([px, py]) => [hull.position[0] + c * px - s * py, hull.position[1] + s * px + c * py]);
      const xs = points.map((p) => p[0]), ys = points.map((p) => p[1]);
      const hx = (Math.min(...xs) + Math.max(...xs)) / 2, hy = (Math.min(...ys) + Math.max(...ys)) / 2;
      circles.push({ index, hx, hy, rho: Math.max(...points.map(([px, py]) => Math.hypot(px - hx, py - hy))) });
    });
    return circles;
  }

  /** 25 points of the light's disk, `[x, y, …]`: its centre and two rings of 12. */
  function diskPoints(light: Light): number[] {
    const [cx, cy] = light.position, r = light.radius, points: number[] = [];
    for (let ring = 0; ring <= 2; ring++) {
      for (let k = 0; k < (ring === 0 ? 1 : 12); k++) points.push(cx + (r * ring / 2) * Math.cos(k * Math.PI / 6), cy + (r * ring / 2) * Math.sin(k * Math.PI / 6));
    }
    return points;
  }

  /** Distance from (px, py) to the segment from (x, y) to (qx, qy). */
  function segmentDistance(px: number, py: number, x: number, y: number, qx: number, qy: number): number {
    const ex = qx - x, ey = qy - y, length2 = ex * ex + ey * ey;
    const t = length2 > 0 ? Math.min(1, Math.max(0, ((px - x) * ex + (py - y) * ey) / length2)) : 0;
    return Math.hypot(x + t * ex - px, y + t * ey - py);
  }

  /**
   * The hulls (by index) whose circle meets a segment from the pixel (x, y) to one of the light's
   * disk points: those the shader must visit there. Every such segment lies within the radius of
   * the segment from the pixel to the centre, so a circle farther than ρ + r from that one meets none.
   */
  function hullsShading(light: Light, circles: readonly ShadingCircle[], disk: readonly number[], x: number, y: number): number[] {
    const [cx, cy] = light.position, shading: number[] = [];
    for (const { index, hx, hy, rho } of circles) {
      if (segmentDistance(hx, hy, x, y, cx, cy) >= rho + light.radius) continue;
      for (let k = 0; k < disk.length; k += 2) {
        if (segmentDistance(hx, hy, x, y, disk[k], disk[k + 1]) < rho * (1 - 1e-9)) {
          shading.push(index);
          break;
        }
      }
    }
    return shading;
  }

  /**
   * The hulls (by index) the shader visits for the pixel (x, y) of a drawn light: each of its bin's
   * two lists from the bins' origin, until the first entry a distance bucket farther than the pixel
   * (as the chunk shadow-visibility walks them). `hullOfRecord` maps a hull's first record to it.
   */
  function hullsVisited(shadowCache: ShadowCache, hullOfRecord: ReadonlyMap<number, number>, draw: ShadowCache['draws'][number], x: number, y: number): Set<number> {
    const { bins, entries } = shadowCache.bins, [originX, originY, filedRadius, bucketWidth] = draw.binning, visited = new Set<number>();
    const dx = x - originX, dy = y - originY, distance = Math.hypot(dx, dy);
    // The shader's pseudo-angle of the zero vector is 0.
    const bin = distance === 0 ? 0 : Math.min(Math.floor(diamondAngle(dx, dy) * (BIN_COUNT / 4)), BIN_COUNT - 1);
    const b = (draw.binRow * BIN_COUNT + bin) * BIN_FLOATS;
    for (const list of [STILL_LIST, MOVING_LIST]) {
      for (let e = bins[b + list]; e < bins[b + list] + bins[b + list + 1]; e++) {
        const [code, hx, hy, rho] = entries.subarray(e * ENTRY_FLOATS, (e + 1) * ENTRY_FLOATS);
        const nearest = Math.hypot(hx - originX, hy - originY) - rho;
        if (nearest > filedRadius + bucketWidth && distance < (Math.floor(nearest / bucketWidth) - 1) * bucketWidth) break;
        visited.add(hullOfRecord.get(Math.floor(Math.floor(code / 2) / ENTRY_MAX_RECORDS)) ?? -1);
      }
    }
    return visited;
  }

  /**
   * Expects every drawn light's bins to lead the shader, at pixels `step` apart within its reach, to
   * every hull that can shade them.
   */
  function expectShadingHullsVisited(shadowCache: ShadowCache, geometry: ShadowGeometry, hulls: Hull[], label: string, step = 3): void {
    const hullOfRecord = new Map<number, number>();
    geometry.firstRecords.forEach((record, index) => {
      if (geometry.recordCounts[index] > 0 && !hullOfRecord.has(record)) hullOfRecord.set(record, index);
    });
    const missed: string[] = [];
    for (let d = 0; d < shadowCache.drawCount; d++) {
      const draw = shadowCache.draws[d], light = draw.light;
      if (draw.hullCount === 0) continue;
      const [cx, cy] = light.position, circles = shadingCircles(light, hulls), disk = diskPoints(light);
      for (let x = cx - draw.reach; x <= cx + draw.reach; x += step) {
        for (let y = cy - draw.reach; y <= cy + draw.reach; y += step) {
          if (Math.hypot(x - cx, y - cy) > draw.reach) continue;
          const shading = hullsShading(light, circles, disk, x, y);
          if (shading.length === 0) continue;
          const visited = hullsVisited(shadowCache, hullOfRecord, draw, x, y);
          for (const index of shading) if (!visited.has(index)) missed.push(`light ${d}, pixel (${x}, ${y}), hull ${index}`);
        }
      }
    }
    expect(missed, `${label}: hulls that shade a pixel its bin does not lead to`).toEqual([]);
  }

  it('files a light anew only when it, a hull near it, or the list of hulls changed', () => {
    const left = new PointLight({ position: [40, 50], range: 40, radius: 3 });
    const right = new PointLight({ position: [160, 50], range: 40, radius: 3 });
    const nearLeft = square(60, 45, 8), nearRight = square(130, 45, 8);
    const hulls = [nearLeft, nearRight];
    const geometry = new ShadowGeometry(), shadowCache = new ShadowCache();
    const filed = () => {
      geometry.update(hulls);
      shadowCache.build([left, right], hulls, geometry, pixelSpace, WIDTH, HEIGHT);
      return shadowCache.filedCount;
    };
    expect(filed()).toBe(2);
    expect(filed()).toBe(0);
    left.setPosition(41, 50);
    expect(filed()).toBe(1);
    nearRight.position = [135, 50];
    expect(filed()).toBe(1);
    right.ignoredHulls.add(nearRight);
    expect(filed()).toBe(1);
    right.ignoredHulls.delete(nearRight);
    right.ignoredHulls.add(nearLeft);
    expect(filed()).toBe(1);
    // Beyond the margin the move gave the left light's filing (at most its reach / 16).
    left.radius = 6;
    expect(filed()).toBe(1);
    right.shadowLayers = 2;
    expect(filed()).toBe(1);
    // A hull moved from near one light to near the other changes both.
    nearLeft.position = [140, 50];
    expect(filed()).toBe(2);
    hulls.push(square(100, 90, 2));
    expect(filed()).toBe(2);
    expect(filed()).toBe(0);
  });

  it('keeps a moving light\'s filing while its disk stays within the margin its speed gave it', () => {
    const hulls: Hull[] = [];
    for (let x = 5; x < WIDTH; x += 12) for (let y = 5; y < HEIGHT; y += 12) hulls.push(square(x, y, 3));
    const light = new PointLight({ position: [40, 50], range: 48, radius: 12 });
    const geometry = new ShadowGeometry(), shadowCache = new ShadowCache();
    geometry.update(hulls);
    let filed = 0;
    for (let frame = 0; frame < 60; frame++) {
      light.setPosition(40 + 0.5 * frame, 50 + 0.25 * frame);
      shadowCache.build([light], hulls, geometry, pixelSpace, WIDTH, HEIGHT);
      filed += shadowCache.filedCount;
      expectShadingHullsVisited(shadowCache, geometry, hulls, `frame ${frame}`);
    }
    // Half a pixel a frame and a margin of 8 frames' travel (at most 48 / 16 = 12 / 4 = 3): filed every 5 or 6 frames.
    expect(filed).toBeGreaterThan(60 / 8);
    expect(filed).toBeLessThan(60 / 4);
    // A still light is filed with no margin again after its next filing.
    light.radius = 16;
    shadowCache.build([light], hulls, geometry, pixelSpace, WIDTH, HEIGHT);
    expect(shadowCache.draws[0].binning[2]).toBeGreaterThan(16);
    light.radius = 20;
    shadowCache.build([light], hulls, geometry, pixelSpace, WIDTH, HEIGHT);
    expect(shadowCache.draws[0].binning[2]).toBe(20);
  });

  it('packs the kept filings’ entries when released spans pile up, and they still equal a new plan’s', () => {
    const hulls: Hull[] = [];
    for (let x = 5; x < WIDTH; x += 10) for (let y = 5; y < HEIGHT; y += 10) hulls.push(square(x, y, 3));
    const still = new PointLight({ position: [30, 50], range: 40, radius: 2 });
    const growing = new PointLight({ position: [150, 50], range: 50, radius: 0.5 });
    const geometry = new ShadowGeometry(), kept = new ShadowCache();
    const pack = vi.spyOn(kept.bins, 'pack');
    geometry.update(hulls);
    for (let frame = 0; frame < 60; frame++) {
      // A wider disk widens every hull's bins: the growing light's span moves to the end time and again.
      growing.radius = 0.5 + frame * 0.25;
      const packs = pack.mock.calls.length;
      kept.build([growing, still], hulls, geometry, pixelSpace, WIDTH, HEIGHT);
      if (frame > 0) expect(kept.filedCount).toBe(1);
      // Packed: every row is uploaded again, the kept light's bins with them.
      if (pack.mock.calls.length > packs) {
        expect(kept.bins.dirtyEntryRows.every((dirty) => dirty === 1)).toBe(true);
        expect(kept.bins.dirtyBinRows[kept.draws.find((draw) => draw.light === still)!.binRow]).toBe(1);
      }
      expect(filings(kept), `frame ${frame}`).toEqual(filings(plan([growing, still], hulls)));
    }
    expect(pack).toHaveBeenCalled();
  });

  it('keeps filings that lead every pixel to the hulls that shade it through random changes to lights and hulls', () => {
    let seed = 11;
    const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    const between = (low: number, high: number) => low + (high - low) * random();
    const lights = Array.from({ length: 6 }, () => new PointLight({ position: [between(0, WIDTH), between(0, HEIGHT)], range: between(20, 60), radius: between(0, 6) }));
    const hulls = Array.from({ length: 30 }, () => square(between(0, WIDTH), between(0, HEIGHT), between(2, 8)));
    const pick = <T>(list: T[]) => list[Math.floor(random() * list.length)];
    const changes: (() => void)[] = [
      () => {},
      () => pick(lights).setPosition(between(0, WIDTH), between(0, HEIGHT)),
      () => { pick(lights).radius = between(0, 6); },
      () => { pick(lights).range = between(20, 60); },
      () => { const light = pick(lights); light.castsShadows = !light.castsShadows; },
      () => { const light = pick(lights); light.enabled = !light.enabled; },
      () => { pick(lights).shadowLayers = random() < 0.5 ? 1 : 2; },
      () => { const light = pick(lights), hull = pick(hulls); if (!light.ignoredHulls.delete(hull)) light.ignoredHulls.add(hull); },
      () => { const hull = pick(hulls); hull.position = [hull.position[0] + between(-10, 10), hull.position[1] + between(-10, 10)]; },
      () => { pick(hulls).rotation = between(0, 6); },
      () => { const hull = pick(hulls); hull.enabled = !hull.enabled; },
      () => { pick(hulls).layers = random() < 0.5 ? 2 : 1; },
      () => hulls.push(square(between(0, WIDTH), between(0, HEIGHT), between(2, 8))),
      () => hulls.splice(Math.floor(random() * hulls.length), 1),
    ];
    const geometry = new ShadowGeometry(), kept = new ShadowCache();
    let filedTotal = 0, drawnTotal = 0;
    for (let frame = 0; frame < 400; frame++) {
      pick(changes)();
      geometry.update(hulls);
      kept.build(lights, hulls, geometry, pixelSpace, WIDTH, HEIGHT);
      filedTotal += kept.filedCount;
      drawnTotal += kept.drawCount;
      const fresh = plan(lights, hulls);
      expect(drawnLights(kept), `frame ${frame}`).toEqual(drawnLights(fresh));
      expectShadingHullsVisited(kept, geometry, hulls, `frame ${frame}`, 7);
    }
    // Most frames change one thing near one light or two: most filings are kept.
    expect(filedTotal / drawnTotal).toBeLessThan(0.5);
  });
});
