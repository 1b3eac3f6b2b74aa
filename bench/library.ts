import type { ReadonlyMat4 } from 'gl-matrix';
import * as current from '../src/index';

/**
 * The part of penumbra-gl's public API the bench uses, and that every renderer it compares has
 * (the working tree's and the baseline built from a git ref, see bench/build.mjs). Kept to
 * PenumbraRenderer, PointLight, Spotlight, TexturedLight, Hull (and DirectionalLight and SURFACE_GLSL where they exist) and the members below, so that
 * an older or newer core fits without the bench knowing its internals.
 */
export interface RendererLibrary {
  PenumbraRenderer: new (gl: WebGL2RenderingContext, options?: BenchRendererOptions) => BenchRenderer;
  PointLight: new (options: BenchLightOptions) => BenchLight;
  Spotlight: new (options: BenchLightOptions & { coneAngle?: number; coneDecay?: number }) => BenchLight;
  TexturedLight: new (options: BenchLightOptions & { texture: WebGLTexture; size?: readonly [number, number] }) => BenchLight;
  Hull: new (points: readonly (readonly [number, number])[], options?: { position?: readonly [number, number]; rotation?: number }) => BenchHull;
  /** Absent before the directional light existed: the scenes with a sun then leave that library out. */
  DirectionalLight?: new (options: { rotation?: number; angularSize?: number; color?: readonly [number, number, number]; intensity?: number }) => BenchLight;
  /** The host's surface helpers, absent before normal-mapped lighting: the scenes with normals then leave that library out. */
  SURFACE_GLSL?: string;
}

export interface BenchRendererOptions {
  ambientColor?: readonly [number, number, number];
  width?: number;
  height?: number;
  viewProjection?: ReadonlyMat4 | null;
  lightmapScale?: number;
  /** Light through the scene's normals (absent before normal-mapped lighting; see `SURFACE_GLSL`). */
  normals?: boolean;
}

export interface BenchRenderer {
  /** `lightsDrawn` and `edges` in every version; a version may add figures (see bench/extraStats.ts). */
  readonly stats: { readonly lightsDrawn: number; readonly edges: number };
  addLight(light: BenchLight): unknown;
  addHull(hull: BenchHull): unknown;
  beginDraw(): void;
  draw(): void;
  renderLightmap(): void;
  dispose(): void;
}

interface BenchLightOptions {
  position?: readonly [number, number];
  range?: number;
  radius?: number;
  color?: readonly [number, number, number];
  intensity?: number;
}

export interface BenchLight {
  /** Absent in versions before the light kinds had names. */
  readonly kind?: string;
  readonly position: readonly [number, number];
  readonly range: number;
  readonly color: readonly [number, number, number];
  setPosition(x: number, y: number): unknown;
}

export interface BenchHull {
  position: readonly [number, number];
  rotation: number;
}

/** The working tree's renderer (fails to type-check if its public API no longer fits the bench). */
export const CURRENT: RendererLibrary = current;
