import createGL from 'gl';
import { afterEach, describe, expect, it } from 'vitest';
import { PenumbraRenderer } from '../../src/index';
import { createContext, destroyContext } from './context';

// What a Node user gets from headless-gl without createWebGL2Context: a WebGL1 context that has
// every WebGL2 method (which then fail deep inside the renderer) but none of the WebGL2 enums.

/** The message for a value that is not a WebGL2 context: what was passed, then what to pass. */
function expectedMessage(got: string): string {
  return `penumbra: PenumbraRenderer needs a WebGL2 rendering context, got ${got}: in a browser pass canvas.getContext('webgl2'); `
    + 'in Node, a headless-gl 9 context made with createGL(width, height, { createWebGL2Context: true })';
}

describe('a context that is not WebGL2', () => {
  const contexts: WebGL2RenderingContext[] = [];
  afterEach(() => {
    for (const gl of contexts.splice(0)) destroyContext(gl);
  });

  it('rejects a headless-gl WebGL1 context up front, naming it and what to pass', () => {
    const gl = createGL(16, 16) as unknown as WebGL2RenderingContext;
    contexts.push(gl);
    // The trap: the WebGL1 context offers the WebGL2 methods the old duck-typed check looked for.
    expect(typeof gl.createVertexArray).toBe('function');
    let thrown: unknown;
    try {
      new PenumbraRenderer(gl);
    } catch (error) {
      thrown = error;
    }
    expect(thrown).toBeInstanceOf(TypeError);
    expect((thrown as Error).message).toBe(expectedMessage('a WebGL1 context (WebGLRenderingContext)'));
  });

  it('rejects what is no context at all, naming it', () => {
    expect(() => new PenumbraRenderer(null as unknown as WebGL2RenderingContext)).toThrow(expectedMessage('null'));
    expect(() => new PenumbraRenderer({} as WebGL2RenderingContext)).toThrow(expectedMessage('an object'));
    expect(() => new PenumbraRenderer('webgl2' as unknown as WebGL2RenderingContext)).toThrow(expectedMessage('a string'));
  });

  it('takes a headless-gl WebGL2 context', () => {
    const gl = createContext(16, 16);
    contexts.push(gl);
    const renderer = new PenumbraRenderer(gl);
    renderer.beginDraw();
    renderer.draw();
    expect(gl.getError()).toBe(gl.NO_ERROR);
    renderer.dispose();
  });
});
