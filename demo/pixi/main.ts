// PixiJS v8 example: a character with a flashlight aimed at the mouse, walking (WASD / arrows)
// through walls that cast soft shadows, with a few lamps. The HUD is drawn after the lighting.
import { Application, Container, Graphics, Text, type WebGLRenderer } from 'pixi.js';
import { PenumbraLayer, PointLight, Spotlight, hullFromBounds } from 'penumbra-gl/pixi';
import {
  HUD_COLOR, Keys, LAMPS, PLAYER_RADIUS, PLAYER_SPEED, PLAYER_START, WALLS, WORLD_HEIGHT, WORLD_WIDTH,
  canvasSize, followPlayer, moveWithCollisions, readPixels, waitFrames,
} from '../examples/level';

const app = new Application<WebGLRenderer>();
// resizeTo: the canvas fills the window and follows it; the lighting resizes with Pixi's render target.
await app.init({ resizeTo: window, preference: 'webgl', background: '#000000', antialias: false });
document.body.appendChild(app.canvas);

// The world container is the camera: its position and scale pan and zoom everything in it.
const world = new Container();
world.addChild(drawFloor());
const walls = WALLS.map(([x, y, w, h]) => world.addChild(new Graphics().rect(x, y, w, h).fill(0x8a7f72)));
const player = world.addChild(new Graphics().circle(0, 0, PLAYER_RADIUS).fill(0xe8d8b0).rect(4, -3, 12, 6).fill(0x444444));

const lighting = new PenumbraLayer(app.renderer, { camera: world, ambientColor: [0.08, 0.08, 0.12] });
for (const wall of walls) lighting.addHull(hullFromBounds(wall, world));
for (const lamp of LAMPS) {
  lighting.addLight(new PointLight({ position: lamp.position, color: lamp.color, range: 220, radius: 8, intensity: 1.2 }));
  world.addChild(new Graphics().circle(lamp.position[0], lamp.position[1], 5).fill(0xffffff));
}
const flashlight = lighting.addLight(new Spotlight({ range: 320, radius: 3, coneAngle: Math.PI / 3.5, coneDecay: 0.6, intensity: 1.3, color: [1, 0.95, 0.8] }));

const hud = new Container();
hud.addChild(new Graphics().roundRect(8, 8, 28, 28, 4).fill(HUD_COLOR));
hud.addChild(new Text({ text: 'WASD / arrows to move, mouse to aim', x: 44, y: 12, style: { fill: 0xffffff, fontSize: 14 } }));
app.stage.addChild(world, lighting, hud);

const position: [number, number] = [PLAYER_START[0], PLAYER_START[1]];
const mouse: [number, number] = [app.screen.width, app.screen.height / 2];
app.canvas.addEventListener('pointermove', (event) => {
  mouse[0] = event.offsetX;
  mouse[1] = event.offsetY;
});
const keys = new Keys(window);
const direction: [number, number] = [0, 0];
const view = { zoom: 1, scroll: [0, 0] as [number, number] };

function update(seconds: number): void {
  keys.direction(direction);
  moveWithCollisions(position, direction[0] * PLAYER_SPEED * seconds, direction[1] * PLAYER_SPEED * seconds);
  const { zoom, scroll } = followPlayer(position, app.screen.width, app.screen.height, view);
  world.scale.set(zoom);
  world.position.set(-scroll[0] * zoom, -scroll[1] * zoom);
  const aim = Math.atan2(mouse[1] / zoom + scroll[1] - position[1], mouse[0] / zoom + scroll[0] - position[0]);
  player.position.set(position[0], position[1]);
  player.rotation = aim;
  flashlight.setPosition(position[0], position[1]);
  flashlight.rotation = aim;
}
app.ticker.add((ticker) => update(Math.min(ticker.deltaMS, 50) / 1000));

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
  removeLighting() {
    lighting.destroy();
    const gl = app.renderer.gl;
    return gl.getError() === gl.NO_ERROR;
  },
};
