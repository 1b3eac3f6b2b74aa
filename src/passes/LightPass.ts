import type { ReadonlyMat4 } from 'gl-matrix';
import type { LightDraw } from '../geometry/FramePlan';
import { createProgram, type Program } from '../gl/program';
import { RenderTarget, type TargetFormat } from '../gl/RenderTarget';
import type { UnitQuad } from '../gl/UnitQuad';
import { Spotlight, TexturedLight, type LightKind } from '../scene/lights';
import { shaderSources } from './shaders';

const MASK_UNIT = 1;
const COOKIE_UNIT = 2;

/**
 * Light pass: owns the lightmap (RGBA16F where the context can render to it, so overlapping lights
 * go above 1), clears it to the ambient colour, and adds each light's quad weighted by the visible
 * fraction of its disk read from the shadow mask.
 */
export class LightPass {
  readonly lightmap: RenderTarget;
  private readonly programs: Record<LightKind, Program>;
  private readonly clearValue = new Float32Array(4);

  constructor(private readonly gl: WebGL2RenderingContext, private readonly quad: UnitQuad, format: TargetFormat, width: number, height: number) {
    this.programs = {
      point: createProgram(gl, 'point light', shaderSources.lightVertex, shaderSources.lightPointFragment),
      spot: createProgram(gl, 'spotlight', shaderSources.lightVertex, shaderSources.lightSpotFragment),
      textured: createProgram(gl, 'textured light', shaderSources.lightVertex, shaderSources.lightTexturedFragment),
    };
    this.lightmap = new RenderTarget(gl, { format, linear: true }, width, height);
  }

  resize(width: number, height: number): void {
    this.lightmap.resize(width, height);
  }

  /** Binds the lightmap and clears it to the ambient colour (alpha 1). Disables the scissor test. */
  begin(ambient: readonly [number, number, number]): void {
    const gl = this.gl;
    this.lightmap.bind();
    gl.disable(gl.SCISSOR_TEST);
    const clear = this.clearValue;
    clear[0] = ambient[0];
    clear[1] = ambient[1];
    clear[2] = ambient[2];
    clear[3] = 1;
    // clearBufferfv leaves the clear colour alone, so the host's need not be saved.
    gl.clearBufferfv(gl.COLOR, 0, clear);
  }

  /** Adds one light into the lightmap; `shadowMask` is null for a light with nothing to shadow it. */
  render(draw: LightDraw, viewProjection: ReadonlyMat4, shadowMask: WebGLTexture | null): void {
    const gl = this.gl;
    const light = draw.light;
    const program = this.programs[light.kind];
    const uniforms = program.uniforms;
    this.lightmap.bind();
    gl.useProgram(program.handle);
    gl.uniformMatrix4fv(uniforms.u_viewProjection, false, viewProjection);
    gl.uniform2f(uniforms.u_quadCorner, draw.quad[0], draw.quad[1]);
    gl.uniform2f(uniforms.u_quadAxisX, draw.quad[2], draw.quad[3]);
    gl.uniform2f(uniforms.u_quadAxisY, draw.quad[4], draw.quad[5]);
    const [r, g, b] = light.color;
    gl.uniform3f(uniforms.u_lightColor, r * light.intensity, g * light.intensity, b * light.intensity);
    gl.uniform2f(uniforms.u_lightPosition, light.position[0], light.position[1]);
    gl.uniform1f(uniforms.u_lightRange, light.range);
    gl.uniform1i(uniforms.u_hasShadowMask, shadowMask ? 1 : 0);
    gl.uniform1i(uniforms.u_shadowMask, MASK_UNIT);
    gl.activeTexture(gl.TEXTURE0 + MASK_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, shadowMask);
    if (light instanceof Spotlight) {
      gl.uniform2f(uniforms.u_direction, Math.cos(light.rotation), Math.sin(light.rotation));
      gl.uniform1f(uniforms.u_coneHalfAngle, light.coneAngle / 2);
      gl.uniform1f(uniforms.u_coneDecay, light.coneDecay);
    } else if (light instanceof TexturedLight) {
      gl.uniform1i(uniforms.u_cookie, COOKIE_UNIT);
      gl.activeTexture(gl.TEXTURE0 + COOKIE_UNIT);
      gl.bindTexture(gl.TEXTURE_2D, light.texture);
    }
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.FUNC_ADD);
    gl.blendFunc(gl.ONE, gl.ONE);
    this.quad.draw(gl.TRIANGLE_FAN);
  }

  dispose(): void {
    for (const program of Object.values(this.programs)) this.gl.deleteProgram(program.handle);
    this.lightmap.dispose();
  }
}
