/**
 * The surface the host writes beside its colour when the renderer has normals (docs/normal-maps.md):
 * the scene target's attachments, the material encoding, and the texture units the light and
 * composite passes read them on. The shaders get the encoding's constant as a define
 * ({@link SURFACE_DEFINES}), in the light passes, the composite and the hosts' helper chunk.
 */

/** The scene target's colour attachments with normals: the locations the host's fragment shader writes. */
export const SceneAttachments = { color: 0, normal: 1, material: 2 } as const;

/** The lightmap's attachments with normals: the diffuse light (with the ambient) and the highlights. */
export const LightmapAttachments = { diffuse: 0, specular: 1 } as const;

/** The material stores log2(shininess) / SHININESS_LOG2_MAX: shininess 1..2^11 in 8 bits, at 4.4 % a step. */
const SHININESS_LOG2_MAX = 11;

/** The encoding's constants as `#define`s. */
export const SURFACE_DEFINES: Readonly<Record<string, string>> = {
  PENUMBRA_SHININESS_LOG2_MAX: SHININESS_LOG2_MAX.toFixed(1),
};

/**
 * The material channel that holds a Blinn-Phong exponent: `log2(shininess) / 11`, for hosts that
 * write the material from JavaScript (a uniform or a vertex attribute); the GLSL helper
 * `penumbraEncodeMaterial` does the same.
 * @param shininess - the exponent, clamped to 1..2048.
 * @returns the channel value, 0..1.
 */
export function encodeShininess(shininess: number): number {
  return Math.log2(Math.min(Math.max(shininess, 1), 2 ** SHININESS_LOG2_MAX)) / SHININESS_LOG2_MAX;
}

/**
 * The normal and material textures of a host that draws into its own targets (see
 * {@link PenumbraRenderer.drawInPlace}), for a renderer made with `normals: true`. Both have the
 * renderer's size and hold the encodings of docs/normal-maps.md for the region lit.
 */
export interface SurfaceTextures {
  /** World-axes normals premultiplied by coverage (location 1 of the scene target). */
  normals: WebGLTexture;
  /** Specular, shininess code and emissive premultiplied by coverage (location 2). Default: none (no highlights, no emission). */
  material?: WebGLTexture | null;
  /** Whether the textures' row 0 is the top of the image (render textures of PixiJS). Default `false`. */
  flipY?: boolean;
}
