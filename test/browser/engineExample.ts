import type { Browser, Page } from 'puppeteer';
import { collectPageErrors } from './chromium';

/** RGBA bytes of one pixel. */
export type Pixel = [number, number, number, number];

/** Opens a built engine example and waits for its test hook and a few rendered frames. */
export async function openExample(browser: Browser, url: string): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.newPage();
  // The examples fill the window: a small one keeps SwiftShader's frames short.
  await page.setViewport({ width: 600, height: 400 });
  const errors = collectPageErrors(page);
  // A shared, busy machine may take SwiftShader well past puppeteer's 30 s to load an example.
  await page.goto(url, { timeout: 120_000 });
  await page.waitForFunction(() => window.penumbraExample !== undefined, { timeout: 60_000 });
  await page.evaluate(() => window.penumbraExample!.frames(3));
  return { page, errors };
}

/** Puts the player at a world position and returns the pixels at the given CSS points. */
export function readAt(page: Page, player: readonly [number, number], points: readonly (readonly [number, number])[]): Promise<Pixel[]> {
  return page.evaluate((player, points) => {
    window.penumbraExample!.setPlayer(player[0], player[1]);
    return window.penumbraExample!.renderAndRead(points);
  }, player, points);
}

/** Moves the mouse and lets the page run a few frames so that the flashlight follows it. */
export async function aimAt(page: Page, x: number, y: number): Promise<void> {
  await page.mouse.move(x, y);
  await page.evaluate(() => window.penumbraExample!.frames(2));
}

/** Mean of the colour channels of a pixel. */
export function brightness([r, g, b]: Pixel): number {
  return (r + g + b) / 3;
}
