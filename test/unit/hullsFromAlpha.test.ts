/**
 * hullsFromAlpha against an independent reference: the hulls are rasterized back (even-odd test of
 * each pixel centre, placed in the world by this file's own sprite transform) and compared with
 * the thresholded alpha.
 *
 * The bounds, and why they hold:
 * - Tolerance 0: exact at every pixel centre. The marching-squares outline at level ½ passes
 *   midway between each solid and each empty pixel centre (a chamfered corner passes √2/4 px from
 *   the nearest centre), and only collinear points are dropped.
 * - Tolerance t: the simplified outline stays within the t-band around the traced one (each
 *   Douglas–Peucker chord has every dropped point within t, hence the whole chain within its
 *   convex t-band), and the trace is within √2/4 px of the pixel edges; so a misclassified centre
 *   lies within t + √2/4 < t + 1 of the true outline (the boundary of the union of solid pixel
 *   squares). Misclassified centres lie in a one-sided band of width t + √2/4 along the outline,
 *   whose length is at most the number of boundary pixel edges: at most edges × (t + ½) of them,
 *   which bounds the IoU from below.
 * - Tolerance t, outlines: the trace runs through the midpoint of every pixel edge of the true
 *   outline, and Douglas–Peucker keeps every traced point within t of the simplified outline; the
 *   reverse holds too (each chain crosses every perpendicular of its chord within t of it). So
 *   each such midpoint is within t of a hull's edge, and each point of a hull's edge within
 *   t + √2/4 of the true outline, or on a cut between two hulls.
 */
import { describe, expect, it } from 'vitest';
import { alphaOutlines } from '../../src/geometry/alphaOutlines';
import { isInsidePolygon, isSimplePolygon, signedArea2 } from '../../src/geometry/polygon';
import type { Hull } from '../../src/scene/Hull';
import { hullsFromAlpha, type AlphaImage, type HullsFromAlphaOptions } from '../../src/scene/hullsFromAlpha';
import { createRandom } from '../reference/randomScenes';

/** An RGBA image whose alpha at pixel (x, y) is `alpha(x, y)`; colour channels carry noise that must not matter. */
function image(width: number, height: number, alpha: (x: number, y: number) => number): AlphaImage {
  const data = new Uint8ClampedArray(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      data[i] = 255;
      data[i + 1] = (x * 7) & 255;
      data[i + 2] = (y * 13) & 255;
      data[i + 3] = alpha(x, y);
    }
  }
  return { data, width, height };
}

/** An image from rows of text: `#` opaque, anything else transparent. */
function textImage(rows: readonly string[]): AlphaImage {
  return image(rows[0].length, rows.length, (x, y) => (rows[y][x] === '#' ? 255 : 0));
}

/** Alpha 255 inside any of the discs `[cx, cy, r]` (pixel centres), minus the holes, else 0. */
function discs(width: number, height: number, solid: ReadonlyArray<readonly number[]>, holes: ReadonlyArray<readonly number[]> = []): AlphaImage {
  const inAny = (list: ReadonlyArray<readonly number[]>, x: number, y: number) =>
    list.some(([cx, cy, r]) => (x + 0.5 - cx) ** 2 + (y + 0.5 - cy) ** 2 <= r * r);
  return image(width, height, (x, y) => (inAny(solid, x, y) && !inAny(holes, x, y) ? 255 : 0));
}

/** Alpha 255 within `halfWidth` of the polyline `line` (pixel centres), else 0. */
function strokes(width: number, height: number, line: ReadonlyArray<readonly number[]>, halfWidth: number): AlphaImage {
  return image(width, height, (x, y) => {
    for (let i = 0; i + 1 < line.length; i++) {
      if (distanceToSegment(x + 0.5, y + 0.5, [...line[i], ...line[i + 1]]) <= halfWidth) return 255;
    }
    return 0;
  });
}

/** The reference: which pixels are solid (alpha ≥ threshold). */
function maskOf(img: AlphaImage, threshold = 128): Uint8Array {
  return Uint8Array.from({ length: img.width * img.height }, (_, i) => (img.data[4 * i + 3] >= threshold ? 1 : 0));
}

interface Placement {
  readonly anchor?: readonly [number, number];
  readonly position?: readonly [number, number];
  readonly rotation?: number;
  readonly scale?: number | readonly [number, number];
  readonly flipX?: boolean;
  readonly flipY?: boolean;
}

/**
 * Where a point of the image (pixels, y down) lands in the world when the image is drawn as a
 * sprite with `placement`: mirrored within the image by the flips, then scaled around the anchor,
 * rotated, and the anchor put at `position`. Written from the sprite model, not from the code.
 */
function spritePoint(img: AlphaImage, placement: Placement, x: number, y: number): [number, number] {
  const { anchor = [0.5, 0.5], position = [0, 0], rotation = 0, scale = 1, flipX = false, flipY = false } = placement;
  const [sx, sy] = typeof scale === 'number' ? [scale, scale] : scale;
  const fx = flipX ? img.width - x : x, fy = flipY ? img.height - y : y;
  const lx = (fx - anchor[0] * img.width) * sx, ly = (fy - anchor[1] * img.height) * sy;
  return [position[0] + lx * Math.cos(rotation) - ly * Math.sin(rotation), position[1] + lx * Math.sin(rotation) + ly * Math.cos(rotation)];
}

/** For each pixel, how many hulls hold its centre (placed as a sprite with `placement`). */
function coverage(img: AlphaImage, hulls: readonly Hull[], placement: Placement = {}): Uint8Array {
  const world = hulls.map((hull) => {
    hull.updateWorld();
    return hull.worldPoints;
  });
  const out = new Uint8Array(img.width * img.height);
  for (let y = 0; y < img.height; y++) {
    for (let x = 0; x < img.width; x++) {
      const point = spritePoint(img, placement, x + 0.5, y + 0.5);
      for (const coords of world) if (isInsidePolygon(coords, point)) out[y * img.width + x]++;
    }
  }
  return out;
}

/** Pixels whose centre is in some hull but not solid, or solid and in none. */
function mismatches(mask: Uint8Array, covered: Uint8Array): number[] {
  const out: number[] = [];
  for (let i = 0; i < mask.length; i++) if ((covered[i] > 0 ? 1 : 0) !== mask[i]) out.push(i);
  return out;
}

/** Pixel edges between a solid pixel and an empty one (or the image's border): the outline's length. */
function boundaryEdges(mask: Uint8Array, width: number, height: number): number {
  const at = (x: number, y: number) => (x >= 0 && y >= 0 && x < width && y < height ? mask[y * width + x] : 0);
  let edges = 0;
  for (let y = -1; y < height; y++) for (let x = -1; x < width; x++) edges += (at(x, y) !== at(x + 1, y) ? 1 : 0) + (at(x, y) !== at(x, y + 1) ? 1 : 0);
  return edges;
}

/**
 * Distance from the centre of pixel `i` to the true outline: the nearest pixel square of the other
 * kind (outside the image counts as empty), searched within `reach`; Infinity when none is that near.
 */
function distanceToOutline(mask: Uint8Array, width: number, height: number, i: number, reach: number): number {
  const cx = (i % width) + 0.5, cy = Math.floor(i / width) + 0.5, own = mask[i];
  let best = Infinity;
  for (let y = Math.floor(cy - reach) - 1; y <= cy + reach; y++) {
    for (let x = Math.floor(cx - reach) - 1; x <= cx + reach; x++) {
      const other = x >= 0 && y >= 0 && x < width && y < height ? mask[y * width + x] : 0;
      if (other === own) continue;
      const dx = Math.max(x - cx, 0, cx - (x + 1)), dy = Math.max(y - cy, 0, cy - (y + 1));
      best = Math.min(best, Math.hypot(dx, dy));
    }
  }
  return best;
}

/** Every hull valid, within the point cap, and (unflipped) stored in pixel space with positive area. */
function expectValid(hulls: readonly Hull[], maxPoints = 64): void {
  for (const hull of hulls) {
    expect(hull.valid).toBe(true);
    expect(hull.points.length).toBeLessThanOrEqual(maxPoints);
  }
}

/** The true outline's pixel edges (between a solid pixel and an empty one or the border), as segments `[x0, y0, x1, y1]`. */
function outlineEdges(mask: Uint8Array, width: number, height: number): number[][] {
  const at = (x: number, y: number) => (x >= 0 && y >= 0 && x < width && y < height ? mask[y * width + x] : 0);
  const outline: number[][] = [];
  for (let y = -1; y < height; y++) {
    for (let x = -1; x < width; x++) {
      if (at(x, y) !== at(x + 1, y)) outline.push([x + 1, y, x + 1, y + 1]);
      if (at(x, y) !== at(x, y + 1)) outline.push([x, y + 1, x + 1, y + 1]);
    }
  }
  return outline;
}

/** Whether (px, py) lies on a pixel edge between two solid pixels (where the splitter may cut). */
function onInnerEdge(mask: Uint8Array, width: number, height: number, px: number, py: number): boolean {
  const at = (x: number, y: number) => (x >= 0 && y >= 0 && x < width && y < height ? mask[y * width + x] : 0);
  const columns = Number.isInteger(px) ? [px - 1, px] : [Math.floor(px)], rows = Number.isInteger(py) ? [py - 1, py] : [Math.floor(py)];
  if (Number.isInteger(py) && columns.some((x) => at(x, py - 1) && at(x, py))) return true;
  return Number.isInteger(px) && rows.some((y) => at(px - 1, y) && at(px, y));
}

function distanceToSegment(px: number, py: number, [ax, ay, bx, by]: readonly number[]): number {
  const ex = bx - ax, ey = by - ay, length2 = ex * ex + ey * ey;
  const along = length2 === 0 ? 0 : Math.min(1, Math.max(0, ((px - ax) * ex + (py - ay) * ey) / length2));
  return Math.hypot(px - ax - along * ex, py - ay - along * ey);
}

/** Each hull's edges in pixel space (its points, unflipped), as segments. */
function hullEdges(hulls: readonly Hull[]): number[][] {
  return hulls.flatMap((hull) => hull.points.map((p, i) => {
    const q = hull.points[(i + 1) % hull.points.length];
    return [p[0], p[1], q[0], q[1]];
  }));
}

/**
 * The outlines of unflipped hulls and the true outline within each other's reach (a two-sided
 * Hausdorff bound): every midpoint of a true outline's pixel edge (the trace runs through all of
 * them) within `tolerance` of a hull's edge; every point of a hull's edge within
 * `tolerance + √2/4` of the true outline (the trace is within √2/4 of it), or on a pixel edge
 * between two solid pixels (a cut between hulls).
 */
function expectHausdorff(img: AlphaImage, hulls: readonly Hull[], tolerance: number): void {
  const mask = maskOf(img), outline = outlineEdges(mask, img.width, img.height), edges = hullEdges(hulls);
  const far: string[] = [];
  const toHulls = nearSegments(edges), toOutline = nearSegments(outline);
  for (const [ax, ay, bx, by] of outline) {
    const mx = (ax + bx) / 2, my = (ay + by) / 2;
    if (!toHulls(mx, my, tolerance + 1e-9)) far.push(`pixel edge midpoint (${mx}, ${my}) farther than ${tolerance} from the hulls`);
  }
  for (const [ax, ay, bx, by] of edges) {
    const samples = Math.ceil(4 * Math.hypot(bx - ax, by - ay));
    for (let k = 0; k <= samples; k++) {
      const px = ax + ((bx - ax) * k) / samples, py = ay + ((by - ay) * k) / samples;
      if (onInnerEdge(mask, img.width, img.height, px, py)) continue;
      if (!toOutline(px, py, tolerance + Math.SQRT2 / 4 + 1e-9)) far.push(`hull edge point (${px}, ${py}) farther than ${tolerance} + √2/4 from the outline`);
    }
  }
  expect(far).toEqual([]);
}

/**
 * Whether some segment of `segments` comes within `limit` of (px, py): the segments filed by the
 * 4 × 4 pixel cells their bounds cover, and only those of the cells within `limit` tested.
 */
function nearSegments(segments: readonly (readonly number[])[]): (px: number, py: number, limit: number) => boolean {
  const CELL = 4, cells = new Map<string, (readonly number[])[]>();
  for (const segment of segments) {
    const [ax, ay, bx, by] = segment;
    for (let i = Math.floor(Math.min(ax, bx) / CELL); i <= Math.floor(Math.max(ax, bx) / CELL); i++) {
      for (let j = Math.floor(Math.min(ay, by) / CELL); j <= Math.floor(Math.max(ay, by) / CELL); j++) {
        const key = `${i},${j}`;
        const list = cells.get(key);
        if (list) list.push(segment);
        else cells.set(key, [segment]);
      }
    }
  }
  return (px, py, limit) => {
    for (let i = Math.floor((px - limit) / CELL); i <= Math.floor((px + limit) / CELL); i++) {
      for (let j = Math.floor((py - limit) / CELL); j <= Math.floor((py + limit) / CELL); j++) {
        for (const segment of cells.get(`${i},${j}`) ?? []) if (distanceToSegment(px, py, segment) <= limit) return true;
      }
    }
    return false;
  };
}

/**
 * The simplified hulls against the mask (see the file's comment): misclassified centres near the
 * outline, the IoU bounded, and the outlines within the tolerance of each other.
 */
function expectWithinTolerance(img: AlphaImage, hulls: readonly Hull[], tolerance: number): { iou: number; wrong: number } {
  expectHausdorff(img, hulls, tolerance);
  const mask = maskOf(img), covered = coverage(img, hulls);
  const wrong = mismatches(mask, covered);
  expect(wrong.filter((i) => !(distanceToOutline(mask, img.width, img.height, i, tolerance + 2) <= tolerance + 1)), 'misclassified pixels far from the outline').toEqual([]);
  let both = 0, either = 0;
  for (let i = 0; i < mask.length; i++) {
    both += mask[i] && covered[i] ? 1 : 0;
    either += mask[i] || covered[i] ? 1 : 0;
  }
  const iou = either === 0 ? 1 : both / either;
  const solid = mask.reduce((a, b) => a + b, 0);
  expect(wrong.length).toBeLessThanOrEqual(boundaryEdges(mask, img.width, img.height) * (tolerance + 0.5));
  expect(iou).toBeGreaterThanOrEqual(1 - (boundaryEdges(mask, img.width, img.height) * (tolerance + 0.5)) / Math.max(solid, 1));
  return { iou, wrong: wrong.length };
}

/**
 * Dense samples (4 × 4 a pixel) in every pixel at least `margin` pixels inside the solid shape:
 * each must be in a hull. Catches gaps between hulls split apart, which pixel centres would miss.
 */
function expectNoGaps(img: AlphaImage, hulls: readonly Hull[], margin: number): void {
  const mask = maskOf(img), world = hulls.map((hull) => (hull.updateWorld(), hull.worldPoints));
  let checked = 0;
  const gaps: string[] = [];
  for (let i = 0; i < mask.length; i++) {
    if (!mask[i] || distanceToOutline(mask, img.width, img.height, i, margin + 1) <= margin) continue;
    const x = i % img.width, y = Math.floor(i / img.width);
    for (let sy = 0; sy < 4; sy++) {
      for (let sx = 0; sx < 4; sx++) {
        const point = spritePoint(img, {}, x + (2 * sx + 1) / 8, y + (2 * sy + 1) / 8);
        if (!world.some((coords) => isInsidePolygon(coords, point))) gaps.push(`sample ${point} in pixel (${x}, ${y})`);
        checked++;
      }
    }
  }
  expect(gaps, 'samples in no hull').toEqual([]);
  expect(checked).toBeGreaterThan(0);
}

const exact: HullsFromAlphaOptions = { tolerance: 0, maxPoints: Infinity };

describe('hullsFromAlpha: tracing', () => {
  it('traces a disc exactly at every pixel centre with tolerance 0, as one hull', () => {
    const img = discs(64, 64, [[30.3, 33.1, 21.7]]);
    const hulls = hullsFromAlpha(img, exact);
    expect(hulls).toHaveLength(1);
    expectValid(hulls, Infinity);
    expect(mismatches(maskOf(img), coverage(img, hulls))).toEqual([]);
  });

  it('keeps discs of many sizes and places (some cut by the border) within the tolerance', () => {
    const random = createRandom(7);
    for (let k = 0; k < 12; k++) {
      const tolerance = [0.5, 1, 2][k % 3];
      const img = discs(48, 40, [[random() * 48, random() * 40, 2 + random() * 20]]);
      const hulls = hullsFromAlpha(img, { tolerance, maxPoints: Infinity });
      expectValid(hulls, Infinity);
      expectWithinTolerance(img, hulls, tolerance);
    }
  });

  it('traces strokes that curl back on themselves (a spiral, an S, a G) within the tolerance', () => {
    const spiral = Array.from({ length: 200 }, (_, i) => {
      const angle = (i / 199) * 5 * Math.PI, r = 4 + 3.2 * angle;
      return [48 + r * Math.cos(angle), 48 + r * Math.sin(angle)];
    });
    const arc = (cx: number, cy: number, r: number, from: number, to: number) =>
      Array.from({ length: 40 }, (_, i) => [cx + r * Math.cos(from + ((to - from) * i) / 39), cy + r * Math.sin(from + ((to - from) * i) / 39)]);
    const letterS = [...arc(30, 22, 12, -0.2, -1.5 * Math.PI), ...arc(30, 46, 12, -Math.PI / 2, 0.7 * Math.PI)];
    const letterG = [...arc(36, 34, 22, -0.6, -2 * Math.PI + 0.2), [58, 34], [40, 34]];
    for (const [name, line, halfWidth] of [['spiral', spiral, 2.2], ['S', letterS, 3], ['G', letterG, 4]] as const) {
      const img = strokes(96, 96, line, halfWidth);
      for (const tolerance of [0, 1, 2.5]) {
        const hulls = hullsFromAlpha(img, { tolerance, maxPoints: Infinity });
        expect(hulls, name).toHaveLength(1);
        expectValid(hulls, Infinity);
        if (tolerance === 0) expect(mismatches(maskOf(img), coverage(img, hulls))).toEqual([]);
        else expectWithinTolerance(img, hulls, tolerance);
      }
    }
  });

  it('keeps a ledge over a long arm within the tolerance (the arm reaches back past where the outline starts)', () => {
    const img = textImage([
      '..................................',
      '.................###############..',
      '.###############################..',
      '.###############################..',
      '..................................',
    ]);
    for (const tolerance of [1, 1.5, 2, 3]) {
      const hulls = hullsFromAlpha(img, { tolerance, maxPoints: Infinity });
      expectValid(hulls, Infinity);
      expectWithinTolerance(img, hulls, tolerance);
    }
  });

  it('simplifies: a large disc at tolerance 1 keeps under a quarter of its traced points, within the bounds', () => {
    const img = discs(128, 128, [[64, 64, 50]]);
    const traced = hullsFromAlpha(img, exact)[0].points.length;
    const hulls = hullsFromAlpha(img, { tolerance: 1, maxPoints: Infinity });
    expect(hulls).toHaveLength(1);
    expect(hulls[0].points.length).toBeLessThan(traced / 4);
    expectWithinTolerance(img, hulls, 1);
  });

  it('splits a donut into ≥ 2 hulls that cover it exactly and leave its hole empty', () => {
    const img = discs(64, 64, [[32, 32, 28]], [[33, 30, 12]]);
    const mask = maskOf(img);
    for (const tolerance of [0, 1, 3]) {
      const hulls = hullsFromAlpha(img, { tolerance, maxPoints: Infinity });
      expect(hulls.length).toBeGreaterThanOrEqual(2);
      expectValid(hulls, Infinity);
      const covered = coverage(img, hulls);
      if (tolerance === 0) {
        expect(mismatches(mask, covered)).toEqual([]);
        // The regions are disjoint, and so are their unsimplified outlines at the pixel centres.
        expect(Math.max(...covered)).toBe(1);
      } else {
        expectWithinTolerance(img, hulls, tolerance);
      }
      expect(covered[30 * 64 + 33]).toBe(0);
      // The cuts run through the ring: simplified hulls still meet along them.
      expectNoGaps(img, hulls, tolerance + 1);
    }
  });

  it('gives one hull per island and drops islands under minArea', () => {
    const islands = [[12, 12, 8], [50, 15, 3], [30, 45, 10], [70, 50, 1.2], [75.5, 5.5, 0.5]];
    const img = discs(80, 60, islands);
    const areas = islands.map(([cx, cy, r]) =>
      maskOf(discs(80, 60, [[cx, cy, r]])).reduce((a, b) => a + b, 0));
    expect(hullsFromAlpha(img, exact)).toHaveLength(5);
    expect(mismatches(maskOf(img), coverage(img, hullsFromAlpha(img, exact)))).toEqual([]);
    const minArea = areas[1] + 1;
    const kept = hullsFromAlpha(img, { ...exact, minArea });
    expect(kept).toHaveLength(areas.filter((a) => a >= minArea).length);
    expect(hullsFromAlpha(img, { ...exact, minArea: areas[1] })).toHaveLength(areas.filter((a) => a >= areas[1]).length);
    // The kept islands are the large ones, traced as before.
    const large = discs(80, 60, [[12, 12, 8], [30, 45, 10]]);
    expect(mismatches(maskOf(large), coverage(large, kept))).toEqual([]);
  });

  it('measures minArea on whole islands: a donut split into pieces smaller than minArea stays', () => {
    const img = discs(40, 40, [[20, 20, 14]], [[20, 20, 9]]);
    const area = maskOf(img).reduce((a, b) => a + b, 0);
    const pieces = hullsFromAlpha(img, exact);
    expect(pieces.length).toBeGreaterThanOrEqual(2);
    expect(hullsFromAlpha(img, { ...exact, minArea: area })).toHaveLength(pieces.length);
    expect(hullsFromAlpha(img, { ...exact, minArea: area + 1 })).toHaveLength(0);
  });

  it('traces a sprite-like blob with holes, a thin handle and islands, within the tolerance and the default cap', () => {
    const img = spriteLike(96);
    for (const tolerance of [0, 1]) {
      const hulls = hullsFromAlpha(img, { tolerance, maxPoints: tolerance === 0 ? Infinity : 64 });
      expectValid(hulls, tolerance === 0 ? Infinity : 64);
      if (tolerance === 0) expect(mismatches(maskOf(img), coverage(img, hulls))).toEqual([]);
      else expectWithinTolerance(img, hulls, tolerance);
      expectNoGaps(img, hulls, tolerance + 1);
    }
  });

  it('handles noise at the threshold: valid hulls, exact with tolerance 0, specks dropped by minArea', () => {
    const random = createRandom(3);
    const img = image(64, 48, (x, y) => {
      const inBlob = (x - 30) ** 2 / 500 + (y - 24) ** 2 / 250 < 1;
      const noise = random() < 0.5 ? 1 : -1;
      return inBlob ? (random() < 0.9 ? 200 : 128 + noise) : 128 + (random() < 0.1 ? 0 : -1);
    });
    const mask = maskOf(img);
    const all = hullsFromAlpha(img, exact);
    expectValid(all, Infinity);
    expect(mismatches(mask, coverage(img, all))).toEqual([]);
    const hulls = hullsFromAlpha(img, { tolerance: 1 });
    expectValid(hulls);
    expectWithinTolerance(img, hulls, 1);
    const cleaned = hullsFromAlpha(img, { tolerance: 1, minArea: 20 });
    expect(cleaned.length).toBeLessThan(hulls.length);
    expectValid(cleaned);
  });

  it('keeps 1-pixel lines (straight, bent, diagonal) valid, backing off the tolerance where it would collapse them', () => {
    const img = textImage([
      '..........................',
      '.####################.....',
      '..........................',
      '.#...........#............',
      '.#...........#####........',
      '.#...............#........',
      '.#...............######...',
      '.#........................',
      '.....#....................',
      '......#...................',
      '.......#..................',
    ]);
    for (const tolerance of [0, 1, 4]) {
      const hulls = hullsFromAlpha(img, { tolerance });
      expectValid(hulls);
      // Straight line, vertical line, staircase, and 3 single diagonal pixels (not 4-connected).
      expect(hulls).toHaveLength(6);
      if (tolerance === 0) expect(mismatches(maskOf(img), coverage(img, hulls))).toEqual([]);
      else expectWithinTolerance(img, hulls, tolerance);
    }
  });

  it('returns no hull for an empty image or one without opaque pixels, one for a full image', () => {
    expect(hullsFromAlpha({ data: new Uint8Array(0), width: 0, height: 0 })).toEqual([]);
    expect(hullsFromAlpha(image(16, 9, () => 0))).toEqual([]);
    expect(hullsFromAlpha(image(16, 9, () => 127))).toEqual([]);
    const full = image(16, 9, () => 255);
    const hulls = hullsFromAlpha(full, exact);
    expect(hulls).toHaveLength(1);
    expect(mismatches(maskOf(full), coverage(full, hulls))).toEqual([]);
    // A full image's outline is its chamfered border: 4 sides, 4 corners.
    expect(hulls[0].edgeCount).toBe(8);
    const one = hullsFromAlpha(image(1, 1, () => 255), exact);
    expect(one).toHaveLength(1);
    expect(one[0].edgeCount).toBe(4);
  });

  it('counts alpha equal to the threshold as solid', () => {
    const img = image(8, 8, (x) => (x < 4 ? 100 : 99));
    expect(mismatches(maskOf(img, 100), coverage(img, hullsFromAlpha(img, { ...exact, threshold: 100 })))).toEqual([]);
    expect(hullsFromAlpha(img, { threshold: 101 })).toEqual([]);
    expect(hullsFromAlpha(img, { threshold: 0 })).toHaveLength(1);
  });

  it('honours the point cap, simplifying harder, on smooth, spiky and noisy outlines', () => {
    const star = image(96, 96, (x, y) => {
      const angle = Math.atan2(y + 0.5 - 48, x + 0.5 - 48), r = Math.hypot(x + 0.5 - 48, y + 0.5 - 48);
      return r < 30 + 14 * Math.sin(9 * angle) ? 255 : 0;
    });
    const holeFree = [discs(96, 96, [[48, 48, 45]]), star, discs(96, 96, [[20, 20, 15], [60, 60, 30], [85, 10, 2]])];
    for (const img of holeFree) {
      for (const maxPoints of [3, 4, 6, 8, 16, 64]) {
        const hulls = hullsFromAlpha(img, { maxPoints });
        expect(hulls.length).toBeGreaterThan(0);
        expectValid(hulls, maxPoints);
      }
    }
    // A hull split from an island with holes keeps the ends of its cuts whatever the cap (the
    // sprite's middle piece has 8), so the cap is checked from 8 points up there.
    for (const maxPoints of [8, 16, 64]) expectValid(hullsFromAlpha(spriteLike(128), { maxPoints }), maxPoints);
    // The star needs more than 16 points to keep its 9 spikes; capped at 64 it keeps them all.
    const capped = hullsFromAlpha(star, { maxPoints: 64 });
    expect(capped[0].points.length).toBeGreaterThanOrEqual(18);
  });
});

describe('hullsFromAlpha: comb-like sprites', () => {
  /** 1-pixel teeth 1 pixel apart hanging from a spine 4 pixels deep, or standing on it (`up`, grass of equal blades). */
  const comb = (width: number, height: number, up = false) =>
    image(width, height, (x, y) => ((up ? y >= height - 4 : y < 4) || x % 2 === 0 ? 255 : 0));
  /** 1-pixel blades of many heights, 1 pixel apart, on a 2-pixel base. */
  const grass = (width: number, height: number) =>
    image(width, height, (x, y) => (y >= height - 2 || (x % 2 === 0 && y >= 1 + ((x * 7919) % (height - 3))) ? 255 : 0));
  /** Bars `bar` pixels wide 4 pixels apart joined by two rails: an island with holes, split along its rows. */
  const fence = (width: number, height: number, bar = 4) =>
    image(width, height, (x, y) => (x % (bar + 4) < bar || Math.abs(y - height / 5) < 3 || Math.abs(y - (4 * height) / 5) < 3 ? 255 : 0));

  it('keeps teeth, blades and bars within the tolerance, exact at tolerance 0, with no gap along the cuts', () => {
    for (const [name, img] of [['comb', comb(41, 20)], ['grass', comb(41, 20, true)], ['blades', grass(40, 24)], ['fence', fence(58, 40, 9)]] as const) {
      for (const tolerance of [0, 1, 2.5]) {
        const hulls = hullsFromAlpha(img, { tolerance, maxPoints: Infinity });
        expectValid(hulls, Infinity);
        if (tolerance === 0) expect(mismatches(maskOf(img), coverage(img, hulls)), name).toEqual([]);
        else expectWithinTolerance(img, hulls, tolerance);
        if (name === 'fence') expectNoGaps(img, hulls, tolerance + 1);
      }
    }
  });

  it('honours the point cap on teeth and blades (the convex outline where no simple one fits)', () => {
    for (const img of [comb(97, 40), comb(97, 40, true), grass(96, 40)]) {
      for (const maxPoints of [4, 16, 64]) expectValid(hullsFromAlpha(img, { maxPoints }), maxPoints);
    }
  });

  it('traces a 2,048 × 256 comb and a 2,048 × 512 fence in near-linear time, not one scan of the outline per tooth', () => {
    // Simplifying by scanning each chain made these quadratic in the outline (tens of seconds);
    // O(n log n) takes a small fraction of the limit even on a loaded machine.
    for (const [name, img] of [['comb', comb(2048, 256)], ['grass', comb(2048, 256, true)], ['fence', fence(2048, 512)]] as const) {
      const start = performance.now();
      const hulls = hullsFromAlpha(img);
      const elapsed = performance.now() - start;
      expect(hulls.length, name).toBeGreaterThan(0);
      for (const hull of hulls) expect(hull.valid).toBe(true);
      expect(elapsed, `${name}: ${elapsed.toFixed(0)} ms`).toBeLessThan(2000);
    }
  });
});

describe('hullsFromAlpha: placement', () => {
  const img = textImage([
    '..........',
    '.######...',
    '.#........',
    '.#..###...',
    '.#..###...',
    '.#........',
    '..........',
  ]);
  const mask = maskOf(img);
  const placements: Placement[] = [
    {},
    { anchor: [0, 0] },
    { anchor: [1, 0.25], position: [100, -40] },
    { scale: 3, position: [5, 7] },
    { scale: [2, 0.5], rotation: 0.7, anchor: [0.2, 0.9], position: [-10, 20] },
    { scale: [-1.5, 1], rotation: -2 },
    { flipX: true },
    { flipY: true, anchor: [0, 0] },
    { flipX: true, flipY: true, scale: [2, -3], rotation: 1, position: [50, 60], anchor: [0.3, 0.6] },
  ];
  for (const placement of placements) {
    it(`places the hulls as a sprite with ${JSON.stringify(placement)}`, () => {
      const hulls = hullsFromAlpha(img, { ...exact, ...placement });
      expect(hulls).toHaveLength(2);
      expectValid(hulls, Infinity);
      expect(mismatches(mask, coverage(img, hulls, placement))).toEqual([]);
    });
  }

  it('sets the hull fields a sprite has: origin in pixels, position, rotation, scale', () => {
    const [hull] = hullsFromAlpha(image(40, 20, () => 255), { anchor: [0.25, 1], position: [3, 4], rotation: 0.5, scale: [2, 3] });
    expect(hull.origin).toEqual([10, 20]);
    expect(hull.position).toEqual([3, 4]);
    expect(hull.rotation).toBe(0.5);
    expect(hull.scale).toEqual([2, 3]);
  });

  it('keeps the outlines in pixel space with positive signed area', () => {
    const outlines = alphaOutlines(img.data, img.width, img.height, 128, { tolerance: 0, maxPoints: Infinity, minArea: 0 });
    for (const coords of outlines) {
      expect(isSimplePolygon(coords)).toBe(true);
      expect(signedArea2(coords)).toBeGreaterThan(0);
    }
  });
});

describe('hullsFromAlpha: validation', () => {
  const ok = image(4, 4, () => 255);
  const cases: Array<[string, () => unknown, ErrorConstructor, string]> = [
    ['image', () => hullsFromAlpha(null as never), TypeError, 'hullsFromAlpha image must be'],
    ['image.width', () => hullsFromAlpha({ ...ok, width: 2.5 }), RangeError, 'image.width must be a non-negative integer, got 2.5'],
    ['image.height', () => hullsFromAlpha({ ...ok, height: '4' as never }), TypeError, 'image.height must be a non-negative integer, got "4"'],
    ['image.data type', () => hullsFromAlpha({ ...ok, data: [1, 2, 3] as never }), TypeError, 'image.data must be a Uint8ClampedArray or Uint8Array'],
    ['image.data length', () => hullsFromAlpha({ ...ok, width: 5 }), RangeError, 'image.data must hold width × height × 4 = 80 bytes, got 64'],
    ['image.data length (too long)', () => hullsFromAlpha({ ...ok, height: 3 }), RangeError, 'image.data must hold width × height × 4 = 48 bytes, got 64'],
    ['options', () => hullsFromAlpha(ok, 5 as never), TypeError, 'hullsFromAlpha options must be an object, got 5'],
    ['threshold', () => hullsFromAlpha(ok, { threshold: 256 }), RangeError, 'options.threshold must be at most 255, got 256'],
    ['threshold NaN', () => hullsFromAlpha(ok, { threshold: NaN }), RangeError, 'options.threshold must be a finite number, got NaN'],
    ['tolerance', () => hullsFromAlpha(ok, { tolerance: -1 }), RangeError, 'options.tolerance must not be negative, got -1'],
    ['maxPoints', () => hullsFromAlpha(ok, { maxPoints: 2 }), RangeError, 'options.maxPoints must be an integer ≥ 3 or Infinity, got 2'],
    ['maxPoints type', () => hullsFromAlpha(ok, { maxPoints: '8' as never }), TypeError, 'options.maxPoints must be an integer ≥ 3 or Infinity, got "8"'],
    ['minArea', () => hullsFromAlpha(ok, { minArea: -3 }), RangeError, 'options.minArea must not be negative, got -3'],
    ['anchor', () => hullsFromAlpha(ok, { anchor: [0.5] }), RangeError, 'options.anchor must be an [x, y] pair or an { x, y } point, got [0.5]'],
    ['position', () => hullsFromAlpha(ok, { position: [0, Infinity] }), RangeError, 'options.position[1] must be a finite number, got Infinity'],
    ['rotation', () => hullsFromAlpha(ok, { rotation: 'a' as never }), TypeError, 'options.rotation must be a finite number, got "a"'],
    ['scale', () => hullsFromAlpha(ok, { scale: NaN }), RangeError, 'options.scale must be a finite number, got NaN'],
    ['scale pair', () => hullsFromAlpha(ok, { scale: [1, NaN] }), RangeError, 'options.scale[1] must be a finite number, got NaN'],
    ['flipX', () => hullsFromAlpha(ok, { flipX: 1 as never }), TypeError, 'options.flipX must be true or false, got 1'],
  ];
  for (const [name, call, kind, message] of cases) {
    it(`rejects a bad ${name} with a ${kind.name} naming it`, () => {
      expect(call).toThrow(kind);
      expect(call).toThrow(message);
    });
  }

  it('accepts a Uint8Array (raw RGBA, as in Node) like ImageData', () => {
    const raw = { data: Uint8Array.from(ok.data), width: 4, height: 4 };
    expect(hullsFromAlpha(raw)).toHaveLength(1);
  });
});

/**
 * A sprite-like image: a blob whose edge wobbles, soft (antialiased) alpha at its rim, two holes
 * (an eye and a mouth), a thin handle, and a few islands, scaled to `size` × `size`.
 */
function spriteLike(size: number): AlphaImage {
  const s = size / 96;
  return image(size, size, (px, py) => {
    const x = (px + 0.5) / s, y = (py + 0.5) / s;
    const angle = Math.atan2(y - 50, x - 44);
    const rim = 30 + 3 * Math.sin(5 * angle) + 1.5 * Math.sin(13 * angle) - Math.hypot(x - 44, y - 50);
    let alpha = Math.max(0, Math.min(255, 128 + 100 * rim));
    if (Math.hypot(x - 36, y - 42) < 5 || (Math.abs(x - 46) < 10 && Math.abs(y - 60) < 2.5)) alpha = 0;
    if (x > 70 && x < 90 && Math.abs(y - 50) < 0.6) alpha = 255;
    if (Math.hypot(x - 85, y - 15) < 6 || Math.hypot(x - 10, y - 88) < 3 || Math.hypot(x - 88, y - 88) < 1) alpha = 255;
    return alpha;
  });
}
