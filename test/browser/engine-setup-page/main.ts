// Real PixiJS and Phaser in Chromium: what each engine's default context gives the integrations,
// Phaser through penumbraGameConfig, and lights following display objects
// (test/browser/engineSetup.test.ts). Each world is a white floor, its origin at WORLD_ORIGIN on the
// canvas, lit by one small spotlight with no ambient light.
import { Application, Container, Graphics } from 'pixi.js';
import Phaser from 'phaser';
import { PenumbraLayer } from '../../../src/integrations/pixi/index';
import { PenumbraPlugin, penumbraGameConfig } from '../../../src/integrations/phaser/index';
import { PointLight, Spotlight, type Light } from '../../../src/index';
import {
  CANVAS, WORLD_ORIGIN, type CarrierChange, type ContextReport, type FollowFrame, type FollowHost, type LitGameReport, type Pixel,
} from './contract';

const [WIDTH, HEIGHT] = CANVAS;
const NO_AMBIENT = { ambientColor: [0, 0, 0] as [number, number, number] };
/** The followed light: a beam of even intensity, a quarter turn wide, 14 units long. */
const lamp = (): Spotlight => new Spotlight({ range: 14, radius: 1, coneAngle: Math.PI / 2, coneDecay: 0 });
const pluginEntry = { key: 'PenumbraPlugin', plugin: PenumbraPlugin, mapping: 'penumbra', data: NO_AMBIENT };
const quietGame = { width: WIDTH, height: HEIGHT, banner: false, audio: { noAudio: true }, backgroundColor: '#000000' };

function nextFrame(): Promise<void> {
  return new Promise((done) => requestAnimationFrame(() => done()));
}

/** Canvas pixels (y down) of the drawing buffer just drawn: read in the task that drew it. */
function readPixels(gl: WebGLRenderingContext, points: readonly (readonly [number, number])[]): Pixel[] {
  const pixel = new Uint8Array(4);
  return points.map(([x, y]) => {
    gl.readPixels(Math.floor(x), gl.drawingBufferHeight - 1 - Math.floor(y), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return [pixel[0], pixel[1], pixel[2], pixel[3]];
  });
}

/** Waits until `ready()` or an uncaught error mentioning penumbra, for at most `ms`. */
async function untilReadyOrError(ready: () => boolean, ms: number): Promise<string | null> {
  let error: string | null = null;
  const onError = (event: ErrorEvent): void => {
    const message = event.error instanceof Error ? event.error.message : event.message;
    if (message.includes('penumbra')) error = message;
  };
  window.addEventListener('error', onError);
  const end = performance.now() + ms;
  while (!ready() && error === null && performance.now() < end) await nextFrame();
  window.removeEventListener('error', onError);
  return error;
}

async function phaserDefaultConfig(): Promise<ContextReport> {
  let created = false;
  class Probe extends Phaser.Scene {
    create(): void {
      created = true;
    }
  }
  const game = new Phaser.Game({ ...quietGame, scene: Probe, plugins: { scene: [pluginEntry] } });
  const error = await untilReadyOrError(() => created, 20_000);
  const webgl2 = game.context instanceof WebGL2RenderingContext;
  game.destroy(true);
  return { error, webgl2 };
}

async function phaserGameConfig(light: [number, number], points: readonly (readonly [number, number])[]): Promise<LitGameReport> {
  let scene: Phaser.Scene | null = null;
  let ownPreBoot = false;
  class Lit extends Phaser.Scene {
    declare penumbra: PenumbraPlugin;
    create(): void {
      this.cameras.main.setScroll(-WORLD_ORIGIN[0], -WORLD_ORIGIN[1]);
      this.add.rectangle(-WORLD_ORIGIN[0], -WORLD_ORIGIN[1], WIDTH, HEIGHT, 0xffffff).setOrigin(0);
      this.penumbra.addLight(new PointLight({ position: light, range: 14, radius: 1 }));
      scene = this;
    }
  }
  const game = new Phaser.Game(penumbraGameConfig({
    ...quietGame, scene: Lit, plugins: { scene: [pluginEntry] }, callbacks: { preBoot: () => { ownPreBoot = true; } },
  }));
  const error = await untilReadyOrError(() => scene !== null, 20_000);
  const gl = game.context as WebGLRenderingContext;
  let pixels: Pixel[] = [];
  if (scene) {
    game.step(performance.now(), 16);
    pixels = readPixels(gl, points);
  }
  const webgl2 = gl instanceof WebGL2RenderingContext;
  game.destroy(true);
  return { error, webgl2, pixels, ownPreBoot };
}

async function pixiWebGL1(): Promise<ContextReport> {
  const app = new Application();
  await app.init({ width: WIDTH, height: HEIGHT, preference: 'webgl', preferWebGLVersion: 1, autoStart: false });
  const gl = (app.renderer as unknown as { gl: WebGLRenderingContext }).gl;
  let error: string | null = null;
  try {
    new PenumbraLayer(app.renderer).destroy();
  } catch (thrown) {
    error = (thrown as Error).message;
  }
  const webgl2 = gl instanceof WebGL2RenderingContext;
  app.destroy({ removeView: true });
  return { error, webgl2 };
}

async function antialiasedOpaque(): Promise<{ pixi: string | null; phaser: string | null }> {
  const app = new Application();
  await app.init({ width: WIDTH, height: HEIGHT, preference: 'webgl', antialias: true, autoStart: false, background: 0x000000 });
  let pixi: string | null = null;
  try {
    new PenumbraLayer(app.renderer).destroy();
  } catch (thrown) {
    pixi = (thrown as Error).message;
  }
  app.destroy({ removeView: true });

  const canvas = document.createElement('canvas');
  const context = canvas.getContext('webgl2', { antialias: true, alpha: false })!;
  let created = false;
  class Probe extends Phaser.Scene {
    create(): void {
      created = true;
    }
  }
  const game = new Phaser.Game({
    ...quietGame, type: Phaser.WEBGL, canvas, context: context as unknown as CanvasRenderingContext2D, scene: Probe, plugins: { scene: [pluginEntry] },
  });
  const phaser = await untilReadyOrError(() => created, 20_000);
  game.destroy(true);
  return { pixi, phaser };
}

/** The light's state after a render; `previous` is the position pair after the render before. */
function frameOf(light: Light, inRenderer: boolean, followers: number, previous: readonly [number, number] | null, pixels: Pixel[]): FollowFrame {
  return {
    position: [...light.position],
    rotation: light.rotation,
    enabled: light.enabled,
    inRenderer,
    followers,
    positionKept: light.position === previous,
    pixels,
  };
}

function pixiHost(): FollowHost {
  let app: Application;
  let layer: PenumbraLayer;
  let carrier: Container;
  let light: Spotlight;
  let previous: readonly [number, number] | null = null;
  const change = (c: CarrierChange): void => {
    if (c.x !== undefined) carrier.x = c.x;
    if (c.y !== undefined) carrier.y = c.y;
    if (c.rotation !== undefined) carrier.rotation = c.rotation;
    if (c.scaleX !== undefined) carrier.scale.x = c.scaleX;
    if (c.scaleY !== undefined) carrier.scale.y = c.scaleY;
    if (c.visible !== undefined) carrier.visible = c.visible;
  };
  const render = (points: readonly (readonly [number, number])[]): FollowFrame => {
    app.render();
    const pixels = readPixels((app.renderer as unknown as { gl: WebGLRenderingContext }).gl, points);
    const frame = frameOf(light, layer.penumbra.lights.includes(light), layer.followers.length, previous, pixels);
    previous = light.position;
    return frame;
  };
  return {
    async start(state) {
      app = new Application();
      await app.init({ width: WIDTH, height: HEIGHT, preference: 'webgl', antialias: false, autoStart: false, background: 0x000000 });
      document.body.appendChild(app.canvas);
      // The camera: lights and hulls are in the world container's space.
      const world = new Container();
      world.position.set(WORLD_ORIGIN[0], WORLD_ORIGIN[1]);
      world.addChild(new Graphics().rect(-WORLD_ORIGIN[0], -WORLD_ORIGIN[1], WIDTH, HEIGHT).fill(0xffffff));
      carrier = world.addChild(new Container());
      change(state);
      layer = new PenumbraLayer(app.renderer, { camera: world, ...NO_AMBIENT });
      app.stage.addChild(world, layer);
      light = lamp();
    },
    follow(options) {
      layer.follow(carrier, light, options);
    },
    async frame(c, points) {
      change(c);
      return render(points);
    },
    unfollow() {
      return layer.unfollow(light);
    },
    async destroyCarrier() {
      carrier.destroy();
      return render([]);
    },
    close() {
      app.destroy({ removeView: true }, { children: true });
    },
  };
}

function phaserHost(): FollowHost {
  let game: Phaser.Game;
  let plugin: PenumbraPlugin;
  let carrier: Phaser.GameObjects.Sprite;
  let light: Spotlight;
  let previous: readonly [number, number] | null = null;
  const change = (c: CarrierChange): void => {
    if (c.x !== undefined) carrier.x = c.x;
    if (c.y !== undefined) carrier.y = c.y;
    if (c.rotation !== undefined) carrier.rotation = c.rotation;
    if (c.scaleX !== undefined) carrier.scaleX = c.scaleX;
    if (c.scaleY !== undefined) carrier.scaleY = c.scaleY;
    if (c.visible !== undefined) carrier.visible = c.visible;
    if (c.flipX !== undefined) carrier.flipX = c.flipX;
  };
  const render = (points: readonly (readonly [number, number])[]): FollowFrame => {
    game.step(performance.now(), 16);
    const pixels = readPixels(game.context as WebGLRenderingContext, points);
    const frame = frameOf(light, plugin.penumbra.lights.includes(light), plugin.followers.length, previous, pixels);
    previous = light.position;
    return frame;
  };
  return {
    async start(state) {
      let ready = false;
      class Follow extends Phaser.Scene {
        declare penumbra: PenumbraPlugin;
        create(): void {
          this.cameras.main.setScroll(-WORLD_ORIGIN[0], -WORLD_ORIGIN[1]);
          this.add.rectangle(-WORLD_ORIGIN[0], -WORLD_ORIGIN[1], WIDTH, HEIGHT, 0xffffff).setOrigin(0);
          // A 20 × 10 white frame drawn from its top-left corner: flipX mirrors it about x = 10.
          const texture = this.textures.createCanvas('carrier', 20, 10)!;
          texture.context.fillStyle = '#ffffff';
          texture.context.fillRect(0, 0, 20, 10);
          texture.refresh();
          carrier = this.add.sprite(0, 0, 'carrier').setOrigin(0, 0);
          change(state);
          light = lamp();
          plugin = this.penumbra;
          ready = true;
        }
      }
      game = new Phaser.Game(penumbraGameConfig({ ...quietGame, scene: Follow, plugins: { scene: [pluginEntry] } }));
      while (!ready) await nextFrame();
    },
    follow(options) {
      plugin.follow(carrier, light, options);
    },
    async frame(c, points) {
      change(c);
      return render(points);
    },
    unfollow() {
      return plugin.unfollow(light);
    },
    async destroyCarrier() {
      carrier.destroy();
      return render([]);
    },
    close() {
      game.destroy(true);
    },
  };
}

window.engineSetup = { phaserDefaultConfig, phaserGameConfig, pixiWebGL1, antialiasedOpaque, pixi: pixiHost(), phaser: phaserHost() };
