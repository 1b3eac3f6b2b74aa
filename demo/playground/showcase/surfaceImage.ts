/**
 * Procedural surfaces for the showcase: a painter writes, per pixel, a height, a colour, a coverage
 * and a material; the image turns the heights into a tangent-space normal map (Sobel of the height
 * field, +z towards the viewer, OpenGL-style green up) and keeps three RGBA8 images side by side:
 * albedo, normal and material (specular, log2(shininess) / 11, emissive).
 */

/** What a painter says about one pixel. Reused between calls: a painter sets every field. */
export interface Texel {
  /** Height in pixels of relief (the normal's slope is its difference between neighbours). */
  height: number;
  /** Colour 0..1. */
  r: number;
  g: number;
  b: number;
  /** Coverage 0..1. */
  alpha: number;
  /** Highlight strength 0..1. */
  specular: number;
  /** Blinn-Phong exponent 1..2048. */
  shininess: number;
  /** 0..1: the colour glows whatever the light. */
  emissive: number;
}

/** Paints pixel (x, y) of a cell of `width` × `height` pixels into `out`. */
type Painter = (x: number, y: number, out: Texel) => void;

/** Three images of the same size: what the showcase's shader samples. */
export class SurfaceImage {
  readonly albedo: Uint8Array;
  readonly normal: Uint8Array;
  readonly material: Uint8Array;
  private readonly heights: Float32Array;

  constructor(readonly width: number, readonly height: number) {
    this.albedo = new Uint8Array(width * height * 4);
    this.normal = new Uint8Array(width * height * 4);
    this.material = new Uint8Array(width * height * 4);
    this.heights = new Float32Array(width * height);
    // Flat and facing the viewer where nothing is painted.
    for (let i = 0; i < width * height; i++) this.normal.set([128, 128, 255, 255], i * 4);
  }

  /**
   * Paints the cell at (x0, y0) of `w` × `h` pixels. `wrap`: the cell tiles, so the normals at its
   * edges read the heights across the opposite edge (floors and walls; `'x'`: across the left and
   * right edges only); otherwise the edges clamp. `bump` scales the slopes.
   */
  paint(x0: number, y0: number, w: number, h: number, painter: Painter, { wrap = false, bump = 1 }: { wrap?: boolean | 'x'; bump?: number } = {}): this {
    const texel: Texel = { height: 0, r: 0, g: 0, b: 0, alpha: 1, specular: 0, shininess: 1, emissive: 0 };
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        texel.height = 0;
        texel.alpha = 1;
        texel.specular = 0;
        texel.shininess = 1;
        texel.emissive = 0;
        painter(x, y, texel);
        const p = (y0 + y) * this.width + x0 + x, i = p * 4;
        this.heights[p] = texel.height;
        this.albedo[i] = byte(texel.r);
        this.albedo[i + 1] = byte(texel.g);
        this.albedo[i + 2] = byte(texel.b);
        this.albedo[i + 3] = byte(texel.alpha);
        this.material[i] = byte(texel.specular);
        this.material[i + 1] = byte(Math.log2(Math.max(1, texel.shininess)) / 11);
        this.material[i + 2] = byte(texel.emissive);
        this.material[i + 3] = 255;
      }
    }
    const at = (x: number, y: number) => {
      x = wrap ? (x + w) % w : Math.min(w - 1, Math.max(0, x));
      y = wrap === true ? (y + h) % h : Math.min(h - 1, Math.max(0, y));
      return this.heights[(y0 + y) * this.width + x0 + x];
    };
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        // Sobel: slopes along x (right) and y (down the image), in height per pixel.
        const dx = (at(x + 1, y - 1) + 2 * at(x + 1, y) + at(x + 1, y + 1) - at(x - 1, y - 1) - 2 * at(x - 1, y) - at(x - 1, y + 1)) / 8;
        const dy = (at(x - 1, y + 1) + 2 * at(x, y + 1) + at(x + 1, y + 1) - at(x - 1, y - 1) - 2 * at(x, y - 1) - at(x + 1, y - 1)) / 8;
        // The normal of z = h(x, y) is (−∂h/∂x, −∂h/∂y, 1) in image axes (y down); green holds
        // the component up the image, −(−∂h/∂y) = ∂h/∂y.
        const nx = -dx * bump, ny = dy * bump, length = Math.hypot(nx, ny, 1);
        const i = ((y0 + y) * this.width + x0 + x) * 4;
        this.normal[i] = byte(nx / length * 0.5 + 0.5);
        this.normal[i + 1] = byte(ny / length * 0.5 + 0.5);
        this.normal[i + 2] = byte(1 / length * 0.5 + 0.5);
        this.normal[i + 3] = 255;
      }
    }
    return this;
  }
}

function byte(value: number): number {
  return Math.round(Math.min(1, Math.max(0, value)) * 255);
}

/** A hash of integer lattice point (x, y) with a seed, in [0, 1). */
export function hash(x: number, y: number, seed: number): number {
  let h = Math.imul(x | 0, 374761393) ^ Math.imul(y | 0, 668265263) ^ Math.imul(seed | 0, 2147483647);
  h = Math.imul(h ^ (h >>> 13), 1274126177);
  h ^= h >>> 16;
  return (h >>> 0) / 4294967296;
}

const smooth = (t: number) => t * t * (3 - 2 * t);

/** Value noise in [0, 1) with lattice period `period` (so a texture of period × cell pixels tiles). */
export function noise(x: number, y: number, period: number, seed: number): number {
  const ix = Math.floor(x), iy = Math.floor(y), fx = smooth(x - ix), fy = smooth(y - iy);
  const wrap = (v: number) => ((v % period) + period) % period;
  const x0 = wrap(ix), x1 = wrap(ix + 1), y0 = wrap(iy), y1 = wrap(iy + 1);
  const a = hash(x0, y0, seed), b = hash(x1, y0, seed), c = hash(x0, y1, seed), d = hash(x1, y1, seed);
  return a + (b - a) * fx + (c - a) * fy + (a - b - c + d) * fx * fy;
}

/** Fractal noise in about [0, 1): `octaves` of {@link noise}, each twice as fine and half as strong; tiles with `period` at the first octave. */
export function fbm(x: number, y: number, period: number, seed: number, octaves = 4): number {
  let sum = 0, weight = 0.5, total = 0;
  for (let o = 0; o < octaves; o++) {
    sum += noise(x, y, period, seed + o * 17) * weight;
    total += weight;
    x *= 2;
    y *= 2;
    period *= 2;
    weight *= 0.5;
  }
  return sum / total;
}

/** 0 below `a`, 1 above `b`, smooth between. */
export function smoothstep(a: number, b: number, x: number): number {
  return smooth(Math.min(1, Math.max(0, (x - a) / (b - a))));
}
