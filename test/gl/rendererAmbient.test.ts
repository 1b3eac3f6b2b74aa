import { afterEach, beforeEach, expect, it } from 'vitest';
import { PenumbraRenderer } from '../../src/index';
import { createContext, destroyContext } from './context';

let gl: WebGL2RenderingContext;

beforeEach(() => {
  gl = createContext(8, 8);
});

afterEach(() => {
  destroyContext(gl);
});

it('ambientColor is a frozen snapshot: writing into it throws and leaves the ambient as it was', () => {
  const renderer = new PenumbraRenderer(gl, { ambientColor: [0.1, 0.2, 0.3] });
  const ambient = renderer.ambientColor;
  expect(Object.isFrozen(ambient)).toBe(true);
  expect(() => { (ambient as unknown as number[])[0] = NaN; }).toThrow(TypeError);
  expect(renderer.ambientColor).toEqual([0.1, 0.2, 0.3]);
  renderer.ambientColor = [1, 1, 1];
  expect(ambient).toEqual([0.1, 0.2, 0.3]);
  renderer.dispose();
});

it('an ambientColor option of null or NaN is an error, as from the setter, not the default', () => {
  expect(() => new PenumbraRenderer(gl, { ambientColor: null as unknown as [number, number, number] }))
    .toThrow(new TypeError("PenumbraRenderer.ambientColor must be an [r, g, b] triple, a 0xrrggbb number or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string, got null"));
  expect(() => new PenumbraRenderer(gl, { ambientColor: NaN }))
    .toThrow(new RangeError("PenumbraRenderer.ambientColor must be an [r, g, b] triple, a 0xrrggbb number or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string; a number must be an integer from 0x000000 to 0xffffff, got NaN"));
});
