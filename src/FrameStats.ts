/** Figures about the last frame, for overlays and benchmarks. */
export interface FrameStats {
  /** Lights added to the renderer. */
  lights: number;
  /**
   * Lights drawn for the last lightmap: enabled, of non-zero intensity and range, and reaching the
   * view. Counted whatever the content layers of the call: a light they leave out counts too.
   */
  lightsDrawn: number;
  /**
   * Lights whose shadow casters were found and filed anew for the last lightmap. A light keeps the
   * previous lightmap's filing of the hulls that stood still (and uploads none of it) while it and
   * the list of hulls are unchanged and no hull near it started or stopped moving, or while it moves
   * within the margin its speed gave its filing; the hulls that changed within the last 30 frames
   * are filed for every light every frame (see docs/shadows.md). A directional light is filed every
   * time.
   */
  lightsFiled: number;
  /** Hulls added to the renderer. */
  hulls: number;
  /** Edges of all valid hulls. */
  edges: number;
  /**
   * Renderer JavaScript time for the last lightmap, in milliseconds, while
   * `PenumbraRenderer.measureCpuTime` is on; else 0.
   */
  cpuTime: number;
  /**
   * The tiles of the shadowed point lights, spotlights and textured lights drawn for the last
   * lightmap, by how they were drawn (docs/shadows.md): lit (the plain light program), dark (not
   * drawn, or the plain program in the colour the shadows keep), exact (an exact shadow program:
   * the lean one or the general one, or for an Illuminated light's dark tiles with hulls in them
   * the held one, lit inside hulls), and outside the light's reach (not drawn). Each such light
   * has 2,048 tiles (32 × 64). This one: the lit tiles.
   */
  tilesLit: number;
  /** The dark tiles of the last lightmap (see {@link FrameStats.tilesLit}). */
  tilesDark: number;
  /** The tiles drawn with an exact shadow program (see {@link FrameStats.tilesLit}). */
  tilesExact: number;
  /** Of the exact tiles, those drawn with the lean exact program: every record that hides part of the disk from a pixel lies in front of it (docs/shadows.md); listed tiles included. */
  tilesLean: number;
  /** Of the exact tiles, those drawn with the held program: dark but inside hulls (docs/shadows.md). */
  tilesHeld: number;
  /** The tiles beyond their light's reach (see {@link FrameStats.tilesLit}). */
  tilesOutside: number;
  /** Shadowed point lights, spotlights and textured lights drawn wholly exact, unclassified (see `PenumbraRendererOptions.classificationBudget`). */
  lightsUnclassified: number;
}
