// What test/browser/pixiGroups.test.ts checks in the page beside pixels: the check's lit groups
// (demo/examples/groupCheck.ts) and a group's life cycle. Not part of the example.
import { Graphics, type Application, type Container } from 'pixi.js';
import { PenumbraGroup, PointLight, type PenumbraLayer } from 'penumbra-gl/pixi';
import { AMBIENT_SQUARE, CHECK_LAYER_A, LIGHT_A, LIGHT_B, LIT_SQUARE, SQUARE_COLOR, type GroupCheckBase } from '../examples/groupCheck';

/** A group through its life: lighting passes in a frame beyond the page's own, and GL objects made. */
interface PixiGroupLifecycle {
  /** Extra lighting passes (`drawInPlace` calls) in one frame: the group in the world, removed, added back, destroyed. */
  extraPasses: [number, number, number, number];
  /** Framebuffers and textures created over frames drawn with the group: none, as Pixi's filter pool lends it its target. */
  createdWithGroup: number;
  /** Whether the context reports no GL error at the end. */
  glClean: boolean;
}

/** `window.penumbraPixiGroups`. */
interface PixiGroupCheck extends GroupCheckBase {
  lifecycle(): PixiGroupLifecycle;
}

declare global {
  interface Window {
    penumbraPixiGroups?: PixiGroupCheck;
  }
}

function square(rect: readonly [number, number, number, number]): Graphics {
  return new Graphics().rect(...rect).fill(SQUARE_COLOR);
}

export function exposeGroupCheck(app: Application, world: Container, lighting: PenumbraLayer): void {
  const gl = (app.renderer as unknown as { gl: WebGL2RenderingContext }).gl;
  let litGroup: PenumbraGroup | null = null;

  /** Counts the lighting passes of one frame. */
  const passesInFrame = (): number => {
    const penumbra = lighting.penumbra;
    const drawInPlace = penumbra.drawInPlace;
    let passes = 0;
    penumbra.drawInPlace = (layers) => {
      passes++;
      drawInPlace.call(penumbra, layers);
    };
    app.render();
    penumbra.drawInPlace = drawInPlace;
    return passes;
  };

  /** Counts the framebuffers and textures created while `draw` runs. */
  const created = (draw: () => void): number => {
    const { createFramebuffer, createTexture } = gl;
    let count = 0;
    gl.createFramebuffer = () => (count++, createFramebuffer.call(gl));
    gl.createTexture = () => (count++, createTexture.call(gl));
    draw();
    gl.createFramebuffer = createFramebuffer;
    gl.createTexture = createTexture;
    return count;
  };

  window.penumbraPixiGroups = {
    setUp() {
      if (litGroup) return;
      litGroup = world.addChild(new PenumbraGroup({ lighting, layers: CHECK_LAYER_A }));
      litGroup.addChild(square(LIT_SQUARE));
      world.addChild(new PenumbraGroup({ lighting, layers: 0 })).addChild(square(AMBIENT_SQUARE));
      lighting.addLight(new PointLight(LIGHT_A));
      lighting.addLight(new PointLight(LIGHT_B));
    },

    setLayers(layers) {
      litGroup!.layers = layers;
    },

    lifecycle() {
      const base = passesInFrame();
      const group = world.addChild(new PenumbraGroup({ lighting, layers: CHECK_LAYER_A }));
      group.addChild(square([60, 560, 20, 20]));
      const inWorld = passesInFrame() - base;
      const createdWithGroup = created(() => {
        for (let i = 0; i < 3; i++) app.render();
      });
      world.removeChild(group);
      const removed = passesInFrame() - base;
      world.addChild(group);
      const addedBack = passesInFrame() - base;
      group.destroy({ children: true });
      const destroyed = passesInFrame() - base;
      return { extraPasses: [inWorld, removed, addedBack, destroyed], createdWithGroup, glClean: gl.getError() === gl.NO_ERROR };
    },
  };
}
