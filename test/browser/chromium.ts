import { existsSync } from 'node:fs';
import puppeteer, { type Browser, type Page } from 'puppeteer';

/** Debian's Chromium; puppeteer's own download is disabled (.puppeteerrc.cjs). */
const CHROMIUM_PATH = process.env.PUPPETEER_EXECUTABLE_PATH ?? '/usr/bin/chromium';

/**
 * Launches headless Chromium with WebGL2 on SwiftShader (no GPU here) and no network chatter.
 * `protocolTimeout` bounds each call into the page (puppeteer's default, 180 s, unless given).
 */
export async function launchChromium(protocolTimeout?: number): Promise<Browser> {
  if (!existsSync(CHROMIUM_PATH)) {
    throw new Error(`Chromium not found at ${CHROMIUM_PATH}: install it (Debian, as root: apt-get update && apt-get install -y chromium) or set PUPPETEER_EXECUTABLE_PATH to a Chromium or Chrome binary; npm test checks this before it starts (node scripts/with-display.mjs --check).`);
  }
  return puppeteer.launch({
    executablePath: CHROMIUM_PATH,
    headless: true,
    protocolTimeout,
    args: [
      '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run',
      '--disable-quic', '--disable-dev-shm-usage',
    ],
  });
}

/** Collects console errors and uncaught exceptions of a page, to assert there were none. */
export function collectPageErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  return errors;
}
