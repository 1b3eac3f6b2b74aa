import { mat4 } from 'gl-matrix';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { renderLightmap, type Lightmap } from './lightmap';

const W = 96, H = 64;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;

beforeEach(() => {
  gl = createContext(W, H);
  renderer = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
});

afterEach(() => {
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
});

const frame = (): Lightmap => renderLightmap(gl, renderer, W, H);
/** A box left of centre, shadowing the pixel (70, 32) from a light at (20, 32). */
const box = (): [number, number][] => [[40, 26], [48, 26], [48, 38], [40, 38]];
const SHADOWED: [number, number] = [70, 32];
const lit = (lightmap: Lightmap) => lightmap.at(...SHADOWED)[0] > 0.3;
const dark = (lightmap: Lightmap) => lightmap.at(...SHADOWED)[0] === 0;

/** Largest difference of red between pixel (x, y) of `a` and (x + offsetX, y + offsetY) of `b`, where both exist. */
function maxDifference(a: Lightmap, b: Lightmap, offsetX = 0, offsetY = 0): number {
  let max = 0;
  for (let y = 0; y < H; y++) {
    for (let x = 0; x < W; x++) {
      const bx = x + offsetX, by = y + offsetY;
      if (bx < 0 || by < 0 || bx >= W || by >= H) continue;
      max = Math.max(max, Math.abs(a.at(x, y)[0] - b.at(bx, by)[0]));
    }
  }
  return max;
}

describe('every change shows in the very next frame', () => {
  it('moving, disabling, re-enabling and removing a hull', () => {
    renderer.addLight(new PointLight({ position: [20, 32], range: 90, radius: 2 }));
    const hull = renderer.addHull(new Hull(box()));
    expect(dark(frame())).toBe(true);
    hull.position = [0, 30];
    expect(lit(frame())).toBe(true);
    hull.position = [0, 0];
    expect(dark(frame())).toBe(true);
    hull.enabled = false;
    expect(lit(frame())).toBe(true);
    hull.enabled = true;
    expect(dark(frame())).toBe(true);
    renderer.removeHull(hull);
    expect(lit(frame())).toBe(true);
  });

  it('reshaping a hull', () => {
    renderer.addLight(new PointLight({ position: [20, 32], range: 90 }));
    const hull = renderer.addHull(new Hull(box()));
    expect(dark(frame())).toBe(true);
    hull.points = [[40, 10], [48, 10], [48, 20], [40, 20]];
    expect(lit(frame())).toBe(true);
  });

  it('for a light that was disabled, or off screen, while the hull changed', () => {
    const light = renderer.addLight(new PointLight({ position: [20, 32], range: 90, radius: 2 }));
    const hull = renderer.addHull(new Hull(box()));
    expect(dark(frame())).toBe(true);
    light.enabled = false;
    frame();
    hull.position = [0, 30];
    frame();
    light.enabled = true;
    expect(lit(frame())).toBe(true);

    light.position = [-500, 32];
    frame();
    hull.position = [0, 0];
    frame();
    light.position = [20, 32];
    expect(dark(frame())).toBe(true);
  });

  it('an invalid hull is ignored until its points are fixed', () => {
    renderer.addLight(new PointLight({ position: [20, 32], range: 90 }));
    const hull = renderer.addHull(new Hull([[40, 26], [48, 38], [48, 26], [40, 38]])); // bow tie
    expect(hull.valid).toBe(false);
    expect(lit(frame())).toBe(true);
    hull.points = box();
    expect(hull.valid).toBe(true);
    expect(dark(frame())).toBe(true);
  });
});

describe('lights inside hulls', () => {
  it('darkens a light whose disk lies wholly inside a hull, and lets a lamp shine through its ignored housing', () => {
    const housing = new Hull([[44, 28], [52, 28], [52, 36], [44, 36]]);
    const lamp = renderer.addLight(new PointLight({ position: [48, 32], range: 30, radius: 2 }));
    renderer.addHull(housing);
    expect(frame().at(60, 32)[0]).toBe(0);
    expect(renderer.stats.lightsDrawn).toBe(1);
    lamp.ignoredHulls.add(housing);
    const lightmap = frame();
    expect(renderer.stats.lightsDrawn).toBe(1);
    expect(lightmap.at(60, 32)[0]).toBeCloseTo(1 - 12 / 30, 1);
    expect(lightmap.at(48, 32)[0]).toBeGreaterThan(0.95);
  });

  it('still shadows a lamp by the hulls it does not ignore', () => {
    const housing = new Hull([[44, 28], [52, 28], [52, 36], [44, 36]]);
    renderer.addLight(new PointLight({ position: [48, 32], range: 40, radius: 0, ignoredHulls: [housing] }));
    renderer.addHull(housing);
    renderer.addHull(new Hull([[60, 28], [64, 28], [64, 36], [60, 36]]));
    const lightmap = frame();
    expect(lightmap.at(75, 32)[0]).toBe(0);
    expect(lightmap.at(30, 32)[0]).toBeGreaterThan(0.4);
  });
});

describe('transforms', () => {
  // An asymmetric right triangle; its shadow tells a mirror image apart.
  const triangle: [number, number][] = [[0, 0], [10, 0], [0, 16]];

  it('a negative-scale hull shadows exactly like its mirror image given as points', () => {
    renderer.addLight(new PointLight({ position: [20, 32], range: 90, radius: 3 }));
    const mirrored = renderer.addHull(new Hull(triangle, { position: [50, 24], scale: [-1, 1] }));
    const viaScale = frame();
    renderer.removeHull(mirrored);
    renderer.addHull(new Hull([[50, 24], [40, 24], [50, 40]]));
    const viaPoints = frame();
    // Same world polygon, same light: identical up to float rounding of the transform.
    expect(maxDifference(viaScale, viaPoints)).toBeLessThan(0.002);
    expect(viaScale.at(80, 24)[0]).toBe(0); // shadow behind it exists
  });

  it('a custom viewProjection moves light and shadows with the camera', () => {
    renderer.addLight(new PointLight({ position: [30, 32], range: 50, radius: 3 }));
    renderer.addHull(new Hull(box()));
    const still = frame();
    // Camera moved by (12, 5) world units: world (x, y) shows at pixel (x − 12, y − 5).
    const projection = mat4.ortho(mat4.create(), 0, W, H, 0, -1, 1);
    renderer.viewProjection = mat4.translate(mat4.create(), projection, [-12, -5, 0]);
    const moved = frame();
    // Up to one step of the 8-bit shadow mask: the pixels' world positions are interpolated across
    // the moved shadow quads, and a rounding difference can tip a penumbra value to the next step.
    expect(maxDifference(moved, still, 12, 5)).toBeLessThanOrEqual(1 / 255);
    expect(maxDifference(moved, still)).toBeGreaterThan(0.1);
    renderer.viewProjection = null;
    expect(maxDifference(frame(), still)).toBe(0);
  });

  it('a zooming viewProjection scales the lit area', () => {
    renderer.addLight(new PointLight({ position: [24, 16], range: 10 }));
    renderer.viewProjection = mat4.scale(mat4.create(), mat4.ortho(mat4.create(), 0, W, H, 0, -1, 1), [2, 2, 1]);
    const lightmap = frame();
    // World (24, 16) shows at pixel (48, 32); range 10 world units = 20 pixels.
    expect(lightmap.at(48, 32)[0]).toBeGreaterThan(0.95);
    expect(lightmap.at(48 + 15, 32)[0]).toBeCloseTo(1 - 15.5 / 20, 1);
    expect(lightmap.at(48 + 21, 32)[0]).toBe(0);
  });

  it('resize reallocates the targets and the default view follows', () => {
    const small = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0], width: 32, height: 32 });
    small.addLight(new PointLight({ position: [80, 50], range: 10 }));
    small.resize(W, H);
    const lightmap = renderLightmap(gl, small, W, H);
    expect(lightmap.at(80, 50)[0]).toBeGreaterThan(0.9);
    expect(lightmap.at(10, 10)[0]).toBe(0);
    small.dispose();
  });
});

describe('lights whose shadows did not change', () => {
  /** Two lights with a box each, one to the left and one to the right, added to `target`. */
  function twoRooms(target: PenumbraRenderer): { left: PointLight; right: PointLight; rightBox: Hull } {
    const left = target.addLight(new PointLight({ position: [15, 32], range: 40, radius: 2 }));
    const right = target.addLight(new PointLight({ position: [80, 32], range: 40, radius: 2 }));
    target.addHull(new Hull([[-3, -5], [3, -5], [3, 5], [-3, 5]], { position: [30, 30] }));
    const rightBox = target.addHull(new Hull([[-3, -5], [3, -5], [3, 5], [-3, 5]], { position: [65, 34] }));
    return { left, right, rightBox };
  }

  /** Counts the texture and buffer uploads of each frame. */
  function countUploads(): { count: number } {
    const counter = { count: 0 };
    const calls = gl as unknown as Record<'texSubImage2D' | 'bufferSubData', (...args: unknown[]) => void>;
    for (const name of ['texSubImage2D', 'bufferSubData'] as const) {
      const upload = calls[name].bind(gl);
      calls[name] = (...args: unknown[]) => {
        counter.count++;
        upload(...args);
      };
    }
    return counter;
  }

  it('are not filed anew nor uploaded, and the lightmap is what a new renderer draws', () => {
    const { left, rightBox } = twoRooms(renderer);
    frame();
    expect(renderer.stats.lightsFiled).toBe(2);
    const uploads = countUploads();
    const still = frame();
    expect(renderer.stats.lightsFiled).toBe(0);
    expect(uploads.count).toBe(0);
    left.setPosition(14, 33);
    frame();
    expect(renderer.stats.lightsFiled).toBe(1);
    // The left light's row of bins and its entries (a run of texture rows each), its tile records and
    // its tile rectangles.
    expect(uploads.count).toBe(4);
    rightBox.position = [66, 35];
    uploads.count = 0;
    const changed = frame();
    expect(renderer.stats.lightsFiled).toBe(1);
    // The box's records and tags, the right light's bins, entries, tile records and tile classes.
    expect(uploads.count).toBe(6);
    expect(maxDifference(still, changed)).toBeGreaterThan(0.1);

    const fresh = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
    const copy = twoRooms(fresh);
    copy.left.setPosition(14, 33);
    copy.rightBox.position = [66, 35];
    const other = renderLightmap(gl, fresh, W, H);
    expect(maxDifference(changed, other)).toBeLessThan(1e-3);
    fresh.dispose();
  });

  it('a moving light keeps its filing while its disk stays within the margin, and lights as a new renderer does', () => {
    // Posts 7 apart: the bins from the wrong centre would miss some of them.
    const boxes = (target: PenumbraRenderer) => {
      for (let x = 4; x < W; x += 7) for (let y = 4; y < H; y += 7) target.addHull(new Hull([[-1, -1], [1, -1], [1, 1], [-1, 1]], { position: [x, y] }));
    };
    boxes(renderer);
    const light = renderer.addLight(new PointLight({ position: [40.5, 30], range: 48, radius: 12 }));
    const fresh = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
    boxes(fresh);
    let copy: PointLight | null = null, filed = 0;
    for (let step = 0; step < 24; step++) {
      light.setPosition(40.5 + 0.5 * step, 30 + 0.3 * step);
      const moving = frame();
      filed += renderer.stats.lightsFiled;
      // A new light where it is: filed without a margin.
      if (copy) fresh.removeLight(copy);
      copy = fresh.addLight(new PointLight({ position: [light.position[0], light.position[1]], range: 48, radius: 12 }));
      // Within the exact core's accuracy (the reference tests' p99, 0.02): the two draw the light
      // as tiles of different grids (the kept filing's bounds are a margin wider), so the pixels'
      // world positions round differently, which moves a few pixels among these posts, where the
      // quadrature is least accurate, by up to 0.008. Bins taken from the wrong centre miss posts: 0.41.
      expect(maxDifference(moving, renderLightmap(gl, fresh, W, H)), `step ${step}`).toBeLessThan(0.02);
    }
    expect(filed).toBeLessThan(24 / 3);
    fresh.dispose();
  });

  it('hulls that keep moving are filed every frame beside the kept filings, and light as a new renderer does', () => {
    const posts = (target: PenumbraRenderer) => {
      for (let x = 4; x < W; x += 7) for (let y = 4; y < H; y += 9) target.addHull(new Hull([[-1, -1], [1, -1], [1, 1], [-1, 1]], { position: [x, y] }));
    };
    const lights = (target: PenumbraRenderer) => {
      target.addLight(new PointLight({ position: [30.5, 30], range: 40, radius: 3 }));
      target.addLight(new PointLight({ position: [66, 34], range: 36, radius: 2 }));
    };
    posts(renderer);
    lights(renderer);
    // Two crates cross the room for 40 frames, the first through the first light's centre (its disk
    // then partly inside the crate), then stand still; a third, beside the second light, is disabled
    // at step 20 (it leaves the kept lists) and enabled again at step 30.
    const crate = (): [number, number][] => [[-2, -2], [2, -2], [2, 2], [-2, 2]];
    const crates = [0, 1, 2].map((i) => renderer.addHull(new Hull(crate(), { position: [10 + 20 * i, 30 + 8 * i] })));
    const fresh = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
    lights(fresh);
    const filed: number[] = [];
    for (let step = 0; step < 75; step++) {
      const t = Math.min(step, 40);
      for (const [i, hull] of crates.slice(0, 2).entries()) {
        hull.position = [10 + t + 20 * i, 30 + 8 * i];
        hull.rotation = 0.05 * t;
      }
      crates[2].enabled = step < 20 || step >= 30;
      const kept = frame();
      filed.push(renderer.stats.lightsFiled);
      const drawn = renderer.stats.lightsDrawn;
      // Hulls added anew: a new layout, every light filed with every hull standing still.
      for (const hull of [...fresh.hulls]) fresh.removeHull(hull);
      posts(fresh);
      for (const hull of crates) fresh.addHull(new Hull(crate(), { position: [hull.position[0], hull.position[1]], rotation: hull.rotation, enabled: hull.enabled }));
      expect(maxDifference(kept, renderLightmap(gl, fresh, W, H)), `step ${step}`).toBeLessThan(1e-3);
      expect(drawn, `step ${step}`).toBe(2);
    }
    // Filed when first drawn and when a hull near them starts moving (or changing) or has stood still
    // for 30 frames since (steps 61 and 71); not while hulls move.
    const refiled = new Set([0, 1, 20, 61, 71]);
    expect(filed.every((count, step) => count === 0 || refiled.has(step)), filed.join(' ')).toBe(true);
    fresh.dispose();
  });

  it('upload changed rows where they belong, past the first row of each texture too', () => {
    // More than a row of records (512): 600 specks along the bottom, in range, then the box.
    const specks = (target: PenumbraRenderer) => {
      for (let i = 0; i < 600; i++) target.addHull(new Hull([[0, 0], [0.1, 0], [0, 0.1]], { position: [(i % 96) + 0.5, 62 + (i % 2)] }));
    };
    specks(renderer);
    const { rightBox } = twoRooms(renderer);
    frame();
    rightBox.position = [66, 30];
    const moved = frame();
    const fresh = new PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
    specks(fresh);
    twoRooms(fresh).rightBox.position = [66, 30];
    expect(maxDifference(moved, renderLightmap(gl, fresh, W, H))).toBeLessThan(1e-3);
    fresh.dispose();
  });
});

describe('frame stats', () => {
  it('counts the scene, and times the frame only when asked', () => {
    renderer.addLight(new PointLight({ position: [20, 32], range: 60 }));
    renderer.addHull(new Hull(box()));
    frame();
    expect(renderer.stats).toMatchObject({ lights: 1, lightsDrawn: 1, hulls: 1, edges: 4, cpuTime: 0 });
    renderer.measureCpuTime = true;
    frame();
    expect(renderer.stats.cpuTime).toBeGreaterThan(0);
  });
});
