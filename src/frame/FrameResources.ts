import { supportsFloatTargets } from '../gl/capabilities';
import { RenderTarget, type TargetFormat } from '../gl/RenderTarget';
import { BlurPass } from '../passes/BlurPass';
import { CompositePass } from '../passes/CompositePass';
import { DebugPass } from '../passes/DebugPass';
import { HullMaskPass } from '../passes/HullMaskPass';
import { LightPass } from '../passes/LightPass';
import { LightShapes } from '../passes/LightShapes';
import { SHADOW_TEXTURE_UNITS, TEXTURE_UNITS, unitsSpanned } from '../passes/textureUnits';
import type { Light } from '../scene/Light';
import { ShadowTextures } from '../shadow/ShadowTextures';
import type { HostFrame } from './HostFrame';
import type { Sizing } from './Sizing';

/** The renderer's GL objects: its targets and passes, made and freed together. */
export interface FrameResources {
  shapes: LightShapes;
  shadows: ShadowTextures;
  scene: RenderTarget;
  light: LightPass;
  composite: CompositePass;
  /** With a lightmap smaller than the scene (see {@link Sizing.edgeAware}); else null. */
  hullMask: HullMaskPass | null;
  blur: BlurPass;
  debug: DebugPass;
}

/**
 * How many texture units (from 0) the renderer's passes bind, saved and restored around every call:
 * those of the light pass, the blur, the composite and the debug pass, with normals those of the
 * light pass's and the composite's surface, upsampling aware of hull edges those of the hull mask
 * and the composite's masks (see {@link TEXTURE_UNITS}).
 */
export function textureUnits(normals: boolean, edgeAware: boolean): number {
  const units = TEXTURE_UNITS;
  return unitsSpanned([
    units.light, units.blur, units.composite, units.debug,
    ...(normals ? [units.lightWithNormals, units.compositeWithNormals] : []),
    ...(edgeAware ? [units.hullMask, units.compositeEdgeAware] : []),
  ]);
}

/**
 * Makes, resizes and frees the {@link FrameResources}, each time with the host's state saved around
 * the GL calls, and chooses the lightmap's format for each context.
 */
export class ResourceBuilder {
  /** Chosen with each build (see {@link ResourceBuilder.chooseLightmapFormat}). */
  lightmapFormat: TargetFormat = 'rgba16f';

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly host: HostFrame, private readonly sizing: Sizing,
    private readonly normals: boolean,
  ) {}

  /**
   * Builds the GL objects, the light programs of the kinds of `lights` among them (lights added
   * while the context was lost, or before a restore). If one fails, those already made are freed
   * before the error goes on (a pass that fails part-way frees its own).
   */
  build(lights: readonly Light[]): FrameResources {
    const gl = this.gl, sizing = this.sizing;
    this.chooseLightmapFormat();
    const made: { dispose(): void }[] = [];
    const keep = <T extends { dispose(): void }>(resource: T): T => {
      made.push(resource);
      return resource;
    };
    try {
      return this.host.run(() => {
        const shapes = keep(new LightShapes(gl));
        const { width, height, lightmapWidth, lightmapHeight, edgeAware } = sizing;
        const shadows = keep(new ShadowTextures(gl, SHADOW_TEXTURE_UNITS));
        const scene = keep(new RenderTarget(gl, { format: 'rgba8', depthStencil: true, colorAttachments: this.normals ? 3 : 1 }, width, height));
        const light = keep(new LightPass(gl, shapes, this.lightmapFormat, lightmapWidth, lightmapHeight, this.normals));
        for (const { kind } of lights) light.prepare(kind);
        return {
          shapes, shadows, scene, light,
          composite: keep(new CompositePass(gl, this.normals, edgeAware)),
          hullMask: edgeAware ? keep(new HullMaskPass(gl, width, height, lightmapWidth, lightmapHeight)) : null,
          blur: keep(new BlurPass(gl, this.lightmapFormat)),
          debug: keep(new DebugPass(gl, shapes)),
        };
      });
    } catch (error) {
      this.host.run(() => {
        for (const resource of made) resource.dispose();
      });
      throw error;
    }
  }

  /** Frees every GL object of `resources`. */
  destroy(resources: FrameResources): void {
    const parts: Record<keyof FrameResources, { dispose(): void } | null> = resources;
    this.host.run(() => {
      for (const part of Object.values(parts)) part?.dispose();
    });
  }

  /** Reallocates the targets at the sizing's size; returns why that failed, or null. */
  resize(resources: FrameResources): string | null {
    const { width, height, lightmapWidth, lightmapHeight } = this.sizing;
    try {
      this.host.run(() => {
        resources.scene.resize(width, height);
        resources.light.resize(lightmapWidth, lightmapHeight);
        resources.hullMask?.resize(width, height, lightmapWidth, lightmapHeight);
      });
    } catch (error) {
      return (error as Error).message;
    }
    return this.gl.getError() === this.gl.OUT_OF_MEMORY ? 'the context is out of memory (OUT_OF_MEMORY)' : null;
  }

  /**
   * Half-float where the context can render to it (which enables the extension: a restored context
   * starts with none). Warns when it falls back to RGBA8, once until the format changes again.
   */
  private chooseLightmapFormat(): void {
    const format = supportsFloatTargets(this.gl) ? 'rgba16f' : 'rgba8';
    if (format === 'rgba8' && this.lightmapFormat !== 'rgba8') {
      console.warn('penumbra: EXT_color_buffer_float is missing; the lightmap falls back to RGBA8, so light sums clamp at 1.');
    }
    this.lightmapFormat = format;
  }
}
