// The baseline renderer: penumbra-gl built from a git ref by bench/build.mjs and bundled beside the
// working tree's. `library` is null when the bench was built with --no-baseline.
declare module 'virtual:penumbra-baseline' {
  export const library: import('./library').RendererLibrary | null;
  /** The ref as given (e.g. `8d3feef`) and the commit it names; null without a baseline. */
  export const baseline: { ref: string; commit: string } | null;
}
