// Real PixiJS and Phaser in Chromium, lighting sprites through their normal maps with their
// integrations: a sprite with a uniform normal map (N), one without (P), and one with a normal map
// under a plain sprite (E), lit by a directional light (test/browser/engineNormals.test.ts).
import { Application, Container, Sprite, Texture } from 'pixi.js';
import Phaser from 'phaser';
import { PenumbraGroup, PenumbraLayer } from '../../../src/integrations/pixi/index';
import { PenumbraPlugin } from '../../../src/integrations/phaser/index';
import { DirectionalLight } from '../../../src/index';
import { afterDispatch, nextEvent } from '../pageEvents';
import {
  ALBEDO, AMBIENT, CANVAS, ELEVATION, FLAT_TEXEL, GROUPED, GROUP_LAYERS, NORMAL_TEXEL, SPRITES, SPRITE_SIZE, TILE_DATA, TOP_ROWS, TOP_TEXEL, WORLD_LAYERS,
  type Engine, type NormalsState,
} from './contract';

const AMBIENT_COLOR: [number, number, number] = [AMBIENT, AMBIENT, AMBIENT];

/** Squares of SPRITE_SIZE side, left to right, each of one opaque colour. */
function solid(...colors: (readonly [number, number, number])[]): HTMLCanvasElement {
  const canvas = Object.assign(document.createElement('canvas'), { width: SPRITE_SIZE * colors.length, height: SPRITE_SIZE });
  const context = canvas.getContext('2d')!;
  const image = context.createImageData(canvas.width, SPRITE_SIZE);
  for (let i = 0; i < image.data.length; i += 4) {
    const rgb = colors[Math.floor(((i / 4) % canvas.width) / SPRITE_SIZE)];
    image.data.set([rgb[0], rgb[1], rgb[2], 255], i);
  }
  context.putImageData(image, 0, 0);
  return canvas;
}

function nextFrame(): Promise<void> {
  return new Promise((done) => requestAnimationFrame(() => done()));
}

/** RGBA at canvas pixels (top-left origin), read right after drawing. */
function readPixels(gl: WebGL2RenderingContext, points: [number, number][]): [number, number, number, number][] {
  const pixel = new Uint8Array(4);
  return points.map(([x, y]) => {
    gl.readPixels(x, gl.drawingBufferHeight - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return [pixel[0], pixel[1], pixel[2], pixel[3]];
  });
}

/** Counts the GL objects made while `draw` runs. */
function countCreated(gl: WebGL2RenderingContext, draw: () => void): number {
  const names = ['createTexture', 'createFramebuffer', 'createBuffer', 'createVertexArray', 'createProgram', 'createRenderbuffer'] as const;
  const saved = names.map((name) => gl[name]);
  let count = 0;
  names.forEach((name, i) => {
    (gl as unknown as Record<string, unknown>)[name] = (...args: unknown[]) => (count++, (saved[i] as (...a: unknown[]) => unknown).apply(gl, args));
  });
  try {
    draw();
  } finally {
    names.forEach((name, i) => ((gl as unknown as Record<string, unknown>)[name] = saved[i]));
  }
  return count;
}

interface Scene {
  gl: WebGL2RenderingContext;
  apply(state: NormalsState): void;
  render(): void;
}

async function pixiScene(): Promise<Scene> {
  const app = new Application();
  await app.init({ width: CANVAS[0], height: CANVAS[1], preference: 'webgl', antialias: false, autoStart: false, background: '#000000' });
  document.body.appendChild(app.canvas);
  const gl = (app.renderer as unknown as { gl: WebGL2RenderingContext }).gl;
  const color = Texture.from(solid([ALBEDO, ALBEDO, ALBEDO]));
  const normals = Texture.from(solid(NORMAL_TEXEL));
  const world = new Container();
  const lighting = new PenumbraLayer(app.renderer, { camera: world, normals: true, ambientColor: AMBIENT_COLOR, layers: WORLD_LAYERS });
  const sprite = (at: readonly [number, number], texture = color) => world.addChild(new Sprite({ texture, anchor: 0.5, position: { x: at[0], y: at[1] } }));
  // The normal map given per sprite for N, per texture source for E's lower sprite (a texture of its own): both ways in use.
  const normal = sprite(SPRITES.normal);
  lighting.setSurface(normal, { normalMap: normals });
  sprite(SPRITES.plain);
  const under = sprite(SPRITES.erased, Texture.from(solid([ALBEDO, ALBEDO, ALBEDO])));
  lighting.setSurface(under.texture.source, { normalMap: normals.source });
  sprite(SPRITES.erased);
  world.addChild(lighting);
  const group = world.addChild(new PenumbraGroup({ lighting, layers: GROUP_LAYERS }));
  lighting.setSurface(group.addChild(new Sprite({ texture: color, anchor: 0.5, position: { x: GROUPED[0], y: GROUPED[1] } })), { normalMap: normals });
  app.stage.addChild(world);
  const light = lighting.addLight(new DirectionalLight({ elevation: ELEVATION, litLayers: WORLD_LAYERS }));
  const groupLight = lighting.addLight(new DirectionalLight({ elevation: ELEVATION, litLayers: GROUP_LAYERS }));
  return {
    gl,
    apply(state) {
      normal.rotation = state.rotation;
      normal.scale.set(state.mirrored ? -1 : 1, 1);
      light.rotation = state.lightRotation;
      groupLight.rotation = state.groupLightRotation;
      world.scale.set(state.zoom);
      world.position.set(-state.scroll[0] * state.zoom, -state.scroll[1] * state.zoom);
    },
    render: () => app.render(),
  };
}

async function phaserScene(): Promise<Scene> {
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  const gl = canvas.getContext('webgl2', { antialias: false })!;
  let scene: Normals | null = null;
  class Normals extends Phaser.Scene {
    declare penumbra: PenumbraPlugin;
    normal!: Phaser.GameObjects.Image;
    light!: DirectionalLight;
    groupLight!: DirectionalLight;
    tiles!: Phaser.Tilemaps.TilemapLayerBase;
    gpuTiles!: Phaser.Tilemaps.TilemapLayerBase;
    create(): void {
      // Phaser's way: the normal map as the texture's data source, as the loader's [url, normalUrl] leaves it.
      this.textures.addCanvas('lit', solid([ALBEDO, ALBEDO, ALBEDO]))!.setDataSource(solid(NORMAL_TEXEL));
      this.textures.addCanvas('plain', solid([ALBEDO, ALBEDO, ALBEDO]));
      this.normal = this.add.image(SPRITES.normal[0], SPRITES.normal[1], 'lit');
      this.add.image(SPRITES.plain[0], SPRITES.plain[1], 'plain');
      this.add.image(SPRITES.erased[0], SPRITES.erased[1], 'lit');
      this.add.image(SPRITES.erased[0], SPRITES.erased[1], 'plain');
      // A tilemap layer from a normal-mapped tileset: its first tile, the same flipped, its second tile.
      const tileNormals = solid(NORMAL_TEXEL, FLAT_TEXEL);
      tileNormals.getContext('2d')!.drawImage(solid(TOP_TEXEL), 0, 0, SPRITE_SIZE, TOP_ROWS, SPRITE_SIZE, 0, SPRITE_SIZE, TOP_ROWS);
      this.textures.addCanvas('tiles', solid([ALBEDO, ALBEDO, ALBEDO], [ALBEDO, ALBEDO, ALBEDO]))!.setDataSource(tileNormals);
      // Drawn by a TilemapLayer or (the same tiles) by a TilemapGPULayer, one visible at a time.
      const tiles = (gpu: boolean) => {
        const map = this.make.tilemap({ data: TILE_DATA.map((row) => [...row]), tileWidth: SPRITE_SIZE, tileHeight: SPRITE_SIZE });
        const tileset = map.addTilesetImage('tiles', 'tiles', SPRITE_SIZE, SPRITE_SIZE)!;
        // Flipped before the layer is made: a GPU layer reads its tiles once, and regenerating its data
        // texture leaves the old one's destroyed wrapper to Phaser 4.2.1's context restore, which throws on it.
        map.getTileAt(4, 3, true, 0)!.flipX = true;
        map.getTileAt(2, 3, true, 0)!.rotation = Math.PI / 2;
        return map.createLayer(0, tileset, 0, 0, gpu);
      };
      this.tiles = tiles(false);
      this.gpuTiles = tiles(true);
      this.penumbra.layers = WORLD_LAYERS;
      this.light = this.penumbra.addLight(new DirectionalLight({ elevation: ELEVATION, litLayers: WORLD_LAYERS }));
      this.groupLight = this.penumbra.addLight(new DirectionalLight({ elevation: ELEVATION, litLayers: GROUP_LAYERS }));
      this.penumbra.addGroup({ layers: GROUP_LAYERS }).add(this.add.image(GROUPED[0], GROUPED[1], 'lit'));
      this.cameras.main.setOrigin(0, 0);
      scene = this;
    }
  }
  const game = new Phaser.Game({
    type: Phaser.WEBGL, canvas, context: gl as unknown as CanvasRenderingContext2D, width: CANVAS[0], height: CANVAS[1],
    banner: false, audio: { noAudio: true }, backgroundColor: '#000000', scene: Normals,
    plugins: { scene: [{ key: 'PenumbraPlugin', plugin: PenumbraPlugin, mapping: 'penumbra', data: { normals: true, ambientColor: AMBIENT_COLOR } }] },
  });
  while (!scene) await nextFrame();
  const s = scene as Normals;
  return {
    gl,
    apply(state) {
      s.normal.setRotation(state.rotation).setFlipX(state.mirrored);
      s.light.rotation = state.lightRotation;
      s.groupLight.rotation = state.groupLightRotation;
      s.tiles.setVisible(!state.gpuTilemap);
      s.gpuTiles.setVisible(state.gpuTilemap);
      s.cameras.main.setZoom(state.zoom).setScroll(state.scroll[0], state.scroll[1]);
    },
    render: () => game.step(performance.now(), 0),
  };
}

const scenes: Partial<Record<Engine, Promise<Scene>>> = {};
function sceneOf(engine: Engine): Promise<Scene> {
  return (scenes[engine] ??= engine === 'pixi' ? pixiScene() : phaserScene());
}

window.engineNormals = {
  async read(engine, state, points) {
    const scene = await sceneOf(engine);
    scene.apply(state);
    scene.render();
    return readPixels(scene.gl, points);
  },
  async created(engine, frames) {
    const scene = await sceneOf(engine);
    scene.render();
    return countCreated(scene.gl, () => {
      for (let i = 0; i < frames; i++) scene.render();
    });
  },
  async acrossContextLoss(engine, state, points) {
    const scene = await sceneOf(engine);
    const gl = scene.gl, canvas = gl.canvas as HTMLCanvasElement;
    const loseContext = gl.getExtension('WEBGL_lose_context');
    if (!loseContext) throw new Error('WEBGL_lose_context is not available');
    scene.apply(state);
    scene.render();
    const before = readPixels(gl, points);
    const lostFrameErrors: string[] = [];
    const frame = (when: string): void => {
      try {
        scene.render();
      } catch (error) {
        lostFrameErrors.push(`${when}: ${String(error)}`);
      }
    };
    const lost = nextEvent(canvas, 'webglcontextlost');
    loseContext.loseContext();
    frame('before the lost event');
    await lost;
    await afterDispatch();
    frame('lost');
    frame('lost, again');
    const restored = nextEvent(canvas, 'webglcontextrestored');
    loseContext.restoreContext();
    await restored;
    await afterDispatch();
    while (gl.getError() !== gl.NO_ERROR);
    scene.render();
    const glErrors: number[] = [];
    for (let error = gl.getError(); error !== gl.NO_ERROR; error = gl.getError()) glErrors.push(error);
    const after = readPixels(gl, points);
    return { before, after, lostFrameErrors, glErrors };
  },
};
