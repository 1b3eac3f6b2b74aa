import { describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight, ShadowType } from '../../src/index';
import { createContext, destroyContext } from './context';
import { drawOnWhite, OUTLINE_SCENE_SIZE, outlineErrors, outlinePixel, renderOutlineScene } from './outlineUpsampling';
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

  it('at half scale, redraws the hull masks when a hull moves or the view pans, as a new renderer draws them', () => {
    const size = 64;
    const gl = createContext(size, size);
    const pan = (x: number) => new Float32Array([2 / size, 0, 0, 0, 0, -2 / size, 0, 0, 0, 0, 1, 0, -1 + (2 * x) / size, 1, 0, 1]);
    const build = (boxX: number, panX: number) => {
      const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], lightmapScale: 0.5, width: size, height: size, viewProjection: pan(panX) });
      renderer.addLight(new PointLight({ position: [8.3, 32.1], range: 80, radius: 4 }));
      const hull = renderer.addHull(new Hull([[-5.05, -11.85], [5.05, -11.85], [5.05, 11.85], [-5.05, 11.85]], { position: [boxX, 32.45] }));
      return { renderer, hull };
    };
    const draw = (renderer: PenumbraRenderer) => drawOnWhite(gl, renderer, size);
    const fresh = (boxX: number, panX: number) => {
      const { renderer } = build(boxX, panX);
      const pixels = draw(renderer);
      renderer.dispose();
      return pixels;
    };
    const kept = build(35.35, 0);
    const first = draw(kept.renderer);
    expect(draw(kept.renderer)).toEqual(first);
    kept.hull.position = [41.1, 32.45];
    const moved = draw(kept.renderer);
    expect(moved).not.toEqual(first);
    expect(moved).toEqual(fresh(41.1, 0));
    kept.renderer.viewProjection = pan(3.3);
    expect(draw(kept.renderer)).toEqual(fresh(41.1, 3.3));
    kept.renderer.dispose();
    expect(gl.getError()).toBe(0);
    destroyContext(gl);
  });

  it('rejects scales outside (0, 1]', () => {
    const gl = createContext(8, 8);
    expect(() => new PenumbraRenderer(gl, { lightmapScale: 0 })).toThrow(RangeError);
    expect(() => new PenumbraRenderer(gl, { lightmapScale: 2 })).toThrow(RangeError);
    destroyContext(gl);
  });
});
