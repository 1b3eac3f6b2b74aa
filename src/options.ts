import type { ReadonlyMat4 } from 'gl-matrix';
import type { PenumbraRenderer } from './PenumbraRenderer';
import type { Dithering, ToneMapping } from './scene/look';
import { describeValue, type ColorLike } from './util/validate';

/**
 * Options of a {@link PenumbraRenderer}; every field has the default shown. A key that is not one
 * of these (a misspelt `ambient`) is a `TypeError` that names it.
 */
export interface PenumbraRendererOptions {
  /** Colour of unlit areas: `[r, g, b]` floats 0..1 per channel, `0xrrggbb` or a CSS string (see {@link ColorLike}). Default `[0.2, 0.2, 0.2]`. */
  ambientColor?: ColorLike;
  /** Draw light quads and shadow geometry as wireframe over the result. Default `false`. */
  debug?: boolean;
  /** World → clip transform. Default: pixel space of the drawing buffer, origin top-left, y down. */
  viewProjection?: ReadonlyMat4 | null;
  /** Width of the internal targets in pixels. Default: the context's drawing buffer width (on a lost context, the restored one's). */
  width?: number;
  /** Height of the internal targets in pixels. Default: the context's drawing buffer height (on a lost context, the restored one's). */
  height?: number;
  /**
   * Resolution of the lightmap relative to `width × height`, in (0, 1]. Below 1 (e.g. 0.5) the
   * light passes shade a quarter of the pixels, for fill-bound scenes; the composite (`draw`,
   * `drawInPlace`) upscales the lightmap with linear filtering except across hull outlines, where
   * each pixel takes the light of the nearest lightmap texels on its own side (through two masks of
   * the hulls, at both resolutions), so that a hull's dark or lit inside does not bleed a rim onto
   * the floor beside it. Default `1`.
   */
  lightmapScale?: number;
  /** Time the renderer's JavaScript per frame into `stats.cpuTime`. Default `false`. */
  measureCpuTime?: boolean;
  /** See {@link PenumbraRenderer.onContextRestored}. Default `null`. */
  onContextRestored?: ((renderer: PenumbraRenderer) => void) | null;
  /** See {@link PenumbraRenderer.exposure}. Default `1`. */
  exposure?: number;
  /** See {@link PenumbraRenderer.toneMapping}. Default `'none'`. */
  toneMapping?: ToneMapping;
  /** See {@link PenumbraRenderer.dithering}. Default `'none'`. */
  dithering?: Dithering;
  /** See {@link PenumbraRenderer.lightmapBlur}. Default `0`. */
  lightmapBlur?: number;
  /**
   * Light through the surface's normals, with Blinn-Phong highlights and emissive pixels:
   * `beginDraw()` binds three colour attachments (colour, normal, material) for the host to write,
   * and each light's `height` sets where it shines from (docs/normal-maps.md). Fixed for the
   * renderer's life. Without it (the default) the renderer builds none of this and its output is as
   * it always was. Default `false`.
   */
  normals?: boolean;
  /**
   * The most hull records (a convex hull of up to 4 points is one; see docs/shadows.md "Tiles") the
   * renderer classifies into lit, dark and exact tiles per frame: its JavaScript's largest per-frame
   * cost. A light whose hulls do not fit what is left of it is drawn wholly with the exact shadow
   * program (the same picture, more GPU time) and classified in a later frame; one whose moving hulls
   * do not fit has its lit tiles drawn exact for that frame. `stats.lightsUnclassified` counts those
   * lights. A non-negative integer or `Infinity`. Default `1024`.
   */
  classificationBudget?: number;
}

/** The options a {@link PenumbraRenderer} takes; any other key is an error. */
export const RENDERER_OPTION_KEYS: readonly string[] = Object.keys({
  ambientColor: true, debug: true, viewProjection: true, width: true, height: true, lightmapScale: true, measureCpuTime: true,
  onContextRestored: true, exposure: true, toneMapping: true, dithering: true, lightmapBlur: true, normals: true, classificationBudget: true,
} satisfies Record<keyof PenumbraRendererOptions, true>);

/** The `classificationBudget` option, checked: a non-negative integer or `Infinity`. */
export function checkClassificationBudget(value: number): number {
  if (typeof value !== 'number' || !(Number.isInteger(value) && value >= 0 || value === Infinity)) {
    throw new RangeError(`PenumbraRenderer.classificationBudget must be a non-negative integer or Infinity, got ${describeValue(value)}`);
  }
  return value;
}
