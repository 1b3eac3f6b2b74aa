import type { ReferenceImage } from './softShadowReference';
import type { ReferenceScene } from './scenes';

/** Error figures of one class of pixels, in units of the light's full strength (colour × intensity). */
export interface ErrorFigures {
  pixels: number;
  mean: number;
  p99: number;
  max: number;
}

/** Figures over all pixels within range, and split by the reference's visibility. */
export interface SceneErrors {
  all: ErrorFigures;
  /** Whole disk visible. */
  lit: ErrorFigures;
  /** No part of the disk visible. */
  umbra: ErrorFigures;
  /** Part of the disk visible. */
  penumbra: ErrorFigures;
}

/**
 * Compares a rendered lightmap (RGB rows top-down) with the reference over every pixel within
 * the light's range; each channel's error is divided by that channel's full strength, and a
 * pixel's error is its worst channel.
 */
export function compareToReference(scene: ReferenceScene, rendered: Float32Array, reference: ReferenceImage): SceneErrors {
  const color = scene.light.color ?? [1, 1, 1];
  const intensity = scene.light.intensity ?? 1;
  const classes = { all: [] as number[], lit: [] as number[], umbra: [] as number[], penumbra: [] as number[] };
  for (let pixel = 0; pixel < reference.width * reference.height; pixel++) {
    if (!reference.inRange[pixel]) continue;
    let error = 0;
    for (let c = 0; c < 3; c++) {
      const full = color[c] * intensity;
      if (full > 0) error = Math.max(error, Math.abs(rendered[pixel * 3 + c] - reference.light[pixel * 3 + c]) / full);
    }
    const visibility = reference.visibility[pixel];
    classes.all.push(error);
    (visibility === 1 ? classes.lit : visibility === 0 ? classes.umbra : classes.penumbra).push(error);
  }
  return {
    all: figuresOf(classes.all), lit: figuresOf(classes.lit),
    umbra: figuresOf(classes.umbra), penumbra: figuresOf(classes.penumbra),
  };
}

function figuresOf(errors: number[]): ErrorFigures {
  if (errors.length === 0) return { pixels: 0, mean: 0, p99: 0, max: 0 };
  const sorted = Float64Array.from(errors).sort();
  let sum = 0;
  for (const error of sorted) sum += error;
  return {
    pixels: sorted.length,
    mean: sum / sorted.length,
    p99: sorted[Math.min(sorted.length - 1, Math.ceil(0.99 * sorted.length) - 1)],
    max: sorted[sorted.length - 1],
  };
}

/** A plain-text table of the figures, one row per scene and pixel class. */
export function formatErrorTable(title: string, rows: ReadonlyArray<{ scene: string; errors: SceneErrors }>): string {
  const header = ['scene', 'class', 'pixels', 'mean', 'p99', 'max'];
  const lines: string[][] = [];
  for (const { scene, errors } of rows) {
    for (const name of ['all', 'lit', 'umbra', 'penumbra'] as const) {
      const f = errors[name];
      lines.push([name === 'all' ? scene : '', name, String(f.pixels),
        f.mean.toFixed(4), f.p99.toFixed(4), f.max.toFixed(4)]);
    }
  }
  const widths = header.map((h, i) => Math.max(h.length, ...lines.map((l) => l[i].length)));
  const format = (cells: string[]) => cells.map((cell, i) => (i === 0 ? cell.padEnd(widths[i]) : cell.padStart(widths[i]))).join('  ');
  return [title, format(header), ...lines.map(format)].join('\n');
}
