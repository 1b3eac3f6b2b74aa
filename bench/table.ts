/** Prints `rows` (the first one the header) as a plain-text table with aligned columns. */
export function printTable(title: string, rows: readonly (readonly string[])[]): void {
  const widths = rows[0].map((_, column) => Math.max(...rows.map((line) => line[column].length)));
  console.log(title);
  for (const [n, line] of rows.entries()) {
    console.log(line.map((cell, column) => cell.padEnd(widths[column])).join(' | '));
    if (n === 0) console.log(widths.map((width) => '-'.repeat(width)).join('-|-'));
  }
}

/** `value` ÷ `reference` to two decimals; '–' when either is missing or the reference is 0 ('=' for 0 ÷ 0). */
export function ratioCell(value: number | null | undefined, reference: number | null | undefined): string {
  if (value == null || reference == null) return '–';
  if (reference === 0) return value === 0 ? '=' : '–';
  return (value / reference).toFixed(2);
}
