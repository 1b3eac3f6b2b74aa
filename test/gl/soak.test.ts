import { describe, expect, it } from 'vitest';
import { Hull, PenumbraRenderer, PointLight, Spotlight } from '../../src/index';
import { createContext, destroyContext } from './context';
import { countGLObjects } from './glObjects';

const W = 16, H = 16;
const ADD_REMOVE_CYCLES = 10_000;
const CREATE_DISPOSE_CYCLES = 200;

describe('soak: GL objects stay flat', () => {
  it(`over ${ADD_REMOVE_CYCLES} cycles of adding a light and a hull, drawing a frame and removing them`, () => {
    const gl = createContext(W, H);
    const objects = countGLObjects(gl);
    const renderer = new PenumbraRenderer(gl);
    // Both kinds the cycles draw, so that their programs (made with a kind's first light) are counted here.
    renderer.addLight(new PointLight({ position: [4, 4], range: 12 }));
    renderer.addLight(new Spotlight({ position: [20, 4], range: 12 }));
    renderer.renderLightmap();
    const afterFirstFrame = objects.live();
    let most = afterFirstFrame;
    for (let cycle = 0; cycle < ADD_REMOVE_CYCLES; cycle++) {
      const x = cycle % 10;
      const light = renderer.addLight(new Spotlight({ position: [x, 8], range: 10, rotation: cycle }));
      const hull = renderer.addHull(new Hull([[8, 4 + x / 10], [12, 4], [12, 10], [8, 10]]));
      renderer.beginDraw();
      renderer.draw();
      renderer.removeLight(light);
      renderer.removeHull(hull);
      most = Math.max(most, objects.live());
    }
    renderer.renderLightmap();
    const atEnd = objects.live();
    renderer.dispose();
    console.log(`soak: ${ADD_REMOVE_CYCLES} add/draw/remove cycles: GL objects ${afterFirstFrame} after the first frame, at most ${most}, ${atEnd} at the end, ${objects.live()} after dispose`);
    expect(gl.getError()).toBe(0);
    destroyContext(gl);
    expect(most).toBe(afterFirstFrame);
    expect(atEnd).toBe(afterFirstFrame);
    expect(objects.byKind()).toEqual({});
  });

  it(`over ${CREATE_DISPOSE_CYCLES} cycles of creating a renderer, drawing a frame and disposing it`, () => {
    const gl = createContext(W, H);
    const objects = countGLObjects(gl);
    let most = 0;
    for (let cycle = 0; cycle < CREATE_DISPOSE_CYCLES; cycle++) {
      const renderer = new PenumbraRenderer(gl, { debug: cycle % 2 === 0 });
      renderer.addLight(new PointLight({ position: [4, 4], range: 12 }));
      renderer.addHull(new Hull([[8, 4], [12, 4], [12, 10], [8, 10]]));
      renderer.beginDraw();
      renderer.draw();
      most = Math.max(most, objects.live());
      renderer.dispose();
      expect(objects.live()).toBe(0);
    }
    console.log(`soak: ${CREATE_DISPOSE_CYCLES} create/draw/dispose cycles: GL objects 0 before, at most ${most} while a renderer lives, ${objects.live()} after the last dispose`);
    expect(gl.getError()).toBe(0);
    destroyContext(gl);
  });
});
