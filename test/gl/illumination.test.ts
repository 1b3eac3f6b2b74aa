import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight, ShadowType, Spotlight, TexturedLight, type Light } from '../../src/index';
import type { IlluminationOptions } from '../../src/scene/illumination';
import { createSceneRenderer, setScene } from '../reference/buildScene';
import { compareReferenceScene, compareWithLightmap, hardCentres, MAX_DIFFERENCE, sceneExclusions, type Exclusions } from '../reference/illuminationComparison';
import { createRandom, randomScene } from '../reference/randomScenes';
import { SceneGeometry } from '../reference/sceneGeometry';
import { box, REFERENCE_SCENES, type Point, type ReferenceScene } from '../reference/scenes';
import { hexagon, uShape } from '../reference/occludedReference';
import { OUTLINE_BAND } from '../reference/softShadowReference';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

/**
 * `renderer.illuminationAt` against the lightmap the same renderer renders on headless-gl: at every
 * pixel centre (the figures count those some light reaches) of the reference scenes, of random scenes (with random
 * shadow types and shadow colours) and of scenes of the features the reference scenes leave out
 * (spotlights, layers, ignored hulls, shadow colour, Illuminated hulls, disabled lights and hulls, a
 * light inside a hull, transformed hulls, hulls crossing inside a disk, a textured light with its
 * cookie sampled on the CPU, ambient light). Each channel must be within {@link MAX_DIFFERENCE} of the lightmap. The random
 * scenes are PENUMBRA_SCENES (default 60) from seed 0x111. Left out, as
 * the reference tests leave them out: pixel centres within 1/16 pixel of a hull outline or of a
 * hard shadow's edge, where the rasterizer's snapping decides (test/reference/softShadowReference),
 * and of a textured light's quad edge or a cookie texel's edge.
 */
const RANDOM_SCENES = Number(process.env.PENUMBRA_SCENES ?? 60);
const RANDOM_SEED = 0x111;

interface Figures {
  group: string;
  scenes: number;
  points: number;
  max: number;
  worst: string;
}
const figures = new Map<string, Figures>();

/** Adds a scene's comparison to its group's figures. */
function record(group: string, scene: string, points: number, max: number, worst: string): void {
  const entry = figures.get(group) ?? { group, scenes: 0, points: 0, max: 0, worst: '' };
  entry.scenes++;
  entry.points += points;
  if (max >= entry.max) {
    entry.max = max;
    entry.worst = `${scene} ${worst}`;
  }
  figures.set(group, entry);
}

afterAll(() => {
  const rows = [...figures.values()];
  const total = rows.reduce((sum, row) => sum + row.points, 0);
  const max = Math.max(0, ...rows.map((row) => row.max));
  console.log([
    `illuminationAt vs the rendered lightmap (headless-gl): max difference ${max.toFixed(4)} over ${total} points (limit ${MAX_DIFFERENCE})`,
    '| scenes | count | points | max difference | where |',
    '|---|---|---|---|---|',
    ...rows.map((row) => `| ${row.group} | ${row.scenes} | ${row.points} | ${row.max.toFixed(4)} | ${row.worst} |`),
  ].join('\n'));
});

/**
 * Renders the renderer's lightmap and compares `illuminationAt` at every pixel centre that is not
 * ambiguous (test/reference/illuminationComparison.ts, shared with the Chromium test).
 */
function compare(
  gl: WebGL2RenderingContext, renderer: PenumbraRenderer, width: number, height: number,
  exclusions: Exclusions, options: IlluminationOptions = {},
): { points: number; max: number; worst: string } {
  const lightmap = renderLightmap(gl, renderer, width, height);
  expect(gl.getError()).toBe(0);
  return compareWithLightmap(renderer, lightmap, exclusions, options);
}

/** The renderer's hulls in world space (every hull, enabled or not, as the exclusions' outlines). */
function worldGeometry(renderer: PenumbraRenderer): SceneGeometry {
  const outlines = (closed: boolean) => renderer.hulls.filter((hull) => hull.valid && hull.closed === closed).map((hull) => {
    hull.updateWorld();
    return Array.from({ length: hull.pointCount }, (_, i): Point => [hull.worldPoints[2 * i], hull.worldPoints[2 * i + 1]]);
  });
  return new SceneGeometry(outlines(true), outlines(false));
}

describe('illuminationAt matches the rendered lightmap: reference scenes', () => {
  for (const scene of REFERENCE_SCENES) {
    it(scene.name, () => {
      const gl = createContext(scene.width, scene.height);
      const renderer = createSceneRenderer(gl, scene);
      const { points, max, worst, glError } = compareReferenceScene(gl, renderer, scene);
      renderer.dispose();
      destroyContext(gl);
      expect(glError).toBe(0);
      record('reference scenes (160 × 120)', scene.name, points, max, worst);
      expect(points).toBeGreaterThan(1000);
      expect(max, worst).toBeLessThanOrEqual(MAX_DIFFERENCE);
    });
  }
});

describe('illuminationAt matches the rendered lightmap: random scenes', () => {
  const WIDTH = 80, HEIGHT = 60;
  let gl: WebGL2RenderingContext;
  let renderer: PenumbraRenderer;
  beforeAll(() => {
    gl = createContext(WIDTH, HEIGHT);
    renderer = new PenumbraRenderer(gl, { width: WIDTH, height: HEIGHT });
  });
  afterAll(() => {
    renderer?.dispose();
    if (gl) destroyContext(gl);
  });

  for (let i = 0; i < RANDOM_SCENES; i++) {
    const seed = RANDOM_SEED + i;
    it(`seed ${seed}`, () => {
      const scene: ReferenceScene = randomScene(seed, WIDTH, HEIGHT);
      setScene(renderer, scene);
      // Beyond the reference scenes: a random ambient colour, shadow type and shadow colour.
      const random = createRandom(seed ^ 0x5a5a);
      renderer.ambientColor = random() < 0.5 ? [0, 0, 0] : [0.1 * random(), 0.1 * random(), 0.1 * random()];
      for (const light of renderer.lights) {
        light.shadowType = random() < 0.5 ? ShadowType.Solid : ShadowType.Illuminated;
        if (random() < 0.4) {
          light.shadowColor = [random(), random(), random()];
          light.shadowStrength = random();
        }
      }
      const { points, max, worst } = compare(gl, renderer, WIDTH, HEIGHT, sceneExclusions(scene, renderer.lights));
      record(`random scenes (${WIDTH} × ${HEIGHT})`, `seed ${seed}`, points, max, worst);
      expect(max, `seed ${seed}: ${worst}\nscene: ${JSON.stringify(scene)}`).toBeLessThanOrEqual(MAX_DIFFERENCE);
    });
  }
});

describe('illuminationAt matches the rendered lightmap: features', () => {
  const WIDTH = 160, HEIGHT = 120;
  let gl: WebGL2RenderingContext;
  let renderer: PenumbraRenderer;
  beforeAll(() => {
    gl = createContext(WIDTH, HEIGHT);
    renderer = new PenumbraRenderer(gl, { width: WIDTH, height: HEIGHT, ambientColor: [0.04, 0.06, 0.1] });
  });
  afterAll(() => {
    renderer?.dispose();
    if (gl) destroyContext(gl);
  });

  /** Replaces the renderer's lights and hulls. */
  function reset(lights: Light[], hulls: Hull[]): void {
    for (const light of [...renderer.lights]) renderer.removeLight(light);
    for (const hull of [...renderer.hulls]) renderer.removeHull(hull);
    for (const light of lights) renderer.addLight(light);
    for (const hull of hulls) renderer.addHull(hull);
  }

  function check(name: string, options: IlluminationOptions = {}, other?: (x: number, y: number) => boolean): void {
    const exclusions = { geometry: worldGeometry(renderer), hardCentres: hardCentres(renderer.lights), other };
    const { points, max, worst } = compare(gl, renderer, WIDTH, HEIGHT, exclusions, options);
    record(`feature scenes (${WIDTH} × ${HEIGHT})`, name, points, max, worst);
    expect(points).toBeGreaterThan(1000);
    expect(max, `${name}: ${worst}`).toBeLessThanOrEqual(MAX_DIFFERENCE);
  }

  it('spotlights (cone decay 0, 1 and 2.5), shadow colour and strength, ambient light', () => {
    reset([
      new Spotlight({ position: [20, 60], rotation: 0.15, coneAngle: Math.PI / 3, coneDecay: 1, range: 150, radius: 6, color: [1, 0.9, 0.7] }),
      new Spotlight({
        position: [140, 15], rotation: 2.3, coneAngle: 0.9, coneDecay: 0, range: 140, radius: 4,
        shadowColor: [0.2, 0.3, 0.6], shadowStrength: 0.7, color: [0.6, 0.8, 1], intensity: 0.9,
      }),
      new Spotlight({ position: [80, 112], rotation: -Math.PI / 2, coneAngle: Math.PI, coneDecay: 2.5, range: 110, radius: 0, shadowType: ShadowType.Illuminated }),
    ], [
      new Hull(box(60, 50, 14, 20)),
      new Hull([[0, 0], [20, 0], [20, 6], [6, 6], [6, 20], [0, 20]], { position: [100, 60], rotation: 0.7, scale: [1.2, -0.8], origin: [5, 5] }),
      new Hull([[0, 0], [12, 3], [4, 12]], { position: [40, 90], rotation: -0.4, scale: 1.5 }),
    ]);
    check('spotlights, shadow colour, ambient');
  });

  it('layers, ignored hulls, castsShadows, disabled lights and hulls, a light inside a hull', () => {
    const wall = new Hull(box(70, 20, 8, 40), { layers: 0b01 });
    const crate = new Hull(box(70, 75, 14, 14), { layers: 0b10 });
    const housing = new Hull(box(26, 52, 10, 10));
    const disabledHull = new Hull(box(100, 40, 10, 30), { enabled: false });
    const blockOfTheTrapped = new Hull(box(130, 90, 20, 20));
    const crateLayerRoom = new Hull(box(115, 5, 30, 25), { layers: 0b10 });
    reset([
      new PointLight({ position: [40, 45], range: 120, radius: 5, shadowLayers: 0b10, color: [1, 0.5, 0.3] }),
      new PointLight({ position: [31, 57], range: 100, radius: 3, ignoredHulls: [housing], color: [0.3, 0.6, 1] }),
      new PointLight({ position: [100, 100], range: 80, radius: 4, castsShadows: false, intensity: 0.5 }),
      new PointLight({ position: [60, 100], range: 100, radius: 4, enabled: false }),
      new PointLight({ position: [140, 100], range: 100, radius: 4 }),
      new PointLight({ position: [130, 17], range: 60, radius: 4, shadowLayers: 0b01, color: [0.5, 1, 0.5] }),
    ], [wall, crate, housing, disabledHull, blockOfTheTrapped, crateLayerRoom]);
    check('layers, ignored hulls, castsShadows, disabled, light inside a hull');
  });

  it('Illuminated and Solid lights on hulls, open polylines, hard lights, overlapping hulls', () => {
    reset([
      new PointLight({ position: [30, 30], range: 140, radius: 7, shadowType: ShadowType.Illuminated }),
      new PointLight({ position: [130.3, 95.2], range: 120, radius: 0, shadowType: ShadowType.Solid, color: [1, 0.8, 0.5] }),
      new PointLight({ position: [80, 62], range: 60, radius: 5, color: [0.5, 0.5, 1] }),
    ], [
      new Hull(box(55, 25, 20, 12)),
      new Hull(box(65, 30, 20, 12)),
      new Hull([[40, 80], [60, 70], [90, 95], [50, 110]]),
      new Hull([[20, 60], [60, 60], [60, 64]], { closed: false }),
      new Hull([[95, 20], [120, 50], [95, 50], [120, 20]], { closed: false }),
      new Hull([[70, 62], [90, 62]], { closed: false }),
    ]);
    check('Illuminated and Solid, polylines, hard light, overlapping hulls');
  });

  it('Occluded lights inside overlapping convex and concave hulls, listed in either order', () => {
    const circle = (cx: number, cy: number, r: number, count: number): Point[] => Array.from({ length: count }, (_, i) => [cx + r * Math.cos((2 * Math.PI * i) / count), cy + r * Math.sin((2 * Math.PI * i) / count)]);
    const hulls = (): Hull[] => [
      new Hull(hexagon(50, 40, 20, 0.2)),
      new Hull(hexagon(72, 44, 22, 0.5)),
      new Hull(uShape(0, 0, 50, 40, 12, 24), { position: [90, 20], rotation: 0.4 }),
      // A convex hull of more records than one bin entry holds, over the U's arm.
      new Hull(circle(122, 40, 16, 90)),
      new Hull(uShape(30, 70, 60, 40, 12, 26)),
      new Hull(uShape(0, 0, 50, 34, 10, 20), { position: [78, 112], rotation: Math.PI, scale: [1.1, 0.9] }),
      new Hull([[20, 90], [140, 84]], { closed: false }),
    ];
    const lights = (): Light[] => [
      new PointLight({ position: [12, 60], range: 170, radius: 6, shadowType: ShadowType.Occluded }),
      new PointLight({ position: [150, 110], range: 150, radius: 3, shadowType: ShadowType.Occluded, color: [0.4, 0.7, 1] }),
    ];
    reset(lights(), hulls());
    check('Occluded lights, overlapping hulls');
    reset(lights(), hulls().reverse());
    check('Occluded lights, overlapping hulls listed in reverse');
  });

  it('hulls and polylines crossing one another inside a wide disk', () => {
    // Where edges cross, the edge a ray meets first changes: the sweep must cut there.
    reset([new PointLight({ position: [80, 60], range: 90, radius: 18, color: [1, 0.9, 0.8] })], [
      new Hull(box(-20, -2, 40, 4), { position: [84, 52], rotation: 0.5 }),
      new Hull(box(-20, -2, 40, 4), { position: [84, 52], rotation: -0.6 }),
      new Hull([[62, 74], [90, 64], [70, 62], [98, 76]], { closed: false }),
    ]);
    check('crossing hulls and polylines inside the disk');
  });

  it('a textured light, its cookie sampled on the CPU; without a sampler, an upper bound', () => {
    // A 2×2 cookie with nearest filtering: red 255, 128, 64, 0 from the first texel on.
    const texels = [255, 128, 64, 0];
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 2, 2, 0, gl.RGBA, gl.UNSIGNED_BYTE, Uint8Array.from(texels.flatMap((red) => [red, 255, 255, 255])));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindTexture(gl.TEXTURE_2D, null);
    const light = new TexturedLight({ texture, position: [70, 55], size: [90, 70], origin: [0.4, 0.6], rotation: 0.5, range: 60, radius: 5, color: [1, 0.7, 0.4] });
    reset([light], [new Hull(box(85, 50, 8, 16)), new Hull([[40, 30], [50, 36], [44, 44]])]);
    const sampler = (_: TexturedLight, u: number, v: number) => texels[Math.min(1, Math.floor(v * 2)) * 2 + Math.min(1, Math.floor(u * 2))] / 255;
    // The quad's outline and the texel edges (u or v = ½) are drawn as rasterized edges / nearest texel picks.
    const quad = new Float32Array(6);
    light.writeQuad(quad);
    const [x0, y0, ax, ay, bx, by] = quad;
    const width = Math.hypot(ax, ay), height = Math.hypot(bx, by);
    const nearEdge = (x: number, y: number) => {
      const u = ((x - x0) * ax + (y - y0) * ay) / (width * width), v = ((x - x0) * bx + (y - y0) * by) / (height * height);
      return [u, u - 0.5, u - 1].some((t) => Math.abs(t) * width < OUTLINE_BAND) || [v, v - 0.5, v - 1].some((t) => Math.abs(t) * height < OUTLINE_BAND);
    };
    check('textured light, cookie sampled', { cookie: sampler }, nearEdge);
    // Without a sampler the cookie counts as 1: never below the lightmap beyond its precision.
    const lightmap = renderLightmap(gl, renderer, WIDTH, HEIGHT);
    let below = 0, above = 0;
    for (let y = 0; y < HEIGHT; y++) {
      for (let x = 0; x < WIDTH; x++) {
        const bound = renderer.illuminationAt(x + 0.5, y + 0.5, { perLight: false }).color[0];
        if (bound < lightmap.at(x, y)[0] - MAX_DIFFERENCE && !nearEdge(x + 0.5, y + 0.5)) below++;
        if (bound > lightmap.at(x, y)[0] + 0.1) above++;
      }
    }
    expect(below).toBe(0);
    expect(above).toBeGreaterThan(1000); // where the cookie is below 1
    gl.deleteTexture(texture);
  });
});

describe('the renderer\'s illuminationAt and isLit', () => {
  it('check their numbers, agree with each other, and follow changes made since the last frame', () => {
    const gl = createContext(64, 64);
    const renderer = new PenumbraRenderer(gl, { ambientColor: [0.2, 0.2, 0.2] });
    renderer.addLight(new PointLight({ position: [10, 32], range: 60, radius: 2 }));
    const wall = renderer.addHull(new Hull(box(20, 20, 4, 24)));
    renderLightmap(gl, renderer, 64, 64);
    expect(() => renderer.illuminationAt(Number.NaN, 0)).toThrow(RangeError);
    expect(() => renderer.illuminationAt(0, Infinity)).toThrow(RangeError);
    expect(() => renderer.isLit(0, 0, Number.NaN)).toThrow(RangeError);
    // Behind the wall: only the ambient colour, and not lit; in front: lit.
    expect(renderer.illuminationAt(40, 32).color).toEqual([0.2, 0.2, 0.2]);
    expect(renderer.illuminationAt(40, 32).lights[0].visibility).toBe(0);
    expect(renderer.isLit(40, 32)).toBe(false);
    expect(renderer.isLit(15, 32)).toBe(true);
    const before = renderer.illuminationAt(15, 32, { includeAmbient: false }).luminance;
    expect(renderer.isLit(15, 32, before - 1e-6)).toBe(true);
    expect(renderer.isLit(15, 32, before + 1e-6)).toBe(false);
    // No frame drawn since: the query sees the hull where it is now.
    wall.setPosition(0, 30);
    expect(renderer.isLit(40, 32)).toBe(true);
    expect(renderer.illuminationAt(40, 32).lights[0].visibility).toBe(1);
    renderer.dispose();
    destroyContext(gl);
  });

  it('check every option, `out` and the cookie, naming the field and the value', () => {
    const gl = createContext(64, 64);
    const renderer = new PenumbraRenderer(gl);
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.bindTexture(gl.TEXTURE_2D, null);
    renderer.addLight(new TexturedLight({ texture, position: [32, 32], range: 20 }));
    const query = (options: unknown, out?: unknown) => renderer.illuminationAt(32, 32, options as IlluminationOptions, out as never);
    const bad: [() => unknown, ErrorConstructor, string][] = [
      [() => query({ cookie: 5 }), TypeError, 'PenumbraRenderer.illuminationAt: options.cookie must be a function (light, u, v) => number, or null, got 5'],
      [() => query(7), TypeError, 'PenumbraRenderer.illuminationAt: options must be an object, got 7'],
      [() => query({ perLight: 'yes' }), TypeError, 'PenumbraRenderer.illuminationAt: options.perLight must be true or false, got "yes"'],
      [() => query({ includeAmbient: 1 }), TypeError, 'PenumbraRenderer.illuminationAt: options.includeAmbient must be true or false, got 1'],
      [() => query({ layers: -1 }), RangeError, 'PenumbraRenderer.illuminationAt: options.layers must be an integer from 0 to 0xffffffff (a bit mask), got -1'],
      [() => query({}, 3), TypeError, 'PenumbraRenderer.illuminationAt: out must be an earlier result (an Illumination), got 3'],
      [() => query({}, {}), TypeError, 'PenumbraRenderer.illuminationAt: out.color must be an array of 3 numbers, got undefined'],
      [() => query({}, { color: [0, 0, 0] }), TypeError, 'PenumbraRenderer.illuminationAt: out.lights must be an array, got undefined'],
      [() => query({}, { color: [0, 0, 0], lights: [5] }), TypeError, 'PenumbraRenderer.illuminationAt: out.lights[0] must be an earlier result\'s entry (with a color array of 3 numbers), got 5'],
      [() => renderer.isLit(32, 32, 0.1, { cookie: 'red' } as unknown as IlluminationOptions), TypeError, 'PenumbraRenderer.isLit: options.cookie must be a function (light, u, v) => number, or null, got "red"'],
      [() => renderer.isLit(32, 32, 0.1, null as unknown as IlluminationOptions), TypeError, 'PenumbraRenderer.isLit: options must be an object, got null'],
      [() => query({ cookie: () => Number.NaN }), RangeError, 'IlluminationOptions.cookie must return a number from 0 to 1, got NaN at (u, v) = (0.5, 0.5)'],
      [() => renderer.isLit(32, 32, 0.1, { cookie: () => '1' as unknown as number }), TypeError, 'IlluminationOptions.cookie must return a number from 0 to 1, got "1" at (u, v) = (0.5, 0.5)'],
    ];
    for (const [call, kind, message] of bad) expect(call).toThrow(new kind(message));
    // A cookie's number outside 0..1 is clamped, as an 8-bit texture holds it.
    expect(query({ cookie: () => Infinity, includeAmbient: false }).color).toEqual([1, 1, 1]);
    expect(query({ cookie: () => 7, includeAmbient: false }).color).toEqual([1, 1, 1]);
    expect(query({ cookie: () => -Infinity, includeAmbient: false }).lights).toEqual([]);
    expect(renderer.isLit(32, 32, 0.99, { cookie: () => Infinity })).toBe(true);
    expect(renderer.isLit(32, 32, 1, { cookie: () => Infinity })).toBe(false);
    // A good result to reuse still works after the errors.
    const out = query({});
    expect(query({ cookie: () => 0.5, includeAmbient: false }, out)).toBe(out);
    expect(out.color).toEqual([0.5, 0.5, 0.5]);
    renderer.dispose();
    gl.deleteTexture(texture);
    destroyContext(gl);
  });
});
