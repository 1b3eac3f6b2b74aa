import { afterEach, describe, expect, it } from 'vitest';
import { createProgram, resolveIncludes } from '../../src/gl/program';
import { PenumbraRenderer } from '../../src/index';
import { createContext, destroyContext } from './context';

const VERTEX = `#version 300 es
void main() { gl_Position = vec4(0.0); }
`;
const BROKEN_FRAGMENT = `#version 300 es
precision mediump float;
out vec4 o_color;
void main() {
  o_color = vec4(undefinedThing);
}
`;

describe('shader programs', () => {
  let gl: WebGL2RenderingContext | null = null;
  afterEach(() => {
    if (gl) destroyContext(gl);
    gl = null;
  });

  it('names the pass and the stage, and shows the failing line, when a shader does not compile', () => {
    gl = createContext(4, 4);
    let message = '';
    try {
      createProgram(gl, 'test pass', VERTEX, BROKEN_FRAGMENT);
    } catch (error) {
      message = (error as Error).message;
    }
    expect(message).toContain('penumbra: test pass: fragment shader failed to compile');
    expect(message).toContain('undefinedThing');
    // The excerpt numbers the source lines around the error (line 5 here).
    expect(message).toMatch(/ {3}5: {3}o_color = vec4\(undefinedThing\);/);
  });

  it('refuses a context that is not WebGL2', () => {
    expect(() => new PenumbraRenderer({} as WebGL2RenderingContext)).toThrow(/needs a WebGL2 rendering context/);
  });

  it('rejects an unknown shader chunk by name', () => {
    expect(() => resolveIncludes('#include "nope"\n', {})).toThrow('unknown shader chunk "nope"');
  });
});
