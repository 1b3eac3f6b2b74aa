import type { RenderTarget } from '../gl/RenderTarget';
import type { Surface } from '../passes/LightPass';
import { SceneAttachments, type SurfaceTextures } from '../passes/surfaceLayout';
import { assertBoolean, describeValue } from '../util/validate';

/**
 * Throws naming the method and field when `surfaces` (the host's, given to `drawInPlace` or
 * `renderLightmap`) is given to a renderer without normals or is malformed. Per frame: the messages
 * are built only on failure.
 */
export function checkSurfaces(method: string, normals: boolean, surfaces: SurfaceTextures | undefined): void {
  if (surfaces === undefined) return;
  if (normals && isObject(surfaces) && isObject(surfaces.normals) && (surfaces.material == null || isObject(surfaces.material))
    && (surfaces.flipY === undefined || typeof surfaces.flipY === 'boolean')) return;
  const name = `PenumbraRenderer.${method}: surfaces`;
  if (!normals) throw new Error(`penumbra: ${name} needs a renderer made with { normals: true }`);
  if (!isObject(surfaces)) throw new TypeError(`${name} must be an object, got ${describeValue(surfaces)}`);
  if (!isObject(surfaces.normals)) throw new TypeError(`${name}.normals must be a WebGLTexture, got ${describeValue(surfaces.normals)}`);
  if (surfaces.material != null && !isObject(surfaces.material)) {
    throw new TypeError(`${name}.material must be a WebGLTexture, got ${describeValue(surfaces.material)}`);
  }
  assertBoolean(`${name}.flipY`, surfaces.flipY as boolean);
}

/** Points `surface` at the host's textures of this call (`external`), or at those of the scene target. */
export function chooseSurface(surface: Surface, scene: RenderTarget, external: SurfaceTextures | null): void {
  const textures = scene.textures;
  surface.normals = external?.normals ?? textures[SceneAttachments.normal];
  // Without a material of the host's: the scene target's, which drawInPlace's beginDraw cleared.
  surface.material = external?.material ?? textures[SceneAttachments.material];
  surface.flipY = external?.flipY ?? false;
}

/** Whether `value` is a non-null object (a WebGL texture is an opaque one). */
function isObject(value: unknown): value is object {
  return typeof value === 'object' && value !== null;
}
