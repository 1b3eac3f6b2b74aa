// PixiJS v8 example: a character with a flashlight aimed at the mouse, walking (WASD / arrows)
// through a tile map's walls that cast soft shadows, past a spinning prop whose shadow is traced
// from its sprite's alpha, with a few lamps; the wheel zooms. The player is drawn in a lit group
// of its own, lit by its own torch only; the lamps' bulbs and a sign glow, drawn after the
// lighting in the camera's container (unlit, following the camera); the HUD is drawn after it all.
// The wall tiles (bevelled bricks) and the prop (a dome) are lit through normal maps made in code.
import { Application, Container, Graphics, Rectangle, Sprite, Text, Texture, type WebGLRenderer } from 'pixi.js';
import { PenumbraGroup, PenumbraLayer, PointLight, Spotlight, TileHulls } from 'penumbra-gl/pixi';
import {
  AMBIENT_COLOR, HUD_COLOR, Keys, LAMPS, PLAYER_LAYER, PLAYER_RADIUS, PLAYER_SPEED, PLAYER_START, PLAYER_TORCH, PROP_POSITION,
  PROP_SIZE, PROP_SPIN, SIGN, SIGN_COLOR, TILE_SIZE, WORLD_HEIGHT, WORLD_LAYER, WORLD_WIDTH, canvasSize, followPlayer,
  levelTiles, moveWithCollisions, propImage, readPixels, waitFrames, zoomFactorAfterWheel,
} from '../examples/level';
import { bricks, brickNormals, propNormals } from '../examples/normalMaps';
import { exposeGroupCheck } from './groupCheck';
import { exposeOccluderCheck } from './occluderCheck';

const app = new Application<WebGLRenderer>();
// resizeTo: the canvas fills the window and follows it; the lighting resizes with Pixi's render target.
await app.init({ resizeTo: window, preference: 'webgl', background: '#000000', antialias: false });
document.body.appendChild(app.canvas);

// The world container is the camera: its position and scale pan and zoom everything in it. The
// lighting layer inside it lights what is drawn before it (the level) with the lights of WORLD_LAYER.
const world = new Container();
world.addChild(drawFloor());
// normals: true lets it light sprites through the normal maps given with setSurface.
const lighting = new PenumbraLayer(app.renderer, { camera: world, ambientColor: AMBIENT_COLOR, layers: WORLD_LAYER, normals: true });

// The walls: a tile map, drawn as brick sprites, whose hulls cover its solid tiles (a few large hulls).
// Every sprite drawn from the brick texture's source is lit through the bricks' normal map.
const tiles = new TileHulls(levelTiles(), { tileSize: TILE_SIZE });
for (const hull of tiles.hulls) lighting.addHull(hull);
const brickTexture = Texture.from(brickCanvas());
lighting.setSurface(brickTexture.source, { normalMap: Texture.from(canvasOf(brickNormals())), specular: 0.15, shininess: 16 });
const walls = world.addChild(new Container());
drawWalls();

// The prop: a sprite whose shadow is traced from its texture's alpha, and follows it as it turns.
const prop = world.addChild(new Sprite({ texture: propTexture(propImage()), anchor: 0.5 }));
prop.position.set(PROP_POSITION[0], PROP_POSITION[1]);
lighting.addOccluder(prop);
// Its normal map, laid out as its atlas: a dome, with a glossy highlight.
const propSurface = { normalMap: propTexture(propNormals()), specular: 0.6, shininess: 40 };
lighting.setSurface(prop, propSurface);
let propSpinning = true;

for (const lamp of LAMPS) {
  lighting.addLight(new PointLight({ position: lamp.position, color: lamp.color, range: 220, radius: 8, intensity: 1.2, litLayers: WORLD_LAYER }));
}
const flashlight = lighting.addLight(new Spotlight({
  range: 320, radius: 3, coneAngle: Math.PI / 3.5, coneDecay: 0.6, intensity: 1.3, color: [1, 0.95, 0.8], litLayers: WORLD_LAYER,
}));
world.addChild(lighting);

// After the lighting, in the camera: the player in a group lit apart, by its own torch only…
const actors = world.addChild(new PenumbraGroup({ lighting, layers: PLAYER_LAYER }));
const player = actors.addChild(new Graphics().circle(0, 0, PLAYER_RADIUS).fill(0xe8d8b0).rect(4, -3, 12, 6).fill(0x444444));
const torch = lighting.addLight(new PointLight({ ...PLAYER_TORCH, litLayers: PLAYER_LAYER }));
// …and what glows: the lamps' bulbs and a sign, unlit.
const glowing = world.addChild(new Graphics());
for (const lamp of LAMPS) glowing.circle(lamp.position[0], lamp.position[1], 5).fill(0xffffff);
glowing.roundRect(...SIGN, 4).fill(SIGN_COLOR);

const hud = new Container();
hud.addChild(new Graphics().roundRect(8, 8, 28, 28, 4).fill(HUD_COLOR));
hud.addChild(new Text({ text: 'WASD / arrows to move, mouse to aim, wheel to zoom', x: 44, y: 12, style: { fill: 0xffffff, fontSize: 14 } }));
app.stage.addChild(world, hud);

const position: [number, number] = [PLAYER_START[0], PLAYER_START[1]];
const mouse: [number, number] = [app.screen.width, app.screen.height / 2];
app.canvas.addEventListener('pointermove', (event) => {
  mouse[0] = event.offsetX;
  mouse[1] = event.offsetY;
});
const keys = new Keys(window);
const direction: [number, number] = [0, 0];
const view = { zoom: 1, scroll: [0, 0] as [number, number] };
let zoomFactor = 1;
app.canvas.addEventListener('wheel', (event) => {
  event.preventDefault();
  zoomFactor = zoomFactorAfterWheel(zoomFactor, event.deltaY);
}, { passive: false });

function update(seconds: number): void {
  keys.direction(direction);
  moveWithCollisions(position, direction[0] * PLAYER_SPEED * seconds, direction[1] * PLAYER_SPEED * seconds);
  const { zoom, scroll } = followPlayer(position, app.screen.width, app.screen.height, view, zoomFactor);
  world.scale.set(zoom);
  world.position.set(-scroll[0] * zoom, -scroll[1] * zoom);
  const aim = Math.atan2(mouse[1] / zoom + scroll[1] - position[1], mouse[0] / zoom + scroll[0] - position[0]);
  player.position.set(position[0], position[1]);
  player.rotation = aim;
  flashlight.setPosition(position[0], position[1]);
  flashlight.rotation = aim;
  torch.setPosition(position[0], position[1]);
  if (propSpinning) prop.rotation += PROP_SPIN * seconds;
}
app.ticker.add((ticker) => update(Math.min(ticker.deltaMS, 50) / 1000));

/** Redraws the wall tiles, one brick sprite per solid tile. */
function drawWalls(): void {
  walls.removeChildren().forEach((sprite) => sprite.destroy());
  for (let y = 0; y < tiles.height; y++) {
    for (let x = 0; x < tiles.width; x++) {
      if (tiles.isSolid(x, y)) walls.addChild(new Sprite({ texture: brickTexture, position: { x: x * TILE_SIZE, y: y * TILE_SIZE } }));
    }
  }
}

/** The wall tile: mortar, then the bricks. */
function brickCanvas(): HTMLCanvasElement {
  const canvas = Object.assign(document.createElement('canvas'), { width: TILE_SIZE, height: TILE_SIZE });
  const context = canvas.getContext('2d')!;
  context.fillStyle = '#5f574e';
  context.fillRect(0, 0, TILE_SIZE, TILE_SIZE);
  context.fillStyle = '#8a7f72';
  for (const [x, y, w, h] of bricks()) context.fillRect(x, y, w, h);
  return canvas;
}

function canvasOf(image: ImageData): HTMLCanvasElement {
  const canvas = Object.assign(document.createElement('canvas'), { width: image.width, height: image.height });
  canvas.getContext('2d')!.putImageData(image, 0, 0);
  return canvas;
}

/**
 * The prop's texture: a frame of a small atlas canvas, as a sprite sheet would give it, trimmed of
 * the image's transparent border (`trim` places it within the image's original size, so the
 * anchor is still the image's centre). The atlas holds other pixels beside it that must not cast.
 * Made from the prop's image, or from its normal map, which is laid out as the image.
 */
function propTexture(image: ImageData): Texture {
  const [left, top, width, height] = [2, 1, 44, 42];  // the opaque part of the prop's image
  const atlas = Object.assign(document.createElement('canvas'), { width: 64, height: 64 });
  const context = atlas.getContext('2d')!;
  context.fillStyle = '#5a4a3a';
  context.fillRect(0, 0, 12, 64);  // another sprite's pixels
  context.putImageData(image, 16 - left, 8 - top, left, top, width, height);
  return new Texture({
    source: Texture.from(atlas).source,
    frame: new Rectangle(16, 8, width, height),
    orig: new Rectangle(0, 0, PROP_SIZE, PROP_SIZE),
    trim: new Rectangle(left, top, width, height),
  });
}

function drawFloor(): Graphics {
  const floor = new Graphics();
  const tile = 40;
  for (let y = 0; y < WORLD_HEIGHT; y += tile) {
    for (let x = 0; x < WORLD_WIDTH; x += tile) {
      floor.rect(x, y, tile, tile).fill(((x + y) / tile) % 2 === 0 ? 0x9a9a9a : 0x8c8c8c);
    }
  }
  return floor;
}

window.penumbraExample = {
  setPlayer(x, y) {
    position[0] = x;
    position[1] = y;
    update(0);
  },
  renderAndRead(points) {
    update(0);
    app.render();
    return readPixels(app.renderer.gl, points);
  },
  frames: waitFrames,
  canvasSize: () => canvasSize(app.renderer.gl),
  setTile(x, y, solid) {
    const { added, removed } = tiles.setTile(x, y, solid);
    for (const hull of removed) lighting.removeHull(hull);
    for (const hull of added) lighting.addHull(hull);
    drawWalls();
  },
  setProp(x, y, rotation, scale, flipX) {
    propSpinning = false;
    prop.position.set(x, y);
    prop.rotation = rotation;
    prop.scale.set(flipX ? -scale : scale, scale);  // Pixi mirrors with a negative scale
  },
  setZoom(factor) {
    zoomFactor = factor;
  },
  setPropRelief(on) {
    lighting.setSurface(prop, on ? propSurface : null);
  },
  removeLighting() {
    lighting.destroy();
    const gl = app.renderer.gl;
    return gl.getError() === gl.NO_ERROR;
  },
};
exposeOccluderCheck(app, world, lighting, (x, y) => window.penumbraExample!.setPlayer(x, y));
exposeGroupCheck(app, world, lighting);
