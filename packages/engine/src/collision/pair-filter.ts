// Whether two shapes may make a contact, decided from their filter rows alone: the rule of
// dynamics/filter.ts's filtersCollide (Box2D's: a shared non-zero group decides, else the
// category and mask bits both ways), with sensors never making contacts. It reads the rows the
// shape table keeps by shape id (dynamics/shape-table.ts, SHAPE_FILTERS: category, mask, group,
// sensor flag), so the broad phase can turn a forbidden pair away before it looks the pair up:
// in a ragdoll rain nine pairs found in ten are bones of one ragdoll or feet (issue #30).

/** Int32s per shape in a filter table: category, mask, group, sensor (1 for a sensor). */
export const FILTER_ROW = 4;

/** Whether shapes `a` and `b` (rows of `filters`) may make a contact. */
export function filterRowsAllow(filters: Int32Array, a: number, b: number): boolean {
  const fa = a * FILTER_ROW;
  const fb = b * FILTER_ROW;
  if (filters[fa + 3] !== 0 || filters[fb + 3] !== 0) return false;
  const group = filters[fa + 2]!;
  if (group === filters[fb + 2] && group !== 0) return group > 0;
  return (filters[fa]! & filters[fb + 1]!) !== 0 && (filters[fb]! & filters[fa + 1]!) !== 0;
}
