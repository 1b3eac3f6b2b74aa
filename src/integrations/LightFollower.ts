import type { Light } from '../index';
import { assertBoolean, assertFinite, assertOptions, frozenVec2, type Vec2Like } from '../util/validate';

/** Options of a light following a display object: where it sits on the object, and whether it turns with it. */
export interface LightFollowOptions {
  /**
   * Where the light sits in the object's local space, in the object's units before its scale:
   * moved, turned, scaled and mirrored with the object. Default `[0, 0]`: the object's own point
   * (its position: a Pixi sprite's anchor, a Phaser sprite's origin).
   */
  offset?: Vec2Like;
  /**
   * The light's direction in the object's local space, in radians (a {@link Spotlight}'s beam, a
   * `TexturedLight`'s turn), turned and mirrored with the object: a lamp on a turret. `null` leaves
   * `light.rotation` to you (a flashlight aimed at the pointer while it follows the player).
   * Default `null`.
   */
  rotation?: number | null;
}

const OPTION_KEYS: readonly string[] = ['offset', 'rotation'];

/**
 * A light that follows a display object, made by the Pixi `PenumbraLayer.follow` or the Phaser
 * `PenumbraPlugin.follow` and updated by them before each render, with no allocation while the
 * object stands still (a move allocates only the frozen pair `light.position` returns).
 *
 * While it follows, it owns `light.position` (the object's transform applied to
 * {@link LightFollower.offset}), `light.rotation` when {@link LightFollower.rotation} is a number,
 * and `light.enabled`, which it writes when the object is shown or hidden: the light shines while
 * {@link LightFollower.enabled} is true and the object is visible and on its stage or display list.
 * The light's `range` and `radius` stay in world units, whatever the object's scale; a mirror
 * turns the light's direction but does not mirror a textured light's picture.
 *
 * It ends when the object is destroyed (the light is removed from the renderer with it, as a
 * destroyed object's hulls are), when the light is removed through the layer or plugin, or on
 * `unfollow` (the light stays where it is, enabled).
 */
export class LightFollower<T extends object = object> {
  /** The display object the light follows. */
  readonly object: T;
  /** The light that follows it. */
  readonly light: Light;
  private _offset: readonly [number, number];
  private _rotation: number | null;
  private _enabled = true;
  /** The object → world transform the light was last placed with, `[a, b, c, d, tx, ty]`. */
  private readonly last = new Float64Array(6);
  /** Whether the light must be placed again whatever the transform. */
  private stale = true;
  /** Whether the light is shown: the state last written into `light.enabled`. */
  private shown = true;

  /** Made by the layer or the plugin. @internal */
  constructor(object: T, light: Light, options: LightFollowOptions, owner: string) {
    assertOptions(`penumbra: ${owner}`, options, OPTION_KEYS);
    this.object = object;
    this.light = light;
    this._offset = frozenVec2('LightFollower.offset', options.offset ?? [0, 0]);
    this._rotation = checkRotation(options.rotation ?? null);
  }

  /** See {@link LightFollowOptions.offset}; takes effect at the next render. */
  get offset(): readonly [number, number] {
    return this._offset;
  }
  set offset(value: Vec2Like) {
    this._offset = frozenVec2('LightFollower.offset', value);
    this.stale = true;
  }

  /** See {@link LightFollowOptions.rotation}; takes effect at the next render. */
  get rotation(): number | null {
    return this._rotation;
  }
  set rotation(value: number | null) {
    this._rotation = checkRotation(value);
    this.stale = true;
  }

  /** Whether the light may shine; it shines while this is true and the object is shown. Default `true`. */
  get enabled(): boolean {
    return this._enabled;
  }
  set enabled(value: boolean) {
    this._enabled = assertBoolean('LightFollower.enabled', value);
  }

  /**
   * Places the light by the object → world transform `m` (`[a, b, c, d, tx, ty]`) when it changed
   * since the last call, and shows or hides it with the object (`shown`). @internal
   */
  place(m: Float64Array, shown: boolean): void {
    const show = shown && this._enabled;
    if (show !== this.shown) {
      this.shown = show;
      this.light.enabled = show;
    }
    if (!show) return;
    const last = this.last;
    if (!this.stale && m[0] === last[0] && m[1] === last[1] && m[2] === last[2] && m[3] === last[3] && m[4] === last[4] && m[5] === last[5]) return;
    this.stale = false;
    last.set(m);
    const a = m[0], b = m[1], c = m[2], d = m[3];
    const [ox, oy] = this._offset;
    const x = a * ox + c * oy + m[4], y = b * ox + d * oy + m[5];
    const light = this.light;
    const position = light.position;
    if (position[0] !== x || position[1] !== y) light.setPosition(x, y);
    if (this._rotation === null) return;
    const dx = Math.cos(this._rotation), dy = Math.sin(this._rotation);
    const ux = a * dx + c * dy, uy = b * dx + d * dy;
    // A transform that squashes the direction to nothing (a zero scale) leaves the last direction.
    if (ux === 0 && uy === 0) return;
    const rotation = Math.atan2(uy, ux);
    if (light.rotation !== rotation) light.rotation = rotation;
  }

  /** Hands `light.enabled` back as it was given: on, if this follower had switched it off. @internal */
  release(): void {
    if (!this.shown) this.light.enabled = true;
    this.shown = true;
  }
}

function checkRotation(value: number | null): number | null {
  return value === null ? null : assertFinite('LightFollower.rotation', value);
}

/** What an engine gives a {@link LightFollowers}: its objects' destruction, and removing a light. */
interface FollowedObjects<T> {
  /** Calls `destroyed(object)` once `object` is destroyed, until {@link FollowedObjects.ignore}. */
  listen(object: T, destroyed: (object: T) => void): void;
  ignore(object: T, destroyed: (object: T) => void): void;
  removeLight(light: Light): void;
}

/**
 * The lights following display objects of one layer or plugin, in the order they started: one
 * follower per light, the engine listening to each followed object's destruction while a follower
 * needs it (the object's lights are then removed). @internal
 */
export class LightFollowers<T extends object> {
  readonly list: LightFollower<T>[] = [];

  constructor(private readonly engine: FollowedObjects<T>) {}

  /** Adds `follower`, ending the one its light had. */
  add(follower: LightFollower<T>): void {
    this.drop(follower.light, true);
    if (!this.list.some((other) => other.object === follower.object)) this.engine.listen(follower.object, this.destroyed);
    this.list.push(follower);
  }

  /** Ends every follower `target` names (the follower itself, its light or its object); whether there was one. */
  unfollow(target: object): boolean {
    let stopped = false;
    for (let i = this.list.length - 1; i >= 0; i--) {
      const follower = this.list[i];
      if (follower !== target && follower.light !== target && follower.object !== target) continue;
      this.stop(i);
      stopped = true;
    }
    return stopped;
  }

  /** Ends the follower of `light`, if any; `keep` leaves the light in the renderer. */
  drop(light: Light, keep: boolean): void {
    const i = this.list.findIndex((follower) => follower.light === light);
    if (i < 0) return;
    this.stop(i);
    if (!keep) this.engine.removeLight(light);
  }

  /** Ends every follower, the lights left where they are. */
  clear(): void {
    for (let i = this.list.length - 1; i >= 0; i--) this.stop(i);
  }

  /** Ends follower `i`: stops listening to its object once no other follower needs it, and hands the light back. */
  private stop(i: number): LightFollower<T> {
    const [follower] = this.list.splice(i, 1);
    if (!this.list.some((other) => other.object === follower.object)) this.engine.ignore(follower.object, this.destroyed);
    follower.release();
    return follower;
  }

  /** A followed object was destroyed: its lights go with it. */
  private readonly destroyed = (object: T): void => {
    for (let i = this.list.length - 1; i >= 0; i--) {
      if (this.list[i].object === object) this.engine.removeLight(this.stop(i).light);
    }
  };
}
