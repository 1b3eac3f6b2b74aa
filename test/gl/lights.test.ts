import { afterEach, describe, expect, it } from 'vitest';
import { Falloff, Hull, PenumbraRenderer, PointLight, ShadowType, Spotlight, TexturedLight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

const W = 96, H = 64;
// Lightmap values are half floats (relative rounding 2^-11) computed from float32 math: 0.005
// absolute is far above that noise and far below any difference these tests look for.
const CLOSE = 0.005;

let gl: WebGL2RenderingContext;
let renderer: PenumbraRenderer;

function setUp(ambient: [number, number, number] = [0, 0, 0]): void {
  gl = createContext(W, H);
  renderer = new PenumbraRenderer(gl, { ambientColor: ambient });
}

afterEach(() => {
  expect(gl.getError()).toBe(0);
  renderer.dispose();
  destroyContext(gl);
});

/** Linear falloff of a light at `[lx, ly]` with `range`, at the centre of pixel (x, y). */
const falloff = (lx: number, ly: number, range: number, x: number, y: number) =>
  Math.max(0, 1 - Math.hypot(x + 0.5 - lx, y + 0.5 - ly) / range);

describe('point light', () => {
  it('adds colour × intensity × linear falloff; intensity is a plain multiplier', () => {
    setUp();
    const light = renderer.addLight(new PointLight({ position: [48, 32], range: 40, color: [1, 0.5, 0.25] }));
    const once = renderLightmap(gl, renderer, W, H).at(60, 40);
    const expected = falloff(48, 32, 40, 60, 40);
    expect(once[0]).toBeCloseTo(expected, 2);
    expect(once[1]).toBeCloseTo(expected * 0.5, 2);
    expect(once[2]).toBeCloseTo(expected * 0.25, 2);
    light.intensity = 2.5;
    const scaled = renderLightmap(gl, renderer, W, H).at(60, 40);
    for (let c = 0; c < 3; c++) expect(Math.abs(scaled[c] - 2.5 * once[c])).toBeLessThan(CLOSE);
    expect(renderLightmap(gl, renderer, W, H).at(48 + 41, 32)[0]).toBe(0); // beyond range
  });

  it('lights every pixel of its range disk, up to the rim, also turned and with a hull in range', () => {
    // The light pass draws a polygon around the range disk, and the shadow mask cuts out the rest
    // of the quad: neither may lose a pixel of the disk.
    setUp();
    const light = renderer.addLight(new PointLight({ position: [40, 32], range: 30, rotation: 0.3 }));
    const compareLeftOf = (maxX: number) => {
      const lightmap = renderLightmap(gl, renderer, W, H);
      let worst = 0;
      for (let y = 0; y < H; y++) {
        for (let x = 0; x < maxX; x++) worst = Math.max(worst, Math.abs(lightmap.at(x, y)[0] - falloff(40, 32, 30, x, y)));
      }
      return worst;
    };
    expect(compareLeftOf(W)).toBeLessThan(CLOSE);
    // A post right of the light shadows only pixels right of it.
    renderer.addHull(new Hull([[60, 30], [62, 30], [62, 34], [60, 34]]));
    expect(compareLeftOf(60)).toBeLessThan(CLOSE);
    light.rotation = 0;
    expect(compareLeftOf(60)).toBeLessThan(CLOSE);
  });

  it('sums overlapping lights above 1.0 in the half-float lightmap', () => {
    setUp();
    expect(renderer.hasFloatLightmap).toBe(true);
    renderer.addLight(new PointLight({ position: [44, 32], range: 60 }));
    renderer.addLight(new PointLight({ position: [52, 32], range: 60 }));
    const [r] = renderLightmap(gl, renderer, W, H).at(48, 32);
    expect(r).toBeCloseTo(falloff(44, 32, 60, 48, 32) + falloff(52, 32, 60, 48, 32), 2);
    expect(r).toBeGreaterThan(1.8);
  });

  it('leaves the ambient colour where no light reaches and adds light on top of it', () => {
    setUp([0.1, 0.2, 0.3]);
    renderer.addLight(new PointLight({ position: [16, 16], range: 10 }));
    const lightmap = renderLightmap(gl, renderer, W, H);
    for (const [x, y] of [[80, 50], [0, 63], [95, 0]]) {
      const rgb = lightmap.at(x, y);
      expect(rgb[0]).toBeCloseTo(0.1, 3);
      expect(rgb[1]).toBeCloseTo(0.2, 3);
      expect(rgb[2]).toBeCloseTo(0.3, 3);
    }
    expect(lightmap.at(16, 16)[0]).toBeCloseTo(0.1 + falloff(16, 16, 10, 16, 16), 2);
  });
});

describe('spotlight', () => {
  // Along +x from (10, 32.5), so row 32's pixel centres lie on the axis; a 90° cone reaches 45°
  // either side of the axis.
  const position: [number, number] = [10, 32.5];
  const coneValue = (decay: number, x: number, y: number) => {
    const angle = Math.atan2(Math.abs(y + 0.5 - position[1]), x + 0.5 - position[0]);
    return falloff(position[0], position[1], 80, x, y) * Math.max(0, 1 - angle / (Math.PI / 4)) ** decay;
  };

  it('lights inside its cone, with the documented cone falloff, and nothing outside', () => {
    setUp();
    renderer.addLight(new Spotlight({ position, range: 80, coneAngle: Math.PI / 2, coneDecay: 1 }));
    const lightmap = renderLightmap(gl, renderer, W, H);
    expect(lightmap.at(50, 32)[0]).toBeCloseTo(coneValue(1, 50, 32), 2);
    expect(lightmap.at(50, 45)[0]).toBeCloseTo(coneValue(1, 50, 45), 2);
    expect(lightmap.at(20, 60)[0]).toBe(0); // 70° off the axis
    expect(lightmap.at(5, 32)[0]).toBe(0); // behind
  });

  it('gets darker off the axis as coneDecay grows, and stays equal on the axis', () => {
    setUp();
    const spot = renderer.addLight(new Spotlight({ position, range: 80, coneAngle: Math.PI / 2, coneDecay: 0.5 }));
    const values = [0.5, 1, 3].map((decay) => {
      spot.coneDecay = decay;
      const lightmap = renderLightmap(gl, renderer, W, H);
      return { axis: lightmap.at(50, 32)[0], off: lightmap.at(50, 50)[0] };
    });
    expect(values[0].off).toBeGreaterThan(values[1].off + 0.05);
    expect(values[1].off).toBeGreaterThan(values[2].off + 0.05);
    expect(values[2].off).toBeCloseTo(coneValue(3, 50, 50), 2);
    expect(Math.abs(values[0].axis - values[2].axis)).toBeLessThan(CLOSE);
  });

  it('follows its rotation', () => {
    setUp();
    renderer.addLight(new Spotlight({ position: [48, 10], range: 60, rotation: Math.PI / 2, coneAngle: Math.PI / 3 }));
    const lightmap = renderLightmap(gl, renderer, W, H);
    expect(lightmap.at(48, 40)[0]).toBeGreaterThan(0.3); // +y is down the screen
    expect(lightmap.at(80, 10)[0]).toBe(0);
  });
});

describe('textured light', () => {
  it('shows the red channel of its cookie, upright, stretched over its size', () => {
    setUp();
    // 2×2 cookie: top-left texel red, every texel green; green must not show.
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 2, 2, 0, gl.RGBA, gl.UNSIGNED_BYTE,
      Uint8Array.of(255, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindTexture(gl.TEXTURE_2D, null);
    renderer.addLight(new TexturedLight({ texture, position: [48, 32], size: [40, 40], range: 40, color: [1, 0.5, 1] }));
    const lightmap = renderLightmap(gl, renderer, W, H);
    expect(lightmap.at(38, 22)).toEqual([1, 0.5, 1]); // top-left quarter: cookie 1, no falloff
    expect(lightmap.at(58, 22)).toEqual([0, 0, 0]);
    expect(lightmap.at(38, 42)).toEqual([0, 0, 0]);
    expect(lightmap.at(20, 22)).toEqual([0, 0, 0]); // outside the quad
    gl.deleteTexture(texture);
  });
});

describe('shadow types', () => {
  it('keeps the inside of hulls dark for Solid lights and lights it for Illuminated ones', () => {
    setUp();
    const light = renderer.addLight(new PointLight({ position: [20, 32], range: 80, radius: 3, shadowType: ShadowType.Solid }));
    renderer.addHull(new Hull([[40, 24], [50, 24], [50, 40], [40, 40]]));
    const solid = renderLightmap(gl, renderer, W, H);
    expect(solid.at(45, 32)[0]).toBe(0);
    expect(solid.at(70, 32)[0]).toBe(0);
    light.shadowType = ShadowType.Illuminated;
    const illuminated = renderLightmap(gl, renderer, W, H);
    expect(illuminated.at(45, 32)[0]).toBeCloseTo(falloff(20, 32, 80, 45, 32), 2);
    expect(illuminated.at(70, 32)[0]).toBe(0); // behind the hull: shadowed either way
    expect(illuminated.at(30, 32)[0]).toBeCloseTo(solid.at(30, 32)[0], 3);
  });

  it('lights the inside of a hull for an Illuminated light even where other hulls hide the whole disk', () => {
    // The shader stops merging once the disk is hidden and then looks only for a hull holding the pixel.
    setUp();
    renderer.addLight(new PointLight({ position: [20, 32], range: 80, radius: 3, shadowType: ShadowType.Illuminated }));
    renderer.addHull(new Hull([[40, 20], [46, 20], [46, 44], [40, 44]]));
    renderer.addHull(new Hull([[58, 28], [66, 28], [66, 36], [58, 36]]));
    const lightmap = renderLightmap(gl, renderer, W, H);
    expect(lightmap.at(62, 32)[0]).toBeCloseTo(falloff(20, 32, 80, 62, 32), 2);
    expect(lightmap.at(54, 32)[0]).toBe(0);
    expect(lightmap.at(72, 32)[0]).toBe(0);
  });
});

describe('several lights', () => {
  it('shadows each light on its own: the lightmap of two lights is the sum of each alone', () => {
    setUp();
    // Both lights put the hull's umbra on the same pixels: the second must not see the first's.
    renderer.addHull(new Hull([[40, 26], [46, 26], [46, 40], [40, 40]]));
    const first = new PointLight({ position: [10, 30], range: 90, radius: 3 });
    const second = new PointLight({ position: [10, 36], range: 90, radius: 3 });
    renderer.addLight(first);
    const alone = renderLightmap(gl, renderer, W, H);
    renderer.removeLight(first);
    renderer.addLight(second);
    const secondAlone = renderLightmap(gl, renderer, W, H);
    renderer.addLight(first);
    const both = renderLightmap(gl, renderer, W, H);
    let worst = 0, shadowed = 0;
    for (let y = 0; y < H; y++) {
      for (let x = 0; x < W; x++) {
        const sum = alone.at(x, y)[0] + secondAlone.at(x, y)[0];
        worst = Math.max(worst, Math.abs(both.at(x, y)[0] - sum));
        if (alone.at(x, y)[0] === 0 && secondAlone.at(x, y)[0] === 0 && x > 46) shadowed++;
      }
    }
    expect(shadowed).toBeGreaterThan(100); // the two umbrae overlap
    expect(worst).toBeLessThan(2 * CLOSE);
  });
});

describe('falloff curves', () => {
  // The curves of Falloff, written out here from their definitions (t = d / range), not imported.
  const curves = {
    linear: (t: number) => Math.max(0, 1 - t),
    smooth: (t: number) => Math.max(0, 1 - t * t) ** 2,
    inverseSquare: (t: number, core: number) => (core * core / (core * core + t * t)) * Math.max(0, 1 - t ** 4) ** 2,
  };
  const cases = [
    { falloff: Falloff.Linear, radius: 0 },
    { falloff: Falloff.Smooth, radius: 0 },
    { falloff: Falloff.InverseSquare, radius: 6 },
    { falloff: Falloff.InverseSquare, radius: 0 },
  ];
  for (const { falloff, radius } of cases) {
    it(`${falloff} (radius ${radius}): every pixel of a point light and a spotlight, and illuminationAt, follow the curve`, () => {
      setUp();
      const range = 40, core = Math.max(radius, 1) / range;
      const point = renderer.addLight(new PointLight({ position: [30, 32], range, radius, falloff }));
      const spot = renderer.addLight(new Spotlight({ position: [70, 32], range, radius, falloff, coneAngle: Math.PI, coneDecay: 0, litLayers: 0b10 }));
      point.litLayers = 0b01;
      for (const [light, layers, [lx, ly]] of [[point, 0b01, [30, 32]], [spot, 0b10, [70, 32]]] as const) {
        const map = renderLightmap(gl, renderer, W, H, layers);
        let worst = 0, worstQuery = 0;
        for (let y = 0; y < H; y++) {
          for (let x = 0; x < W; x++) {
            const t = Math.hypot(x + 0.5 - lx, y + 0.5 - ly) / range;
            // The spotlight's cone (half angle π/2, decay 0) keeps the half plane ahead of it.
            if (light === spot && x + 0.5 < lx) continue;
            const expected = curves[falloff](t, core);
            worst = Math.max(worst, Math.abs(map.at(x, y)[0] - expected));
            const queried = renderer.illuminationAt(x + 0.5, y + 0.5, { layers, includeAmbient: false }).color[0];
            worstQuery = Math.max(worstQuery, Math.abs(queried - expected));
          }
        }
        expect(worst).toBeLessThan(CLOSE);
        expect(worstQuery).toBeLessThan(1e-9);
      }
    });
  }
});
