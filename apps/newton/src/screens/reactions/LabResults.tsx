import { Box, Typography } from '@mui/material';
import { useI18n } from '../../i18n/i18n.tsx';
import {
  kineticEnergyOf,
  momentumOf,
  totalKineticEnergyOf,
  totalMomentumOf,
  type CollisionRecord,
} from './collision-lab.ts';

/** Below this (kg m/s) a momentum component reads as none: a 1-D lab shows no y row. */
const NEGLIGIBLE = 5e-4;

/**
 * Before and after the chosen pair's last collision: each particle's momentum (its x and,
 * when any moves up or down, y component, kg m/s) and kinetic energy (J), and the totals.
 * Walls and the tilt are not in it: the record spans only the collision's own steps.
 */
export function LabResults({ record }: { record: CollisionRecord | null }) {
  const { t, number } = useI18n();
  if (record === null) {
    return (
      <Typography variant="body2" sx={{ color: 'text.secondary', px: 0.5 }} data-lab="waiting">
        {t('lab.waiting')}
      </Typography>
    );
  }
  const labels = record.before.map((state) => state.label);
  const columns = [...labels, 'total'];
  const rowFor = (moment: 'before' | 'after') => {
    const states = record[moment];
    const p = states.map(momentumOf);
    const total = totalMomentumOf(states);
    return {
      px: [...p.map((v) => v.x), total.x],
      py: [...p.map((v) => v.y), total.y],
      ke: [...states.map(kineticEnergyOf), totalKineticEnergyOf(states)],
    };
  };
  const before = rowFor('before');
  const after = rowFor('after');
  const hasY = [...before.py, ...after.py].some((value) => Math.abs(value) >= NEGLIGIBLE);
  const rows: { key: string; label: string; values: number[] }[] = [
    { key: 'px-before', label: t('lab.pxBefore'), values: before.px },
    { key: 'px-after', label: t('lab.pxAfter'), values: after.px },
    ...(hasY
      ? [
          { key: 'py-before', label: t('lab.pyBefore'), values: before.py },
          { key: 'py-after', label: t('lab.pyAfter'), values: after.py },
        ]
      : []),
    { key: 'ke-before', label: t('lab.keBefore'), values: before.ke },
    { key: 'ke-after', label: t('lab.keAfter'), values: after.ke },
  ];
  return (
    <Box
      component="table"
      aria-label={t('lab.results')}
      sx={{
        borderCollapse: 'collapse',
        width: '100%',
        fontVariantNumeric: 'tabular-nums',
        '& th, & td': { px: 0.5, py: 0.25, textAlign: 'right', fontSize: '0.8125rem' },
        '& th[scope="row"]': { textAlign: 'left', fontWeight: 400, color: 'text.secondary' },
        '& td:last-of-type, & th:last-of-type': { fontWeight: 700 },
      }}
    >
      <thead>
        <tr>
          <Box component="th" scope="col" sx={{ textAlign: 'left' }}>
            {t('lab.atTime', { time: number(record.time, 2, 2) })}
          </Box>
          {columns.map((column) => (
            <th key={column} scope="col">
              {column === 'total' ? t('lab.total') : column}
            </th>
          ))}
        </tr>
      </thead>
      <tbody>
        {rows.map((row) => (
          <tr key={row.key}>
            <th scope="row">{row.label}</th>
            {row.values.map((value, index) => (
              <td
                key={columns[index]}
                data-readout={`lab-${row.key}-${columns[index]}`}
                data-value={value}
              >
                {number(value, 3, 3)}
              </td>
            ))}
          </tr>
        ))}
      </tbody>
    </Box>
  );
}
