import { Hull, PenumbraRenderer, PointLight, type ShadowType } from '../../src/index';

/**
 * The scene of the edge-aware upsampling checks (test/gl/lightmapScale.test.ts, and in Chromium
 * test/browser/reference.test.ts): a box lit from its left, wider than the light's disk (so it has
 * an umbra), its sides off the pixel grid, on a white scene of 64 × 64 pixels. At half scale each
 * lightmap texel covers 2 × 2 pixels; upsampled bilinearly, the lightmap's jump at the outline
 * smeared a texel across it: the lit floor before a Solid box came out up to 156 steps too dark, the
 * floor in an Illuminated box's umbra 46 steps too light.
 */
export const OUTLINE_SCENE_SIZE = 64;

/** Renders the scene through `draw()` into the context's default framebuffer and reads it: 8-bit RGBA, rows bottom-up. */
export function renderOutlineScene(gl: WebGL2RenderingContext, lightmapScale: number, shadowType: ShadowType): Uint8Array {
  const size = OUTLINE_SCENE_SIZE;
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], lightmapScale, width: size, height: size });
  renderer.addLight(new PointLight({ position: [8.3, 32.1], range: 80, radius: 4, shadowType }));
  renderer.addHull(new Hull([[30.3, 20.6], [40.4, 20.6], [40.4, 44.3], [30.3, 44.3]]));
  const pixels = drawOnWhite(gl, renderer, size);
  renderer.dispose();
  return pixels;
}

/** Draws `renderer`'s frame over a white scene into the context's default framebuffer (`size` pixels square) and reads it: 8-bit RGBA, rows bottom-up. */
export function drawOnWhite(gl: WebGL2RenderingContext, renderer: PenumbraRenderer, size: number): Uint8Array {
  renderer.beginDraw();
  gl.clearColor(1, 1, 1, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  const pixels = new Uint8Array(size * size * 4);
  gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

/** Within one texel (2 pixels), linear falloff over range 80 changes by 2 × 255 / 80 ≈ 6.4 steps. */
const OUTLINE_TOLERANCE = 8;

/**
 * The pixels on both sides of the box's lit side (x = 30.3) and far side (x = 40.4), away from the
 * corners (where shadow edges start sharp), whose red differs between the two renders by more
 * than {@link OUTLINE_TOLERANCE}, as `(x, y): half, full`.
 */
export function outlineErrors(full: ArrayLike<number>, half: ArrayLike<number>): string[] {
  const errors: string[] = [];
  for (const x of [28, 29, 30, 31, 39, 40, 41, 42]) {
    for (let y = 26; y <= 39; y++) {
      if (Math.abs(outlinePixel(half, x, y) - outlinePixel(full, x, y)) > OUTLINE_TOLERANCE) errors.push(`(${x}, ${y}): ${outlinePixel(half, x, y)} at half scale, ${outlinePixel(full, x, y)} at full`);
    }
  }
  return errors;
}

/** Red of world pixel (x, y) (y down) of a render. */
export function outlinePixel(pixels: ArrayLike<number>, x: number, y: number): number {
  return pixels[((OUTLINE_SCENE_SIZE - 1 - y) * OUTLINE_SCENE_SIZE + x) * 4];
}
