import { CURRENT, type BenchHull, type BenchLight, type BenchRendererOptions } from '../library';

/** The weight of a pixel in the statistics build's program channels (light-common's PROGRAM). */
const PROGRAM_WEIGHT = 1024;

/** Frames the statistics renderer draws at most until every light is classified. */
const MAX_CLASSIFYING_FRAMES = 32;

function unclassified(renderer: { stats: object }): number {
  return (renderer.stats as { lightsUnclassified?: number }).lightsUnclassified ?? 0;
}

/** Per light pixel (every pixel a light adds to), what the shadow loop did in one frame. */
interface ShadowStatistics {
  /** Light pixels shaded (a light's fragments where its falloff is above 0, shadowed or not). */
  pixels: number;
  /** Records (convex pieces of hulls) the first pass over the pixel's bin visited, in all. */
  visits: number;
  /** Light pixels that visited none: lights with no hull in range, and pixels nearer than every hull in their bin. */
  decidedWithoutLoop: number;
  /** Light pixels the quadrature takes (records seen past that the closed form does not cover). */
  swept: number;
  /** Light pixels drawn by the held, the lean and the general shadow program (the others: a plain light program). */
  held: number;
  lean: number;
  general: number;
}

/**
 * Renders one frame of the working tree's renderer with the light pass's statistics build: on a
 * `Proxy` of the context, each light fragment stage gets `#define SHADOW_STATISTICS` (the chunk
 * light-common then writes 1, the records visited, whether none was and whether the quadrature
 * took the pixel, instead of light) and the
 * lightmap becomes RGBA32F (half floats would round the sums). Reads the lightmap back and sums it.
 * Needs EXT_color_buffer_float and EXT_float_blend.
 */
export function measureShadowStatistics(gl: WebGL2RenderingContext, options: BenchRendererOptions, lights: readonly BenchLight[], hulls: readonly BenchHull[]): ShadowStatistics {
  if (!gl.getExtension('EXT_float_blend') || !gl.getExtension('EXT_color_buffer_float')) throw new Error('bench statistics: need EXT_float_blend and EXT_color_buffer_float');
  let lightStages = 0;
  const renderer = new CURRENT.PenumbraRenderer(statisticsContext(gl, () => lightStages++), { ...options, ambientColor: [0, 0, 0], lightmapScale: 1 });
  try {
    // A kind of light's stages are compiled when its first light is added.
    for (const light of lights) renderer.addLight(light);
    if (lightStages === 0) throw new Error('bench statistics: no light stage was compiled with SHADOW_STATISTICS');
    for (const hull of hulls) renderer.addHull(hull);
    // As the measured renderer has them after its first frames: every light classified (a new
    // renderer classifies as many records a frame as its budget allows, the rest drawn exact).
    renderer.renderLightmap();
    for (let frame = 1; frame < MAX_CLASSIFYING_FRAMES && unclassified(renderer) > 0; frame++) renderer.renderLightmap();
    return sumLightmap(gl, (renderer as unknown as { lightmapTexture: WebGLTexture }).lightmapTexture);
  } finally {
    renderer.dispose();
  }
}

/** `gl` with light stages built for statistics and RGBA16F textures allocated as RGBA32F. */
function statisticsContext(gl: WebGL2RenderingContext, onLightStage: () => void): WebGL2RenderingContext {
  const methods = new Map<PropertyKey, unknown>();
  const shaderSource = (shader: WebGLShader, source: string) => {
    const isLightStage = source.includes('void writeLight(');
    if (isLightStage) onLightStage();
    gl.shaderSource(shader, isLightStage ? source.replace('\n', '\n#define SHADOW_STATISTICS\n') : source);
  };
  const texImage2D = (...args: unknown[]) => {
    if (args[2] === gl.RGBA16F) {
      args[2] = gl.RGBA32F;
      args[7] = gl.FLOAT;
    }
    (gl.texImage2D as (...a: unknown[]) => void)(...args);
  };
  return new Proxy(gl, {
    get(target, key) {
      if (key === 'shaderSource') return shaderSource;
      if (key === 'texImage2D') return texImage2D;
      const value: unknown = Reflect.get(target, key);
      if (typeof value !== 'function') return value;
      if (!methods.has(key)) methods.set(key, value.bind(target));
      return methods.get(key);
    },
  });
}

function sumLightmap(gl: WebGL2RenderingContext, texture: WebGLTexture): ShadowStatistics {
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
  const texels = new Float32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, texels);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.deleteFramebuffer(framebuffer);
  // The lightmap is cleared to alpha 1: every texel starts with one that no light wrote.
  const sums: ShadowStatistics = { pixels: 0, visits: 0, decidedWithoutLoop: 0, swept: -width * height, held: 0, lean: 0, general: 0 };
  for (let i = 0; i < texels.length; i += 4) {
    // Each program channel holds PROGRAM_WEIGHT per pixel of its program above a count below it
    // (light-common's statistics build).
    sums.pixels += texels[i] % PROGRAM_WEIGHT;
    sums.held += Math.floor(texels[i] / PROGRAM_WEIGHT);
    sums.visits += texels[i + 1];
    sums.decidedWithoutLoop += texels[i + 2] % PROGRAM_WEIGHT;
    sums.lean += Math.floor(texels[i + 2] / PROGRAM_WEIGHT);
    sums.swept += texels[i + 3] % PROGRAM_WEIGHT;
    sums.general += Math.floor(texels[i + 3] / PROGRAM_WEIGHT);
  }
  return sums;
}
