import { describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';
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

  it('rejects scales outside (0, 1]', () => {
    const gl = createContext(8, 8);
    expect(() => new PenumbraRenderer(gl, { lightmapScale: 0 })).toThrow(RangeError);
    expect(() => new PenumbraRenderer(gl, { lightmapScale: 2 })).toThrow(RangeError);
    destroyContext(gl);
  });
});
