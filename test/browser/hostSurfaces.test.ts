import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openBuiltPage, type BuiltPage } from './builtPage';
import type { MrtFrame, MultisampledFigures } from './host-surfaces-page/main';

// Host framebuffers that headless-gl cannot make (test/browser/host-surfaces-page/main.ts): each
// frame is compared with the same frame drawn into a framebuffer of one RGBA8 attachment.

/** What test/browser/host-surfaces-page/main.ts puts on `window`. */
interface HostSurfacesPageApi {
  mrtFrames(): { draw: MrtFrame; inPlace: MrtFrame; reference: { lit: number; dark: number } };
  multisampledInPlace(): MultisampledFigures;
  opaqueMultisampledInPlace(): { alphaBits: number; samples: number; thrown: string; glError: number };
  textureMisuse(): { thrown: string[]; glError: number };
}

const GL_COLOR_ATTACHMENT0 = 0x8ce0, GL_COLOR_ATTACHMENT1 = 0x8ce1;

let page: BuiltPage;

beforeAll(async () => {
  page = await openBuiltPage('host-surfaces-page', 'mrtFrames');
});

afterAll(async () => {
  await page?.close();
});

describe('host framebuffers in Chromium', () => {
  it('with two draw buffers: draw() and drawInPlace() light attachment 0 alone and leave the draw and read buffers as the host set them', async () => {
    const { draw, inPlace, reference } = await page.page.evaluate(() => (window as unknown as HostSurfacesPageApi).mrtFrames());
    // The comparison tests something: the frame has lit and shadowed pixels.
    expect(reference.lit).toBeGreaterThan(100);
    expect(reference.dark).toBeGreaterThan(100);
    for (const [call, frame] of [['draw', draw], ['drawInPlace', inPlace]] as const) {
      expect(frame, call).toEqual({
        glError: 0, attachment0Differs: 0, attachment1Differs: 0,
        drawBuffers: [GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1], readBuffer: GL_COLOR_ATTACHMENT1, drawFramebufferKept: true,
      });
    }
  });

  it('multisampled (the canvas): drawInPlace lights a viewport of the renderer\'s size at the origin, and refuses any other naming it, before anything is bound', async () => {
    const figures = await page.page.evaluate(() => (window as unknown as HostSurfacesPageApi).multisampledInPlace());
    expect(figures.samples).toBeGreaterThan(0);
    expect(figures.atOrigin).toEqual({ differs: 0, glError: 0 });
    expect(figures.refused.map((r) => r.thrown)).toEqual([
      expect.stringMatching(/PenumbraRenderer\.drawInPlace: the bound framebuffer is multisampled \(\d+ samples\).*viewport \[16, 16, 32, 32\] must be \[0, 0, 32, 32\]/),
      expect.stringMatching(/viewport \[0, 0, 64, 64\] must be \[0, 0, 32, 32\]/),
      expect.stringMatching(/viewport \[0, 0, 32, 16\] must be \[0, 0, 32, 32\]/),
    ]);
    for (const refusal of figures.refused) expect(refusal, refusal.viewport.join()).toMatchObject({ glError: 0, stateKept: true });
    expect(figures.afterwards).toEqual({ differs: 0, glError: 0 });
  });

  it('multisampled and opaque (an antialiased canvas with alpha: false): drawInPlace refuses it naming the cause, where the copy would leave it black', async () => {
    const figures = await page.page.evaluate(() => (window as unknown as HostSurfacesPageApi).opaqueMultisampledInPlace());
    expect(figures.samples).toBeGreaterThan(0);
    expect(figures.alphaBits).toBe(0);
    expect(figures.thrown).toMatch(/PenumbraRenderer\.drawInPlace: the bound framebuffer is multisampled \(\d+ samples\) and has no alpha.*\{ alpha: true \}/);
    expect(figures.glError).toBe(0);
  });

  it('TexturedLight refuses a texture that is no WebGLTexture, and the renderer one of another context, at addLight and at the next frame', async () => {
    const { thrown, glError } = await page.page.evaluate(() => (window as unknown as HostSurfacesPageApi).textureMisuse());
    expect(thrown).toEqual([
      'TypeError: TexturedLight.texture must be a WebGLTexture, got {}',
      'TypeError: TexturedLight.texture must be a WebGLTexture, got a WebGLBuffer',
      expect.stringMatching(/^TypeError: penumbra: PenumbraRenderer\.addLight: the TexturedLight's texture must be a texture of the renderer's WebGL context .*got a WebGLTexture$/),
      expect.stringMatching(/^TypeError: penumbra: PenumbraRenderer\.lights\[1\] \(TexturedLight\)\.texture must be a texture of the renderer's WebGL context/),
    ]);
    expect(glError).toBe(0);
    expect(page.pageErrors).toEqual([]);
  });
});
