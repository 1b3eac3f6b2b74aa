import { grow } from './ShadowBins';
import type { ShadowGeometry } from './ShadowGeometry';

/**
 * A hull that changed within this many frames is a moving one: filed into every light's moving list
 * each frame rather than kept in the filings (which it would end at every change). A hull that
 * starts or stops moving ends the filings it overlaps once.
 */
export const MOVING_FRAMES = 30;
/** `changedFrames` of a hull that has not changed since the layout: it stands still. */
const NEVER = -(2 ** 30);

/**
 * Which hulls move and which stand still, frame to frame (see {@link MOVING_FRAMES}): the two
 * kinds of shadow caster the shadow cache's two hull grids file, and the boxes of the hulls that started or
 * stopped moving this frame, which end the filings they overlap.
 */
export class HullMotion {
  /** The moving hulls, `movingCount` of them: those that changed within the last {@link MOVING_FRAMES} frames. */
  movingHulls = new Int32Array(64);
  movingCount = 0;
  /** Per hull: 1 when it casts shadows and stands still; and when it casts shadows and moves. */
  stillCasters = new Uint8Array(0);
  movingCasters = new Uint8Array(0);
  /**
   * Boxes (`[minX, minY, maxX, maxY]` each) of the hulls that started or stopped moving this frame,
   * `endingCount` of them: a still hull's before and after its change, where the still hulls' lists
   * may hold it; a hull that stopped, where they now should.
   */
  endingBoxes = new Float64Array(64);
  endingCount = 0;
  /** Per hull (by index in the layout): the last frame it changed, {@link NEVER} when it has not since the layout. */
  private changedFrames = new Int32Array(0);

  /** After a new layout: every hull stands still. */
  forget(geometry: ShadowGeometry, hullCount: number): void {
    if (this.changedFrames.length < hullCount) {
      const capacity = Math.ceil(hullCount * 1.5);
      this.changedFrames = new Int32Array(capacity);
      this.stillCasters = new Uint8Array(capacity);
      this.movingCasters = new Uint8Array(capacity);
    }
    this.changedFrames.fill(NEVER);
    this.stillCasters.set(geometry.castsShadow.subarray(0, hullCount));
    this.movingCasters.fill(0);
    this.movingCount = 0;
  }

  /** Sorts the hulls that changed in `frame`, and those that stood still for {@link MOVING_FRAMES} frames, between moving and still. */
  update(geometry: ShadowGeometry, frame: number): void {
    const changedFrames = this.changedFrames, castsShadow = geometry.castsShadow;
    this.endingCount = 0;
    for (let m = 0; m < this.movingCount;) {
      const index = this.movingHulls[m];
      if (frame - changedFrames[index] <= MOVING_FRAMES) {
        m++;
        continue;
      }
      this.movingHulls[m] = this.movingHulls[--this.movingCount];
      this.movingCasters[index] = 0;
      this.stillCasters[index] = castsShadow[index];
      if (castsShadow[index] !== 0) this.addEndingBox(geometry.coarseBounds, 4 * index);
    }
    for (let k = 0; k < geometry.changedCount; k++) {
      const index = geometry.changedIndices[k];
      if (frame - changedFrames[index] > MOVING_FRAMES) {
        if (this.movingCount === this.movingHulls.length) this.movingHulls = grow(this.movingHulls, this.movingCount, this.movingCount);
        this.movingHulls[this.movingCount++] = index;
        if (this.stillCasters[index] !== 0) this.addEndingBox(geometry.changedBoxes, 4 * k);
      }
      changedFrames[index] = frame;
      this.stillCasters[index] = 0;
      this.movingCasters[index] = castsShadow[index];
    }
  }

  /** Adds `boxes[at .. at + 3]` to `endingBoxes`. */
  private addEndingBox(boxes: Float64Array, at: number): void {
    const k = 4 * this.endingCount++;
    if (k === this.endingBoxes.length) this.endingBoxes = grow(this.endingBoxes, k, k);
    for (let i = 0; i < 4; i++) this.endingBoxes[k + i] = boxes[at + i];
  }
}
