import { mat4 } from 'gl-matrix';

/** A 2D affine transform as both engines store it: x' = a·x + c·y + tx, y' = b·x + d·y + ty. */
export interface Affine2D {
  a: number;
  b: number;
  c: number;
  d: number;
  tx: number;
  ty: number;
}

/**
 * Writes world → clip into `out` for an engine target of `width` × `height` units: the engine's
 * camera transform (world → target units, or none) followed by an orthographic projection with
 * the origin at the top-left and y down, or y up when the engine draws that target upside down.
 */
export function setViewProjection(out: mat4, width: number, height: number, flipY: boolean, camera: Affine2D | null): mat4 {
  mat4.ortho(out, 0, width, flipY ? 0 : height, flipY ? height : 0, -1, 1);
  if (!camera) return out;
  // Column-major: only the 2D linear part and the translation of the camera matter.
  const m = CAMERA;
  m[0] = camera.a;
  m[1] = camera.b;
  m[4] = camera.c;
  m[5] = camera.d;
  m[12] = camera.tx;
  m[13] = camera.ty;
  return mat4.multiply(out, out, m);
}

/** Scratch matrix, so that the per-frame path allocates nothing. */
const CAMERA = mat4.create();
