import { resolve } from 'node:path';
import type { Page } from 'puppeteer';
import { launchChromium } from '../test/browser/chromium';
import { serveDirectory } from '../test/browser/staticServer';

/** How long the stress preset runs before its figures are read (SwiftShader frames take seconds). */
const STRESS_SECONDS = 30;
/** `--showcase`: only the showcase picture (quick to iterate on). */
const showcaseOnly = process.argv.includes('--showcase');
/** `--daylight=0.7`: the showcase's daylight for its picture (default night). */
const daylight = Number(process.argv.find((arg) => arg.startsWith('--daylight='))?.slice(11) ?? 0);
const showcaseName = process.argv.find((arg) => arg.startsWith('--out='))?.slice(6) ?? 'docs/showcase.png';

const root = resolve(import.meta.dirname, '..');
const server = await serveDirectory(resolve(root, 'demo-dist'));
const browser = await launchChromium();
const wait = (ms: number) => new Promise((done) => setTimeout(done, ms));

/**
 * The showcase as a game shows it: no panel, gizmos, stats or help; the level filling the view.
 * Flames and torches flicker for a while first.
 */
async function captureShowcase(page: Page): Promise<void> {
  await page.evaluate((value) => {
    const { playground } = window;
    playground.selectPreset('Showcase');
    // The panel collapsed (the view then centres on the whole canvas), then hidden with the rest of the editor.
    const gui = document.querySelector<HTMLElement>('.lil-gui.lil-root')!;
    gui.querySelector<HTMLElement>(':scope > .lil-title')!.click();
    for (const element of [gui, document.getElementById('gizmos'), document.getElementById('help'), document.getElementById('stats')]) {
      element!.style.visibility = 'hidden';
    }
    const row = [...document.querySelectorAll('.lil-gui .lil-controller')].find((c) => c.querySelector('.lil-name')?.textContent === 'daylight');
    const input = row?.querySelector('input');
    if (input) {
      input.value = String(value);
      input.dispatchEvent(new Event('input'));
      input.dispatchEvent(new Event('blur'));
    }
    playground.setCamera(640, 392, 0.935);
  }, daylight);
  await wait(6000);
  const figures = await page.evaluate(() => window.playground.overlayFigures());
  console.log(`showcase: ${figures.fps.toFixed(2)} fps · renderer CPU ${figures.cpuTime.toFixed(2)} ms/frame · lights ${figures.lights} · hulls ${figures.hulls}`);
  const screenshot = resolve(root, showcaseName);
  await page.screenshot({ path: screenshot });
  console.log(`wrote ${screenshot}`);
}

try {
  const page = await browser.newPage();
  page.on('console', (message) => { if (message.type() === 'error' || message.type() === 'warn') console.log(`page: ${message.text()}`); });
  page.on('pageerror', (error) => console.log(`page error: ${String(error)}`));
  await page.setViewport({ width: 1280, height: 720 });
  await page.goto(server.url);
  const start = Date.now();
  await page.waitForFunction(() => window.playground !== undefined, { timeout: 900_000 });
  console.log(`page ready after ${((Date.now() - start) / 1000).toFixed(1)} s`);
  if (!showcaseOnly) {
    // The editor on the previous default level: light handles, hulls and the panel.
    await page.evaluate(() => window.playground.selectPreset('Dungeon'));
    // Let the flame flicker, the spotlight sweep and the walkers move a little first.
    await wait(4000);
    const screenshot = resolve(root, 'docs/playground.png');
    await page.screenshot({ path: screenshot });
    console.log(`wrote ${screenshot}`);
  }
  await captureShowcase(page);
  if (!showcaseOnly) {
    await page.evaluate(() => window.playground.selectPreset('Stress'));
    await wait(STRESS_SECONDS * 1000);
    const figures = await page.evaluate(() => window.playground.overlayFigures());
    const renderer = await page.evaluate(() => window.playground.rendererStats());
    console.log(`stress preset, 1280×720 CSS px, Chromium on SwiftShader (CPU), after ${STRESS_SECONDS} s:`);
    console.log(`  fps ${figures.fps.toFixed(2)} · renderer CPU ${figures.cpuTime.toFixed(2)} ms/frame (last frame ${renderer.cpuTime.toFixed(2)} ms)`);
    console.log(`  lights ${figures.lights} (drawn ${figures.lightsDrawn}) · hulls ${figures.hulls} · edges ${figures.edges}`);
  }
} finally {
  await browser.close();
  await server.close();
}
