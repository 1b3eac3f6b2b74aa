// What the engine-options page and its test share (no engine imported here: the test runs in Node).
import type { PenumbraPluginOptions } from '../../../src/integrations/phaser/PenumbraPlugin';

/** Size of the engines' canvases, in pixels. */
export const CANVAS: readonly [number, number] = [200, 120];

/** What the renderer behind an engine got, read back from GL and from the renderer. */
export interface RendererReport {
  /** Width and height of the lightmap texture, probed on the GL context. */
  lightmapSize: [number, number];
  ambientColor: number[];
  debug: boolean;
  /** The look: exposure, tone mapping, dithering and lightmap blur. */
  look: [number, string, string, number];
  measureCpuTime: boolean;
  /** `stats.cpuTime` of several frames. */
  cpuTimes: number[];
  /** Whether `onContextRestored` is the function the options gave. */
  restoredHandlerKept: boolean;
  /** `stats` of the last frame: the page adds 3 lights and 4 hulls. */
  lights: number;
  lightsDrawn: number;
  hulls: number;
}

/** How the Phaser page passes the options: the plugin entry's `data`, or `configure()` in `create` after adding the lights and hulls. */
export type PhaserRoute = 'data' | 'configure';

/** What main.ts puts on `window`. */
interface EngineOptionsPage {
  pixi(options: PenumbraPluginOptions): Promise<RendererReport>;
  phaser(route: PhaserRoute, options: PenumbraPluginOptions): Promise<RendererReport>;
}

declare global {
  interface Window {
    engineOptions?: EngineOptionsPage;
  }
}

