import { createRequire } from 'node:module';
import { beforeAll, describe, expect, it } from 'vitest';
import {
  createSceneObjects, DEFAULT_LIGHT_RADIUS, describeScene, DirectionalLight, Hull, hullsFromAlpha, hullsFromTiles, PointLight, readScene,
  Spotlight, TexturedLight, TileHulls, writeScene, type ColorLike, type Light, type Vec2Like,
} from '../../src/index';
import { IlluminationQuery } from '../../src/scene/illumination';
import { messageOf } from './thrown';

/**
 * The conventions of the engines the library sits in, across the public API: colours as hex numbers
 * and CSS strings besides `[r, g, b]` floats, points as `{ x, y }` objects (real PixiJS points and
 * Phaser vectors) besides `[x, y]` pairs, and the default light radius. Unknown option keys are in
 * options.test.ts (for the built bundle too).
 */

const texture = {} as WebGLTexture;

/** Every light class, made with `options`. */
const LIGHTS: [string, (options: Record<string, unknown>) => Light][] = [
  ['PointLight', (options) => new PointLight(options)],
  ['Spotlight', (options) => new Spotlight(options)],
  ['TexturedLight', (options) => new TexturedLight({ texture, ...options })],
  ['DirectionalLight', (options) => new DirectionalLight(options)],
];

/** Colours in each form taken and the floats they mean, written out by hand: each byte / 255, no sRGB decoding. */
const COLOURS: [ColorLike, [number, number, number]][] = [
  [0xff8800, [1, 136 / 255, 0]],
  [0x000000, [0, 0, 0]],
  [0xffffff, [1, 1, 1]],
  [0x0a141e, [10 / 255, 20 / 255, 30 / 255]],
  ['#ff8800', [1, 136 / 255, 0]],
  ['#FF8800', [1, 136 / 255, 0]],
  ['#f80', [1, 136 / 255, 0]],
  ['#0A141E', [10 / 255, 20 / 255, 30 / 255]],
  ['  #123  ', [0x11 / 255, 0x22 / 255, 0x33 / 255]],
  ['rgb(255, 136, 0)', [1, 136 / 255, 0]],
  ['rgb(255 136 0)', [1, 136 / 255, 0]],
  ['RGB( 10 ,20,30 )', [10 / 255, 20 / 255, 30 / 255]],
  ['rgb(100%, 50%, 0%)', [1, 0.5, 0]],
  ['rgb(12.75 25.5% .0)', [0.05, 0.255, 0]],
  [[0.25, 2, 0], [0.25, 2, 0]],
  [new Float32Array([0.5, 0.25, 0.125]), [0.5, 0.25, 0.125]],
];

/** Colours that are no colour, each a RangeError showing the value. */
const BAD_COLOURS: ColorLike[] = [
  0x1000000, -1, 0.5, NaN, Infinity, 'red', 'white', '#12', '#12345', '#1234', '#12345678', '#ggg', '0xff8800', 'ff8800', 'rgb(1, 2)',
  'rgba(1, 2, 3, 0.5)', 'rgb(1, 2, 3, 4)', 'rgb(1 2 3 / 50%)', 'rgb(256, 0, 0)', 'rgb(-1, 0, 0)', 'rgb(0, 101%, 0)', 'rgb(a, b, c)', 'rgb(1,,2,3)', '',
];

const COLOR_MESSAGE = "must be an [r, g, b] triple, a 0xrrggbb number or a '#rrggbb', '#rgb' or 'rgb(r, g, b)' string";

function expectClose(actual: readonly number[], expected: readonly number[]): void {
  expect(actual).toHaveLength(expected.length);
  actual.forEach((value, i) => expect(value).toBeCloseTo(expected[i], 12));
}

describe('colours: hex numbers and CSS strings as well as [r, g, b] floats', () => {
  for (const [className, make] of LIGHTS) {
    it(`${className}: color and shadowColor take every form, by option and by setter, and read back as frozen [r, g, b] floats`, () => {
      for (const [given, expected] of COLOURS) {
        for (const field of ['color', 'shadowColor'] as const) {
          const fromOption = make({ [field]: given });
          expectClose(fromOption[field], expected);
          expect(Object.isFrozen(fromOption[field])).toBe(true);
          expect(Array.isArray(fromOption[field])).toBe(true);
          const fromSetter = make({});
          fromSetter[field] = given;
          expect(fromSetter[field]).toEqual(fromOption[field]);
        }
      }
    });

    it(`${className}: a malformed colour is an error naming the field and showing the value, and changes nothing`, () => {
      const light = make({ color: 0x336699 });
      for (const bad of BAD_COLOURS) {
        for (const field of ['color', 'shadowColor'] as const) {
          const message = messageOf(() => { light[field] = bad; }, RangeError);
          expect(message).toMatch(new RegExp(`^${className}\\.${field} ${escape(COLOR_MESSAGE)}`));
          expect(message).toContain(`got ${typeof bad === 'string' ? JSON.stringify(bad) : String(bad)}`);
          expect(messageOf(() => make({ [field]: bad }), RangeError)).toBe(message);
        }
      }
      expectClose(light.color, [0x33 / 255, 0x66 / 255, 0x99 / 255]);
      for (const wrongType of [null, {}, true, () => 1, Symbol('red')]) {
        expect(messageOf(() => { light.color = wrongType as unknown as ColorLike; }, TypeError)).toMatch(new RegExp(`^${className}\\.color ${escape(COLOR_MESSAGE)}, got `));
      }
      expect(messageOf(() => { light.color = [1, 1]; }, RangeError)).toBe(`${className}.color ${COLOR_MESSAGE}, got [1,1]`);
      expect(messageOf(() => { light.color = [1, NaN, 1]; }, RangeError)).toBe(`${className}.color[1] must be a finite number, got NaN`);
    });
  }

  it('a light of a hex colour gives the same light as one of the floats it reads back as', () => {
    const hull = new Hull([[40, -10], [50, -10], [50, 10], [40, 10]]);
    const query = new IlluminationQuery();
    const byHex = new PointLight({ position: [0, 0], range: 100, color: 0xff8800, shadowColor: '#336699', shadowStrength: 0.5 });
    const byFloats = new PointLight({ position: [0, 0], range: 100, color: [1, 136 / 255, 0], shadowColor: [0x33 / 255, 0x66 / 255, 0x99 / 255], shadowStrength: 0.5 });
    for (const point of [[20, 0], [60, 0], [60, 9]] as const) {
      const hex = query.at([byHex], [hull], [0, 0, 0], point[0], point[1], { perLight: false }, undefined);
      const floats = query.at([byFloats], [hull], [0, 0, 0], point[0], point[1], { perLight: false }, undefined);
      expectClose(hex.color, floats.color);
    }
  });
});

/** A Phaser 4 `Vector2`, the real class (its source is plain CommonJS and needs no browser). */
type PhaserVector2 = { x: number; y: number; length(): number };
const Vector2 = createRequire(import.meta.url)('../../node_modules/phaser/src/math/Vector2.js') as new (x: number, y: number) => PhaserVector2;

/** PixiJS v8, loaded once: it reads `navigator` when imported, which Node 20 has not. */
let pixi: typeof import('pixi.js');
beforeAll(async () => {
  (globalThis as { navigator?: unknown }).navigator ??= { userAgent: 'node' };
  pixi = await import('pixi.js');
});

/** The forms of the point (x, y): a pair, a plain object, a Pixi `Point`, a Pixi sprite's `position` (an `ObservablePoint`, accessors), a Phaser `Vector2`, a typed array. */
function pointForms(x: number, y: number): [string, Vec2Like][] {
  const sprite = new pixi.Sprite();
  sprite.position.set(x, y);
  return [
    ['pair', [x, y]], ['object', { x, y }], ['Pixi Point', new pixi.Point(x, y)], ['Pixi ObservablePoint', sprite.position],
    ['Phaser Vector2', new Vector2(x, y)], ['Float64Array', new Float64Array([x, y])],
  ];
}

describe('points: { x, y } objects, Pixi points and Phaser vectors as well as [x, y] pairs', () => {
  for (const [className, make] of LIGHTS.filter(([name]) => name !== 'DirectionalLight')) {
    it(`${className}: position and origin take every form and read back as frozen [x, y] pairs`, () => {
      for (const [form, point] of pointForms(3.5, -4)) {
        for (const field of ['position', 'origin'] as const) {
          const light = make({ [field]: point });
          expect(light[field], form).toEqual([3.5, -4]);
          expect(Array.isArray(light[field]) && Object.isFrozen(light[field])).toBe(true);
          const set = make({});
          set[field] = point;
          expect(set[field], form).toEqual([3.5, -4]);
        }
      }
    });
  }

  it('TexturedLight: size takes { x, y }', () => {
    expect(new TexturedLight({ texture, size: { x: 30, y: 20 } }).size).toEqual([30, 20]);
    expect(messageOf(() => new TexturedLight({ texture, size: { x: 30, y: -1 } }), RangeError)).toBe('TexturedLight.size[1] must not be negative, got -1');
  });

  it('Hull: points (forms mixed), position, origin and scale take every form and place the hull as pairs do', () => {
    const pairs: [number, number][] = [[0, 0], [10, 0], [10, 5], [0, 5]];
    const reference = new Hull(pairs, { position: [100, 50], origin: [5, 2.5], scale: [2, -3], rotation: 0.3 });
    reference.updateWorld();
    for (const [form, position] of pointForms(100, 50)) {
      const forms = pointForms(10, 0);
      const points = pairs.map(([x, y], i) => (i === 1 ? forms[i % forms.length][1] : { x, y }));
      const hull = new Hull(points, { position, origin: pointForms(5, 2.5)[2][1], scale: new Vector2(2, -3), rotation: 0.3 });
      expect(hull.points, form).toEqual(pairs);
      expect(Object.isFrozen(hull.points) && hull.points.every((point) => Object.isFrozen(point) && Array.isArray(point))).toBe(true);
      expect([hull.position, hull.origin, hull.scale]).toEqual([[100, 50], [5, 2.5], [2, -3]]);
      hull.updateWorld();
      expect(hull.worldPoints).toEqual(reference.worldPoints);
    }
    const sprite = new pixi.Sprite();
    sprite.scale.set(0.5, 4);
    const hull = new Hull(pairs);
    hull.scale = sprite.scale;
    hull.position = sprite.position;
    expect([hull.scale, hull.position]).toEqual([[0.5, 4], [0, 0]]);
  });

  it('a malformed point names its component as it was given (name[1] or name.y) and shows the value', () => {
    const light = new PointLight();
    expect(messageOf(() => { light.position = { x: 1 } as unknown as Vec2Like; }, TypeError)).toBe('PointLight.position.y must be a finite number, got undefined');
    expect(messageOf(() => { light.position = { x: NaN, y: 0 }; }, RangeError)).toBe('PointLight.position.x must be a finite number, got NaN');
    expect(messageOf(() => { light.position = { x: '1', y: 0 } as unknown as Vec2Like; }, TypeError)).toBe('PointLight.position.x must be a finite number, got "1"');
    expect(messageOf(() => { light.position = {} as unknown as Vec2Like; }, TypeError)).toBe('PointLight.position must be an [x, y] pair or an { x, y } point, got {}');
    expect(messageOf(() => { light.position = 'here' as unknown as Vec2Like; }, TypeError)).toBe('PointLight.position must be an [x, y] pair or an { x, y } point, got "here"');
    expect(messageOf(() => { light.position = [1]; }, RangeError)).toBe('PointLight.position must be an [x, y] pair or an { x, y } point, got [1]');
    expect(light.position).toEqual([0, 0]);
    expect(messageOf(() => new Hull([[0, 0], { x: 1, y: Infinity }, [0, 1]]), RangeError)).toBe('Hull.points[1].y must be a finite number, got Infinity');
    expect(messageOf(() => new Hull([[0, 0], [1, 0], null as unknown as Vec2Like]), TypeError)).toBe('Hull.points[2] must be an [x, y] pair or an { x, y } point, got null');
    expect(messageOf(() => new Hull([[0, 0]], { scale: { x: 1, y: NaN } }), RangeError)).toBe('Hull.scale.y must be a finite number, got NaN');
  });

  it('hullsFromTiles and TileHulls take position and tileSize as { x, y }', () => {
    const rows = [[1, 1, 0], [0, 1, 1]];
    const expected = hullsFromTiles(rows, { tileSize: [16, 8], position: [-5, 3] }).map((hull) => hull.points);
    for (const [form, position] of pointForms(-5, 3)) {
      expect(hullsFromTiles(rows, { tileSize: { x: 16, y: 8 }, position }).map((hull) => hull.points), form).toEqual(expected);
      expect(new TileHulls(rows, { tileSize: new Vector2(16, 8), position }).hulls.map((hull) => hull.points), form).toEqual(expected);
    }
    expect(messageOf(() => hullsFromTiles(rows, { position: { x: 0, y: NaN } }), RangeError)).toBe('hullsFromTiles options.position.y must be a finite number, got NaN');
    expect(messageOf(() => hullsFromTiles(rows, { tileSize: { x: 0, y: 1 } }), RangeError))
      .toBe('hullsFromTiles options.tileSize must be a positive finite number or [w, h] pair, got {"x":0,"y":1}');
  });

  it('hullsFromAlpha takes anchor, position and scale as { x, y } (a Pixi sprite\'s, as they are)', () => {
    const data = new Uint8ClampedArray(6 * 4 * 4);
    for (let i = 0; i < 6 * 4; i++) data[4 * i + 3] = i % 6 >= 1 && i % 6 <= 4 && i >= 6 && i < 18 ? 255 : 0;
    const image = { data, width: 6, height: 4 };
    const sprite = new pixi.Sprite();
    sprite.anchor.set(0.25, 0.75);
    sprite.position.set(40, 30);
    sprite.scale.set(2, -1);
    const fromSprite = hullsFromAlpha(image, { anchor: sprite.anchor, position: sprite.position, scale: sprite.scale });
    const fromPairs = hullsFromAlpha(image, { anchor: [0.25, 0.75], position: [40, 30], scale: [2, -1] });
    expect(fromSprite).toHaveLength(1);
    fromSprite[0].updateWorld();
    fromPairs[0].updateWorld();
    expect(fromSprite[0].worldPoints).toEqual(fromPairs[0].worldPoints);
    expect([fromSprite[0].position, fromSprite[0].origin, fromSprite[0].scale]).toEqual([[40, 30], [1.5, 3], [2, -1]]);
  });
});

describe('the default light radius', () => {
  it(`is ${DEFAULT_LIGHT_RADIUS} world units for every light with a radius, so that a default light casts soft shadows`, () => {
    expect(DEFAULT_LIGHT_RADIUS).toBe(10);
    for (const [className, make] of LIGHTS.filter(([name]) => name !== 'DirectionalLight')) expect(make({}).radius, className).toBe(10);
    // A light of the defaults beside a wall: a point near the shadow's edge is in part shadow (0 < visibility < 1).
    const light = new PointLight({ position: [0, 0] });
    const wall = new Hull([[30, 0], [40, 0], [40, 40], [30, 40]]);
    const result = new IlluminationQuery().at([light], [wall], [0, 0, 0], 80, 0, {}, undefined);
    expect(result.lights).toHaveLength(1);
    expect(result.lights[0].visibility).toBeGreaterThan(0.2);
    expect(result.lights[0].visibility).toBeLessThan(0.8);
  });

  it('a scene file without radius still means radius 0 (the format keeps its own default), and a default light round-trips as 10', () => {
    const old = readScene(JSON.stringify({
      format: 'penumbra-scene', version: 2, lights: [{ kind: 'point', position: [1, 2] }, { kind: 'spot', position: [3, 4] }, { kind: 'textured', position: [5, 6], cookie: 'c' }],
    }));
    const { lights } = createSceneObjects(old, () => texture);
    expect(lights.map((light) => light.radius)).toEqual([0, 0, 0]);
    for (const version of [1, 3]) {
      expect(readScene(JSON.stringify({ format: 'penumbra-scene', version, lights: [{ kind: 'point', position: [0, 0] }] })).lights[0]).toMatchObject({ radius: 0 });
    }
    const saved = writeScene(describeScene({
      hulls: [], lights: [new PointLight(), new Spotlight(), new TexturedLight({ texture })], ambient: [0, 0, 0], camera: { center: [0, 0], zoom: 1 },
      cookieName: () => 'c',
    }));
    const reread = createSceneObjects(readScene(saved), () => texture).lights;
    expect(reread.map((light) => light.radius)).toEqual([10, 10, 10]);
    expect(reread.map((light) => light.kind)).toEqual(['point', 'spot', 'textured']);
  });
});

function escape(text: string): string {
  return text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}
