import {
  Box,
  Button,
  Dialog,
  DialogActions,
  DialogContent,
  DialogTitle,
  Slider,
  TextField,
  Typography,
} from '@mui/material';
import { useEffect, useState } from 'react';
import { useI18n } from '../../i18n/i18n.tsx';
import {
  MAX_ACCELERATION,
  MAX_MASS,
  MIN_ACCELERATION,
  MIN_MASS,
  forceFor,
  type SquareSettings,
} from './forces-scene.ts';

export interface SquareDialogProps {
  readonly open: boolean;
  readonly name: string;
  readonly settings: SquareSettings;
  readonly onClose: () => void;
  readonly onConfirm: (settings: SquareSettings) => void;
}

const clamp = (value: number, min: number, max: number): number =>
  Math.min(max, Math.max(min, value));

interface FieldProps {
  readonly id: string;
  readonly label: string;
  readonly unit: string;
  readonly value: number;
  readonly min: number;
  readonly max: number;
  readonly step: number;
  readonly onChange: (value: number) => void;
}

/** A number with a slider and a text field, kept in step. */
function NumberField({ id, label, unit, value, min, max, step, onChange }: FieldProps) {
  const [text, setText] = useState(String(value));
  useEffect(() => {
    setText((current) => (Number(current.replace(',', '.')) === value ? current : String(value)));
  }, [value]);
  return (
    <Box sx={{ mb: 2 }}>
      <Typography id={`${id}-label`} variant="body2" gutterBottom>
        {label}
      </Typography>
      <Box sx={{ display: 'flex', gap: 2, alignItems: 'center' }}>
        <Slider
          value={value}
          min={min}
          max={max}
          step={step}
          onChange={(_event, next) => onChange(next as number)}
          aria-labelledby={`${id}-label`}
          sx={{ flex: 1 }}
        />
        <TextField
          id={id}
          value={text}
          size="small"
          sx={{ width: 120 }}
          onChange={(event) => {
            setText(event.target.value);
            const parsed = Number(event.target.value.replace(',', '.'));
            if (event.target.value.trim() !== '' && Number.isFinite(parsed)) {
              onChange(clamp(parsed, min, max));
            }
          }}
          slotProps={{
            htmlInput: { inputMode: 'decimal', 'aria-label': `${label} (${unit})` },
            input: { endAdornment: <Typography variant="body2">{unit}</Typography> },
          }}
        />
      </Box>
    </Box>
  );
}

/** Sets a square's mass and desired acceleration; shows the force F = m a the app will apply. */
export function SquareDialog({ open, name, settings, onClose, onConfirm }: SquareDialogProps) {
  const { t, unit } = useI18n();
  const [mass, setMass] = useState(settings.mass);
  const [acceleration, setAcceleration] = useState(settings.acceleration);
  useEffect(() => {
    if (open) {
      setMass(settings.mass);
      setAcceleration(settings.acceleration);
    }
  }, [open, settings]);
  const force = forceFor(mass, acceleration);
  return (
    <Dialog
      open={open}
      onClose={onClose}
      aria-labelledby="square-dialog-title"
      fullWidth
      maxWidth="xs"
    >
      <DialogTitle id="square-dialog-title">{t('forces.dialogTitle', { name })}</DialogTitle>
      <DialogContent>
        <NumberField
          id="square-mass"
          label={t('forces.mass')}
          unit="kg"
          value={mass}
          min={MIN_MASS}
          max={MAX_MASS}
          step={0.1}
          onChange={setMass}
        />
        <NumberField
          id="square-acceleration"
          label={t('forces.acceleration')}
          unit="m/s²"
          value={acceleration}
          min={MIN_ACCELERATION}
          max={MAX_ACCELERATION}
          step={0.1}
          onChange={setAcceleration}
        />
        <Box
          sx={{ p: 1.5, borderRadius: 2, bgcolor: 'rgba(255, 138, 101, 0.12)' }}
          aria-live="polite"
        >
          <Typography variant="body2" sx={{ color: 'text.secondary' }}>
            {t('forces.force')}
          </Typography>
          <Typography variant="h6" component="p" data-readout="dialog-force">
            {unit(mass, 'kg', 2)} · {unit(acceleration, 'm/s²', 2)} = <b>{unit(force, 'N', 2)}</b>
          </Typography>
        </Box>
      </DialogContent>
      <DialogActions>
        <Button onClick={onClose}>{t('app.cancel')}</Button>
        <Button variant="contained" onClick={() => onConfirm({ mass, acceleration })}>
          {t('app.ok')}
        </Button>
      </DialogActions>
    </Dialog>
  );
}
