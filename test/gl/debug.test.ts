import { afterEach, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';

const W = 64, H = 64;
let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;

afterEach(() => {
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
});

/** RGB bytes of world pixel (x, y) (y down) of the default framebuffer. */
function colourAt(x: number, y: number): number[] {
  const pixel = new Uint8Array(4);
  gl.readPixels(x, H - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return Array.from(pixel.subarray(0, 3));
}

it('draws the light quad in yellow and each shadow caster\'s quad in magenta over the result', () => {
  gl = createContext(W, H);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], debug: true });
  renderer.addLight(new PointLight({ position: [10, 33], range: 20, radius: 3 }));
  renderer.addHull(new Hull([[20, 26], [26, 26], [26, 40], [20, 40]]));
  renderer.beginDraw();
  gl.clearColor(0, 0, 0, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  // The quad's top side runs along y = 13; the hull's left side is the line x = 20.
  const near = (x: number, y: number, dx: number, dy: number) => [-1, 0, 1].map((k) => colourAt(x + k * dx, y + k * dy));
  expect(near(5, 13, 0, 1)).toContainEqual([255, 255, 0]);
  expect(near(20, 33, 1, 0)).toContainEqual([255, 0, 255]);
  // Away from every outline: the scene (black) times the light stays black.
  expect(colourAt(40, 5)).toEqual([0, 0, 0]);
});
