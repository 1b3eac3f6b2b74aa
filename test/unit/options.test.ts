import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import * as source from '../../src/index';
import { messageOf } from './thrown';

type Library = typeof source;

/**
 * The built bundle, minified as it ships: its messages must name the public classes too. `npm test`
 * builds it first; run `npm run build` before running this file alone.
 */
const DIST_ENTRY = new URL('../../dist/index.js', import.meta.url);

const texture = {} as WebGLTexture;
const LIGHTS = [
  ['PointLight', (lib: Library, options: object) => new lib.PointLight(options)],
  ['Spotlight', (lib: Library, options: object) => new lib.Spotlight(options)],
  ['TexturedLight', (lib: Library, options: object) => new lib.TexturedLight({ texture, ...options })],
] as const;

/** A bad value for each checked option and the error it must throw: TypeError for a wrong type, RangeError out of range. */
const BAD_OPTIONS: [string, unknown, ErrorConstructor][] = [
  ['position', [0, NaN], RangeError], ['position', null, TypeError],
  ['origin', [Infinity, 0], RangeError], ['origin', 5, TypeError],
  ['color', [1, -5, 1], RangeError], ['color', 'red', TypeError],
  ['range', -1, RangeError], ['range', '100', TypeError],
  ['radius', NaN, RangeError], ['radius', null, TypeError],
  ['intensity', Infinity, RangeError], ['intensity', true, TypeError],
  ['rotation', NaN, RangeError], ['rotation', Symbol('spin'), TypeError],
  ['shadowType', 'dark', RangeError],
];

function testLibrary(name: string, load: () => Library): void {
  describe(`messages name the field and the public class (${name})`, () => {
    let lib: Library;
    beforeAll(() => {
      lib = load();
    });

    for (const [className, make] of LIGHTS) {
      it(`${className}: a bad option throws what the setter throws`, () => {
        for (const [field, value, type] of BAD_OPTIONS) {
          const fromOption = messageOf(() => make(lib, { [field]: value }), type);
          const light = make(lib, {}) as unknown as Record<string, unknown>;
          const fromSetter = messageOf(() => { light[field] = value; }, type);
          expect(fromOption).toBe(fromSetter);
          expect(fromOption).toMatch(new RegExp(`^${className}\\.${field}(\\[\\d\\])? must `));
          expect(fromOption).not.toMatch(/got $/);
        }
      });

      it(`${className}: NaN, null and 0 where a vector goes are errors, not defaults`, () => {
        expect(messageOf(() => make(lib, { position: NaN }), TypeError)).toBe(`${className}.position must be an [x, y] pair, got NaN`);
        expect(messageOf(() => make(lib, { origin: null }), TypeError)).toBe(`${className}.origin must be an [x, y] pair, got null`);
        expect(messageOf(() => make(lib, { color: 0 }), TypeError)).toBe(`${className}.color must be an [r, g, b] triple, got 0`);
        expect(messageOf(() => make(lib, { color: [1, 1] }), RangeError)).toBe(`${className}.color must be an [r, g, b] triple, got [1,1]`);
      });

      it(`${className}: enabled, castsShadows, shadowType and ignoredHulls are checked when set`, () => {
        expect(messageOf(() => make(lib, { enabled: 'yes' }), TypeError)).toBe(`${className}.enabled must be true or false, got "yes"`);
        expect(messageOf(() => make(lib, { castsShadows: 0 }), TypeError)).toBe(`${className}.castsShadows must be true or false, got 0`);
        expect(messageOf(() => make(lib, { shadowType: 'dark' }), RangeError))
          .toBe(`${className}.shadowType must be one of "solid", "illuminated", "occluded", got "dark"`);
        expect(messageOf(() => make(lib, { ignoredHulls: 5 }), TypeError)).toBe(`${className}.ignoredHulls must be an iterable of Hulls, got 5`);
        const hull = new lib.Hull([[0, 0], [1, 0], [0, 1]]);
        expect(messageOf(() => make(lib, { ignoredHulls: [hull, 'wall'] }), TypeError)).toBe(`${className}.ignoredHulls[1] must be a Hull, got "wall"`);
        expect([...(make(lib, { ignoredHulls: new Set([hull]) }) as source.Light).ignoredHulls]).toEqual([hull]);
        const light = make(lib, {}) as source.Light;
        expect(() => { light.enabled = 1 as unknown as boolean; }).toThrow(TypeError);
        expect(light.enabled).toBe(true);
      });
    }

    it('Spotlight: cone options, and a light constructed with null options', () => {
      expect(messageOf(() => new lib.Spotlight({ coneAngle: NaN }), RangeError)).toBe('Spotlight.coneAngle must be a finite number, got NaN');
      expect(messageOf(() => new lib.Spotlight({ coneDecay: -1 }), RangeError)).toBe('Spotlight.coneDecay must not be negative, got -1');
      expect(messageOf(() => new lib.PointLight(null as unknown as object), TypeError)).toBe('PointLight options must be an object, got null');
    });

    it('TexturedLight: the texture and the size are checked when set', () => {
      expect(messageOf(() => new lib.TexturedLight({} as source.TexturedLightOptions), TypeError)).toBe('TexturedLight.texture is required');
      expect(messageOf(() => new lib.TexturedLight({ texture: null as unknown as WebGLTexture }), TypeError))
        .toBe('TexturedLight.texture must be a WebGLTexture, got null');
      const light = new lib.TexturedLight({ texture });
      expect(messageOf(() => { light.texture = 7 as unknown as WebGLTexture; }, TypeError)).toBe('TexturedLight.texture must be a WebGLTexture, got 7');
      expect(light.texture).toBe(texture);
      expect(messageOf(() => new lib.TexturedLight({ texture, size: null as unknown as [number, number] }), TypeError))
        .toBe('TexturedLight.size must be an [x, y] pair, got null');
      expect(messageOf(() => new lib.TexturedLight({ texture, size: [1, -1] }), RangeError)).toBe('TexturedLight.size[1] must not be negative, got -1');
    });

    it('Hull: options and setters', () => {
      const points: [number, number][] = [[0, 0], [1, 0], [0, 1]];
      expect(messageOf(() => new lib.Hull(points, { position: NaN as unknown as [number, number] }), TypeError)).toBe('Hull.position must be an [x, y] pair, got NaN');
      expect(messageOf(() => new lib.Hull(points, { origin: null as unknown as [number, number] }), TypeError)).toBe('Hull.origin must be an [x, y] pair, got null');
      expect(messageOf(() => new lib.Hull(points, { scale: NaN }), RangeError)).toBe('Hull.scale must be a finite number, got NaN');
      expect(messageOf(() => new lib.Hull(points, { enabled: 'no' as unknown as boolean }), TypeError)).toBe('Hull.enabled must be true or false, got "no"');
      expect(messageOf(() => new lib.Hull(5 as unknown as [number, number][]), TypeError)).toBe('Hull.points must be an array of [x, y] pairs, got 5');
      expect(messageOf(() => new lib.Hull([[0, 0], [1, ''], [0, 1]] as unknown as [number, number][]), TypeError))
        .toBe('Hull.points[1][1] must be a finite number, got ""');
    });

    it('the renderer-free messages show symbols and cut long values', () => {
      expect(messageOf(() => new lib.PointLight({ range: Symbol('far') as unknown as number }), TypeError)).toBe('PointLight.range must be a finite number, got Symbol(far)');
      const message = messageOf(() => new lib.PointLight({ position: 'x'.repeat(1_000_000) as unknown as [number, number] }), TypeError);
      expect(message.length).toBeLessThan(150);
    });
  });
}

const distLibrary = existsSync(DIST_ENTRY) ? ((await import(/* @vite-ignore */ DIST_ENTRY.href)) as Library) : undefined;

testLibrary('src', () => source);
testLibrary('dist', () => {
  if (!distLibrary) throw new Error(`${fileURLToPath(DIST_ENTRY)} is missing: run npm run build first`);
  return distLibrary;
});
