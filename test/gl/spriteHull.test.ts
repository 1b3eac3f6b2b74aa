import { describe, expect, it } from 'vitest';
import { hullsFromAlpha, type Hull } from '../../src/index';
import { createSceneRenderer } from '../reference/buildScene';
import type { Point, ReferenceScene } from '../reference/scenes';
import { computeReference } from '../reference/softShadowReference';
import { createContext, destroyContext } from './context';
import { renderLightmap } from './lightmap';

// A sprite's shadow from hullsFromAlpha against the exact shadow of the shape its alpha was drawn
// from: two discs, rasterized (a pixel is opaque when its centre lies inside), traced and placed in
// the world. The traced outline lies within EDGE_LIMIT of the true circles: a pixel square reaches
// √2/2 past its centre, marching squares cuts or fills a staircase corner by at most √2/4 more, and
// simplification moves the outline by at most TOLERANCE. A larger occluder hides more of every
// disk, so wherever the sprite's shadow is right, the rendered light lies between the exact light
// around the discs grown by EDGE_LIMIT (darker) and shrunk by it (lighter), to within the
// renderer's own limits against the reference (test/reference/limits.ts: p99 0.02, max 0.1).
const TOLERANCE = 1;
const EDGE_LIMIT = TOLERANCE + Math.SQRT2 / 2 + Math.SQRT2 / 4;
const IMAGE_WIDTH = 64, IMAGE_HEIGHT = 48;
/** Discs in image pixels: centre x, centre y, radius. */
const DISCS = [[20, 22, 14], [49, 30, 6]] as const;
/** Where the image's top-left corner lands in the world (the anchor is [0, 0], scale 1). */
const PLACE: Point = [70, 30];
const WIDTH = 200, HEIGHT = 120;
const LIGHT = { position: [30, 60] as Point, range: 190, radius: 6 };

function discImage(): { data: Uint8Array; width: number; height: number } {
  const data = new Uint8Array(IMAGE_WIDTH * IMAGE_HEIGHT * 4);
  for (let y = 0; y < IMAGE_HEIGHT; y++) {
    for (let x = 0; x < IMAGE_WIDTH; x++) {
      const inside = DISCS.some(([cx, cy, r]) => Math.hypot(x + 0.5 - cx, y + 0.5 - cy) <= r);
      data[(y * IMAGE_WIDTH + x) * 4 + 3] = inside ? 255 : 0;
    }
  }
  return { data, width: IMAGE_WIDTH, height: IMAGE_HEIGHT };
}

/**
 * The discs in the world as polygons of 96 points, their radius changed by `grow`: inscribed in the
 * circle when shrinking, circumscribed about it when growing, so each polygon is inside or outside
 * the true circle as the bracket needs.
 */
function discPolygons(grow: number): Point[][] {
  const count = 96;
  return DISCS.map(([cx, cy, r]) => {
    const radius = (r + grow) / (grow > 0 ? Math.cos(Math.PI / count) : 1);
    return Array.from({ length: count }, (_, i): Point => {
      const angle = (2 * Math.PI * i) / count;
      return [PLACE[0] + cx + radius * Math.cos(angle), PLACE[1] + cy + radius * Math.sin(angle)];
    });
  });
}

const worldOutline = (hull: Hull): Point[] => {
  hull.updateWorld();
  return Array.from({ length: hull.worldPoints.length / 2 }, (_, i): Point => [hull.worldPoints[2 * i], hull.worldPoints[2 * i + 1]]);
};

const sceneOf = (name: string, hulls: Point[][]): ReferenceScene => ({ name, width: WIDTH, height: HEIGHT, lights: [LIGHT], hulls });

describe('a sprite hull from hullsFromAlpha, on headless-gl', () => {
  const hulls = hullsFromAlpha(discImage(), { tolerance: TOLERANCE, anchor: [0, 0], position: PLACE });

  it('casts the shadow of the shape its alpha was drawn from, to within the tracing tolerance', () => {
    expect(hulls).toHaveLength(2);
    const scene = sceneOf('sprite discs', hulls.map(worldOutline));
    const gl = createContext(WIDTH, HEIGHT);
    const renderer = createSceneRenderer(gl, scene);
    const rendered = renderLightmap(gl, renderer, WIDTH, HEIGHT).rgb;
    expect(gl.getError()).toBe(0);
    renderer.dispose();
    destroyContext(gl);

    const darkest = computeReference(sceneOf('discs grown', discPolygons(EDGE_LIMIT))).light;
    const lightest = computeReference(sceneOf('discs shrunk', discPolygons(-EDGE_LIMIT))).light;
    const exact = computeReference(sceneOf('discs', discPolygons(0)));
    const outside: number[] = [];
    let penumbra = 0;
    for (let pixel = 0; pixel < WIDTH * HEIGHT; pixel++) {
      if (!exact.inRange[pixel]) continue;
      const value = rendered[pixel * 3];
      outside.push(Math.max(0, darkest[pixel * 3] - value, value - lightest[pixel * 3]));
      if (exact.visibility[0][pixel] > 0.05 && exact.visibility[0][pixel] < 0.95) penumbra++;
    }
    outside.sort((a, b) => a - b);
    const p99 = outside[Math.floor(outside.length * 0.99)], max = outside[outside.length - 1];
    console.log(`sprite discs: ${outside.length} pixels, ${penumbra} in the exact penumbra; outside the bracket: p99 ${p99.toFixed(4)}, max ${max.toFixed(4)}`);
    expect(penumbra).toBeGreaterThan(1500);
    expect(p99).toBeLessThanOrEqual(0.02);
    expect(max).toBeLessThanOrEqual(0.1);
  });
});
