import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { PenumbraRenderer } from '../../src/index';
import { createContext, destroyContext } from './context';
import { countGLObjects } from './glObjects';

// headless-gl 9.0.0-rc.10 cannot draw into several colour attachments (its drawBuffers maps every
// attachment but the first to garbage: stackgl/headless-gl pull request 336), so normal-mapped
// lighting is compared with its CPU reference in Chromium (test/browser/normals.test.ts). Here:
// what such a context and a renderer without normals answer.
let gl: WebGL2RenderingContext;
let without: PenumbraRenderer;

beforeAll(() => {
  gl = createContext(32, 16);
  without = new PenumbraRenderer(gl);
});

afterAll(() => {
  if (gl) destroyContext(gl);
});

describe('normals on a context without multiple draw buffers', () => {
  it('refuses { normals: true } naming what the context lacks, and frees what it made', () => {
    const objects = countGLObjects(gl);
    expect(() => new PenumbraRenderer(gl, { normals: true }))
      .toThrow('penumbra: this WebGL2 context cannot draw into 3 colour attachments at once (drawBuffers did not take), which { normals: true } needs');
    expect(objects.byKind()).toEqual({});
    expect(gl.getError()).toBe(gl.NO_ERROR);
  });

  it('names the option the normal textures and surfaces need', () => {
    expect(() => without.normalTexture).toThrow('penumbra: PenumbraRenderer.normalTexture needs a renderer made with { normals: true }');
    expect(() => without.specularTexture).toThrow('penumbra: PenumbraRenderer.specularTexture needs a renderer made with { normals: true }');
    expect(() => without.drawInPlace(undefined, { normals: without.lightmapTexture }))
      .toThrow('penumbra: PenumbraRenderer.drawInPlace: surfaces needs a renderer made with { normals: true }');
    expect(() => new PenumbraRenderer(gl, { normals: 1 as unknown as boolean })).toThrow(new TypeError('PenumbraRenderer.normals must be true or false, got 1'));
  });
});
