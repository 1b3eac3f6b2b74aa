import { describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { checkHostStateAcrossPublicCalls, setUnpackParameters } from './hostParameters';
import { readTexture } from './readTexture';

// The same check runs in Chromium (test/browser/reference.test.ts).
describe('every host parameter, on headless-gl', () => {
  it('is as the host set it after each public call', () => {
    const gl = createContext(64, 48);
    const report = checkHostStateAcrossPublicCalls(gl, 64, 48);
    console.log(`headless-gl: ${report.compared} parameters compared after each of ${report.calls.length} public calls; rejected setup steps: ${report.unsupported.join(', ') || 'none'}; host vertex array rebound after each call (raw-name context): ${report.rawNames}`);
    destroyContext(gl);
    expect(report.failures).toEqual([]);
    // The context is headless-gl as users get it, unpatched (test/gl/context.ts).
    expect(report.rawNames).toBe(true);
    expect(report.compared).toBeGreaterThan(300);
  });

  it('is as the host set it after each public call of a renderer with a half-scale lightmap (hull masks)', () => {
    const gl = createContext(64, 48);
    const report = checkHostStateAcrossPublicCalls(gl, 64, 48, false, 0.5);
    destroyContext(gl);
    expect(report.failures).toEqual([]);
    expect(report.compared).toBeGreaterThan(300);
  });

  it('does not change what is drawn: the same lightmap under the host’s unpack parameters', () => {
    const W = 32, H = 24;
    const gl = createContext(W, H);
    const lightmap = (): Float32Array => {
      const renderer = new PenumbraRenderer(gl);
      renderer.addLight(new PointLight({ position: [8, 12], range: 30, radius: 2 }));
      const hull = renderer.addHull(new Hull([[16, 8], [20, 8], [20, 16], [16, 16]]));
      renderer.renderLightmap();
      // A moved hull uploads only its dirty rows: the other upload path.
      hull.position = [1, 2];
      renderer.renderLightmap();
      const texels = readTexture(gl, renderer.lightmapTexture, W, H);
      renderer.dispose();
      return texels;
    };
    const plain = lightmap();
    setUnpackParameters(gl);
    const hostile = lightmap();
    expect(gl.getError()).toBe(0);
    destroyContext(gl);
    expect(hostile).toEqual(plain);
  });
});
