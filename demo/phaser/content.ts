// What the Phaser example is made of, exported for the tests too: the flashlight, and the art,
// drawn in code into one texture laid out like an atlas: the wall tile (the tilemap's tileset)
// and the prop's frame beside it.
import type { SpotlightOptions } from 'penumbra-gl';
import { PROP_SIZE, TILE_SIZE, propImage } from '../examples/level';
import { brickNormals, propNormals } from '../examples/normalMaps';

/** The player's flashlight (placed and aimed every frame). */
export const FLASHLIGHT: Readonly<SpotlightOptions> = {
  range: 320, radius: 3, coneAngle: Math.PI / 3.5, coneDecay: 0.6, intensity: 1.3, color: [1, 0.95, 0.8],
};

/** Key of the texture. */
export const ART_KEY = 'level-art';
/** Index of the wall tile in the tileset (the texture cut into TILE_SIZE squares from its top-left). */
export const WALL_TILE = 0;
/** Name of the prop's frame. */
export const PROP_FRAME = 'prop';
/** Top-left of the prop's pixels in the texture: its frame is a crop of the texture, right of the wall tile. */
export const PROP_CUT: readonly [number, number] = [TILE_SIZE + 4, 0];
/**
 * Width of the prop's untrimmed frame. The frame is trimmed as an atlas packer trims an image
 * whose right columns are empty: the star's PROP_SIZE columns sit at the left of a frame this
 * wide. The sprite keeps Phaser's default origin, the untrimmed frame's centre, so the star sits
 * (PROP_TRIMMED_WIDTH − PROP_SIZE) / 2 left of the sprite's position and circles it as it turns;
 * flipX mirrors the untrimmed frame in place, moving the star to the other side (the star itself
 * is symmetric left–right: without the trim a flip would change nothing).
 */
export const PROP_TRIMMED_WIDTH = PROP_SIZE + 16;

/** Draws the texture: a stone wall tile and the prop's star. */
export function drawArt(): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  canvas.width = PROP_CUT[0] + PROP_SIZE;
  canvas.height = PROP_SIZE;
  const context = canvas.getContext('2d')!;
  // Stone: mortar, then two courses of bricks, the lower one offset by half a brick.
  const half = TILE_SIZE / 2;
  context.fillStyle = '#5f574e';
  context.fillRect(0, 0, TILE_SIZE, TILE_SIZE);
  context.fillStyle = '#8a7f72';
  for (const [x, y, w] of [[1, 1, TILE_SIZE - 2], [1, half + 1, half - 2], [half + 1, half + 1, half - 2]]) {
    context.fillRect(x, y, w, half - 2);
  }
  context.putImageData(propImage(), PROP_CUT[0], PROP_CUT[1]);
  return canvas;
}

/** The art's normal map, laid out as the art: the wall tile's bevelled bricks and the prop's dome (its data source in Phaser). */
export function drawArtNormals(): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  canvas.width = PROP_CUT[0] + PROP_SIZE;
  canvas.height = PROP_SIZE;
  const context = canvas.getContext('2d')!;
  // Flat (facing the viewer) where nothing is drawn.
  context.fillStyle = 'rgb(128, 128, 255)';
  context.fillRect(0, 0, canvas.width, canvas.height);
  context.putImageData(brickNormals(), 0, 0);
  context.putImageData(propNormals(), PROP_CUT[0], PROP_CUT[1]);
  return canvas;
}
