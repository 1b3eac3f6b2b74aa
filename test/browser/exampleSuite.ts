import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'puppeteer';
import { HUD_COLOR, PLAYER_START, VIEW_HEIGHT, VIEW_WIDTH } from '../../demo/examples/level';
import { launchChromium } from './chromium';
import { aimAt, brightness, openExample, readAt } from './engineExample';
import { serveDirectory, type StaticServer } from './staticServer';

// The camera centres the player; the wall at x 400..440 is 70 world units (87.5 px) east of the start.
const CENTER = [VIEW_WIDTH / 2, VIEW_HEIGHT / 2] as const;
const IN_FRONT = [CENTER[0] + 50, CENTER[1]] as const;
const BEHIND_WALL = [CENTER[0] + 160, CENTER[1]] as const;
const ABOVE = [CENTER[0], CENTER[1] - 50] as const;
const HUD = [20, 20] as const;

/** The browser tests every engine example must pass: same level, same test hook. */
export function describeExample(title: string, path: string): void {
describe(title, () => {
  let server: StaticServer;
  let browser: Browser;
  let page: Page;
  let errors: string[];

  beforeAll(async () => {
    server = await serveDirectory('demo-dist');
    browser = await launchChromium();
    ({ page, errors } = await openExample(browser, `${server.url}${path}`));
  });
  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });

  it('runs without console errors', () => {
    expect(errors).toEqual([]);
  });

  it('lights the flashlight cone and leaves the floor behind a wall in shadow', async () => {
    await aimAt(page, VIEW_WIDTH - 5, CENTER[1]);
    const [front, behind] = await readAt(page, PLAYER_START, [IN_FRONT, BEHIND_WALL]);
    expect(brightness(front)).toBeGreaterThan(100);
    expect(brightness(behind)).toBeLessThan(30);
  });

  it('keeps the exact colours of the HUD drawn after the lighting', async () => {
    const [hud] = await readAt(page, PLAYER_START, [HUD]);
    expect(hud).toEqual([(HUD_COLOR >> 16) & 0xff, (HUD_COLOR >> 8) & 0xff, HUD_COLOR & 0xff, 255]);
  });

  it('moves the lit cone with the mouse', async () => {
    await aimAt(page, CENTER[0], 5);
    const [front, above] = await readAt(page, PLAYER_START, [IN_FRONT, ABOVE]);
    expect(brightness(above)).toBeGreaterThan(100);
    expect(brightness(front)).toBeLessThan(30);
  });

  it('frees its GL resources without GL errors when the lighting is removed, and the engine keeps drawing', async () => {
    const clean = await page.evaluate(() => window.penumbraExample!.removeLighting());
    expect(clean).toBe(true);
    const [hud, floor] = await readAt(page, PLAYER_START, [HUD, BEHIND_WALL]);
    expect(hud[1]).toBe((HUD_COLOR >> 8) & 0xff);
    // Unlit, the floor shows its own grey.
    expect(brightness(floor)).toBeGreaterThan(120);
    expect(errors).toEqual([]);
  });
});
}
