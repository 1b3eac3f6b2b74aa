import { LIT, UMBRA, type ReferenceImage } from './softShadowReference';
import type { ReferenceScene } from './scenes';

/** Error figures of one class of pixels, in units of full light (see {@link compareToReference}). */
interface ErrorFigures {
  pixels: number;
  mean: number;
  p99: number;
  max: number;
}

/** Figures over all pixels within range, and split by the reference's visibility. */
export interface SceneErrors {
  all: ErrorFigures;
  /** Every light in range sees its whole disk. */
  lit: ErrorFigures;
  /** No light in range sees any part of its disk (hull insides included). */
  umbra: ErrorFigures;
  /** The rest: part of some disk visible. */
  penumbra: ErrorFigures;
  /** Pixels within range left out as ambiguous (see `ReferenceImage.ambiguous`). */
  ambiguous: number;
}

/**
 * Compares a rendered lightmap (RGB rows top-down) with the reference over every pixel within
 * range of some light, leaving out the reference's ambiguous pixels (centres on a hull outline or
 * on a hard shadow's edge, to within the renderer's precision).
 *
 * Errors are in units of full light of the strongest light: each channel's error is divided by the
 * largest colour × intensity any light of the scene has in that channel, and a pixel's error is its
 * worst channel. With one light this is that light's full strength; with several, an error of 0.01
 * is a hundredth of the brightest light at its centre, whichever lights it comes from (the lightmap
 * holds only their sum, so errors cannot be split per light).
 */
export function compareToReference(scene: ReferenceScene, rendered: Float32Array, reference: ReferenceImage): SceneErrors {
  const full = [0, 1, 2].map((c) => Math.max(...scene.lights.map((l) => (l.color ?? [1, 1, 1])[c] * (l.intensity ?? 1))));
  const classes = { all: [] as number[], lit: [] as number[], umbra: [] as number[], penumbra: [] as number[] };
  let ambiguous = 0;
  for (let pixel = 0; pixel < reference.width * reference.height; pixel++) {
    if (!reference.inRange[pixel]) continue;
    if (reference.ambiguous[pixel]) {
      ambiguous++;
      continue;
    }
    let error = 0;
    for (let c = 0; c < 3; c++) {
      if (full[c] > 0) error = Math.max(error, Math.abs(rendered[pixel * 3 + c] - reference.light[pixel * 3 + c]) / full[c]);
    }
    const shade = reference.shade[pixel];
    classes.all.push(error);
    (shade === LIT ? classes.lit : shade === UMBRA ? classes.umbra : classes.penumbra).push(error);
  }
  return {
    all: figuresOf(classes.all), lit: figuresOf(classes.lit),
    umbra: figuresOf(classes.umbra), penumbra: figuresOf(classes.penumbra), ambiguous,
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
