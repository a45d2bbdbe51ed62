import type { Body } from '@physical/engine';

/** One logged quantity of a particle: its column's name and unit, and this step's value. */
export interface ParticleCell {
  readonly name: string;
  readonly unit: string;
  value: number;
}

/**
 * The measurement log's row of every particle (x, y, vx, vy, px, py, KE), built each step without
 * new objects: each particle's seven cells (and their column names) are made once, the first
 * time its label is seen, and only their values change. With 50 particles the row was 350 new
 * objects and names a step, most of the lab's per-step cost on a slow phone.
 */
export class ParticleColumns {
  private readonly byLabel = new Map<string, ParticleCell[]>();
  private readonly row: ParticleCell[] = [];

  /** The cells of `particles` (body and label, in order) with this step's values. */
  fill(particles: Iterable<readonly [Body, { readonly label: string }]>): readonly ParticleCell[] {
    const row = this.row;
    row.length = 0;
    for (const [body, { label }] of particles) {
      const cells = this.cellsOf(label);
      const { x, y } = body.position;
      const v = body.linearVelocity;
      const m = body.mass;
      cells[0]!.value = x;
      cells[1]!.value = y;
      cells[2]!.value = v.x;
      cells[3]!.value = v.y;
      cells[4]!.value = m * v.x;
      cells[5]!.value = m * v.y;
      cells[6]!.value = 0.5 * m * (v.x * v.x + v.y * v.y);
      for (const cell of cells) row.push(cell);
    }
    return row;
  }

  private cellsOf(label: string): ParticleCell[] {
    let cells = this.byLabel.get(label);
    if (cells === undefined) {
      cells = [
        { name: `${label} x`, unit: 'm', value: 0 },
        { name: `${label} y`, unit: 'm', value: 0 },
        { name: `${label} vx`, unit: 'm/s', value: 0 },
        { name: `${label} vy`, unit: 'm/s', value: 0 },
        { name: `${label} px`, unit: 'kg m/s', value: 0 },
        { name: `${label} py`, unit: 'kg m/s', value: 0 },
        { name: `${label} KE`, unit: 'J', value: 0 },
      ];
      this.byLabel.set(label, cells);
    }
    return cells;
  }
}
