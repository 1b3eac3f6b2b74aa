import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import type { Page } from 'puppeteer';
import { build } from 'vite';
import type { HostStateReport } from '../gl/hostParameters';
import type { IlluminationComparison } from '../reference/illuminationComparison';
import type { ReferenceScene } from '../reference/scenes';
import { collectPageErrors, launchChromium } from './chromium';
import { serveDirectory } from './staticServer';
import type { DirectionalReferenceScene } from '../reference/directionalReference';
import type { SurfaceFigures } from '../reference/surfaceComparison';

/** What test/browser/reference-page/main.ts puts on `window`. */
export interface ReferencePageApi {
  renderScene(scene: ReferenceScene): number[];
  /** The lightmap of a directional light's scene (test/reference/directionalReference.ts). */
  renderDirectionalScene(scene: DirectionalReferenceScene): number[];
  renderAcrossContextLoss(scene: ReferenceScene): Promise<{ before: number[]; after: number[]; lostFrameError: string | null; windowErrors: string[] }>;
  /** The host-parameter check (test/gl/hostParameters.ts), of a renderer with normals when `normals`. */
  checkHostState(normals?: boolean): HostStateReport;
  compareIllumination(scene: ReferenceScene): IlluminationComparison & { glError: number; floatLightmap: boolean };
  /** Normal-mapped lighting against its CPU reference (test/reference/surfaceComparison.ts). */
  compareSurfaces(): SurfaceFigures;
  /** The messages a renderer with normals throws for malformed `drawInPlace` surfaces. */
  surfaceMisuse(): string[];
  /** A frame of a renderer with normals before a context loss and after the restore: the output bytes that differ. */
  surfacesAcrossContextLoss(): Promise<{ differingBytes: number; litBytes: number }>;
}

/** The reference page open in headless Chromium. */
export interface ReferencePage {
  page: Page;
  /** Console errors and uncaught exceptions of the page so far. */
  pageErrors: string[];
  /** Closes the browser and the server and removes the built page. */
  close(): Promise<void>;
}

/**
 * Builds test/browser/reference-page with Vite (it imports the library's sources and the shared
 * test code), serves it and opens it in Chromium, ready once its entry points are on `window`.
 */
export async function openReferencePage(): Promise<ReferencePage> {
  const outDir = mkdtempSync(join(tmpdir(), 'penumbra-reference-page-'));
  // Whatever is open when a later step throws is closed again, in reverse order.
  const closers: (() => unknown)[] = [() => rmSync(outDir, { recursive: true, force: true })];
  const close = async () => {
    for (const closer of [...closers].reverse()) await closer();
  };
  try {
    await build({
      configFile: false,
      root: resolve(import.meta.dirname, 'reference-page'),
      base: './',
      logLevel: 'warn',
      build: { outDir, emptyOutDir: true },
    });
    const server = await serveDirectory(outDir);
    closers.push(() => server.close());
    const browser = await launchChromium();
    closers.push(() => browser.close());
    const page = await browser.newPage();
    const pageErrors = collectPageErrors(page);
    await page.goto(server.url, { waitUntil: 'load' });
    await page.waitForFunction(() => 'renderScene' in window);
    return { page, pageErrors, close };
  } catch (error) {
    await close();
    throw error;
  }
}
