import { afterEach, beforeEach, expect, it } from 'vitest';
import { PenumbraRenderer, PointLight, type PenumbraRendererOptions } from '../../src/index';
import { messageOf } from '../unit/thrown';
import { createContext, destroyContext } from './context';

/**
 * The renderer's options and queries in the engines' conventions: a colour as a hex number or a CSS
 * string, and an unknown key rejected with its name (and the key meant, when one is close).
 */

let gl: WebGL2RenderingContext;

beforeEach(() => {
  gl = createContext(8, 8);
});

afterEach(() => {
  destroyContext(gl);
});

it('ambientColor takes a hex number and CSS strings, and reads back as [r, g, b] floats', () => {
  const renderer = new PenumbraRenderer(gl, { ambientColor: 0x334455 });
  expect(renderer.ambientColor).toEqual([0x33 / 255, 0x44 / 255, 0x55 / 255]);
  renderer.ambientColor = '#345';
  expect(renderer.ambientColor).toEqual([0x33 / 255, 0x44 / 255, 0x55 / 255]);
  renderer.ambientColor = 'rgb(51, 68, 85)';
  expect(renderer.ambientColor).toEqual([0x33 / 255, 0x44 / 255, 0x55 / 255]);
  expect(messageOf(() => { renderer.ambientColor = 'grey'; }, RangeError)).toMatch(/^PenumbraRenderer\.ambientColor must be .*, got "grey"$/);
  expect(renderer.ambientColor).toEqual([0x33 / 255, 0x44 / 255, 0x55 / 255]);
  renderer.dispose();
});

it('an unknown option key is a TypeError naming it, with the close known key when there is one', () => {
  const options = (extra: object) => extra as PenumbraRendererOptions;
  expect(messageOf(() => new PenumbraRenderer(gl, options({ ambient: [0.1, 0.1, 0.1] })), TypeError))
    .toBe("PenumbraRenderer options.ambient is not an option (did you mean 'ambientColor'?)");
  expect(messageOf(() => new PenumbraRenderer(gl, options({ lightMapScale: 0.5 })), TypeError))
    .toBe("PenumbraRenderer options.lightMapScale is not an option (did you mean 'lightmapScale'?)");
  expect(messageOf(() => new PenumbraRenderer(gl, options({ tonemapping: 'aces' })), TypeError))
    .toBe("PenumbraRenderer options.tonemapping is not an option (did you mean 'toneMapping'?)");
  expect(messageOf(() => new PenumbraRenderer(gl, options({ shadows: true })), TypeError)).toMatch(/^PenumbraRenderer options.shadows is not an option \(the options are ambientColor, debug, .*classificationBudget\)$/);
  expect(messageOf(() => new PenumbraRenderer(gl, null as unknown as PenumbraRendererOptions), TypeError)).toBe('PenumbraRenderer options must be an object, got null');
  // Every documented option together is accepted.
  const renderer = new PenumbraRenderer(gl, {
    ambientColor: '#000', debug: false, viewProjection: null, width: 8, height: 8, lightmapScale: 1, measureCpuTime: false, onContextRestored: null,
    exposure: 1, toneMapping: 'none', dithering: 'none', lightmapBlur: 0, normals: false, classificationBudget: 16,
  });
  renderer.dispose();
});

it('illuminationAt and isLit reject an unknown query option key, naming it; isLit takes only cookie and layers', () => {
  const renderer = new PenumbraRenderer(gl);
  renderer.addLight(new PointLight({ position: [4, 4], range: 10 }));
  expect(messageOf(() => renderer.illuminationAt(4, 4, { perlight: false } as object), TypeError))
    .toBe("PenumbraRenderer.illuminationAt: options.perlight is not an option (did you mean 'perLight'?)");
  expect(messageOf(() => renderer.isLit(4, 4, 0.1, { perLight: false } as object), TypeError))
    .toBe('PenumbraRenderer.isLit: options.perLight is not an option (the options are cookie, layers)');
  expect(messageOf(() => renderer.isLit(4, 4, 0.1, { layer: 1 } as object), TypeError))
    .toBe("PenumbraRenderer.isLit: options.layer is not an option (did you mean 'layers'?)");
  expect(renderer.illuminationAt(4, 4, { perLight: true, includeAmbient: false, cookie: null, layers: 1 }).lights).toHaveLength(1);
  expect(renderer.isLit(4, 4, 0.1, { cookie: null, layers: 1 })).toBe(true);
  renderer.dispose();
});
