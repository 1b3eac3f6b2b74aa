import { resolve } from 'node:path';
import { launchChromium } from '../test/browser/chromium';
import { serveDirectory } from '../test/browser/staticServer';

/** How long the stress preset runs before its figures are read (SwiftShader frames take seconds). */
const STRESS_SECONDS = 30;

const root = resolve(import.meta.dirname, '..');
const server = await serveDirectory(resolve(root, 'demo-dist'));
const browser = await launchChromium();
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 720 });
  await page.goto(server.url);
  await page.waitForFunction(() => window.playground !== undefined);
  // Let the flame flicker, the spotlight sweep and the walkers move a little first.
  await new Promise((done) => setTimeout(done, 4000));
  const screenshot = resolve(root, 'docs/playground.png');
  await page.screenshot({ path: screenshot });
  console.log(`wrote ${screenshot}`);

  await page.evaluate(() => window.playground.selectPreset('Stress'));
  await new Promise((done) => setTimeout(done, STRESS_SECONDS * 1000));
  const figures = await page.evaluate(() => window.playground.overlayFigures());
  const renderer = await page.evaluate(() => window.playground.rendererStats());
  console.log(`stress preset, 1280×720 CSS px, Chromium on SwiftShader (CPU), after ${STRESS_SECONDS} s:`);
  console.log(`  fps ${figures.fps.toFixed(2)} · renderer CPU ${figures.cpuTime.toFixed(2)} ms/frame (last frame ${renderer.cpuTime.toFixed(2)} ms)`);
  console.log(`  lights ${figures.lights} (drawn ${figures.lightsDrawn}) · hulls ${figures.hulls} · edges ${figures.edges}`);
} finally {
  await browser.close();
  await server.close();
}
