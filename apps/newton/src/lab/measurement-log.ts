/** One measured quantity: a column of the CSV. */
export interface Quantity {
  /** Column name, e.g. "A x" (who and what). */
  readonly name: string;
  /** SI unit, e.g. "m/s". */
  readonly unit: string;
}

/** Rows a new log has room for before it first grows (it doubles up to `maxRows`). */
const FIRST_CAPACITY = 256;

/**
 * What a screen measured, step by step: a time and named values per row, written out as CSV
 * (one column per quantity, in the order they first appeared; a cell is empty where a quantity
 * was not measured, e.g. before a particle was added). Holds the newest `maxRows` rows.
 *
 * Stored by column in flat `Float64Array` rings (NaN where nothing was measured): a step of 50
 * particles adds 350 numbers, which as a `Map` per row made 350 entries and a new hash table each
 * step, and garbage a slow phone collected in the middle of its frames.
 */
export class MeasurementLog {
  /** Row slots allocated: grows by doubling up to `maxRows`, then the ring overwrites. */
  private capacity = 0;
  /** Slot of the oldest row, and the rows held. */
  private start = 0;
  private count = 0;
  private times = new Float64Array(0);
  private columns: Float64Array[] = [];
  private quantities: Quantity[] = [];
  private readonly columnOf = new Map<string, number>();

  constructor(readonly maxRows = 7200) {
    if (!Number.isInteger(maxRows) || maxRows < 1) {
      throw new RangeError(`maxRows must be a whole number of 1 or more, got ${maxRows}`);
    }
  }

  get length(): number {
    return this.count;
  }

  /** The slot of row `row` (0 the oldest). */
  private slot(row: number): number {
    const slot = this.start + row;
    return slot >= this.capacity ? slot - this.capacity : slot;
  }

  private timeAt(row: number): number {
    return this.times[this.slot(row)]!;
  }

  /**
   * Adds the given values at `time` (s): to the row of that time if there is one (worlds stepped
   * side by side, as Forces' two tracks, each add their own columns to the same moment), else as
   * a new row in time order.
   */
  add(time: number, values: readonly (Quantity & { value: number })[]): void {
    let at = this.count;
    while (at > 0 && this.timeAt(at - 1) > time + 1e-9) at--;
    let slot: number;
    if (at > 0 && Math.abs(this.timeAt(at - 1) - time) <= 1e-9) slot = this.slot(at - 1);
    else slot = this.insertRow(at, time);
    if (slot < 0) return;
    for (const item of values) {
      let column = this.columnOf.get(item.name);
      if (column === undefined) column = this.addColumn(item);
      this.columns[column]![slot] = item.value;
    }
  }

  /** A new row at `row` (its cells unmeasured); returns its slot, or -1 when it fell off. */
  private insertRow(row: number, time: number): number {
    if (this.count === this.capacity) {
      if (this.capacity < this.maxRows) this.grow();
      else {
        // Full: the oldest row goes (a row older than all that are kept has no place).
        if (row === 0) return -1;
        this.start = this.slot(1);
        this.count--;
        row--;
      }
    }
    const end = this.count++;
    // Rows after `row` move up one (only when a world a step behind adds an older time).
    for (let i = end; i > row; i--) {
      const to = this.slot(i);
      const from = this.slot(i - 1);
      this.times[to] = this.times[from]!;
      for (const column of this.columns) column[to] = column[from]!;
    }
    const slot = this.slot(row);
    this.times[slot] = time;
    for (const column of this.columns) column[slot] = NaN;
    return slot;
  }

  /** Twice the room (at most `maxRows`), the rows copied oldest first. */
  private grow(): void {
    const capacity = Math.min(this.maxRows, Math.max(FIRST_CAPACITY, this.capacity * 2));
    const copy = (old: Float64Array): Float64Array<ArrayBuffer> => {
      const next = new Float64Array(capacity).fill(NaN);
      for (let row = 0; row < this.count; row++) next[row] = old[this.slot(row)]!;
      return next;
    };
    this.times = copy(this.times);
    this.columns = this.columns.map(copy);
    this.start = 0;
    this.capacity = capacity;
  }

  private addColumn(quantity: Quantity): number {
    const index = this.columns.length;
    this.columnOf.set(quantity.name, index);
    this.quantities.push({ name: quantity.name, unit: quantity.unit });
    this.columns.push(new Float64Array(this.capacity).fill(NaN));
    return index;
  }

  /** Forgets the rows after `time` (s): the simulation was rewound to it. */
  truncateAfter(time: number): void {
    while (this.count > 0 && this.timeAt(this.count - 1) > time + 1e-9) this.count--;
  }

  clear(): void {
    this.capacity = 0;
    this.start = 0;
    this.count = 0;
    this.times = new Float64Array(0);
    this.columns = [];
    this.quantities = [];
    this.columnOf.clear();
  }

  /**
   * The log as CSV (RFC 4180): a header `t (s),A x (m),...`, then one line per row. Numbers are
   * written with a decimal point and up to 9 significant digits, whatever the page's language,
   * so every spreadsheet and script reads them.
   */
  toCsv(): string {
    const header = ['t (s)', ...this.quantities.map((q) => `${q.name} (${q.unit})`)].map(csvCell);
    const lines = [header.join(',')];
    for (let row = 0; row < this.count; row++) {
      const slot = this.slot(row);
      const cells = [formatNumber(this.times[slot]!)];
      for (const column of this.columns) cells.push(formatNumber(column[slot]!));
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
