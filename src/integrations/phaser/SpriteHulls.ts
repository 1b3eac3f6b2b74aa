import Phaser from 'phaser';
import { Hull, type AlphaImage } from '../../index';
import { forgetFrameOutlines, frameOutlines, traceImage, type Outline } from './frameOutlines';
import { describe, readPlacement, type HullTarget, type Placement } from './shared';

/** A game object drawn from a texture frame: a `Sprite` or an `Image` (physics ones too). */
export type FrameObject = Phaser.GameObjects.Sprite | Phaser.GameObjects.Image;

/**
 * Options of {@link SpriteHulls} and {@link PenumbraPlugin.addSprite}: how the frame's alpha is
 * traced, as for the core's `hullsFromAlpha` (same meanings, same defaults).
 */
export interface SpriteHullsOptions {
  /** A pixel is solid when its alpha is ≥ this (0–255). Default `128`. */
  threshold?: number;
  /** Largest distance in pixels between a hull's outline and the traced outline. Default `1`. */
  tolerance?: number;
  /** Most points per hull, an integer ≥ 3 or `Infinity`. Default `64`. */
  maxPoints?: number;
  /** Islands of fewer solid pixels than this are dropped. Default `0`. */
  minArea?: number;
  /**
   * Pixels to trace instead of the frame's, covering the frame's cut (its rectangle in the
   * texture; a larger or smaller image is stretched over it): for a frame whose pixels cannot be
   * read back (a `DynamicTexture`, a cross-origin image), or a simpler shadow shape. The same
   * image is used whatever frame the sprite shows. Default: the frame's own pixels.
   */
  image?: AlphaImage;
}

/**
 * Hulls traced from a sprite's texture frame alpha that follow the sprite: its position,
 * rotation, scale, origin, flipX and flipY, a Container's transform, the frame it shows (an
 * animation swaps the hulls), and its visibility (an invisible sprite, or one on no display list,
 * casts no shadow). Usually made with {@link PenumbraPlugin.addSprite}:
 *
 * ```ts
 * const crate = this.add.sprite(300, 200, 'atlas', 'crate');
 * this.penumbra.addSprite(crate, { tolerance: 1.5 });
 * crate.setRotation(0.3).setFlipX(true); // the shadow turns and flips with it
 * ```
 *
 * A frame's pixels (its cut from the source image, turned upright if the atlas stored it rotated;
 * a trimmed frame keeps its offset) are read and traced once per frame and trace options, then
 * shared by every sprite showing that frame. Before each render the sprite's transform is
 * compared with the hulls' and copied only when it changed; a still sprite costs a few reads.
 * Not followed: a sprite's own crop (`setCrop`: the whole frame casts) and a scroll factor other than 1.
 *
 * The hulls go when the sprite is destroyed, when its scene shuts down, or on {@link SpriteHulls.destroy}.
 */
export class SpriteHulls {
  /** The sprite whose shadow the hulls cast. */
  readonly sprite: FrameObject;
  private readonly target: HullTarget;
  private readonly trace: SpriteHullsOptions;
  private readonly image: AlphaImage | null;
  private readonly imageOutlines: readonly Outline[] | null;
  private readonly events: Phaser.Events.EventEmitter;
  private readonly placement: Placement = { x: 0, y: 0, rotation: 0, scaleX: 1, scaleY: 1 };
  private hullList: readonly Hull[] = [];
  private frame: Phaser.Textures.Frame | null = null;
  // The transform the hulls have now; NaN: not set yet.
  private x = NaN;
  private y = NaN;
  private rotation = NaN;
  private scaleX = NaN;
  private scaleY = NaN;
  private originX = NaN;
  private originY = NaN;
  private enabled = true;
  private destroyed = false;
  /** Called once when destroyed (the plugin forgets it). @internal */
  onDestroy: (() => void) | null = null;

  /**
   * Traces the sprite's frame (or `options.image`), adds the hulls to `target` and follows the sprite.
   * @throws TypeError for something that is not a sprite or image, a frame whose pixels cannot be
   * read, or an option of the wrong type; RangeError for an option out of range (from `hullsFromAlpha`).
   */
  constructor(sprite: FrameObject, target: HullTarget, options: SpriteHullsOptions = {}) {
    if (!(sprite as Partial<FrameObject> | null)?.frame?.source) throw new TypeError(`penumbra: SpriteHulls needs a Phaser Sprite or Image, got ${describe(sprite)}`);
    if (typeof target?.addHull !== 'function' || typeof target.removeHull !== 'function') {
      throw new TypeError(`penumbra: SpriteHulls target must have addHull and removeHull (the plugin or a PenumbraRenderer), got ${describe(target)}`);
    }
    if (typeof options !== 'object' || options === null) throw new TypeError(`penumbra: SpriteHulls options must be an object, got ${describe(options)}`);
    const { threshold, tolerance, maxPoints, minArea, image } = options;
    this.sprite = sprite;
    this.target = target;
    this.trace = { threshold, tolerance, maxPoints, minArea };
    this.image = image ?? null;
    this.imageOutlines = image === undefined ? null : traceImage(image, this.trace);
    this.showFrame(sprite.frame);

    this.events = sprite.scene.sys.events;
    sprite.once(Phaser.GameObjects.Events.DESTROY, this.destroy, this);
    this.events.on(Phaser.Scenes.Events.PRE_RENDER, this.update, this);
    this.events.once(Phaser.Scenes.Events.SHUTDOWN, this.destroy, this);
  }

  /** The current hulls (new ones when the sprite shows another frame). */
  get hulls(): readonly Hull[] {
    return this.hullList;
  }

  /** Whether {@link SpriteHulls.destroy} ran (or the sprite or scene went). */
  get isDestroyed(): boolean {
    return this.destroyed;
  }

  /**
   * Brings the hulls in step with the sprite: its frame, transform and visibility. Runs before
   * every render of the sprite's scene; call it yourself only to read the hulls right after a change.
   */
  update(): void {
    if (this.destroyed) return;
    const sprite = this.sprite;
    if (sprite.frame !== this.frame) this.showFrame(sprite.frame);
    this.follow();
  }

  /**
   * Reads and traces the frame's pixels again (after its canvas was redrawn, say), for every
   * sprite that shows the frame from now on, and rebuilds this sprite's hulls.
   */
  retrace(): void {
    if (this.destroyed) return;
    if (!this.image && this.frame) forgetFrameOutlines(this.frame);
    this.showFrame(this.sprite.frame);
  }

  /** Removes the hulls from the target and stops following the sprite; safe to call twice. */
  destroy(): void {
    if (this.destroyed) return;
    this.destroyed = true;
    this.sprite.off(Phaser.GameObjects.Events.DESTROY, this.destroy, this);
    this.events.off(Phaser.Scenes.Events.PRE_RENDER, this.update, this);
    this.events.off(Phaser.Scenes.Events.SHUTDOWN, this.destroy, this);
    for (const hull of this.hullList) this.target.removeHull(hull);
    this.hullList = [];
    this.onDestroy?.();
    this.onDestroy = null;
  }

  /** Replaces the hulls with those of `frame` and places them. */
  private showFrame(frame: Phaser.Textures.Frame): void {
    const outlines = this.imageOutlines ?? frameOutlines(frame, this.trace);
    for (const hull of this.hullList) this.target.removeHull(hull);
    this.frame = frame;
    this.hullList = Object.freeze(outlines.map((points) => new Hull(points)));
    this.x = this.y = this.rotation = this.scaleX = this.scaleY = this.originX = this.originY = NaN;
    this.enabled = true;
    this.follow();
    for (const hull of this.hullList) this.target.addHull(hull);
  }

  /**
   * Copies the sprite's transform to the hulls where it changed. Phaser draws the frame's cut
   * (`cutWidth × cutHeight` pixels of the texture, `1 / resolution` units each) at
   * `frame.x − displayOrigin` in the sprite's space, mirrored within the untrimmed frame when
   * flipped, then applies `T(x, y) · R(rotation) · S(scale × flip)`; a hull's own transform is
   * `position + R(rotation) · ((point − origin) × scale)`, so with `k` units per traced pixel
   * its origin is `−offset / k` and its scale `scale × flip × k`.
   */
  private follow(): void {
    const sprite = this.sprite, frame = this.frame!;
    const p = readPlacement(sprite, true, this.placement);
    const resolution = frame.source.resolution || 1;
    const traceWidth = this.image ? this.image.width : frame.cutWidth;
    const traceHeight = this.image ? this.image.height : frame.cutHeight;
    const kx = traceWidth > 0 ? frame.cutWidth / (resolution * traceWidth) : 1;
    const ky = traceHeight > 0 ? frame.cutHeight / (resolution * traceHeight) : 1;
    const ox = sprite.displayOriginX, oy = sprite.displayOriginY;
    let offsetX = frame.x - ox, offsetY = frame.y - oy;
    if (sprite.flipX && !frame.customPivot) offsetX += 2 * ox - frame.realWidth;
    if (sprite.flipY && !frame.customPivot) offsetY += 2 * oy - frame.realHeight;
    const originX = -offsetX / kx, originY = -offsetY / ky;
    const scaleX = p.scaleX * (sprite.flipX ? -kx : kx), scaleY = p.scaleY * (sprite.flipY ? -ky : ky);
    const enabled = sprite.visible && (sprite.displayList != null || sprite.parentContainer != null);

    const hulls = this.hullList;
    if (p.x !== this.x || p.y !== this.y) {
      this.x = p.x;
      this.y = p.y;
      for (const hull of hulls) hull.setPosition(p.x, p.y);
    }
    if (p.rotation !== this.rotation) {
      this.rotation = p.rotation;
      for (const hull of hulls) hull.rotation = p.rotation;
    }
    if (scaleX !== this.scaleX || scaleY !== this.scaleY) {
      this.scaleX = scaleX;
      this.scaleY = scaleY;
      for (const hull of hulls) hull.scale = [scaleX, scaleY];
    }
    if (originX !== this.originX || originY !== this.originY) {
      this.originX = originX;
      this.originY = originY;
      for (const hull of hulls) hull.origin = [originX, originY];
    }
    if (enabled !== this.enabled) {
      this.enabled = enabled;
      for (const hull of hulls) hull.enabled = enabled;
    }
  }
}
