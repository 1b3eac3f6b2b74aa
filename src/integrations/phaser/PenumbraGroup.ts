import Phaser from 'phaser';
import type { LightOptions } from '../../index';
import { ALL_LAYERS, assertLayerMask } from '../../util/validate';
import type { PenumbraPlugin } from './PenumbraPlugin';

/** Options of a {@link PenumbraGroup}; see {@link PenumbraPlugin.addGroup}. */
export interface PenumbraGroupOptions {
  /**
   * The content layers of the group's children, a bit mask: they are lit by the ambient colour and
   * the lights whose `litLayers` share a bit with it (see {@link LightOptions.litLayers}); 0 leaves
   * the ambient colour only. Default `0xffffffff` (every light).
   */
  layers?: number;
  /**
   * The group's depth in the scene. Default the lighting layer's depth ({@link PenumbraPlugin.layer}):
   * made after it, the group is drawn after it, and above the objects it lights.
   */
  depth?: number;
  /** Game objects to move into the group. */
  children?: Phaser.GameObjects.GameObject[];
}

/** The lit framebuffer's tint, opaque white, which changes nothing: the Layer put its alpha in its children's. */
const OPAQUE_WHITE = 0xffffffff;

/**
 * A Phaser 4 `Layer` whose children are lit apart, by the ambient colour and the lights of its
 * content {@link PenumbraGroup.layers} only: a player lit by its own torch and not by the lamps
 * (`torch.litLayers = PLAYER`, lamps' `litLayers = WORLD`, the player in a group of layers `PLAYER`).
 * Make one with {@link PenumbraPlugin.addGroup}; add children as to any `Layer`.
 *
 * It must be drawn after the lighting layer (below it, the lighting layer would light its content
 * a second time): its depth defaults to the lighting layer's. Its children are drawn, through the
 * same camera, into a transparent framebuffer the size of the drawing context (the group's own, made
 * on first use and resized with the canvas), lit there by the plugin's renderer (same lights, hulls,
 * shadows and camera as the world), then drawn into the context at the group's place. Content that
 * must stay unlit needs no group: give it a depth above the lighting layer's.
 *
 * Removing the group from the scene or destroying it frees its framebuffer. While the plugin has no
 * renderer (destroyed) the children are drawn unlit. The members it inherits from Phaser's `Layer`
 * are documented by Phaser.
 *
 * @noInheritDoc
 */
export class PenumbraGroup extends Phaser.GameObjects.Layer {
  private _layers = ALL_LAYERS;
  private target: Phaser.Renderer.WebGL.DrawingContext | null = null;
  private readonly renderOptions: Phaser.Types.Renderer.WebGL.RenderNodes.BatchHandlerQuadRenderOptions = {};

  /** Prefer {@link PenumbraPlugin.addGroup}, which also adds the group to the scene. */
  constructor(scene: Phaser.Scene, private readonly plugin: PenumbraPlugin, options: PenumbraGroupOptions = {}) {
    super(scene, options.children);
    this.layers = options.layers ?? ALL_LAYERS;
    this.setDepth(options.depth ?? plugin.layer.depth);
    // Before the Layer's own step, which it runs to draw the children into the group's framebuffer.
    this.addRenderStep(this.renderLit, 0);
  }

  /** The content layers of the group's children; see {@link PenumbraGroupOptions.layers}. */
  get layers(): number {
    return this._layers;
  }
  set layers(value: number) {
    this._layers = assertLayerMask('PenumbraGroup.layers', value);
  }

  /** Called by Phaser when the group leaves the scene's display list: frees its framebuffer. @internal */
  override removedFromScene(): void {
    super.removedFromScene();
    this.freeTarget();
  }

  /** Destroys the group and its children, and frees its framebuffer. */
  override destroy(fromScene?: boolean): void {
    super.destroy(fromScene);
    this.freeTarget();
  }

  /** The render step: the children into the group's framebuffer (by the next steps), lit, then into the context. */
  private readonly renderLit: Phaser.Types.GameObjects.RenderWebGLStep = (renderer, gameObject, context, parentMatrix, renderStep = 0, displayList, displayListIndex) => {
    const next = renderStep + 1;
    if (!this.plugin.canLight) {
      gameObject.renderWebGLStep(renderer, gameObject, context, parentMatrix, next, displayList, displayListIndex);
      return;
    }
    const camera = context.camera!;
    const target = this.fitTarget(renderer, context.width, context.height);
    target.setCamera(camera);
    target.use();
    gameObject.renderWebGLStep(renderer, gameObject, target, parentMatrix, next, displayList, displayListIndex);
    const nodes = renderer.renderNodes;
    nodes.getNode('YieldContext')!.run(target);
    // Drawn into a framebuffer, the children took the camera's framebuffer view (its position left out).
    this.plugin.lightContext(target, camera.getViewMatrix(true), this._layers, this.list, null);
    nodes.getNode('RebindContext')!.run(target);
    this.drawTarget(renderer, context, target);
  };

  /** The group's framebuffer at `width` × `height`, made or resized as needed. */
  private fitTarget(renderer: Phaser.Renderer.WebGL.WebGLRenderer, width: number, height: number): Phaser.Renderer.WebGL.DrawingContext {
    const target = this.target;
    if (!target) return (this.target = new Phaser.Renderer.WebGL.DrawingContext(renderer, { width, height, autoClear: true }));
    if (target.width !== width || target.height !== height) target.resize(width, height);
    return target;
  }

  /**
   * Draws the lit framebuffer into `context` as Phaser's Camera node draws a camera's framebuffer
   * into its parent context: placed by the camera's position when the context is the canvas (the
   * children were drawn without it), the texture read from v = 1 at the top (GL keeps rows bottom up).
   */
  private drawTarget(renderer: Phaser.Renderer.WebGL.WebGLRenderer, context: Phaser.Renderer.WebGL.DrawingContext, target: Phaser.Renderer.WebGL.DrawingContext): void {
    const external = context.useCanvas ? context.camera!.matrixExternal : null;
    const a = external ? external.a : 1, b = external ? external.b : 0, c = external ? external.c : 0;
    const d = external ? external.d : 1, e = external ? external.e : 0, f = external ? external.f : 0;
    const w = target.width, h = target.height;
    const options = this.renderOptions;
    options.alphaStrategy = context.alphaStrategy;
    options.smoothPixelArt = renderer.game.config.smoothPixelArt;
    const quads = renderer.renderNodes.getNode('BatchHandlerQuadSingle') as Phaser.Renderer.WebGL.RenderNodes.BatchHandlerQuadSingle;
    quads.batch(
      context, target.texture!,
      e, f, // top-left
      c * h + e, d * h + f, // bottom-left
      a * w + e, b * w + f, // top-right
      a * w + c * h + e, b * w + d * h + f, // bottom-right
      0, 1, 1, -1,
      Phaser.TintModes.MULTIPLY, OPAQUE_WHITE, OPAQUE_WHITE, OPAQUE_WHITE, OPAQUE_WHITE,
      options,
    );
  }

  private freeTarget(): void {
    this.target?.destroy();
    this.target = null;
  }
}
