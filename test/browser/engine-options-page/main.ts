// Real PixiJS and Phaser in Chromium, each given renderer options through its integration: the
// page reports what the renderer it made really got (test/browser/engineOptions.test.ts).
import { Application } from 'pixi.js';
import Phaser from 'phaser';
import { PenumbraLayer } from '../../../src/integrations/pixi/index';
import { PenumbraPlugin, type PenumbraPluginOptions } from '../../../src/integrations/phaser/index';
import { Hull, PointLight, type PenumbraRenderer } from '../../../src/index';
import { CANVAS, type PhaserRoute, type RendererReport } from './contract';

const FRAMES = 6;
const onRestored = (): void => {};

function withHandler(options: PenumbraPluginOptions): PenumbraPluginOptions {
  return { ...options, onContextRestored: onRestored };
}

function nextFrame(): Promise<void> {
  return new Promise((done) => requestAnimationFrame(() => done()));
}

/** A scene with something to time: a few lights over a few hulls. */
function populate(add: { addLight(light: PointLight): unknown; addHull(hull: Hull): unknown }): void {
  for (let i = 0; i < 4; i++) add.addHull(new Hull([[0, 0], [16, 0], [16, 16], [0, 16]], { position: [30 + i * 40, 50] }));
  for (let i = 0; i < 3; i++) add.addLight(new PointLight({ position: [40 + i * 60, 30], range: 120, radius: 6 }));
}

/**
 * The size of a texture, found from which 1×1 `texSubImage2D` writes GL accepts (WebGL has no size
 * query). Writes one texel (the lightmap is redrawn every frame); restores the binding and unpack flags.
 */
function textureSize(gl: WebGL2RenderingContext, texture: WebGLTexture, float: boolean): [number, number] {
  const bound = gl.getParameter(gl.TEXTURE_BINDING_2D) as WebGLTexture | null;
  const flip = gl.getParameter(gl.UNPACK_FLIP_Y_WEBGL) as boolean;
  const premultiply = gl.getParameter(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL) as boolean;
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
  gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, false);
  while (gl.getError() !== gl.NO_ERROR) { /* drain errors made before */ }
  const texel = float ? new Uint16Array(4) : new Uint8Array(4);
  const fits = (x: number, y: number): boolean => {
    gl.texSubImage2D(gl.TEXTURE_2D, 0, x, y, 1, 1, gl.RGBA, float ? gl.HALF_FLOAT : gl.UNSIGNED_BYTE, texel);
    return gl.getError() === gl.NO_ERROR;
  };
  // The first x (then y) where one texel no longer fits.
  const side = (at: (i: number) => boolean): number => {
    let low = 0;
    let high = 1;
    while (at(high)) high *= 2;
    while (high - low > 1) {
      const middle = (low + high) >> 1;
      if (at(middle)) low = middle;
      else high = middle;
    }
    return high;
  };
  const size: [number, number] = fits(0, 0) ? [side((x) => fits(x, 0)), side((y) => fits(0, y))] : [0, 0];
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, flip);
  gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, premultiply);
  gl.bindTexture(gl.TEXTURE_2D, bound);
  return size;
}

function report(gl: WebGL2RenderingContext, penumbra: PenumbraRenderer, cpuTimes: number[]): RendererReport {
  return {
    lightmapSize: textureSize(gl, penumbra.lightmapTexture, penumbra.hasFloatLightmap),
    ambientColor: [...penumbra.ambientColor],
    debug: penumbra.debug,
    look: [penumbra.exposure, penumbra.toneMapping, penumbra.dithering, penumbra.lightmapBlur],
    measureCpuTime: penumbra.measureCpuTime,
    cpuTimes,
    restoredHandlerKept: penumbra.onContextRestored === onRestored,
    lights: penumbra.stats.lights,
    lightsDrawn: penumbra.stats.lightsDrawn,
    hulls: penumbra.stats.hulls,
  };
}

async function pixi(options: PenumbraPluginOptions): Promise<RendererReport> {
  const app = new Application();
  await app.init({ width: CANVAS[0], height: CANVAS[1], preference: 'webgl', antialias: false, autoStart: false });
  document.body.appendChild(app.canvas);
  const gl = (app.renderer as unknown as { gl: WebGL2RenderingContext }).gl;
  const layer = new PenumbraLayer(app.renderer, withHandler(options));
  populate(layer);
  app.stage.addChild(layer);
  const cpuTimes: number[] = [];
  for (let i = 0; i < FRAMES; i++) {
    app.render();
    cpuTimes.push(layer.penumbra.stats.cpuTime);
  }
  const result = report(gl, layer.penumbra, cpuTimes);
  app.destroy({ removeView: true }, { children: true });
  return result;
}

async function phaser(route: PhaserRoute, options: PenumbraPluginOptions): Promise<RendererReport> {
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  const gl = canvas.getContext('webgl2', { antialias: false })!;
  let plugin: PenumbraPlugin | null = null;
  class Probe extends Phaser.Scene {
    declare penumbra: PenumbraPlugin;
    create(): void {
      populate(this.penumbra);
      // After the lights and hulls are in: configure() must carry them over to the new renderer.
      if (route === 'configure') this.penumbra.configure(withHandler(options));
      plugin = this.penumbra;
    }
  }
  const entry = { key: 'PenumbraPlugin', plugin: PenumbraPlugin, mapping: 'penumbra', data: route === 'data' ? withHandler(options) : undefined };
  const game = new Phaser.Game({
    type: Phaser.WEBGL, canvas, context: gl as unknown as CanvasRenderingContext2D, width: CANVAS[0], height: CANVAS[1],
    banner: false, audio: { noAudio: true }, scene: Probe, plugins: { scene: [entry] },
  });
  while (!plugin) await nextFrame();
  const penumbra = (plugin as PenumbraPlugin).penumbra;
  const cpuTimes: number[] = [];
  for (let i = 0; i < FRAMES; i++) {
    await nextFrame();
    cpuTimes.push(penumbra.stats.cpuTime);
  }
  const result = report(gl, penumbra, cpuTimes);
  game.destroy(true);
  return result;
}

window.engineOptions = { pixi, phaser };
