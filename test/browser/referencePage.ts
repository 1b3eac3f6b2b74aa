import type { HostStateReport } from '../gl/hostParameters';
import type { IlluminationComparison } from '../reference/illuminationComparison';
import type { ReferenceScene } from '../reference/scenes';
import { openBuiltPage, type BuiltPage } from './builtPage';
import type { DirectionalReferenceScene } from '../reference/directionalReference';
import type { SurfaceFigures } from '../reference/surfaceComparison';
import type { ShadowType } from '../../src/index';

/** What test/browser/reference-page/main.ts puts on `window`. */
export interface ReferencePageApi {
  renderScene(scene: ReferenceScene): number[];
  /** The lightmap of a directional light's scene (test/reference/directionalReference.ts). */
  renderDirectionalScene(scene: DirectionalReferenceScene): number[];
  renderAcrossContextLoss(scene: ReferenceScene): Promise<{ before: number[]; after: number[]; lostFrameError: string | null; windowErrors: string[] }>;
  /** The host-parameter check (test/gl/hostParameters.ts), of a renderer with normals when `normals`. */
  checkHostState(normals?: boolean, lightmapScale?: number): HostStateReport;
  outlineScene(lightmapScale: number, shadowType: ShadowType): number[];
  compareIllumination(scene: ReferenceScene): IlluminationComparison & { glError: number; floatLightmap: boolean };
  /** Normal-mapped lighting against its CPU reference (test/reference/surfaceComparison.ts). */
  compareSurfaces(): SurfaceFigures;
  /** The messages a renderer with normals throws for malformed `drawInPlace` surfaces. */
  surfaceMisuse(): string[];
  /** A frame of a renderer with normals before a context loss and after the restore: the output bytes that differ. */
  surfacesAcrossContextLoss(): Promise<{ differingBytes: number; litBytes: number }>;
}

/** The reference page open in headless Chromium. */
export type ReferencePage = BuiltPage;

/**
 * Builds test/browser/reference-page with Vite (it imports the library's sources and the shared
 * test code), serves it and opens it in Chromium, ready once its entry points are on `window`.
 */
export function openReferencePage(): Promise<ReferencePage> {
  return openBuiltPage('reference-page', 'renderScene');
}
