import {
  Container, Filter, GlProgram, Rectangle, defaultFilterVert,
  type ContainerOptions, type DestroyOptions, type FilterSystem, type RenderSurface, type Texture, type WebGLRenderer,
} from 'pixi.js';
import type { LightOptions } from '../../index';
import { ALL_LAYERS, assertLayerMask } from '../../util/validate';
import type { PenumbraLayer } from './PenumbraLayer';

/**
 * Options of a {@link PenumbraGroup}: the lighting and the layers, plus Pixi's container options
 * (`label`, `position`, `children`, …), which Pixi documents.
 *
 * @noInheritDoc
 */
export interface PenumbraGroupOptions extends ContainerOptions {
  /** The lighting layer whose renderer (lights, hulls, ambient colour) and camera light the group. */
  lighting: PenumbraLayer;
  /**
   * The content layers of the group's children, a bit mask: they are lit by the ambient colour and
   * the lights whose `litLayers` share a bit with it (see {@link LightOptions.litLayers}); 0 leaves
   * the ambient colour only. Default `0xffffffff` (every light).
   */
  layers?: number;
}

type BindOptions = ReturnType<WebGLRenderer['renderTarget']['getBindState']>;

/**
 * Half the side of the group's filter area, in its local units: far larger than any view, so that
 * Pixi, which clips a filter's area to the viewport, gives the filter the whole viewport.
 */
const EVERYWHERE = 1e9;

/** Draws the filter's input as it is (pixi.js 8.22's PassthroughFilter throws when made: its WGSL fails Pixi's own parser). */
const PASS_THROUGH = `in vec2 vTextureCoord;
out vec4 finalColor;
uniform sampler2D uTexture;
void main() {
  finalColor = texture(uTexture, vTextureCoord);
}
`;

/**
 * A PixiJS v8 container whose children are lit apart, by the ambient colour and the lights of its
 * content {@link PenumbraGroup.layers} only: a player lit by its own torch and not by the lamps
 * (`torch.litLayers = PLAYER`, lamps' `litLayers = WORLD`, the player in a group of layers `PLAYER`).
 *
 * Put it after its {@link PenumbraLayer} in the draw order (before it, the layer would light its
 * content a second time), with the camera's transform: e.g. inside the camera container, after the
 * layer. Its children are drawn into a transparent texture the size of the frame, lit there by the
 * lighting's renderer (same lights, hulls, shadows and camera as the world), then drawn into the frame
 * at the group's place with normal alpha blending. Content that must stay unlit needs no group:
 * draw it after the layer.
 *
 * ```ts
 * const WORLD = 0b01, PLAYER = 0b10;
 * const lighting = new PenumbraLayer(app.renderer, { camera: world, layers: WORLD });
 * const actors = new PenumbraGroup({ lighting, layers: PLAYER });
 * world.addChild(floor, lighting, actors, glowingSign);   // the sign, after the layer: unlit
 * actors.addChild(player);
 * lighting.addLight(new PointLight({ position: [200, 150], range: 300, litLayers: WORLD }));  // a lamp: the world only
 * const torch = lighting.addLight(new PointLight({ range: 80, litLayers: PLAYER }));          // the player only
 * ```
 *
 * The lighting is a filter, the first of the group's `filters`: add others after it
 * (`group.filters = [...group.filters, blur]`), or on a child. The frame's texture is Pixi's, lent
 * by its filter pool for the time of the group's drawing. While the lighting is destroyed the
 * children are drawn unlit. The members it inherits from Pixi's `Container` are documented by Pixi.
 *
 * @noInheritDoc
 */
export class PenumbraGroup extends Container {
  /** The lighting layer whose renderer and camera light the group. */
  readonly lighting: PenumbraLayer;

  private _layers = ALL_LAYERS;
  private readonly lightingFilter: GroupLightingFilter;

  constructor(options: PenumbraGroupOptions) {
    const { lighting, layers = ALL_LAYERS, ...containerOptions } = options;
    super(containerOptions);
    this.lighting = lighting;
    this.layers = layers;
    this.lightingFilter = new GroupLightingFilter(this);
    this.filters = [this.lightingFilter, ...(this.filters ?? [])];
    this.filterArea = new Rectangle(-EVERYWHERE, -EVERYWHERE, 2 * EVERYWHERE, 2 * EVERYWHERE);
  }

  /** The content layers of the group's children; see {@link PenumbraGroupOptions.layers}. */
  get layers(): number {
    return this._layers;
  }
  set layers(value: number) {
    this._layers = assertLayerMask('PenumbraGroup.layers', value);
  }

  /** Destroys the container, then its lighting filter. */
  override destroy(options?: DestroyOptions): void {
    super.destroy(options);
    this.lightingFilter.destroy();
  }
}

/**
 * The group's lighting: Pixi's filter system draws the group's children into a transparent
 * texture (the input) and calls `apply`, which lights it in place, then draws it into the output
 * with a pass-through shader, as any filter draws its result. WebGL only, as the lighting.
 */
class GroupLightingFilter extends Filter {
  private readonly bindInput = { clear: false } as BindOptions;

  constructor(private readonly owner: PenumbraGroup) {
    super({
      glProgram: GlProgram.from({ vertex: defaultFilterVert, fragment: PASS_THROUGH, name: 'penumbra-group' }),
      // The children at the frame's own resolution and antialiasing, as they would be drawn unfiltered.
      resolution: 'inherit',
      antialias: 'inherit',
    });
  }

  /**
   * The input covers the whole viewport from its top-left (the filter area is everywhere, clipped
   * to the viewport), its children at their global positions: as the frame, which the lighting
   * expects.
   */
  override apply(filters: FilterSystem, input: Texture, output: RenderSurface, clearMode: boolean): void {
    const lighting = this.owner.lighting;
    if (!lighting.destroyed) {
      const pixi = filters.renderer as WebGLRenderer;
      this.bindInput.target = input;
      pixi.renderTarget.bind(this.bindInput);
      lighting.lightBoundTarget(pixi, this.owner.layers, this.owner, null);
      // A multisampled input was resolved into its texture before apply: resolve the lit colour again.
      pixi.renderTarget.finishRenderPass();
    }
    filters.applyFilter(this, input, output, clearMode);
  }
}
