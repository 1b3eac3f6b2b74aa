import type { PenumbraRenderer } from '../../src/index';
import { lightmapToWorldRows } from '../reference/buildScene';
import { readTexture } from './readTexture';

/** A lightmap read back, addressed in world pixels (default view: origin top-left, y down). */
export interface Lightmap {
  width: number;
  height: number;
  /** RGB rows top-down. */
  rgb: Float32Array;
  /** The `[r, g, b]` of world pixel (x, y). */
  at(x: number, y: number): [number, number, number];
}

/** Builds the renderer's lightmap (of the lights lighting content `layers`, default all) and reads it back. */
export function renderLightmap(gl: WebGL2RenderingContext, renderer: PenumbraRenderer, width: number, height: number, layers?: number): Lightmap {
  renderer.renderLightmap(layers);
  const rgb = lightmapToWorldRows(readTexture(gl, renderer.lightmapTexture, width, height), width, height);
  return {
    width, height, rgb,
    at: (x, y) => {
      const i = (y * width + x) * 3;
      return [rgb[i], rgb[i + 1], rgb[i + 2]];
    },
  };
}
