// The lighting equation with normals (docs/normal-maps.md) on the CPU, and a host scene that writes
// a known surface: four bands of 32 pixels across a 128 × 64 view, drawn by one full-screen
// triangle whose fragment shader is the "art". Plain WebGL2 and TypeScript: used by the headless-gl
// test and the Chromium reference page alike.
import { DirectionalLight, Hull, PointLight, Spotlight, type Light } from '../../src/index';

export const SURFACE_WIDTH = 128, SURFACE_HEIGHT = 64;
export const SURFACE_AMBIENT = [0.1, 0.1, 0.1] as const;

/**
 * A band's surface: its albedo, the coverage of its normal and material, and the transform of the
 * "sprite" (image axes → world axes) its normal map is drawn with.
 */
interface Band {
  albedo: readonly [number, number, number];
  coverage: number;
  specular: number;
  shininess: number;
  emissive: number;
  /** The rotation of the sprite, its mirroring of the image's x axis, its uniform scale. */
  rotation: number;
  mirrored: boolean;
  scale: number;
}

/**
 * Band 0: no normal, no material (lit as without normals). Band 1: a mirrored sprite turned by
 * 0.9 rad, shiny. Band 2: an upright sprite at coverage 0.6 (a partly covered pixel), very shiny.
 * Band 3: a sprite turned by −2 at scale 2, emissive, not shiny.
 */
/** Albedos are multiples of 1/255 (0.2, 0.4, 0.6, 0.8), so the RGBA8 scene target stores them exactly. */
export const SURFACE_BANDS: readonly Band[] = [
  { albedo: [0.8, 0.6, 0.4], coverage: 0, specular: 0, shininess: 1, emissive: 0, rotation: 0, mirrored: false, scale: 1 },
  { albedo: [0.6, 0.4, 0.8], coverage: 1, specular: 0.7, shininess: 24, emissive: 0, rotation: 0.9, mirrored: true, scale: 1 },
  { albedo: [0.6, 0.6, 0.6], coverage: 0.6, specular: 1, shininess: 8, emissive: 0, rotation: 0, mirrored: false, scale: 1 },
  { albedo: [0.4, 0.8, 0.4], coverage: 1, specular: 0, shininess: 1, emissive: 0.4, rotation: -2, mirrored: false, scale: 2 },
];

/** The tangent-space normal map at a pixel centre (GL window coordinates): a field of slopes in every direction, OpenGL style (green up). */
function tangentNormal(fragX: number, fragY: number): [number, number, number] {
  const x = 0.6 * Math.sin(0.21 * fragX + 0.13 * fragY), y = 0.5 * Math.cos(0.17 * fragY - 0.07 * fragX);
  const length = Math.hypot(x, y, 1);
  return [x / length, y / length, 1 / length];
}

/** The world normal the host means at a pixel centre: the tangent normal turned by the band's sprite (its image y axis points down the image). */
export function worldNormal(band: Band, fragX: number, fragY: number): [number, number, number] {
  const [tx, ty, tz] = tangentNormal(fragX, fragY);
  // Image axes (x right, y down the image): green up is −y. Mirroring flips the image's x axis.
  const imageX = band.mirrored ? -tx : tx, imageY = -ty;
  const cos = Math.cos(band.rotation), sin = Math.sin(band.rotation);
  const x = cos * imageX - sin * imageY, y = sin * imageX + cos * imageY;
  const length = Math.hypot(x, y, tz);
  return [x / length, y / length, tz / length];
}

export function bandAt(fragX: number): Band {
  return SURFACE_BANDS[Math.min(SURFACE_BANDS.length - 1, Math.floor(fragX / 32))];
}

/**
 * The host's fragment shader: colour, normal and material at locations 0, 1, 2 through the
 * package's helpers (`surfaceGlsl`: SURFACE_GLSL). The same bands and field as above, in GLSL.
 */
export function surfaceHostFragment(surfaceGlsl: string): string {
  const bands = SURFACE_BANDS.map((band, i) => {
    const cos = Math.cos(band.rotation) * band.scale, sin = Math.sin(band.rotation) * band.scale, flip = band.mirrored ? -1 : 1;
    // mat2 columns: the world vectors of the image's +x (mirrored or not) and +y axes.
    return `  if (band == ${i}) {
    albedo = vec3(${band.albedo.map(f).join(', ')}); coverage = ${f(band.coverage)};
    specular = ${f(band.specular)}; shininess = ${f(band.shininess)}; emissive = ${f(band.emissive)};
    worldFromImage = mat2(${f(flip * cos)}, ${f(flip * sin)}, ${f(-sin)}, ${f(cos)});
  }`;
  }).join('\n');
  return `#version 300 es
precision highp float;
${surfaceGlsl}
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_material;
void main() {
  vec2 p = gl_FragCoord.xy;
  int band = min(${SURFACE_BANDS.length - 1}, int(p.x / 32.0));
  vec3 albedo; float coverage, specular, shininess, emissive; mat2 worldFromImage;
${bands}
  vec3 raw = vec3(0.6 * sin(0.21 * p.x + 0.13 * p.y), 0.5 * cos(0.17 * p.y - 0.07 * p.x), 1.0);
  vec3 texel = normalize(raw) * 0.5 + 0.5;
  o_color = vec4(albedo, 1.0);
  o_normal = penumbraEncodeNormal(penumbraWorldNormal(texel, worldFromImage, true), coverage);
  o_material = penumbraEncodeMaterial(specular, shininess, emissive, coverage);
}`;
}

function f(value: number): string {
  return Number.isInteger(value) ? value.toFixed(1) : String(value);
}

/** The lights of the reference, one at a time, with the hulls that shadow them (in world units, pixel space, y down). */
interface SurfaceCase {
  name: string;
  light: () => Light;
  hulls: () => Hull[];
}

const box = () => [new Hull([[70, 20], [76, 20], [76, 30], [70, 30]])];

export const SURFACE_CASES: readonly SurfaceCase[] = [
  {
    name: 'a point light at height 25, smooth falloff, shadowed by a box',
    light: () => new PointLight({ position: [50, 24], range: 110, radius: 3, height: 25, falloff: 'smooth', color: [1, 0.9, 0.7], intensity: 1.3 }),
    hulls: box,
  },
  {
    name: 'a low point light (height 6), inverse-square falloff',
    light: () => new PointLight({ position: [96, 44], range: 90, height: 6, falloff: 'inverseSquare', intensity: 2 }),
    hulls: () => [],
  },
  {
    name: 'a spotlight at its default height (a quarter of its range)',
    light: () => new Spotlight({ position: [10, 10], range: 140, rotation: 0.4, coneAngle: 1.4, color: [0.7, 0.8, 1] }),
    hulls: box,
  },
  {
    name: 'a directional light at elevation 0.5, shadowed by a box',
    light: () => new DirectionalLight({ rotation: 2.5, elevation: 0.5, angularSize: 0.05, color: [1, 0.95, 0.8] }),
    hulls: box,
  },
];

/** The unit vector from the world point (x, y) towards the light (docs/normal-maps.md). */
export function towardsLight(light: Light, x: number, y: number): [number, number, number] {
  if (light instanceof DirectionalLight) {
    const c = Math.cos(light.elevation);
    return [-Math.cos(light.rotation) * c, -Math.sin(light.rotation) * c, Math.sin(light.elevation)];
  }
  const dx = light.position[0] - x, dy = light.position[1] - y, dz = light.height;
  const length = Math.hypot(dx, dy, dz);
  return [dx / length, dy / length, dz / length];
}

/** What the light pass decodes from the stored bytes of the normal and material at a pixel. */
export interface StoredSurface {
  coverage: number;
  normal: [number, number, number];
  specular: number;
  shininess: number;
  emissive: number;
}

export function decodeSurface(normalBytes: ArrayLike<number>, materialBytes: ArrayLike<number>, offset: number): StoredSurface {
  const coverage = normalBytes[offset + 3] / 255;
  let normal: [number, number, number] = [0, 0, 1];
  if (coverage > 0) {
    const n = [0, 1, 2].map((c) => (normalBytes[offset + c] / 255 / coverage) * 2 - 1);
    const length = Math.hypot(n[0], n[1], n[2]);
    normal = [n[0] / length, n[1] / length, n[2] / length];
  }
  const materialCoverage = materialBytes[offset + 3] / 255;
  const unmultiplied = (c: number) => (materialCoverage > 0 ? materialBytes[offset + c] / 255 / materialCoverage : 0);
  return { coverage, normal, specular: unmultiplied(0), shininess: 2 ** (unmultiplied(1) * 11), emissive: unmultiplied(2) };
}

/**
 * The light's diffuse and highlight factors at a surface: multiply the light as it arrives (colour ×
 * falloff × shadow, which the lightmap without normals holds above the ambient) by them.
 */
export function surfaceFactors(surface: StoredSurface, towards: readonly [number, number, number]): { diffuse: number; highlight: number } {
  const [nx, ny, nz] = surface.normal;
  const nDotL = Math.max(0, nx * towards[0] + ny * towards[1] + nz * towards[2]);
  const diffuse = 1 + (nDotL - 1) * surface.coverage;
  if (nDotL <= 0 || surface.specular === 0) return { diffuse, highlight: 0 };
  const hx = towards[0], hy = towards[1], hz = towards[2] + 1, h = Math.hypot(hx, hy, hz);
  const nDotH = Math.max(0, (nx * hx + ny * hy + nz * hz) / h);
  return { diffuse, highlight: surface.coverage * surface.specular * nDotH ** surface.shininess };
}
