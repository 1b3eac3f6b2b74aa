import { Light, LIGHT_OPTION_KEYS, type LightOptions } from './Light';
import { assertNonNegative, describeValue, frozenVec2, type Vec2Like } from '../util/validate';

/** Options of a {@link TexturedLight}. */
export interface TexturedLightOptions extends LightOptions {
  /** The light cookie: intensity is read from its red channel. Must belong to the renderer's context. */
  texture: WebGLTexture;
  /** Size of the textured quad in world units `[width, height]`. Default `[2 × range, 2 × range]`. */
  size?: Vec2Like;
}

/** The options a textured light takes; any other key is an error. */
const TEXTURED_LIGHT_OPTION_KEYS: readonly string[] = [
  ...LIGHT_OPTION_KEYS,
  ...Object.keys({ texture: true, size: true } satisfies Record<Exclude<keyof TexturedLightOptions, keyof LightOptions>, true>),
];

/**
 * A light whose intensity at each pixel comes from a texture (a "light cookie", red channel)
 * stretched over a quad of `size`, with `origin` as its pivot at `position` and turned by
 * `rotation`. No procedural falloff: animate the texture for flicker. Shadows are cast
 * from `position` over the whole quad; `range` sets the default `size`.
 */
export class TexturedLight extends Light {
  private _texture: WebGLTexture;
  private _size: readonly [number, number] | null = null;

  constructor(options: TexturedLightOptions) {
    super(options);
    if (options?.texture === undefined) throw new TypeError('TexturedLight.texture is required');
    this._texture = checkTexture(options.texture);
    if (options.size !== undefined) this.size = options.size;
  }

  get kind(): 'textured' {
    return 'textured';
  }

  /** @internal */
  protected override get optionKeys(): readonly string[] {
    return TEXTURED_LIGHT_OPTION_KEYS;
  }

  /**
   * The light cookie texture, a WebGLTexture of the renderer's context: a value of another kind
   * throws a TypeError when set; the renderer checks the context when the light is added and when
   * the texture changes (see `PenumbraRenderer.addLight`).
   */
  get texture(): WebGLTexture {
    return this._texture;
  }
  set texture(value: WebGLTexture) {
    this._texture = checkTexture(value);
  }

  /** Size of the quad in world units, frozen; `2 × range` on each side unless a size was given. */
  get size(): readonly [number, number] {
    return this._size ?? Object.freeze([2 * this.range, 2 * this.range] as const);
  }
  set size(value: Vec2Like) {
    const size = frozenVec2('TexturedLight.size', value);
    assertNonNegative('TexturedLight.size[0]', size[0]);
    assertNonNegative('TexturedLight.size[1]', size[1]);
    this._size = size;
  }

  /**
   * The size given, or null while the quad follows `range`: a scene file saves null then, since
   * `2 × range` can overflow where `range` does not.
   * @internal
   */
  get givenSize(): readonly [number, number] | null {
    return this._size;
  }

  protected override quadWidth(): number {
    return this._size ? this._size[0] : super.quadWidth();
  }
  protected override quadHeight(): number {
    return this._size ? this._size[1] : super.quadHeight();
  }

  protected override quadPivot(): readonly [number, number] {
    return this.origin;
  }

  /** The farthest corner of the quad: the cookie has no falloff, so it may light its whole quad. */
  override reach(): number {
    const pivot = this.quadPivot();
    const x = Math.max(pivot[0], 1 - pivot[0]) * this.quadWidth();
    const y = Math.max(pivot[1], 1 - pivot[1]) * this.quadHeight();
    return Math.sqrt(x * x + y * y);
  }

  /** The cookie may light the quad's corners. */
  override isConfinedToRangeDisk(): boolean {
    return false;
  }
}

/**
 * Throws unless `value` is a WebGLTexture: an instance of the platform's class where there is one
 * (browsers), else any object (headless-gl in Node has no global class). Whether it belongs to a
 * renderer's context is for the renderer to check, when the light is added and drawn.
 */
function checkTexture(value: WebGLTexture): WebGLTexture {
  const textureClass = (globalThis as { WebGLTexture?: unknown }).WebGLTexture;
  const isTexture = typeof value === 'object' && value !== null && (typeof textureClass !== 'function' || value instanceof textureClass);
  if (!isTexture) throw new TypeError(`TexturedLight.texture must be a WebGLTexture, got ${describeTexture(value)}`);
  return value;
}

/**
 * A texture as messages show it: an object by its class (WebGL objects have no fields to list).
 * @internal
 */
export function describeTexture(value: unknown): string {
  const name = typeof value === 'object' && value !== null ? (value as { constructor?: { name?: unknown } }).constructor?.name : undefined;
  return typeof name === 'string' && name !== '' && name !== 'Object' ? `a ${name}` : describeValue(value);
}
