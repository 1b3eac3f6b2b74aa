import { createTexture, drawCookie, lanternCookie, windowCookie } from './textures';

const FLAME_SIZE = 64;

/**
 * The light cookies textured lights can use, by name (the name is what scene files store).
 * `flame` is animated: it is redrawn every frame so the light flickers.
 */
export class Cookies {
  /** Cookie names in the order the panel lists them. */
  readonly names = ['flame', 'window', 'lantern'] as const;
  private readonly textures = new Map<string, WebGLTexture>();
  private readonly flamePixels = new Uint8Array(FLAME_SIZE * FLAME_SIZE * 4);
  private readonly flame: WebGLTexture;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.flame = createTexture(gl, drawCookie(FLAME_SIZE, () => 1), false);
    this.textures.set('flame', this.flame);
    this.textures.set('window', createTexture(gl, drawCookie(128, windowCookie), false));
    this.textures.set('lantern', createTexture(gl, drawCookie(128, lanternCookie), false));
  }

  /** The texture of a cookie name, or null when there is none (the scene loader reports it). */
  resolve = (name: string): WebGLTexture | null => this.textures.get(name) ?? null;

  /** The name of a cookie texture. */
  nameOf = (texture: WebGLTexture): string => {
    for (const [name, candidate] of this.textures) if (candidate === texture) return name;
    throw new Error('playground: a textured light uses a texture that is not one of the cookies');
  };

  /** Redraws the flame cookie for time `t` (seconds): a radial glow whose size and centre waver. */
  update(t: number): void {
    const pixels = this.flamePixels;
    const strength = 0.8 + 0.12 * Math.sin(t * 13.1) + 0.08 * Math.sin(t * 31.7 + 1.3);
    const cx = 0.5 + 0.03 * Math.sin(t * 7.3), cy = 0.5 + 0.03 * Math.cos(t * 5.9);
    for (let y = 0; y < FLAME_SIZE; y++) {
      for (let x = 0; x < FLAME_SIZE; x++) {
        const dx = (x + 0.5) / FLAME_SIZE - cx, dy = (y + 0.5) / FLAME_SIZE - cy;
        const falloff = Math.max(0, 1 - Math.sqrt(dx * dx + dy * dy) * 2);
        const value = Math.min(255, falloff * falloff * strength * 300);
        const i = (y * FLAME_SIZE + x) * 4;
        pixels[i] = pixels[i + 1] = pixels[i + 2] = value;
        pixels[i + 3] = 255;
      }
    }
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.flame);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, FLAME_SIZE, FLAME_SIZE, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    gl.generateMipmap(gl.TEXTURE_2D);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }
}
