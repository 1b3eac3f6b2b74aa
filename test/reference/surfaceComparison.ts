// Normal-mapped lighting (docs/normal-maps.md) compared with the CPU version of its equation
// (test/reference/surfaceReference.ts), on a WebGL2 context that can draw into several colour
// attachments (Chromium: headless-gl 9.0.0-rc.10 cannot). Runs where the context is (the reference
// page) and hands back figures only.
//
// The reference takes the light as it arrives (colour × falloff × shadow) from a renderer without
// normals, whose shadows the reference tests hold to the disk-sampling reference, and the normal
// and material as the scene target stored them (8 bits a channel), so what is compared is the
// light pass's and the composite's arithmetic.
import { createProgram } from '../../src/gl/program';
import { Hull, PenumbraRenderer, PointLight, SURFACE_GLSL, type Light } from '../../src/index';
import { readTexture } from '../gl/readTexture';
import {
  SURFACE_AMBIENT, SURFACE_BANDS, SURFACE_CASES, SURFACE_HEIGHT as HEIGHT, SURFACE_WIDTH as WIDTH, bandAt, decodeSurface,
  surfaceFactors, surfaceHostFragment, towardsLight, worldNormal, type StoredSurface,
} from './surfaceReference';

/** What {@link compareSurfaceLighting} measured. Errors of float targets in units of light, of the output in 8-bit steps. */
export interface SurfaceFigures {
  /** Largest difference of a stored normal byte from the world normal the host meant, in 8-bit steps. */
  normalStorage: number;
  cases: { name: string; diffuse: number; highlight: number; darkenedPixels: number; highlightPixels: number }[];
  /** Largest difference of the output from albedo × (lightmap + emissive) + highlights, in 8-bit steps. */
  composite: number;
  /** Largest difference of an emissive pixel with no light from albedo × (ambient + emissive), in 8-bit steps. */
  emissiveUnlit: number;
  /** Output bytes of the band without normals that differ from a renderer without normals'. */
  bandWithoutNormalDiffers: number;
  /** Output bytes of a colour-only frame that differ from a renderer without normals'. */
  colorOnlyDiffers: number;
  glError: number;
}

const FULL_SCREEN_VERTEX = `#version 300 es
void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}`;

/** The host of the band scene: `draw` writes colour, normal and material of every pixel into the bound target. */
export function createSurfaceHost(gl: WebGL2RenderingContext): { draw(): void; dispose(): void } {
  const program = createProgram(gl, 'surface host', FULL_SCREEN_VERTEX, surfaceHostFragment(SURFACE_GLSL)).handle;
  const vertexArray = gl.createVertexArray();
  return {
    draw() {
      gl.useProgram(program);
      gl.bindVertexArray(vertexArray);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    },
    dispose() {
      gl.deleteProgram(program);
      gl.deleteVertexArray(vertexArray);
    },
  };
}

/** Renders the band scene under every case on `gl` (WIDTH × HEIGHT) and measures it against the reference. */
export function compareSurfaceLighting(gl: WebGL2RenderingContext): SurfaceFigures {
  const withNormals = new PenumbraRenderer(gl, { ambientColor: SURFACE_AMBIENT, normals: true });
  const without = new PenumbraRenderer(gl, { ambientColor: SURFACE_AMBIENT });
  const host = createSurfaceHost(gl);
  const drawSurfaceScene = () => host.draw();

  /** A frame of `renderer` lit by `lights` and shadowed by `hulls`; the output bytes, rows bottom-up. */
  const frame = (renderer: PenumbraRenderer, lights: readonly Light[], hulls: readonly Hull[], drawHost = drawSurfaceScene): Uint8Array => {
    for (const light of [...renderer.lights]) renderer.removeLight(light);
    for (const hull of [...renderer.hulls]) renderer.removeHull(hull);
    for (const light of lights) renderer.addLight(light);
    for (const hull of hulls) renderer.addHull(hull);
    renderer.beginDraw();
    drawHost();
    renderer.draw();
    return readBytes(gl, null);
  };
  const storedSurfaces = (): StoredSurface[] => {
    const normals = readBytes(gl, withNormals.normalTexture), material = readBytes(gl, withNormals.materialTexture);
    return Array.from({ length: WIDTH * HEIGHT }, (_, p) => decodeSurface(normals, material, p * 4));
  };

  frame(withNormals, [], []);
  const normalStorage = normalStorageError(readBytes(gl, withNormals.normalTexture));

  const cases = SURFACE_CASES.map((scene) => {
    const light = scene.light();
    frame(without, [light], scene.hulls());
    const arriving = readTexture(gl, without.lightmapTexture, WIDTH, HEIGHT);
    frame(withNormals, [light], scene.hulls());
    const diffuse = readTexture(gl, withNormals.lightmapTexture, WIDTH, HEIGHT);
    const highlights = readTexture(gl, withNormals.specularTexture, WIDTH, HEIGHT);
    const surfaces = storedSurfaces();
    const figures = { name: scene.name, diffuse: 0, highlight: 0, darkenedPixels: 0, highlightPixels: 0 };
    for (let p = 0; p < WIDTH * HEIGHT; p++) {
      const [x, y] = worldOf(p);
      const factors = surfaceFactors(surfaces[p], towardsLight(light, x, y));
      if (factors.highlight > 0.05) figures.highlightPixels++;
      if (factors.diffuse < 0.5) figures.darkenedPixels++;
      for (let c = 0; c < 3; c++) {
        const arrived = arriving[p * 4 + c] - SURFACE_AMBIENT[c];
        figures.diffuse = Math.max(figures.diffuse, Math.abs(diffuse[p * 4 + c] - (SURFACE_AMBIENT[c] + arrived * factors.diffuse)));
        figures.highlight = Math.max(figures.highlight, Math.abs(highlights[p * 4 + c] - arrived * factors.highlight));
      }
    }
    return figures;
  });

  const first = SURFACE_CASES[0];
  const lit = frame(withNormals, [first.light()], first.hulls());
  const composite = compositeError(lit, readTexture(gl, withNormals.lightmapTexture, WIDTH, HEIGHT),
    readTexture(gl, withNormals.specularTexture, WIDTH, HEIGHT), storedSurfaces());
  const plain = frame(without, [first.light()], first.hulls());
  const bandWithout = SURFACE_BANDS.findIndex((band) => band.coverage === 0);
  let bandWithoutNormalDiffers = 0;
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    if (Math.floor((p % WIDTH) / 32) !== bandWithout) continue;
    for (let c = 0; c < 4; c++) if (lit[p * 4 + c] !== plain[p * 4 + c]) bandWithoutNormalDiffers++;
  }

  const emissiveUnlit = emissiveError(frame(withNormals, [], []));

  // Colour only: the normal and material stay as beginDraw cleared them.
  const drawFlat = () => gl.clearBufferfv(gl.COLOR, 0, [0.7, 0.5, 0.3, 1]);
  const lights = [new PointLight({ position: [40, 30], range: 90, radius: 4 }), new PointLight({ position: [100, 20], range: 60, height: 2, falloff: 'smooth' })];
  const hulls = [new Hull([[60, 20], [66, 20], [66, 44], [60, 44]])];
  const flatWith = frame(withNormals, lights, hulls, drawFlat), flatWithout = frame(without, lights, hulls, drawFlat);
  let colorOnlyDiffers = 0;
  for (let i = 0; i < flatWith.length; i++) if (flatWith[i] !== flatWithout[i]) colorOnlyDiffers++;

  const glError = gl.getError();
  withNormals.dispose();
  without.dispose();
  host.dispose();
  return { normalStorage, cases, composite, emissiveUnlit, bandWithoutNormalDiffers, colorOnlyDiffers, glError };
}

/** Reads an RGBA8 texture of the view's size (or the bound framebuffer, for null), rows bottom-up. */
function readBytes(gl: WebGL2RenderingContext, texture: WebGLTexture | null): Uint8Array {
  const framebuffer = texture ? gl.createFramebuffer() : null;
  if (texture) {
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  }
  const bytes = new Uint8Array(WIDTH * HEIGHT * 4);
  gl.readPixels(0, 0, WIDTH, HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
  if (texture) {
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(framebuffer);
  }
  return bytes;
}

/** The world position of the centre of the pixel p (rows from the bottom): pixel space, y down. */
function worldOf(p: number): [number, number] {
  return [(p % WIDTH) + 0.5, HEIGHT - Math.floor(p / WIDTH) - 0.5];
}

function normalStorageError(normals: Uint8Array): number {
  let largest = 0;
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    const fragX = (p % WIDTH) + 0.5, fragY = Math.floor(p / WIDTH) + 0.5;
    const band = bandAt(fragX);
    const n = worldNormal(band, fragX, fragY);
    for (let c = 0; c < 3; c++) largest = Math.max(largest, Math.abs(normals[p * 4 + c] - (n[c] * 0.5 + 0.5) * band.coverage * 255));
    largest = Math.max(largest, Math.abs(normals[p * 4 + 3] - band.coverage * 255));
  }
  return largest;
}

function compositeError(output: Uint8Array, diffuse: Float32Array, highlights: Float32Array, surfaces: StoredSurface[]): number {
  let largest = 0;
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    const band = bandAt((p % WIDTH) + 0.5);
    for (let c = 0; c < 3; c++) {
      const exact = band.albedo[c] * (diffuse[p * 4 + c] + surfaces[p].emissive) + highlights[p * 4 + c];
      largest = Math.max(largest, Math.abs(output[p * 4 + c] - Math.min(1, exact) * 255));
    }
  }
  return largest;
}

function emissiveError(output: Uint8Array): number {
  let largest = 0;
  for (let p = 0; p < WIDTH * HEIGHT; p++) {
    const band = bandAt((p % WIDTH) + 0.5);
    if (band.emissive === 0) continue;
    for (let c = 0; c < 3; c++) largest = Math.max(largest, Math.abs(output[p * 4 + c] - band.albedo[c] * (SURFACE_AMBIENT[c] + band.emissive) * 255));
  }
  return largest;
}
