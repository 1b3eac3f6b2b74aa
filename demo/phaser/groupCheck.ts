// What test/browser/phaserGroups.test.ts checks in the page beside pixels: the check's lit groups
// (demo/examples/groupCheck.ts) and a group's life cycle, its framebuffer watched on the GL context.
// Not part of the example.
import Phaser from 'phaser';
import { PointLight, type PenumbraGroup, type PenumbraPlugin } from 'penumbra-gl/phaser';
import { AMBIENT_SQUARE, CHECK_LAYER_A, LIGHT_A, LIGHT_B, LIT_SQUARE, SQUARE_COLOR, type GroupCheckBase } from '../examples/groupCheck';

/** A group through its life: the GL objects (framebuffers, textures, renderbuffers) made for it. */
interface PhaserGroupLifecycle {
  /** Made by the first frame drawn with the group: its framebuffer and what is attached to it. */
  made: number;
  /** Made by the next frames: none, the framebuffer is kept. */
  madeLater: number;
  /** Of those first made, still alive once the group left the display list and a frame was drawn. */
  liveWhenRemoved: number;
  /** Made by the first frame after the group was added back. */
  madeWhenAddedBack: number;
  /** Of those, still alive once the group was destroyed. */
  liveWhenDestroyed: number;
  /** Whether the context reports no GL error at the end. */
  glClean: boolean;
}

/** `window.penumbraPhaserGroups`. */
interface PhaserGroupCheck extends GroupCheckBase {
  lifecycle(): PhaserGroupLifecycle;
  /** Makes the main camera draw through a framebuffer of its own (`forceComposite`), as camera filters do, or not. */
  setComposite(on: boolean): void;
}

declare global {
  interface Window {
    penumbraPhaserGroups?: PhaserGroupCheck;
  }
}

/** A GL object made while watching, with the test of whether it still exists. */
interface Made {
  object: WebGLFramebuffer | WebGLTexture | WebGLRenderbuffer;
  alive(): boolean;
}

/** Installs `window.penumbraPhaserGroups` for a scene running the plugin as `penumbra`. */
export function installGroupCheck(scene: Phaser.Scene & { penumbra: PenumbraPlugin }): void {
  const gl = (scene.game.renderer as Phaser.Renderer.WebGL.WebGLRenderer).gl as WebGL2RenderingContext;
  const square = (rect: readonly [number, number, number, number]) => scene.add.rectangle(rect[0], rect[1], rect[2], rect[3], SQUARE_COLOR).setOrigin(0);
  const frame = () => scene.game.step(performance.now(), 0);
  let litGroup: PenumbraGroup | null = null;

  /** The framebuffers, textures and renderbuffers created while `draw` runs. */
  const made = (draw: () => void): Made[] => {
    const { createFramebuffer, createTexture, createRenderbuffer } = gl;
    const objects: Made[] = [];
    gl.createFramebuffer = () => {
      const object = createFramebuffer.call(gl);
      objects.push({ object, alive: () => gl.isFramebuffer(object) });
      return object;
    };
    gl.createTexture = () => {
      const object = createTexture.call(gl);
      objects.push({ object, alive: () => gl.isTexture(object) });
      return object;
    };
    gl.createRenderbuffer = () => {
      const object = createRenderbuffer.call(gl);
      objects.push({ object, alive: () => gl.isRenderbuffer(object) });
      return object;
    };
    draw();
    Object.assign(gl, { createFramebuffer, createTexture, createRenderbuffer });
    return objects;
  };
  const alive = (objects: Made[]) => objects.filter((made) => made.alive()).length;

  window.penumbraPhaserGroups = {
    setUp() {
      if (litGroup) return;
      litGroup = scene.penumbra.addGroup({ layers: CHECK_LAYER_A, children: [square(LIT_SQUARE)] });
      scene.penumbra.addGroup({ layers: 0, children: [square(AMBIENT_SQUARE)] });
      scene.penumbra.addLight(new PointLight(LIGHT_A));
      scene.penumbra.addLight(new PointLight(LIGHT_B));
    },

    setLayers(layers) {
      litGroup!.layers = layers;
    },

    setComposite(on) {
      scene.cameras.main.setForceComposite(on);
    },

    lifecycle() {
      const group = scene.penumbra.addGroup({ layers: CHECK_LAYER_A, children: [square([60, 560, 20, 20])] });
      const first = made(frame);
      const later = made(() => {
        frame();
        frame();
      });
      scene.children.remove(group);
      frame();
      const liveWhenRemoved = alive(first);
      scene.add.existing(group);
      const again = made(frame);
      group.destroy();
      frame();
      return {
        made: first.length, madeLater: later.length, liveWhenRemoved, madeWhenAddedBack: again.length,
        liveWhenDestroyed: alive(again), glClean: gl.getError() === gl.NO_ERROR,
      };
    },
  };
}
