import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import type { Page } from 'puppeteer';
import { build } from 'vite';
import { collectPageErrors, launchChromium } from './chromium';
import { serveDirectory } from './staticServer';

/** A test page built with Vite and open in headless Chromium. */
export interface BuiltPage {
  page: Page;
  /** Console errors and uncaught exceptions of the page so far. */
  pageErrors: string[];
  /** Closes the browser and the server and removes the built page. */
  close(): Promise<void>;
}

/**
 * Builds the page in test/browser/`directory` with Vite (pages import the library's sources and
 * the shared test code), serves it and opens it in Chromium, ready once `window[ready]` exists.
 * Generous timeouts: Chromium on a shared machine can take a minute to load an engine.
 */
export async function openBuiltPage(directory: string, ready: string): Promise<BuiltPage> {
  const outDir = mkdtempSync(join(tmpdir(), `penumbra-${directory}-`));
  // Whatever is open when a later step throws is closed again, in reverse order.
  const closers: (() => unknown)[] = [() => rmSync(outDir, { recursive: true, force: true })];
  const close = async () => {
    for (const closer of [...closers].reverse()) await closer();
  };
  try {
    await build({
      configFile: false,
      root: resolve(import.meta.dirname, directory),
      base: './',
      logLevel: 'warn',
      // The engine pages bundle PixiJS and Phaser whole.
      build: { outDir, emptyOutDir: true, chunkSizeWarningLimit: 4000 },
    });
    const server = await serveDirectory(outDir);
    closers.push(() => server.close());
    const browser = await launchChromium();
    closers.push(() => browser.close());
    const page = await browser.newPage();
    const pageErrors = collectPageErrors(page);
    await page.goto(server.url, { waitUntil: 'load', timeout: 120_000 });
    await page.waitForFunction((name) => name in window, { timeout: 60_000 }, ready);
    return { page, pageErrors, close };
  } catch (error) {
    await close();
    throw error;
  }
}
