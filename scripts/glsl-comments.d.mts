import type { Plugin } from 'vite';

/** See glsl-comments.mjs: the shaders' `?raw` imports without their comments and blank lines. */
export function stripGlslComments(): Plugin;
