import { describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight, ShadowType } from '../../src/index';
import { createContext, destroyContext } from './context';
import { OUTLINE_SCENE_SIZE, outlineErrors, outlinePixel, renderOutlineScene } from './outlineUpsampling';
import { readTexture } from './readTexture';

describe('lightmapScale', () => {
  it('renders the lightmap and shadows at a fraction of the resolution', () => {
    const gl = createContext(64, 64);
    const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], lightmapScale: 0.5 });
    renderer.addLight(new PointLight({ position: [16, 32], range: 60, radius: 4 }));
    renderer.addHull(new Hull([[28, 24], [36, 24], [36, 40], [28, 40]]));
    renderer.renderLightmap();
    expect(gl.getError()).toBe(0);
    const pixels = readTexture(gl, renderer.lightmapTexture, 32, 32);
    // World (x, y) sits in lightmap texel (x / 2, y / 2), rows bottom-up.
    const at = (x: number, y: number) => pixels[((31 - Math.floor(y / 2)) * 32 + Math.floor(x / 2)) * 4];
    expect(at(16, 32)).toBeGreaterThan(0.9);
    expect(at(50, 32)).toBeLessThan(0.05);
    renderer.dispose();
    destroyContext(gl);
  });

  for (const shadowType of [ShadowType.Solid, ShadowType.Illuminated]) {
    it(`at half scale, keeps the light on each side of a ${shadowType} hull's outline (no rim, no seam)`, () => {
      const render = (scale: number) => {
        const gl = createContext(OUTLINE_SCENE_SIZE, OUTLINE_SCENE_SIZE);
        const pixels = renderOutlineScene(gl, scale, shadowType);
        expect(gl.getError()).toBe(0);
        destroyContext(gl);
        return pixels;
      };
      const full = render(1), half = render(0.5);
      expect(outlineErrors(full, half)).toEqual([]);
      // What the check covers: lit floor before the box; a dark (Solid) or lit (Illuminated) box; its umbra.
      expect(outlinePixel(full, 29, 32)).toBeGreaterThan(150);
      if (shadowType === ShadowType.Solid) expect(outlinePixel(full, 31, 32)).toBe(0);
      else expect(outlinePixel(full, 31, 32)).toBeGreaterThan(150);
      expect(outlinePixel(full, 42, 32)).toBe(0);
    });
  }

  it('rejects scales outside (0, 1]', () => {
    const gl = createContext(8, 8);
    expect(() => new PenumbraRenderer(gl, { lightmapScale: 0 })).toThrow(RangeError);
    expect(() => new PenumbraRenderer(gl, { lightmapScale: 2 })).toThrow(RangeError);
    destroyContext(gl);
  });
});
