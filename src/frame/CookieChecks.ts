import type { Light } from '../scene/Light';
import { describeTexture, TexturedLight } from '../scene/TexturedLight';

/**
 * Checks that each textured light's cookie is a texture of the renderer's context. A cookie found
 * to be one is remembered per light and checked again only when it changes: `gl.isTexture` is a
 * round trip to the GPU process in browsers. Forgotten when the context is restored.
 */
export class CookieChecks {
  private checked = new WeakMap<TexturedLight, WebGLTexture>();

  constructor(private readonly gl: WebGL2RenderingContext) {}

  /** Per frame: throws naming the first textured light whose cookie is not a texture of this context. */
  checkAll(lights: readonly Light[]): void {
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      if (light instanceof TexturedLight && this.checked.get(light) !== light.texture) this.check(light, `PenumbraRenderer.lights[${i}] (TexturedLight).texture`);
    }
  }

  /** Throws naming `name` unless the light's cookie is a texture of this context. */
  check(light: TexturedLight, name: string): void {
    const texture = light.texture;
    if (!isTextureOf(this.gl, texture)) {
      throw new TypeError(`penumbra: ${name} must be a texture of the renderer's WebGL context (not another context's, a deleted one, ` +
        `one never bound, or one from before a context loss), got ${describeTexture(texture)}`);
    }
    this.checked.set(light, texture);
  }

  /** Forgets every check, for a restored context. */
  forget(): void {
    this.checked = new WeakMap();
  }

  /** Warns naming each textured light whose cookie is not a texture of the restored context. */
  warnOfOld(lights: readonly Light[]): void {
    lights.forEach((light, index) => {
      if (light instanceof TexturedLight && !this.gl.isTexture(light.texture)) {
        console.warn(`penumbra: lights[${index}] (TexturedLight) still has its cookie texture from before the context loss; give it a new one in PenumbraRenderer.onContextRestored`);
      }
    });
  }
}

/** Whether `texture` is a live texture of `gl` (`isTexture` throws for an object that is no WebGLTexture). */
function isTextureOf(gl: WebGL2RenderingContext, texture: WebGLTexture): boolean {
  try {
    return gl.isTexture(texture);
  } catch {
    return false;
  }
}
