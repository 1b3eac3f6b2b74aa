import { beforeAll, describe, expect, it } from 'vitest';
import type * as source from '../../src/index';
import { messageOf } from './thrown';

/** The library's exports: from the sources (test/unit/options.test.ts) or the built bundle (test/package/distOptions.test.ts). */
export type Library = typeof source;

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
  ['color', [1, -5, 1], RangeError], ['color', 'red', RangeError], ['color', 0x1000000, RangeError], ['color', {}, TypeError],
  ['range', -1, RangeError], ['range', '100', TypeError],
  ['radius', NaN, RangeError], ['radius', null, TypeError],
  ['intensity', Infinity, RangeError], ['intensity', true, TypeError],
  ['rotation', NaN, RangeError], ['rotation', Symbol('spin'), TypeError],
  ['shadowType', 'dark', RangeError],
];

/** The checks of the options' and setters' error messages, on the library `load` gives, named `name`. */
export function testLibrary(name: string, load: () => Library): void {
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
        expect(messageOf(() => make(lib, { position: NaN }), TypeError)).toBe(`${className}.position must be an [x, y] pair or an { x, y } point, got NaN`);
        expect(messageOf(() => make(lib, { origin: null }), TypeError)).toBe(`${className}.origin must be an [x, y] pair or an { x, y } point, got null`);
        expect(messageOf(() => make(lib, { color: null }), TypeError))
          .toBe(`${className}.color must be an [r, g, b] triple, a 0xrrggbb number or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string, got null`);
        expect(messageOf(() => make(lib, { color: [1, 1] }), RangeError))
          .toBe(`${className}.color must be an [r, g, b] triple, a 0xrrggbb number or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string, got [1,1]`);
        expect(messageOf(() => make(lib, { color: 1.5 }), RangeError)).toBe(`${className}.color must be an [r, g, b] triple, a 0xrrggbb number `
          + `or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string; a number must be an integer from 0x000000 to 0xffffff, got 1.5`);
        expect(messageOf(() => make(lib, { color: '#12345' }), RangeError)).toBe(`${className}.color must be an [r, g, b] triple, a 0xrrggbb number `
          + `or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string (channels 0–255 or 0–100%), got "#12345"`);
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
        .toBe('TexturedLight.size must be an [x, y] pair or an { x, y } point, got null');
      expect(messageOf(() => new lib.TexturedLight({ texture, size: [1, -1] }), RangeError)).toBe('TexturedLight.size[1] must not be negative, got -1');
    });

    it('Hull: options and setters', () => {
      const points: [number, number][] = [[0, 0], [1, 0], [0, 1]];
      expect(messageOf(() => new lib.Hull(points, { position: NaN as unknown as [number, number] }), TypeError)).toBe('Hull.position must be an [x, y] pair or an { x, y } point, got NaN');
      expect(messageOf(() => new lib.Hull(points, { origin: null as unknown as [number, number] }), TypeError)).toBe('Hull.origin must be an [x, y] pair or an { x, y } point, got null');
      expect(messageOf(() => new lib.Hull(points, { scale: NaN }), RangeError)).toBe('Hull.scale must be a finite number, got NaN');
      expect(messageOf(() => new lib.Hull(points, { enabled: 'no' as unknown as boolean }), TypeError)).toBe('Hull.enabled must be true or false, got "no"');
      expect(messageOf(() => new lib.Hull(5 as unknown as [number, number][]), TypeError)).toBe('Hull.points must be an array of [x, y] pairs or { x, y } points, got 5');
      expect(messageOf(() => new lib.Hull([[0, 0], [1, ''], [0, 1]] as unknown as [number, number][]), TypeError))
        .toBe('Hull.points[1][1] must be a finite number, got ""');
    });

    for (const [className, make] of LIGHTS) {
      it(`${className}: an unknown option key is a TypeError naming it, with the close known key when there is one`, () => {
        expect(messageOf(() => make(lib, { positon: [1, 2] }), TypeError)).toBe(`${className} options.positon is not an option (did you mean 'position'?)`);
        expect(messageOf(() => make(lib, { colour: 0xff0000 }), TypeError)).toBe(`${className} options.colour is not an option (did you mean 'color'?)`);
        expect(messageOf(() => make(lib, { Radius: 4 }), TypeError)).toBe(`${className} options.Radius is not an option (did you mean 'radius'?)`);
        expect(messageOf(() => make(lib, { castShadows: false }), TypeError)).toBe(`${className} options.castShadows is not an option (did you mean 'castsShadows'?)`);
        expect(messageOf(() => make(lib, { shadow: [0, 0, 0] }), TypeError)).toMatch(new RegExp(`^${className} options.shadow is not an option \\(did you mean 'shadow(Type|Layers|Color|Strength)'\\?\\)$`));
        // Far from every key: the message lists the options.
        const listed = messageOf(() => make(lib, { brightness: 2 }), TypeError);
        expect(listed).toMatch(new RegExp(`^${className} options.brightness is not an option \\(the options are position, range, radius, color, intensity, rotation, origin, shadowType, .*shadowStrength[^)]*\\)$`));
        // Whatever the value, even undefined; a key that is no identifier is quoted.
        expect(messageOf(() => make(lib, { positon: undefined }), TypeError)).toBe(`${className} options.positon is not an option (did you mean 'position'?)`);
        expect(messageOf(() => make(lib, { 'the range': 5 }), TypeError)).toMatch(new RegExp(`^${className} options\\["the range"\\] is not an option`));
        // Inherited keys are not the caller's: they are neither read nor rejected.
        expect(make(lib, Object.create({ positon: [1, 2] }) as object)).toBeInstanceOf(lib.Light);
      });
    }

    it('Spotlight, TexturedLight and DirectionalLight: their own keys are known to them only; a directional light takes no positional key', () => {
      expect(messageOf(() => new lib.Spotlight({ coneangle: 1 } as object), TypeError)).toBe("Spotlight options.coneangle is not an option (did you mean 'coneAngle'?)");
      expect(messageOf(() => new lib.PointLight({ coneAngle: 1 } as object), TypeError)).toMatch(/^PointLight options.coneAngle is not an option \(the options are /);
      expect(messageOf(() => new lib.TexturedLight({ texture, sise: [1, 1] } as object as source.TexturedLightOptions), TypeError))
        .toBe("TexturedLight options.sise is not an option (did you mean 'size'?)");
      for (const key of ['position', 'range', 'radius', 'origin', 'falloff', 'height']) {
        const message = messageOf(() => new lib.DirectionalLight({ [key]: undefined }), TypeError);
        expect(message).toMatch(new RegExp(`^DirectionalLight options.${key} is not an option`));
      }
      expect(messageOf(() => new lib.DirectionalLight({ angularsize: 0.1 } as object), TypeError)).toBe("DirectionalLight options.angularsize is not an option (did you mean 'angularSize'?)");
      expect(new lib.Spotlight({ coneAngle: 1, coneDecay: 2, position: [1, 2] }).coneAngle).toBe(1);
      expect(new lib.DirectionalLight({ angularSize: 0.1, elevation: 1, color: 0xffffff }).angularSize).toBe(0.1);
    });

    it('Hull, hullsFromTiles, TileHulls and hullsFromAlpha: an unknown option key is a TypeError naming it', () => {
      const points: [number, number][] = [[0, 0], [1, 0], [0, 1]];
      expect(messageOf(() => new lib.Hull(points, { postion: [1, 2] } as object), TypeError)).toBe("Hull options.postion is not an option (did you mean 'position'?)");
      expect(messageOf(() => new lib.Hull(points, { layer: 2 } as object), TypeError)).toBe("Hull options.layer is not an option (did you mean 'layers'?)");
      expect(messageOf(() => new lib.Hull(points, { points } as object), TypeError))
        .toBe('Hull options.points is not an option (the options are position, origin, rotation, scale, enabled, closed, layers)');
      expect(messageOf(() => lib.hullsFromTiles([[1]], { tilesize: 32 } as object), TypeError)).toBe("hullsFromTiles options.tilesize is not an option (did you mean 'tileSize'?)");
      expect(messageOf(() => new lib.TileHulls([[1]], { chunk: 8 } as object), TypeError)).toBe("TileHulls options.chunk is not an option (did you mean 'chunkSize'?)");
      const image = { data: new Uint8ClampedArray(4), width: 1, height: 1 };
      expect(messageOf(() => lib.hullsFromAlpha(image, { treshold: 10 } as object), TypeError)).toBe("hullsFromAlpha options.treshold is not an option (did you mean 'threshold'?)");
      expect(messageOf(() => lib.hullsFromAlpha(image, null as unknown as object), TypeError)).toBe('hullsFromAlpha options must be an object, got null');
    });

    it('the renderer-free messages show symbols and cut long values', () => {
      expect(messageOf(() => new lib.PointLight({ range: Symbol('far') as unknown as number }), TypeError)).toBe('PointLight.range must be a finite number, got Symbol(far)');
      const message = messageOf(() => new lib.PointLight({ position: 'x'.repeat(1_000_000) as unknown as [number, number] }), TypeError);
      expect(message.length).toBeLessThan(150);
    });
  });
}
