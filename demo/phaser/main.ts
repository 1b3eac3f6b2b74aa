// Phaser 4 example: a character with a flashlight aimed at the mouse, walking (WASD / arrows)
// through a tilemap's walls that cast soft shadows, past a spinning prop whose shadow is traced
// from its sprite's alpha, with a few lamps; the wheel zooms. The player is in a lit group of its
// own, lit by its own torch only; the lamps' bulbs and a sign glow above the lighting layer (unlit,
// following the camera); the HUD is above it all. The walls and the prop are lit through their normal maps
// (bevelled bricks and a dome, made in code), Phaser's own: the art texture's data source, which the
// tileset shares.
import Phaser from 'phaser';
import { DEFAULT_LAYER_DEPTH, PenumbraPlugin, PointLight, Spotlight } from 'penumbra-gl/phaser';
import {
  AMBIENT_COLOR, HUD_COLOR, Keys, LAMPS, PLAYER_LAYER, PLAYER_RADIUS, PLAYER_SPEED, PLAYER_START, PLAYER_TORCH, PROP_POSITION,
  PROP_SPIN, SIGN, SIGN_COLOR, TILE_SIZE, WORLD_HEIGHT, WORLD_LAYER, WORLD_WIDTH, canvasSize, followPlayer, levelTiles,
  moveWithCollisions, readPixels, waitFrames, zoomFactorAfterWheel,
} from '../examples/level';
import { installGroupCheck } from './groupCheck';
import { installOccluderCheck } from './occluderCheck';
import { ART_KEY, FLASHLIGHT, PROP_CUT, PROP_FRAME, PROP_TRIMMED_WIDTH, WALL_TILE, drawArt, drawArtNormals } from './content';

class LevelScene extends Phaser.Scene {
  declare penumbra: PenumbraPlugin;
  private readonly position: [number, number] = [PLAYER_START[0], PLAYER_START[1]];
  private readonly direction: [number, number] = [0, 0];
  private readonly view = { zoom: 1, scroll: [0, 0] as [number, number] };
  private zoomFactor = 1;
  private readonly keys = new Keys(window);
  private player!: Phaser.GameObjects.Graphics;
  private hud!: Phaser.GameObjects.Container;
  private flashlight!: Spotlight;
  private torch!: PointLight;
  private walls!: Phaser.Tilemaps.TilemapLayer;
  private prop!: Phaser.GameObjects.Sprite;
  private propSpinning = true;

  create(): void {
    const floor = this.add.graphics();
    const tile = 40;
    for (let y = 0; y < WORLD_HEIGHT; y += tile) {
      for (let x = 0; x < WORLD_WIDTH; x += tile) {
        floor.fillStyle(((x + y) / tile) % 2 === 0 ? 0x9a9a9a : 0x8c8c8c).fillRect(x, y, tile, tile);
      }
    }
    // The art: one texture drawn in code, the wall tile and the prop's frame (a trimmed crop of it).
    // Its normal map goes in as Phaser keeps one (what this.load.image(key, [url, normalUrl]) does).
    const art = this.textures.addCanvas(ART_KEY, drawArt())!;
    art.setDataSource(drawArtNormals());
    const [propWidth, propHeight] = [art.source[0].width - PROP_CUT[0], art.source[0].height - PROP_CUT[1]];
    art.add(PROP_FRAME, 0, PROP_CUT[0], PROP_CUT[1], propWidth, propHeight)!.setTrim(PROP_TRIMMED_WIDTH, propHeight, 0, 0, propWidth, propHeight);

    // The walls: a tilemap layer, whose colliding tiles cast shadows and follow putTileAt / removeTileAt,
    // lit through the bricks of the art's normal map (the tileset's texture).
    const map = this.make.tilemap({ data: levelTiles().map((row) => row.map((wall) => (wall ? WALL_TILE : -1))), tileWidth: TILE_SIZE, tileHeight: TILE_SIZE });
    const tileset = map.addTilesetImage(ART_KEY, ART_KEY, TILE_SIZE, TILE_SIZE)!;
    this.walls = (map.createLayer(0, tileset, 0, 0) as Phaser.Tilemaps.TilemapLayer).setCollision(WALL_TILE);
    this.penumbra.addTilemapLayer(this.walls);

    // The prop: its shadow is traced from its frame's alpha and follows it (turning about the frame's centre).
    this.prop = this.add.sprite(PROP_POSITION[0], PROP_POSITION[1], ART_KEY, PROP_FRAME);
    this.penumbra.addSprite(this.prop);
    this.penumbra.setMaterial(this.prop, { specular: 0.6, shininess: 40 });
    // The level is lit by the lights of WORLD_LAYER.
    this.penumbra.layers = WORLD_LAYER;
    for (const lamp of LAMPS) {
      this.penumbra.addLight(new PointLight({ position: lamp.position, color: lamp.color, range: 220, radius: 8, intensity: 1.2, litLayers: WORLD_LAYER }));
    }
    this.flashlight = this.penumbra.addLight(new Spotlight({ ...FLASHLIGHT, litLayers: WORLD_LAYER }));
    this.cameras.main.setOrigin(0, 0);

    // The player, in a group lit apart (drawn after the lighting layer), by its own torch only.
    this.player = this.add.graphics().fillStyle(0xe8d8b0).fillCircle(0, 0, PLAYER_RADIUS).fillStyle(0x444444).fillRect(4, -3, 12, 6);
    this.penumbra.addGroup({ layers: PLAYER_LAYER, children: [this.player] });
    this.torch = this.penumbra.addLight(new PointLight({ ...PLAYER_TORCH, litLayers: PLAYER_LAYER }));

    // Above the lighting layer, in no group: unlit. The glowing bulbs and sign follow the camera…
    const glowing = this.add.graphics().setDepth(DEFAULT_LAYER_DEPTH + 1).fillStyle(0xffffff);
    for (const lamp of LAMPS) glowing.fillCircle(lamp.position[0], lamp.position[1], 5);
    glowing.fillStyle(SIGN_COLOR).fillRoundedRect(...SIGN, 4);
    // …the HUD does not (scroll factor 0).
    const hud = this.add.container(0, 0).setScrollFactor(0).setDepth(DEFAULT_LAYER_DEPTH + 2);
    hud.add(this.add.graphics().fillStyle(HUD_COLOR).fillRect(8, 8, 28, 28));
    hud.add(this.add.text(44, 12, 'WASD / arrows to move, mouse to aim, wheel to zoom', { color: '#ffffff', fontSize: '14px' }));
    this.hud = hud;
    this.input.on('wheel', (_pointer: unknown, _objects: unknown, _dx: number, dy: number) => {
      this.zoomFactor = zoomFactorAfterWheel(this.zoomFactor, dy);
    });
    this.exposeTestHook();
    installOccluderCheck(this);
    installGroupCheck(this);
  }

  override update(_time: number, delta: number): void {
    this.step(Math.min(delta, 50) / 1000);
  }

  private step(seconds: number): void {
    const { position, direction } = this;
    this.keys.direction(direction);
    moveWithCollisions(position, direction[0] * PLAYER_SPEED * seconds, direction[1] * PLAYER_SPEED * seconds);
    const { zoom, scroll } = followPlayer(position, this.scale.width, this.scale.height, this.view, this.zoomFactor);
    this.cameras.main.setZoom(zoom).setScroll(scroll[0], scroll[1]);
    // The camera zooms about its origin (0, 0), the HUD too: scaled back, it keeps its size and place.
    this.hud.setScale(1 / zoom);
    const pointer = this.input.activePointer;
    const aim = Math.atan2(pointer.y / zoom + scroll[1] - position[1], pointer.x / zoom + scroll[0] - position[0]);
    this.player.setPosition(position[0], position[1]).setRotation(aim);
    this.flashlight.setPosition(position[0], position[1]);
    this.flashlight.rotation = aim;
    this.torch.setPosition(position[0], position[1]);
    if (this.propSpinning) this.prop.rotation += PROP_SPIN * seconds;
  }

  private exposeTestHook(): void {
    const renderer = this.game.renderer as Phaser.Renderer.WebGL.WebGLRenderer;
    const gl = renderer.gl as WebGL2RenderingContext;
    window.penumbraExample = {
      setPlayer: (x, y) => {
        this.position[0] = x;
        this.position[1] = y;
        this.step(0);
      },
      renderAndRead: (points) => {
        this.step(0);
        // One full game step (update and render) now, then read before the browser presents.
        this.game.step(performance.now(), 0);
        return readPixels(gl, points);
      },
      frames: waitFrames,
      canvasSize: () => canvasSize(gl),
      setTile: (x, y, solid) => {
        if (solid) this.walls.putTileAt(WALL_TILE, x, y);
        else this.walls.removeTileAt(x, y);
      },
      setProp: (x, y, rotation, scale, flipX) => {
        this.propSpinning = false;
        this.prop.setPosition(x, y).setRotation(rotation).setScale(scale).setFlipX(flipX);
      },
      setZoom: (factor) => {
        this.zoomFactor = factor;
      },
      removeLighting: () => {
        this.plugins.removeScenePlugin('PenumbraPlugin');
        this.penumbra.destroy();
        return gl.getError() === gl.NO_ERROR;
      },
    };
  }
}

// Phaser 4 creates a WebGL1 context by default; the lighting needs WebGL2, which Phaser accepts.
const canvas = document.createElement('canvas');
document.body.appendChild(canvas);
const context = canvas.getContext('webgl2', { antialias: false, alpha: true })!;
new Phaser.Game({
  type: Phaser.WEBGL,
  canvas,
  context: context as unknown as CanvasRenderingContext2D,
  // RESIZE: the canvas fills its parent (the page, made 100% high) and follows the window; the main
  // camera takes the new size, and the lighting layer resizes with the drawing context.
  scale: { mode: Phaser.Scale.RESIZE, width: window.innerWidth, height: window.innerHeight },
  backgroundColor: '#000000',
  scene: LevelScene,
  // Renderer options go in the plugin entry's data (or to this.penumbra.configure() in a scene).
  plugins: { scene: [{ key: 'PenumbraPlugin', plugin: PenumbraPlugin, mapping: 'penumbra', data: { ambientColor: AMBIENT_COLOR, normals: true } }] },
});
