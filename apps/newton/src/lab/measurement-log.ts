/** One measured quantity: a column of the CSV. */
export interface Quantity {
  /** Column name, e.g. "A x" (who and what). */
  readonly name: string;
  /** SI unit, e.g. "m/s". */
  readonly unit: string;
}

interface Row {
  readonly time: number;
  readonly values: Map<string, number>;
}

/**
 * What a screen measured, step by step: a time and named values per row, written out as CSV
 * (one column per quantity, in the order they first appeared; a cell is empty where a quantity
 * was not measured, e.g. before a particle was added). Holds the newest `maxRows` rows.
 */
export class MeasurementLog {
  private rows: Row[] = [];
  private readonly quantities = new Map<string, Quantity>();

  constructor(readonly maxRows = 7200) {}

  get length(): number {
    return this.rows.length;
  }

  /**
   * Adds the given values at `time` (s): to the row of that time if there is one (worlds stepped
   * side by side, as Forces' two tracks, each add their own columns to the same moment), else as
   * a new row in time order.
   */
  add(time: number, values: readonly (Quantity & { value: number })[]): void {
    let at = this.rows.length;
    while (at > 0 && this.rows[at - 1]!.time > time + 1e-9) at--;
    const same = at > 0 && Math.abs(this.rows[at - 1]!.time - time) <= 1e-9;
    const map = same ? this.rows[at - 1]!.values : new Map<string, number>();
    for (const item of values) {
      if (!this.quantities.has(item.name))
        this.quantities.set(item.name, { name: item.name, unit: item.unit });
      map.set(item.name, item.value);
    }
    if (same) return;
    this.rows.splice(at, 0, { time, values: map });
    if (this.rows.length > this.maxRows) this.rows.splice(0, this.rows.length - this.maxRows);
  }

  /** Forgets the rows after `time` (s): the simulation was rewound to it. */
  truncateAfter(time: number): void {
    let end = this.rows.length;
    while (end > 0 && this.rows[end - 1]!.time > time + 1e-9) end--;
    this.rows.length = end;
  }

  clear(): void {
    this.rows = [];
    this.quantities.clear();
  }

  /**
   * The log as CSV (RFC 4180): a header `t (s),A x (m),...`, then one line per row. Numbers are
   * written with a decimal point and up to 9 significant digits, whatever the page's language,
   * so every spreadsheet and script reads them.
   */
  toCsv(): string {
    const columns = [...this.quantities.values()];
    const header = ['t (s)', ...columns.map((q) => `${q.name} (${q.unit})`)].map(csvCell);
    const lines = [header.join(',')];
    for (const row of this.rows) {
      const cells = [formatNumber(row.time)];
      for (const q of columns) {
        const value = row.values.get(q.name);
        cells.push(value === undefined ? '' : formatNumber(value));
      }
      lines.push(cells.join(','));
    }
    return `${lines.join('\r\n')}\r\n`;
  }
}

/** A number for CSV: at most 9 significant digits, no exponent for everyday sizes, no "-0". */
export function formatNumber(value: number): string {
  if (!Number.isFinite(value)) return '';
  const rounded = Number(value.toPrecision(9));
  return Object.is(rounded, -0) ? '0' : String(rounded);
}

/** A CSV cell: quoted when it holds a comma, quote or line break (RFC 4180). */
export function csvCell(text: string): string {
  return /[",\r\n]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text;
}
