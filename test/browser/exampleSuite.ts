import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'puppeteer';
import { HUD_COLOR, PLAYER_START } from '../../demo/examples/level';
import { launchChromium } from './chromium';
import { aimAt, brightness, openExample, readAt, type Pixel } from './engineExample';
import { serveDirectory, type StaticServer } from './staticServer';

// The examples fill the window. At the sizes used here (600 × 400, then 720 × 450) the zoom is 1.25
// and the camera centres the player at the start (the view stays inside the level): the points are
// relative to the canvas centre. The wall at x 400..440 is 70 world units (87.5 px) east of the start.
const HUD = [20, 20] as const;

/** Points of the view of a canvas `width` × `height` CSS pixels. */
function pointsOf([width, height]: readonly [number, number]) {
  const center = [width / 2, height / 2] as const;
  return {
    center,
    inFront: [center[0] + 50, center[1]] as const,
    /** 2 world units before the wall: lit only if the player is drawn at the centre. */
    beforeWall: [center[0] + 85, center[1]] as const,
    behindWall: [center[0] + 160, center[1]] as const,
    above: [center[0], center[1] - 50] as const,
  };
}

/** The browser tests every engine example must pass: same level, same test hook. */
export function describeExample(title: string, path: string): void {
  describe(title, () => {
    let server: StaticServer;
    let browser: Browser;
    let page: Page;
    let errors: string[];
    let view: ReturnType<typeof pointsOf>;
    let canvasWidth = 0;

  /** The canvas's CSS and buffer size, and the window's inner size. */
    const sizes = () => page.evaluate(() => ({ ...window.penumbraExample!.canvasSize(), window: [window.innerWidth, window.innerHeight] }));

  /** Aims at the right edge from the start and reads the lit floor in front and the floor behind the wall. */
    async function frontAndBehind(): Promise<[Pixel, Pixel]> {
      await aimAt(page, canvasWidth - 5, view.center[1]);
      const [front, behind] = await readAt(page, PLAYER_START, [view.inFront, view.behindWall]);
      return [front, behind];
    }

    beforeAll(async () => {
      server = await serveDirectory('demo-dist');
      browser = await launchChromium();
      ({ page, errors } = await openExample(browser, `${server.url}${path}`));
      const { css } = await sizes();
      view = pointsOf(css);
      canvasWidth = css[0];
    });
    afterAll(async () => {
      await browser?.close();
      await server?.close();
    });

    it('runs without console errors', () => {
      expect(errors).toEqual([]);
    });

    it('fills the window', async () => {
      const { css, buffer, window } = await sizes();
      expect(css).toEqual(window);
      expect(buffer).toEqual(window);
    });

    it('lights the flashlight cone and leaves the floor behind a wall in shadow', async () => {
      const [front, behind] = await frontAndBehind();
      expect(brightness(front)).toBeGreaterThan(100);
      expect(brightness(behind)).toBeLessThan(30);
    });

    it('keeps the exact colours of the HUD drawn after the lighting', async () => {
      const [hud] = await readAt(page, PLAYER_START, [HUD]);
      expect(hud).toEqual([(HUD_COLOR >> 16) & 0xff, (HUD_COLOR >> 8) & 0xff, HUD_COLOR & 0xff, 255]);
    });

    it('moves the lit cone with the mouse', async () => {
      await aimAt(page, view.center[0], 5);
      const [front, above] = await readAt(page, PLAYER_START, [view.inFront, view.above]);
      expect(brightness(above)).toBeGreaterThan(100);
      expect(brightness(front)).toBeLessThan(30);
    });

    it('follows the window when it is resized: the canvas, the camera centred on the player, the lighting', async () => {
      await page.setViewport({ width: 720, height: 450 });
      await page.evaluate(() => window.penumbraExample!.frames(3));
      const { css, buffer } = await sizes();
      expect(css).toEqual([720, 450]);
      expect(buffer).toEqual([720, 450]);
      view = pointsOf(css);
      canvasWidth = css[0];
      const [front, behind] = await frontAndBehind();
      expect(brightness(front)).toBeGreaterThan(100);
      expect(brightness(behind)).toBeLessThan(30);
    // A camera still centred for the old size would draw the player 60 px to the left: this floor would be behind the wall.
      const [beforeWall] = await readAt(page, PLAYER_START, [view.beforeWall]);
      expect(brightness(beforeWall)).toBeGreaterThan(100);
    });

    it('frees its GL resources without GL errors when the lighting is removed, and the engine keeps drawing', async () => {
      const clean = await page.evaluate(() => window.penumbraExample!.removeLighting());
      expect(clean).toBe(true);
      const [hud, floor] = await readAt(page, PLAYER_START, [HUD, view.behindWall]);
      expect(hud[1]).toBe((HUD_COLOR >> 8) & 0xff);
    // Unlit, the floor shows its own grey.
      expect(brightness(floor)).toBeGreaterThan(120);
      expect(errors).toEqual([]);
    });
  });
}
