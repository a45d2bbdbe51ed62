import { Box, Typography } from '@mui/material';
import type { ReactNode } from 'react';

/**
 * A labelled live value: "Speed / 0.734 m/s". The value is a text, or a `LiveText` that
 * rewrites itself without a render.
 */
export function Readout({ label, value, name }: { label: string; value: ReactNode; name: string }) {
  return (
    <Box sx={{ minWidth: 0 }}>
      <Typography
        variant="caption"
        component="div"
        sx={{ color: 'text.secondary', lineHeight: 1.2 }}
      >
        {label}
      </Typography>
      <Typography
        variant="body2"
        component="div"
        data-readout={name}
        sx={{ fontVariantNumeric: 'tabular-nums', fontWeight: 500, whiteSpace: 'nowrap' }}
      >
        {value}
      </Typography>
    </Box>
  );
}
