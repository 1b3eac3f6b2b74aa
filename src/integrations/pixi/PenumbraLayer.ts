import { mat4 } from 'gl-matrix';
import { RenderContainer, type Container, type Renderer, type WebGLRenderer } from 'pixi.js';
import { PenumbraRenderer, type Hull, type Light, type PenumbraRendererOptions } from '../../index';
import { setViewProjection } from '../viewProjection';

/** Options of a {@link PenumbraLayer}: the core renderer's options plus the camera. */
export interface PenumbraLayerOptions extends Omit<PenumbraRendererOptions, 'viewProjection' | 'width' | 'height'> {
  /**
   * The container whose local space is the world of the lights and hulls (typically the
   * "world" container you pan and zoom as a camera). Its world transform drives the lighting's
   * view-projection every frame. Default `null`: lights and hulls are in stage (screen) pixels.
   */
  camera?: Container | null;
}

type BindState = ReturnType<WebGLRenderer['renderTarget']['getBindState']>;

/**
 * A PixiJS v8 display object that lights everything drawn before it in the same render target.
 * Put it in the stage after the world and before the HUD: the world is multiplied by the
 * lightmap (ambient + lights, with soft shadows from the hulls), the HUD drawn after it stays
 * unlit. It shares Pixi's WebGL2 context; after lighting it calls `renderer.resetState()` and
 * rebinds Pixi's current render target, so Pixi carries on with a correct state.
 *
 * ```ts
 * const lighting = new PenumbraLayer(app.renderer, { camera: world, ambientColor: [0.1, 0.1, 0.15] });
 * app.stage.addChild(world, lighting, hud);
 * lighting.addLight(new PointLight({ position: [200, 150], range: 300, radius: 10 }));
 * ```
 *
 * Only the WebGL renderer is supported (`preference: 'webgl'`). `destroy()` frees the GL resources.
 * The members it inherits from Pixi's `RenderContainer` are documented by Pixi.
 *
 * @noInheritDoc
 */
export class PenumbraLayer extends RenderContainer {
  /** The core renderer: lights, hulls, ambient colour, debug wireframe and stats. */
  readonly penumbra: PenumbraRenderer;
  /** See {@link PenumbraLayerOptions.camera}. */
  camera: Container | null;

  private readonly bindState = {} as BindState;
  private readonly viewProjection = mat4.create();
  private targetWidth = 0;
  private targetHeight = 0;

  constructor(renderer: Renderer, options: PenumbraLayerOptions = {}) {
    super({ label: 'PenumbraLayer' });
    const gl = (renderer as Partial<WebGLRenderer>).gl;
    if (!gl) throw new TypeError('penumbra: PenumbraLayer needs Pixi\'s WebGL renderer (Application.init({ preference: \'webgl\' }))');
    const { camera = null, ...rendererOptions } = options;
    this.camera = camera;
    // Every renderer option goes through; the size and the view follow Pixi's target each frame.
    this.penumbra = new PenumbraRenderer(gl, {
      ...rendererOptions,
      viewProjection: null,
      width: gl.drawingBufferWidth,
      height: gl.drawingBufferHeight,
    });
    this.targetWidth = gl.drawingBufferWidth;
    this.targetHeight = gl.drawingBufferHeight;
  }

  /** Adds a light (in the camera's space); see {@link PenumbraRenderer.addLight}. */
  addLight<T extends Light>(light: T): T {
    return this.penumbra.addLight(light);
  }
  /** Removes a light; returns whether it was there. */
  removeLight(light: Light): boolean {
    return this.penumbra.removeLight(light);
  }
  /** Adds a hull (in the camera's space); see {@link PenumbraRenderer.addHull}. */
  addHull(hull: Hull): Hull {
    return this.penumbra.addHull(hull);
  }
  /** Removes a hull; returns whether it was there. */
  removeHull(hull: Hull): boolean {
    return this.penumbra.removeHull(hull);
  }

  /** Called by Pixi's render pipe at this object's place in the draw order. @internal */
  override render(renderer: Renderer): void {
    const pixi = renderer as WebGLRenderer;
    const targets = pixi.renderTarget;
    const target = targets.renderTarget;
    this.fitTarget(target.pixelWidth, target.pixelHeight);
    // Pixi draws render textures upside down (row 0 at the top) and the screen right side up.
    const cameraTransform = this.camera?.worldTransform ?? null;
    setViewProjection(this.viewProjection, target.width, target.height, !target.isRoot, cameraTransform);
    this.penumbra.viewProjection = this.viewProjection;
    targets.getBindState(this.bindState);
    this.penumbra.drawInPlace();
    // The engine's own mechanism for foreign GL code; it forgets the bound target too, so bind it back.
    pixi.resetState();
    targets.bind(this.bindState);
  }

  /** Frees the lighting's GL resources, then destroys the display object. */
  override destroy(options?: Parameters<RenderContainer['destroy']>[0]): void {
    this.penumbra.dispose();
    super.destroy(options);
  }

  private fitTarget(width: number, height: number): void {
    if (width === this.targetWidth && height === this.targetHeight) return;
    this.targetWidth = width;
    this.targetHeight = height;
    this.penumbra.resize(width, height);
  }
}
