import { Box, TextField, Typography } from '@mui/material';
import { useState } from 'react';
import { useI18n, type MessageKey } from '../../i18n/i18n.tsx';
import { MAX_MASS, MAX_SPEED, MIN_MASS } from './reactions-scene.ts';

/** One chosen particle as the setup table shows it. */
export interface LabRow {
  readonly label: string;
  readonly mass: number;
  readonly vx: number;
  readonly vy: number;
  /** The particle is the one selected (its row is marked). */
  readonly selected: boolean;
}

/** Which value of a row was typed. */
export type LabField = 'mass' | 'vx' | 'vy';

/** Props of {@link LabSetup}. */
export interface LabSetupProps {
  readonly rows: readonly LabRow[];
  /** Changes with every outside change of the values (a drag, a step): the fields refill. */
  readonly version: number;
  readonly onChange: (label: string, field: LabField, value: number) => void;
}

/** A signed decimal with a point or a comma ("-1,5"); null when it is not one. */
export function readSigned(text: string): number | null {
  const match = /^\s*([-+−]?)(\d+(?:[.,]\d*)?|[.,]\d+)\s*$/.exec(text);
  if (match === null) return null;
  const value = Number(match[2]!.replace(',', '.'));
  return match[1] === '-' || match[1] === '−' ? -value : value;
}

const NAMES: Record<LabField, MessageKey> = { mass: 'lab.massOf', vx: 'lab.vxOf', vy: 'lab.vyOf' };

const RANGES: Record<LabField, [number, number]> = {
  mass: [MIN_MASS, MAX_MASS],
  vx: [-MAX_SPEED, MAX_SPEED],
  vy: [-MAX_SPEED, MAX_SPEED],
};

/** One number field of the table: applies a valid value on Enter or leaving it. */
function LabField({
  label,
  field,
  value,
  name,
  onChange,
}: {
  label: string;
  field: LabField;
  value: number;
  name: string;
  onChange: LabSetupProps['onChange'];
}) {
  const { t, number } = useI18n();
  const [text, setText] = useState(() => number(value, 3));
  const [min, max] = RANGES[field];
  const parsed = readSigned(text);
  const valid = parsed !== null && parsed >= min && parsed <= max;
  const commit = (): void => {
    if (valid && Math.abs(parsed - value) > 1e-12) onChange(label, field, parsed);
  };
  return (
    <TextField
      size="small"
      value={text}
      onChange={(event) => setText(event.target.value)}
      onBlur={commit}
      onKeyDown={(event) => {
        if (event.key === 'Enter') commit();
      }}
      error={!valid}
      slotProps={{
        htmlInput: {
          inputMode: 'decimal',
          'aria-label': name,
          'aria-invalid': !valid,
          'aria-description': t('lab.range', { min: number(min), max: number(max) }),
          'data-lab-input': `${label}-${field}`,
          style: { fontVariantNumeric: 'tabular-nums', padding: '10px 8px', minHeight: 28 },
        },
      }}
      sx={{ minWidth: 0 }}
    />
  );
}

/**
 * The collision lab's table: for each chosen particle its mass and velocity (x right, y down
 * the screen), typed in. Each field checks its range and applies on Enter or on leaving it.
 */
export function LabSetup({ rows, version, onChange }: LabSetupProps) {
  const { t } = useI18n();
  if (rows.length === 0) {
    return (
      <Typography variant="body2" sx={{ color: 'text.secondary', px: 0.5 }}>
        {t('lab.choose')}
      </Typography>
    );
  }
  return (
    <Box
      role="group"
      aria-label={t('lab.setup')}
      sx={{
        display: 'grid',
        gridTemplateColumns: '2.2em repeat(3, minmax(0, 1fr))',
        gap: 0.75,
        alignItems: 'center',
      }}
    >
      <span />
      <Typography variant="caption" component="div">
        {t('lab.mass')}
      </Typography>
      <Typography variant="caption" component="div">
        {t('lab.vx')}
      </Typography>
      <Typography variant="caption" component="div">
        {t('lab.vy')}
      </Typography>
      {rows.map((row) => (
        <Box key={row.label} sx={{ display: 'contents' }}>
          <Typography
            component="div"
            sx={{ fontWeight: 700, color: row.selected ? 'primary.main' : 'text.primary' }}
          >
            {row.label}
          </Typography>
          {(['mass', 'vx', 'vy'] as const).map((field) => (
            <LabField
              key={`${row.label}-${field}-${version}`}
              label={row.label}
              field={field}
              value={row[field]}
              name={t(NAMES[field], { name: row.label })}
              onChange={onChange}
            />
          ))}
        </Box>
      ))}
    </Box>
  );
}
