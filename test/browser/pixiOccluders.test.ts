import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'puppeteer';
import { PROP_POSITION, TILE_SIZE, followPlayer, levelTiles } from '../../demo/examples/level';
import type { GraphicsReport, Placement } from '../../demo/pixi/occluderCheck';
import { launchChromium } from './chromium';
import { brightness, openExample, readAt } from './engineExample';
import { serveDirectory, type StaticServer } from './staticServer';

// The Pixi example's occluders in Chromium: the tile map's hulls after setTile, the prop sprite's
// alpha hulls following it, and a Graphics' hulls against Pixi's own shapes. The pixel points are
// derived from geometry below: for each pair of scenes, points on the floor that one scene lights
// and the other shadows, with margins for the light's disk and the hulls' tolerance, so that each
// test sees the state flip where the hulls moved.

type Vec = readonly [number, number];
/** The prop as setProp places it. */
interface Prop { x: number; y: number; rotation: number; scale: number; flipX: boolean }
/** What lights a floor point: the flashlight at the player, aimed at `aim`, past the tiles and the prop. */
interface Scene { player: Vec; aim: Vec; tiles: number[][]; prop: Prop }

/** The flashlight's radius, as demo/pixi/main.ts makes it (range 320, cone π / 3.5: bright enough within 150 units and 16°). */
const FLASHLIGHT_RADIUS = 3;
/** The window: small, as SwiftShader's frames of the exact shadows are slow. */
const VIEW: Vec = [480, 320];
/**
 * Margin around the star's outline, image pixels: the traced hull is within 1 px (tolerance) of
 * the outline of the pixels whose centres are in the star, itself within ½ px of the star; plus
 * the distance table's own error.
 */
const STAR_MARGIN = 1.8;
/** Margin around the tiles, world units. */
const TILE_MARGIN = 1.5;
const LIT = 40;
const DARK = 25;

const BASE_PROP: Prop = { x: PROP_POSITION[0], y: PROP_POSITION[1], rotation: 0, scale: 1, flipX: false };

/** The prop image's star (demo/examples/level.ts, propImage): solid within this radius of its centre, image pixels. */
function starRadius(angle: number): number {
  return 10 + 13 * Math.abs(Math.cos(((angle + Math.PI / 2) * 5) / 2)) ** 2;
}

/** Signed distance to the star's outline (negative inside), image pixels from its centre, on a 0.25 px grid over ±26 px. */
const STAR_DISTANCE = (() => {
  const outline: number[] = [];
  for (let i = 0; i < 360; i++) {
    const angle = (i / 360) * 2 * Math.PI;
    outline.push(starRadius(angle) * Math.cos(angle), starRadius(angle) * Math.sin(angle));
  }
  const size = 209, table = new Float32Array(size * size);
  for (let row = 0; row < size; row++) {
    for (let column = 0; column < size; column++) {
      const x = -26 + column * 0.25, y = -26 + row * 0.25;
      const inside = Math.hypot(x, y) <= starRadius(Math.atan2(y, x));
      table[row * size + column] = (inside ? -1 : 1) * distanceToEdges([outline], x, y);
    }
  }
  return (x: number, y: number): number => {
    const column = Math.round((x + 26) / 0.25), row = Math.round((y + 26) / 0.25);
    return column < 0 || row < 0 || column >= size || row >= size ? Math.hypot(x, y) - 23 : table[row * size + column];
  };
})();

/** World point (x, y) in the prop's image, image pixels from its centre. */
function propLocal(prop: Prop, x: number, y: number): Vec {
  const dx = x - prop.x, dy = y - prop.y;
  const cos = Math.cos(prop.rotation), sin = Math.sin(prop.rotation);
  return [(dx * cos + dy * sin) / (prop.flipX ? -prop.scale : prop.scale), (-dx * sin + dy * cos) / prop.scale];
}

/** Signed distance from world point (x, y) to the prop's star, in image pixels (its hole, which no light outside reaches, filled). */
function starDistance(prop: Prop, x: number, y: number): number {
  if (Math.hypot(x - prop.x, y - prop.y) > 25 * prop.scale) return 2 * STAR_MARGIN;  // far: clear of it
  const [lx, ly] = propLocal(prop, x, y);
  return STAR_DISTANCE(lx, ly);
}

function solidTile(tiles: number[][], x: number, y: number): boolean {
  return tiles[Math.floor(y / TILE_SIZE)]?.[Math.floor(x / TILE_SIZE)] === 1;
}

/** Whether a point blocks light: `grown` with the margins added (maybe blocks), else with them taken off (surely blocks). */
function blocks(scene: Scene, x: number, y: number, grown: boolean): boolean {
  const m = TILE_MARGIN;
  const corners = [solidTile(scene.tiles, x - m, y - m), solidTile(scene.tiles, x + m, y - m), solidTile(scene.tiles, x - m, y + m), solidTile(scene.tiles, x + m, y + m)];
  if (grown ? corners.some(Boolean) : corners.every(Boolean)) return true;
  return starDistance(scene.prop, x, y) < (grown ? STAR_MARGIN : -STAR_MARGIN);
}

function segmentBlocked(scene: Scene, from: Vec, to: Vec, grown: boolean): boolean {
  const length = Math.hypot(to[0] - from[0], to[1] - from[1]);
  const steps = Math.ceil(length / 0.25);
  for (let i = 0; i <= steps; i++) {
    const t = i / steps;
    if (blocks(scene, from[0] + (to[0] - from[0]) * t, from[1] + (to[1] - from[1]) * t, grown)) return true;
  }
  return false;
}

/**
 * 'lit' when no line from the point to the light's disk can meet a hull, or when the point is
 * well inside the prop (a light lights the inside of a hull: ShadowType.Illuminated), 'dark' when
 * every line surely meets one; undefined when it is close, or off the flashlight's bright middle,
 * or near the player, the prop's outline or its hole.
 */
function classify(scene: Scene, q: Vec): 'lit' | 'dark' | undefined {
  const [px, py] = scene.player;
  const distance = Math.hypot(q[0] - px, q[1] - py);
  if (distance < 25 || distance > 150) return undefined;
  const angle = Math.atan2(q[1] - py, q[0] - px) - Math.atan2(scene.aim[1] - py, scene.aim[0] - px);
  if (Math.abs(Math.atan2(Math.sin(angle), Math.cos(angle))) > (16 * Math.PI) / 180) return undefined;
  const inProp = starDistance(scene.prop, q[0], q[1]);
  if (Math.hypot(...propLocal(scene.prop, q[0], q[1])) < 5 + STAR_MARGIN + 1) return undefined;  // the hole, and the cut across it
  if (inProp < -STAR_MARGIN) return 'lit';
  if (inProp < STAR_MARGIN) return undefined;
  const disk: Vec[] = [[px, py]];
  for (let k = 0; k < 8; k++) disk.push([px + FLASHLIGHT_RADIUS * Math.cos((k * Math.PI) / 4), py + FLASHLIGHT_RADIUS * Math.sin((k * Math.PI) / 4)]);
  if (disk.every((l) => !segmentBlocked(scene, q, l, true))) return 'lit';
  if (disk.every((l) => segmentBlocked(scene, q, l, false))) return 'dark';
  return undefined;
}

/** World points (on a grid over `area`) that scene `a` lights and `b` shadows or the other way round, up to `count`, spread out. */
function flippingPoints(a: Scene, b: Scene, area: [number, number, number, number], count = 4): { world: Vec; a: 'lit' | 'dark' }[] {
  const found: { world: Vec; a: 'lit' | 'dark' }[] = [];
  for (let y = area[1]; y <= area[3]; y += 3) {
    for (let x = area[0]; x <= area[2]; x += 3) {
      const [cssX, cssY] = toCss(a.player, [x, y]);
      if (cssX < 2 || cssY < 2 || cssX > VIEW[0] - 2 || cssY > VIEW[1] - 2) continue;
      const stateA = classify(a, [x, y]);
      const stateB = stateA && classify(b, [x, y]);
      if (stateA && stateB && stateA !== stateB) found.push({ world: [x, y], a: stateA });
    }
  }
  // Farthest-first: the first one, then each time the one farthest from those taken.
  const chosen = found.slice(0, 1);
  while (chosen.length < Math.min(count, found.length)) {
    let best = found[0], bestDistance = -1;
    for (const candidate of found) {
      const d = Math.min(...chosen.map((c) => Math.hypot(c.world[0] - candidate.world[0], c.world[1] - candidate.world[1])));
      if (d > bestDistance) [best, bestDistance] = [candidate, d];
    }
    chosen.push(best);
  }
  return chosen;
}

/** CSS pixel of a world point, with the camera the example puts on the player in a `VIEW`-sized window. */
function toCss(player: Vec, [x, y]: Vec): Vec {
  const { zoom, scroll } = followPlayer(player, VIEW[0], VIEW[1], { zoom: 1, scroll: [0, 0] });
  return [(x - scroll[0]) * zoom, (y - scroll[1]) * zoom];
}

/** Distance from a point to the nearest edge of any of the outlines. */
function distanceToEdges(outlines: number[][], x: number, y: number): number {
  let best = Infinity;
  for (const o of outlines) {
    for (let i = 0; i < o.length; i += 2) {
      const ax = o[i], ay = o[i + 1], bx = o[(i + 2) % o.length], by = o[(i + 3) % o.length];
      const t = Math.max(0, Math.min(1, ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2 || 1)));
      best = Math.min(best, Math.hypot(x - ax - t * (bx - ax), y - ay - t * (by - ay)));
    }
  }
  return best;
}

function inOutline(o: number[], x: number, y: number): boolean {
  let inside = false;
  for (let i = 0, j = o.length - 2; i < o.length; j = i, i += 2) {
    if ((o[i + 1] > y) !== (o[j + 1] > y) && x < ((o[j] - o[i]) * (y - o[i + 1])) / (o[j + 1] - o[i + 1]) + o[i]) inside = !inside;
  }
  return inside;
}

describe('PixiJS example: occluders from tiles, sprites and Graphics', () => {
  let server: StaticServer;
  let browser: Browser;
  let page: Page;
  let errors: string[];

  beforeAll(async () => {
    server = await serveDirectory('demo-dist');
    browser = await launchChromium();
    ({ page, errors } = await openExample(browser, `${server.url}pixi/`));
    await page.setViewport({ width: VIEW[0], height: VIEW[1] });
    await page.evaluate(() => window.penumbraExample!.frames(2));  // Pixi resizes on the next frame
    // Shadows are what these tests read: the prop lit flat, not through its dome's relief.
    await page.evaluate(() => window.penumbraExample!.setPropRelief!(false));
  });
  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });

  /**
   * Places the prop, aims at `scene.aim` and reads the brightness at the points' CSS pixels. The
   * example aims when it updates, which readAt does before it renders: no frames to wait for.
   */
  async function render(scene: Scene, points: readonly Vec[]): Promise<number[]> {
    const { x, y, rotation, scale, flipX } = scene.prop;
    await page.evaluate((x, y, rotation, scale, flipX) => window.penumbraExample!.setProp(x, y, rotation, scale, flipX), x, y, rotation, scale, flipX);
    const aim = toCss(scene.player, scene.aim);
    await page.mouse.move(aim[0], aim[1]);
    const pixels = await readAt(page, scene.player, points.map((point) => toCss(scene.player, point)));
    return pixels.map(brightness);
  }

  /**
   * Renders scenes `a` and `b` (after `prepare`, which puts the page's tiles as the scene has them)
   * and expects each flipping point lit or dark as geometry says.
   */
  async function expectFlip(a: Scene, b: Scene, area: [number, number, number, number], prepare?: (scene: Scene) => Promise<void>): Promise<void> {
    const points = flippingPoints(a, b, area);
    expect(points.length, 'points whose light the change flips').toBeGreaterThanOrEqual(2);
    for (const [scene, stateOf] of [[a, (s: 'lit' | 'dark') => s], [b, (s: 'lit' | 'dark') => (s === 'lit' ? 'dark' : 'lit')]] as const) {
      await prepare?.(scene);
      const values = await render(scene, points.map((p) => p.world));
      const got = values.map((v) => (v > LIT ? 'lit' : v < DARK ? 'dark' : `between (${v.toFixed(0)})`));
      expect(got, `at ${points.map((p) => p.world.join(',')).join(' ')}`).toEqual(points.map((p) => stateOf(p.a)));
    }
  }

  const tiles = levelTiles();
  // The flashlight 100 units north of the prop, aimed at it. The points that flip are mostly on the
  // prop and beside it: the arms' edges, and the notches between the arms, which a neighbouring arm
  // shadows while an arm turned there is lit inside.
  const propScene = (prop: Partial<Prop>): Scene => ({ player: [PROP_POSITION[0], PROP_POSITION[1] - 100], aim: PROP_POSITION, tiles, prop: { ...BASE_PROP, ...prop } });
  const PROP_AREA: [number, number, number, number] = [PROP_POSITION[0] - 50, PROP_POSITION[1] - 50, PROP_POSITION[0] + 50, PROP_POSITION[1] + 50];

  it('lets light through a hole that setTile knocks in a wall, and shadows it again when the tiles are put back', async () => {
    const hole: Vec[] = [[20, 14], [21, 14], [20, 15], [21, 15]];  // the wall at x 400..440, rows y 280..320
    const open = tiles.map((row) => [...row]);
    for (const [x, y] of hole) open[y][x] = 0;
    const start: Vec = [330, 300];
    const walled: Scene = { player: start, aim: [500, 300], tiles, prop: BASE_PROP };
    const holed: Scene = { ...walled, tiles: open };
    const setTiles = (solid: boolean) => page.evaluate((hole, solid) => {
      for (const [x, y] of hole) window.penumbraExample!.setTile(x, y, solid);
    }, hole, solid);
    try {
      await expectFlip(holed, walled, [445, 260, 500, 340], (scene) => setTiles(scene === walled));
    } finally {
      await setTiles(true);
    }
  });

  it('moves the prop\'s shadow with the sprite', async () => {
    await expectFlip(propScene({}), propScene({ y: PROP_POSITION[1] + 20 }), PROP_AREA);
  });

  it('turns the prop\'s shadow with the sprite', async () => {
    await expectFlip(propScene({}), propScene({ rotation: Math.PI / 5 }), PROP_AREA);
  });

  it('scales the prop\'s shadow with the sprite', async () => {
    await expectFlip(propScene({}), propScene({ scale: 1.5 }), PROP_AREA);
  });

  it('mirrors the prop\'s shadow with a negative scale, before its rotation as Pixi does', async () => {
    // The star is left–right symmetric, so mirroring then turning by θ is turning by θ, while
    // mirroring after the turn (or losing the mirror's sign) would turn it by −θ.
    await expectFlip(propScene({ rotation: Math.PI / 10, flipX: true }), propScene({ rotation: -Math.PI / 10 }), PROP_AREA);
  });

  it('traces the prop\'s hulls from its atlas frame\'s alpha, placed within the image by the frame\'s trim', async () => {
    // Every hull point is a point of the traced outline (simplifying only drops points), so it lies
    // within ½ px of the star's outline or of its hole's (radius 5), whatever the transform.
    const prop: Prop = { x: PROP_POSITION[0] + 10, y: PROP_POSITION[1] - 5, rotation: 0.7, scale: 1.3, flipX: true };
    await page.evaluate(({ x, y, rotation, scale, flipX }) => window.penumbraExample!.setProp(x, y, rotation, scale, flipX), prop);
    const outlines = await page.evaluate(() => window.penumbraPixiOccluders!.occluderOutlines());
    const far: string[] = [];
    let points = 0;
    for (const outline of outlines) {
      for (let i = 0; i < outline.length; i += 2) {
        const [lx, ly] = propLocal(prop, outline[i], outline[i + 1]);
        const off = Math.min(Math.abs(STAR_DISTANCE(lx, ly)), Math.abs(Math.hypot(lx, ly) - 5));
        points++;
        if (off > 0.75) far.push(`(${lx.toFixed(2)}, ${ly.toFixed(2)}) ${off.toFixed(2)} px off`);
      }
    }
    expect(points, 'hull points').toBeGreaterThan(20);
    expect(far, 'hull points off the star\'s outlines').toEqual([]);
  });

  it('leaves a still prop\'s hulls untouched while the camera pans', async () => {
    await page.evaluate((x, y) => window.penumbraExample!.setProp(x, y, 0.3, 1, false), PROP_POSITION[0], PROP_POSITION[1]);
    const still = await page.evaluate(() => window.penumbraPixiOccluders!.stillWhilePanning([470, 330], [380, 250]));
    expect(still).toBe(true);
  });

  it('covers a Graphics\' shapes with its hulls (holes cut, curves within the tolerance), through its transform and its parent\'s', async () => {
    const tolerance = 0.5;
    const placements: Placement[] = [
      { x: 0, y: 0, rotation: 0, scaleX: 1, scaleY: 1 },
      { x: 30, y: -20, rotation: 0.7, scaleX: 1.5, scaleY: 1.5 },
      { x: 250, y: 40, rotation: -0.8, scaleX: -1.3, scaleY: 0.9 },  // mirrored
      { x: 20, y: 10, rotation: 0.2, scaleX: 1, scaleY: 1, skewX: 0.35 },  // skewed
    ];
    const reports: GraphicsReport[] = await page.evaluate((placements, tolerance) => window.penumbraPixiOccluders!.graphics(placements, tolerance), placements, tolerance);
    reports.forEach(({ hulls, samples, linear: [a, b, c, d] }, i) => {
      // How far a local unit can stretch: the largest singular value of the local → camera map.
      const sum = (a * a + b * b + c * c + d * d) / 2, det = a * d - b * c;
      const stretch = Math.sqrt(sum + Math.sqrt(Math.max(0, sum * sum - det * det)));
      let inside = 0, wrong = 0;
      const far: string[] = [];
      for (let k = 0; k < samples.length; k += 3) {
        const [x, y, pixiInside] = [samples[k], samples[k + 1], samples[k + 2] === 1];
        if (pixiInside) inside++;
        if (hulls.some((o) => inOutline(o, x, y)) === pixiInside) continue;
        wrong++;
        const distance = distanceToEdges(hulls, x, y);
        if (distance > tolerance * stretch + 1e-6 && far.length < 5) far.push(`(${x.toFixed(1)}, ${y.toFixed(1)}) ${pixiInside ? 'in' : 'out'} ${distance.toFixed(2)} from a hull edge`);
      }
      expect(far, `placement ${i}: samples where hulls and shapes disagree beyond the tolerance`).toEqual([]);
      expect(inside, `placement ${i}: samples inside the shapes`).toBeGreaterThan(2000);
      expect(wrong / inside, `placement ${i}: share of samples near an edge that disagree`).toBeLessThan(0.05);
    });
  });

  it('adds a Graphics occluder\'s hulls, disables them off the stage, re-reads them when redrawn and drops them when destroyed', async () => {
    const report = await page.evaluate(() => window.penumbraPixiOccluders!.lifecycle());
    expect(report).toEqual({ addedToRenderer: true, disabledWhenRemoved: true, enabledWhenAddedBack: true, replacedWhenRedrawn: true, goneWhenDestroyed: true });
  });

  it('runs without console errors', () => {
    expect(errors).toEqual([]);
  });
});
