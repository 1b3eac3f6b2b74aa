import { mat4 } from 'gl-matrix';
import type { PenumbraRenderer, SurfaceTextures } from '../index';
import { setViewProjection, type Affine2D } from './viewProjection';

/** The bound framebuffer's viewport as an engine sees it: its size in pixels and in engine units. */
export interface InPlaceView {
  /** Size of the viewport in pixels: the renderer is sized to it, as `drawInPlace` requires. */
  pixelWidth: number;
  pixelHeight: number;
  /** Size of the viewport in the engine's units (pixels over the engine's resolution). */
  width: number;
  height: number;
  /** Whether the engine draws into this target upside down (its top in GL's row 0): Pixi's render textures. */
  flipY: boolean;
}

/**
 * What the engine lighting layers and lit groups do to light what the engine drew: the bound
 * framebuffer's viewport lit in place by one renderer, looking through the engine's camera. One per
 * renderer: it remembers the size it last gave it, so that a frame of the same size resizes nothing.
 * The layer of an engine and its groups share one, since they share the renderer.
 */
export class InPlaceLighting {
  private readonly viewProjection = mat4.create();
  private pixelWidth: number;
  private pixelHeight: number;

  /** `width` × `height`: the size the renderer was made with. */
  constructor(readonly renderer: PenumbraRenderer, width: number, height: number) {
    this.pixelWidth = width;
    this.pixelHeight = height;
  }

  /**
   * Lights the bound framebuffer's viewport `view` in place with the lights of content `layers`,
   * through `camera` (world → engine units, or none), and through the normals and materials of
   * `surfaces` when given (a renderer with normals). The context state is left as it was.
   */
  draw(view: InPlaceView, camera: Affine2D | null, layers: number, surfaces: SurfaceTextures | null = null): void {
    const renderer = this.renderer;
    if (view.pixelWidth !== this.pixelWidth || view.pixelHeight !== this.pixelHeight) {
      this.pixelWidth = view.pixelWidth;
      this.pixelHeight = view.pixelHeight;
      renderer.resize(view.pixelWidth, view.pixelHeight);
    }
    renderer.viewProjection = setViewProjection(this.viewProjection, view.width, view.height, view.flipY, camera);
    if (surfaces) renderer.drawInPlace(layers, surfaces);
    else renderer.drawInPlace(layers);
  }
}
