import type { ReferenceScene } from './scenes';

/**
 * The ground truth of SPEC §6, computed on the CPU without any of the renderer's math: the light
 * is a uniformly emitting disk, sampled at area-uniform points; a sample lights a pixel centre when
 * the straight segment between them crosses no hull edge. Radius 0 is a single sample at the centre
 * (hard shadows).
 */
export interface ReferenceImage {
  width: number;
  height: number;
  /** Fraction of the disk visible from each pixel centre, rows top-down (world y down). */
  visibility: Float32Array;
  /** Expected lightmap RGB per pixel (falloff × visibility × colour × intensity), rows top-down. */
  light: Float32Array;
  /** 1 where the pixel centre is closer to the light than its range. */
  inRange: Uint8Array;
}

/**
 * Disk samples. A sunflower (Fibonacci) pattern is area-uniform and low-discrepancy: for a disk
 * cut by a straight line its visible fraction errs by about N^-3/4, ≈ 0.001 for N = 4096, far
 * below the 0.01 mean the renderer is held to.
 */
export const DISK_SAMPLES = 4096;
const GOLDEN_ANGLE = Math.PI * (3 - Math.sqrt(5));

function diskSamples(cx: number, cy: number, radius: number): Float64Array {
  if (radius === 0) return Float64Array.of(cx, cy);
  const samples = new Float64Array(DISK_SAMPLES * 2);
  for (let i = 0; i < DISK_SAMPLES; i++) {
    const r = radius * Math.sqrt((i + 0.5) / DISK_SAMPLES);
    const angle = i * GOLDEN_ANGLE;
    samples[2 * i] = cx + r * Math.cos(angle);
    samples[2 * i + 1] = cy + r * Math.sin(angle);
  }
  return samples;
}

/** True when segment p→s crosses segment a→b (parallel segments count as not crossing: zero measure). */
function crosses(px: number, py: number, sx: number, sy: number, ax: number, ay: number, bx: number, by: number): boolean {
  const dx = sx - px, dy = sy - py, ex = bx - ax, ey = by - ay;
  const denominator = dx * ey - dy * ex;
  if (denominator === 0) return false;
  const qx = ax - px, qy = ay - py;
  const t = (qx * ey - qy * ex) / denominator;
  const u = (qx * dy - qy * dx) / denominator;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

export function computeReference(scene: ReferenceScene): ReferenceImage {
  const { width, height, light } = scene;
  const [lx, ly] = light.position;
  const color = light.color ?? [1, 1, 1];
  const intensity = light.intensity ?? 1;
  const samples = diskSamples(lx, ly, light.radius);
  const sampleCount = samples.length / 2;
  const edges = hullEdges(scene.hulls);
  const candidates = new Float64Array(edges.length);
  const visibility = new Float32Array(width * height);
  const lightOut = new Float32Array(width * height * 3);
  const inRange = new Uint8Array(width * height);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const px = x + 0.5, py = y + 0.5;
      const pixel = y * width + x;
      const falloff = Math.max(0, 1 - Math.hypot(px - lx, py - ly) / light.range);
      if (falloff === 0) continue;
      inRange[pixel] = 1;
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
      let visible = sampleCount;
      if (candidateCount > 0) {
        for (let s = 0; s < sampleCount; s++) {
          const sx = samples[2 * s], sy = samples[2 * s + 1];
          for (let e = 0; e < candidateCount; e += 4) {
            if (crosses(px, py, sx, sy, candidates[e], candidates[e + 1], candidates[e + 2], candidates[e + 3])) {
              visible--;
              break;
            }
          }
        }
      }
      const fraction = visible / sampleCount;
      visibility[pixel] = fraction;
      for (let c = 0; c < 3; c++) lightOut[pixel * 3 + c] = falloff * fraction * color[c] * intensity;
    }
  }
  return { width, height, visibility, light: lightOut, inRange };
}

/** All hull edges as `[ax, ay, bx, by, …]`. */
function hullEdges(hulls: ReferenceScene['hulls']): Float64Array {
  const edges: number[] = [];
  for (const hull of hulls) {
    for (let i = 0; i < hull.length; i++) {
      const a = hull[i], b = hull[(i + 1) % hull.length];
      edges.push(a[0], a[1], b[0], b[1]);
    }
  }
  return Float64Array.from(edges);
}
