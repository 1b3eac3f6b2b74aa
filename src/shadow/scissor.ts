import type { ReadonlyMat4 } from 'gl-matrix';

/**
 * The pixel rectangle `[x, y, width, height]` (GL window coordinates, origin bottom-left) covered
 * by the world-space box `bounds = [minX, minY, maxX, maxY]` under `viewProjection`, clamped to a
 * `targetWidth × targetHeight` target. Written into `out`; returns false when it is empty.
 */
export function scissorOf(
  bounds: ArrayLike<number>, viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number, out: Int32Array,
): boolean {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (let corner = 0; corner < 4; corner++) {
    const x = bounds[corner & 1 ? 2 : 0];
    const y = bounds[corner & 2 ? 3 : 1];
    const m = viewProjection;
    const w = m[3] * x + m[7] * y + m[15];
    const sx = ((m[0] * x + m[4] * y + m[12]) / w * 0.5 + 0.5) * targetWidth;
    const sy = ((m[1] * x + m[5] * y + m[13]) / w * 0.5 + 0.5) * targetHeight;
    if (sx < minX) minX = sx;
    if (sx > maxX) maxX = sx;
    if (sy < minY) minY = sy;
    if (sy > maxY) maxY = sy;
  }
  const x0 = Math.max(0, Math.floor(minX));
  const y0 = Math.max(0, Math.floor(minY));
  const x1 = Math.min(targetWidth, Math.ceil(maxX));
  const y1 = Math.min(targetHeight, Math.ceil(maxY));
  out[0] = x0;
  out[1] = y0;
  out[2] = x1 - x0;
  out[3] = y1 - y0;
  return x1 > x0 && y1 > y0;
}
