import { DiskVisibility } from '../../src/geometry/diskVisibility';
import { SceneGeometry, segmentsCross } from './sceneGeometry';
import type { ReferenceLight, ReferenceScene } from './scenes';

/**
 * The ground truth the renderer is tested against, on the CPU: each light is a uniformly emitting
 * disk, and a pixel centre receives falloff × colour × intensity × the fraction of the disk whose
 * straight segment to it crosses no hull edge; the lights add up. Pixel centres inside a hull
 * receive nothing for Solid lights (the default: without that rule a pixel inside a hull that
 * overlaps a disk would see the part of the disk inside the same hull), and the whole disk for
 * Illuminated ones (scene.shadowType; Occluded scenes have their own reference).
 *
 * Two ways to get the fraction:
 * - `'sampled'`: tests the segments to area-uniform disk samples ({@link diskSamples}). The plainest
 *   statement of the model, shares no code with the library, slow and good to about N^-3/4 per
 *   straight cut across the disk for N samples.
 * - `'exact'` (default): the CPU light query's closed-form sweep over the directions from the pixel
 *   (`DiskVisibility`, src/geometry/diskVisibility.ts), exact to rounding and fast: what the
 *   rendering tests compare the GPU's lightmaps with. It shares no code with the shaders, and is
 *   held to `'sampled'` and to closed-form cases by test/unit/reference.test.ts,
 *   test/unit/illumination.test.ts and test/accuracy/.
 */
export interface ReferenceOptions {
  method?: 'exact' | 'sampled';
  /** Disk samples for `'sampled'`. Default {@link DISK_SAMPLES}. */
  samples?: number;
  /** Computes only pixels whose x and y are multiples of `step` (the others count as out of range). Default 1. */
  step?: number;
}

/** A pixel's shading class over the lights in range. */
export const LIT = 0, PENUMBRA = 1, UMBRA = 2;

export interface ReferenceImage {
  width: number;
  height: number;
  /** Per light, in scene order: fraction of its disk visible from each pixel centre, rows top-down (world y down); 0 inside hulls and out of its range. */
  visibility: Float32Array[];
  /** Expected lightmap RGB per pixel (Σ falloff × visibility × colour × intensity), rows top-down. */
  light: Float32Array;
  /** 1 where the pixel centre is closer than its range to at least one light. */
  inRange: Uint8Array;
  /**
   * 1 where the expected value may flip at a distance below the renderer's precision, so a
   * rendered pixel cannot be held to it: see {@link OUTLINE_BAND} and {@link HARD_EDGE_BAND}.
   */
  ambiguous: Uint8Array;
  /** Per pixel: LIT (every light in range sees all of its disk), UMBRA (none sees any) or PENUMBRA. */
  shade: Uint8Array;
}

/**
 * Pixel centres this close to a hull outline (in pixels) are ambiguous: the renderer darkens hull
 * insides by rasterizing them, and rasterizers snap vertices to a sub-pixel grid. headless-gl and
 * Chromium's SwiftShader both report SUBPIXEL_BITS = 4 (the WebGL minimum): a 1/16 pixel grid, so a
 * centre within half a step (1/32) of the outline may land on either side. The band is a whole step.
 */
export const OUTLINE_BAND = 1 / 16;
/**
 * Pixel centres this close to the edge of a hard shadow (the ray from a radius-0 light through a
 * hull point) are ambiguous too: the renderer may draw that edge as geometry, rasterized on the
 * same 1/16 pixel grid (one such pixel, 0.007 from the ray, flips in Chromium).
 */
export const HARD_EDGE_BAND = 1 / 16;

export function computeReference(scene: ReferenceScene, options: ReferenceOptions = {}): ReferenceImage {
  const { width, height } = scene;
  const { method = 'exact', step = 1 } = options;
  const geometry = new SceneGeometry(scene.hulls, scene.polylines);
  const fractionOf = visibleFraction(scene, { method, samples: options.samples });
  const pixels = width * height;
  const visibility = scene.lights.map(() => new Float32Array(pixels));
  const light = new Float32Array(pixels * 3);
  const inRange = new Uint8Array(pixels);
  const ambiguous = new Uint8Array(pixels);
  const shade = new Uint8Array(pixels);
  for (let y = 0; y < height; y += step) {
    for (let x = 0; x < width; x += step) {
      const px = x + 0.5, py = y + 0.5;
      const pixel = y * width + x;
      const insideHull = geometry.isInsideHull(px, py);
      if (geometry.isNearOutline(px, py, OUTLINE_BAND)) ambiguous[pixel] = 1;
      let all = true, none = true;
      scene.lights.forEach((source, l) => {
        const [lx, ly] = source.position;
        const falloff = Math.max(0, 1 - Math.hypot(px - lx, py - ly) / source.range);
        if (falloff === 0) return;
        inRange[pixel] = 1;
        if (source.radius === 0 && nearHardEdge(geometry, px, py, lx, ly)) ambiguous[pixel] = 1;
        // As stored (float32): a disk that nothing hides is LIT though the sweep's sum may miss 1 by rounding.
        const fraction = insideHull ? (scene.shadowType === 'illuminated' ? 1 : 0) : Math.fround(fractionOf(px, py, source));
        visibility[l][pixel] = fraction;
        if (fraction !== 1) all = false;
        if (fraction !== 0) none = false;
        const color = source.color ?? [1, 1, 1];
        const intensity = source.intensity ?? 1;
        for (let c = 0; c < 3; c++) light[pixel * 3 + c] += falloff * fraction * color[c] * intensity;
      });
      shade[pixel] = all ? LIT : none ? UMBRA : PENUMBRA;
    }
  }
  return { width, height, visibility, light, inRange, ambiguous, shade };
}

/** The fraction of a light's disk whose segment to (px, py) crosses no edge of the scene (see {@link ReferenceOptions}). */
export type FractionOf = (px: number, py: number, light: ReferenceLight) => number;

/** The scene's visible fraction by `method` (default `'exact'`): one function for many points and lights. */
export function visibleFraction(scene: ReferenceScene, { method = 'exact', samples = DISK_SAMPLES }: Omit<ReferenceOptions, 'step'> = {}): FractionOf {
  return method === 'sampled' ? sampledFraction(new SceneGeometry(scene.hulls, scene.polylines), samples) : exactFraction(scene);
}

function exactFraction(scene: ReferenceScene): FractionOf {
  const visibility = new DiskVisibility();
  const outlines = [
    ...scene.hulls.map((points) => ({ points: Float64Array.from(points.flat()), closed: true })),
    ...(scene.polylines ?? []).map((points) => ({ points: Float64Array.from(points.flat()), closed: false })),
  ];
  return (px, py, { position: [cx, cy], radius }) => {
    visibility.begin(px, py, cx, cy, radius);
    for (const { points, closed } of outlines) visibility.addOutline(points, points.length / 2, closed);
    return visibility.fraction();
  };
}

/** Whether the pixel lies within HARD_EDGE_BAND of a ray from the light's centre through a hull point between them. */
function nearHardEdge(geometry: SceneGeometry, px: number, py: number, lx: number, ly: number): boolean {
  const v = geometry.vertices;
  const dx = px - lx, dy = py - ly;
  const lengthSquared = dx * dx + dy * dy;
  for (let i = 0; i < v.length; i += 2) {
    const vx = v[i] - lx, vy = v[i + 1] - ly;
    const along = vx * dx + vy * dy;
    if (along <= 0 || along > lengthSquared) continue;
    // Distance from the pixel to the line through the light and the point.
    if (Math.abs(vx * dy - vy * dx) < HARD_EDGE_BAND * Math.sqrt(vx * vx + vy * vy)) return true;
  }
  return false;
}

/**
 * Disk samples for the sampling reference. A sunflower (Fibonacci) pattern is area-uniform and
 * low-discrepancy: for a disk cut by a straight line its visible fraction errs by about N^-3/4,
 * ≈ 0.002 for N = 4096.
 */
export const DISK_SAMPLES = 4096;
const GOLDEN_ANGLE = Math.PI * (3 - Math.sqrt(5));

export function diskSamples(cx: number, cy: number, radius: number, count: number): Float64Array {
  if (radius === 0) return Float64Array.of(cx, cy);
  const samples = new Float64Array(count * 2);
  for (let i = 0; i < count; i++) {
    const r = radius * Math.sqrt((i + 0.5) / count);
    const angle = i * GOLDEN_ANGLE;
    samples[2 * i] = cx + r * Math.cos(angle);
    samples[2 * i + 1] = cy + r * Math.sin(angle);
  }
  return samples;
}

/** The sampling reference: the share of disk samples whose segment to the pixel centre crosses no hull edge. */
function sampledFraction(geometry: SceneGeometry, count: number): FractionOf {
  const edges = geometry.edges;
  const candidates = new Float64Array(edges.length);
  const samplesOf = new Map<ReferenceLight, Float64Array>();
  return (px, py, light) => {
    let samples = samplesOf.get(light);
    if (!samples) samplesOf.set(light, (samples = diskSamples(light.position[0], light.position[1], light.radius, count)));
    const [lx, ly] = light.position;
    // Only edges overlapping the box around the pixel and the disk can block a segment.
    const minX = Math.min(px, lx - light.radius), maxX = Math.max(px, lx + light.radius);
    const minY = Math.min(py, ly - light.radius), maxY = Math.max(py, ly + light.radius);
    let candidateCount = 0;
    for (let e = 0; e < edges.length; e += 4) {
      const ax = edges[e], ay = edges[e + 1], bx = edges[e + 2], by = edges[e + 3];
      if (Math.max(ax, bx) < minX || Math.min(ax, bx) > maxX || Math.max(ay, by) < minY || Math.min(ay, by) > maxY) continue;
      candidates.set(edges.subarray(e, e + 4), candidateCount);
      candidateCount += 4;
    }
    return shareOfSamplesSeen(px, py, samples, candidates, candidateCount);
  };
}

/** The share of `samples` (`[x, y, …]`) whose segment to (px, py) crosses none of the edges in the first `edgeFloats` of `edges`. */
export function shareOfSamplesSeen(px: number, py: number, samples: Float64Array, edges: Float64Array, edgeFloats: number): number {
  if (edgeFloats === 0) return 1;
  const crosses = segmentsCross; // a local: vitest's module transform makes every imported call a property read
  const sampleCount = samples.length / 2;
  let visible = sampleCount;
  for (let s = 0; s < sampleCount; s++) {
    const sx = samples[2 * s], sy = samples[2 * s + 1];
    for (let e = 0; e < edgeFloats; e += 4) {
      if (crosses(px, py, sx, sy, edges[e], edges[e + 1], edges[e + 2], edges[e + 3])) {
        visible--;
        break;
      }
    }
  }
  return visible / sampleCount;
}
