/**
 * Per-scene figures a renderer may report in its `stats` beyond what every version has (the
 * shadow core v2 hooks). The bench prints a column per entry, '–' where the renderer's stats lack
 * the key (the baseline, or a core that does not report it); nothing here reaches into the
 * renderer. The figure is read after the last measured frame.
 */
export const EXTRA_STATS = [
  { key: 'shadowVisitsPerPixel', label: 'hulls visited / shaded px', format: (value: number) => value.toFixed(2) },
  { key: 'shadowSkipShare', label: 'px decided w/o loop', format: (value: number) => `${(value * 100).toFixed(1)}%` },
  { key: 'shadowQuadratureShare', label: 'px swept (quadrature)', format: (value: number) => `${(value * 100).toFixed(2)}%` },
  // The shadow core v3's tiles: the share of a shadowed light's tiles drawn lit (plain program),
  // exact (shadow program), and not drawn (dark, or beyond its reach).
  { key: 'tilesLitShare', label: 'tiles lit', format: (value: number) => `${(value * 100).toFixed(1)}%` },
  { key: 'tilesExactShare', label: 'tiles exact', format: (value: number) => `${(value * 100).toFixed(1)}%` },
  { key: 'tilesLeanShare', label: 'tiles lean', format: (value: number) => `${(value * 100).toFixed(1)}%` },
  { key: 'tilesHeldShare', label: 'tiles held', format: (value: number) => `${(value * 100).toFixed(1)}%` },
  { key: 'tilesDarkShare', label: 'tiles dark', format: (value: number) => `${(value * 100).toFixed(1)}%` },
] as const;

export type ExtraStatKey = (typeof EXTRA_STATS)[number]['key'];
export type ExtraStats = Partial<Record<ExtraStatKey, number>>;

/** The EXTRA_STATS figures present in `stats` as finite numbers. */
export function readExtraStats(stats: object): ExtraStats {
  const found: ExtraStats = {};
  for (const { key } of EXTRA_STATS) {
    const value: unknown = (stats as Record<string, unknown>)[key];
    if (typeof value === 'number' && Number.isFinite(value)) found[key] = value;
  }
  return found;
}

/** The table cells of `extra` (undefined: not measured), in EXTRA_STATS order. */
export function extraStatCells(extra: ExtraStats | undefined): string[] {
  return EXTRA_STATS.map(({ key, format }) => {
    const value = extra?.[key];
    return value === undefined ? '–' : format(value);
  });
}
