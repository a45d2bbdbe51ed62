import { Box, Typography } from '@mui/material';

/** A labelled live value: "Speed / 0.734 m/s". */
export function Readout({ label, value, name }: { label: string; value: string; name: string }) {
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
