// The engine examples' normal maps, made in code from height functions: bevelled bricks for the
// wall tiles and a dome for the prop. OpenGL-style (green up the image), the default of both plugins.
import { PROP_SIZE, TILE_SIZE } from './level';

/** The bricks of a wall tile, `[x, y, width, height]` in tile pixels: two courses, the lower offset by half a brick. */
export function bricks(): [number, number, number, number][] {
  const half = TILE_SIZE / 2;
  return [[1, 1, TILE_SIZE - 2, half - 2], [1, half + 1, half - 2, half - 2], [half + 1, half + 1, half - 2, half - 2]];
}

/** Bevel width of the bricks, pixels. */
const BEVEL = 3;

/** Height of a wall tile at a pixel centre, 0..1: flat brick faces bevelled down to the mortar. */
function brickHeight(x: number, y: number): number {
  let height = 0;
  for (const [bx, by, bw, bh] of bricks()) {
    const inside = Math.min(x - bx, bx + bw - x, y - by, by + bh - y);
    if (inside > 0) height = Math.max(height, Math.min(1, inside / BEVEL));
  }
  return height;
}

/** Height of the prop at a pixel centre, 0..1: a dome over its image. */
function domeHeight(x: number, y: number): number {
  const r = Math.hypot(x - PROP_SIZE / 2, y - PROP_SIZE / 2) / (PROP_SIZE / 2);
  return Math.sqrt(Math.max(0, 1 - r * r));
}

/**
 * A normal map of `height` (0..1 at pixel centres) over `width` × `rows` pixels, `depth` pixels
 * deep at height 1: normal = normalize(−∂h/∂x, −∂h/∂y, 1) from central differences, green up.
 */
function normalMap(width: number, rows: number, depth: number, height: (x: number, y: number) => number): ImageData {
  const data = new Uint8ClampedArray(width * rows * 4);
  for (let y = 0; y < rows; y++) {
    for (let x = 0; x < width; x++) {
      const cx = x + 0.5, cy = y + 0.5;
      const dx = ((height(cx + 1, cy) - height(cx - 1, cy)) / 2) * depth;
      const dy = ((height(cx, cy + 1) - height(cx, cy - 1)) / 2) * depth;
      const length = Math.hypot(dx, dy, 1);
      const i = (y * width + x) * 4;
      data[i] = (0.5 - (0.5 * dx) / length) * 255;
      // Green up the image: image y points down, so up is −y.
      data[i + 1] = (0.5 + (0.5 * dy) / length) * 255;
      data[i + 2] = (0.5 + 0.5 / length) * 255;
      data[i + 3] = 255;
    }
  }
  return new ImageData(data, width, rows);
}

/** The wall tile's normal map, TILE_SIZE square. */
export function brickNormals(): ImageData {
  return normalMap(TILE_SIZE, TILE_SIZE, 2, brickHeight);
}

/** The prop's normal map, PROP_SIZE square, laid out as `propImage()`. */
export function propNormals(): ImageData {
  return normalMap(PROP_SIZE, PROP_SIZE, 6, domeHeight);
}
