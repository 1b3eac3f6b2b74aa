/**
 * Per-scene figures a renderer may report in its `stats` beyond what every version has (the
 * shadow core v2 hooks). The bench prints a column per entry, '–' where the renderer's stats lack
 * the key (the baseline, or a core that does not report it); nothing here reaches into the
 * renderer. The figure is read after the last measured frame.
 */
function percent(value: number): string {
  return `${(value * 100).toFixed(1)}%`;
}

export const EXTRA_STATS = [
  { key: 'shadowVisitsPerPixel', label: 'hulls visited / shaded px', format: (value: number) => value.toFixed(2) },
  { key: 'shadowSkipShare', label: 'px decided w/o loop', format: (value: number) => `${(value * 100).toFixed(1)}%` },
  { key: 'shadowQuadratureShare', label: 'px swept (quadrature)', format: (value: number) => `${(value * 100).toFixed(2)}%` },
  // The shadow core v3's programs: of the light pixels (each light's pixels where its falloff is
  // above 0, hulls or not), the share drawn by the plain light program (lit), the held, lean and
  // general shadow programs, and not drawn (dark); and the records an exact pixel visits, mean.
  { key: 'pixelsLitShare', label: 'px lit', format: percent },
  { key: 'pixelsHeldShare', label: 'px held', format: percent },
  { key: 'pixelsLeanShare', label: 'px lean', format: percent },
  { key: 'pixelsGeneralShare', label: 'px general', format: percent },
  { key: 'pixelsNotDrawnShare', label: 'px not drawn', format: percent },
  { key: 'exactVisitsPerPixel', label: 'records / exact px', format: (value: number) => value.toFixed(2) },
] as const;

type ExtraStatKey = (typeof EXTRA_STATS)[number]['key'];
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
