import { describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { readTexture } from './readTexture';

describe('smoke', () => {
  it('renders a light with a hull', () => {
    const gl = createContext(64, 64);
    const renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
    renderer.addLight(new PointLight({ position: [16, 32], range: 60, radius: 4 }));
    renderer.addHull(new Hull([[28, 24], [36, 24], [36, 40], [28, 40]]));
    renderer.renderLightmap();
    expect(gl.getError()).toBe(0);
    const pixels = readTexture(gl, renderer.lightmapTexture, 64, 64);
    const at = (x: number, y: number) => pixels[((63 - y) * 64 + x) * 4];
    expect(at(16, 32)).toBeGreaterThan(0.9);
    expect(at(50, 32)).toBeLessThan(0.05);
    renderer.dispose();
    destroyContext(gl);
  });
});
