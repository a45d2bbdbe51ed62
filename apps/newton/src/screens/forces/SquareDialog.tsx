import {
  Box,
  Button,
  Dialog,
  DialogActions,
  IconButton,
  DialogContent,
  DialogTitle,
  Slider,
  TextField,
  Typography,
} from '@mui/material';
import { useEffect, useState } from 'react';
import { AddIcon, MinusIcon } from '../../app/icons.tsx';
import { parseDecimal } from '../../app/parse-decimal.ts';
import { useI18n } from '../../i18n/i18n.tsx';
import { MAX_FORCE, MAX_MASS, MIN_FORCE, MIN_MASS, type SquareSettings } from './forces-scene.ts';

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
  readonly text: string;
  readonly min: number;
  readonly max: number;
  readonly step: number;
  readonly onText: (text: string) => void;
}

/**
 * A number three ways, kept in step: a slider, a text field validated as you type (the error
 * and the range show under it) and minus / plus buttons that step it (PhET's number spinner).
 */
function NumberField({ id, label, unit, text, min, max, step, onText }: FieldProps) {
  const { t, number } = useI18n();
  const parsed = parseDecimal(text, min, max);
  const range = t('field.range', { min: number(min, 2), max: number(max, 2), unit });
  const error = parsed.ok
    ? null
    : parsed.reason === 'outOfRange'
      ? t('field.outOfRange', { min: number(min, 2), max: number(max, 2), unit })
      : parsed.reason === 'empty'
        ? t('field.empty')
        : t('field.notANumber');
  const current = parsed.ok ? parsed.value : null;
  const stepBy = (direction: number): void => {
    const from = current ?? min;
    const next = clamp(Math.round((from + direction * step) / step) * step, min, max);
    onText(String(Math.round(next * 100) / 100));
  };
  return (
    <Box sx={{ mb: 1.5 }}>
      <Typography id={`${id}-label`} variant="body2" gutterBottom>
        {label}
      </Typography>
      <Slider
        value={current ?? min}
        min={min}
        max={max}
        step={step}
        onChange={(_event, next) => onText(String(next as number))}
        aria-labelledby={`${id}-label`}
        getAriaValueText={(value) => `${number(value, 2)} ${unit}`}
        sx={{ mx: 1, width: 'calc(100% - 16px)' }}
      />
      <Box sx={{ display: 'flex', gap: 1, alignItems: 'flex-start' }}>
        <IconButton
          aria-label={t('field.decrease', { label })}
          onClick={() => stepBy(-1)}
          disabled={current !== null && current <= min}
          data-action={`${id}-minus`}
          sx={{ width: 48, height: 48 }}
        >
          <MinusIcon />
        </IconButton>
        <TextField
          id={id}
          value={text}
          size="small"
          error={error !== null}
          helperText={error ?? range}
          sx={{ flex: 1 }}
          onChange={(event) => onText(event.target.value)}
          slotProps={{
            htmlInput: {
              inputMode: 'decimal',
              'aria-label': `${label} (${unit})`,
              'aria-invalid': error !== null,
              'aria-describedby': `${id}-helper-text`,
            },
            input: { endAdornment: <Typography variant="body2">{unit}</Typography> },
            formHelperText: { id: `${id}-helper-text`, 'data-helper': id } as object,
          }}
        />
        <IconButton
          aria-label={t('field.increase', { label })}
          onClick={() => stepBy(1)}
          disabled={current !== null && current >= max}
          data-action={`${id}-plus`}
          sx={{ width: 48, height: 48 }}
        >
          <AddIcon />
        </IconButton>
      </Box>
    </Box>
  );
}

/**
 * Sets a square's mass and the force that will push it: the cause. The acceleration is the
 * effect, for the learner to measure on the track (not given away here).
 */
export function SquareDialog({ open, name, settings, onClose, onConfirm }: SquareDialogProps) {
  const { t } = useI18n();
  const [massText, setMassText] = useState(String(settings.mass));
  const [forceText, setForceText] = useState(String(settings.force));
  useEffect(() => {
    if (open) {
      setMassText(String(settings.mass));
      setForceText(String(settings.force));
    }
  }, [open, settings]);
  const mass = parseDecimal(massText, MIN_MASS, MAX_MASS);
  const force = parseDecimal(forceText, MIN_FORCE, MAX_FORCE);
  const valid = mass.ok && force.ok;
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
          text={massText}
          min={MIN_MASS}
          max={MAX_MASS}
          step={0.1}
          onText={setMassText}
        />
        <NumberField
          id="square-force"
          label={t('forces.force')}
          unit="N"
          text={forceText}
          min={MIN_FORCE}
          max={MAX_FORCE}
          step={0.1}
          onText={setForceText}
        />
      </DialogContent>
      <DialogActions>
        <Button onClick={onClose} sx={{ minHeight: 48 }}>
          {t('app.cancel')}
        </Button>
        <Button
          variant="contained"
          disabled={!valid}
          sx={{ minHeight: 48, minWidth: 64 }}
          onClick={() => {
            if (mass.ok && force.ok) onConfirm({ mass: mass.value, force: force.value });
          }}
        >
          {t('app.ok')}
        </Button>
      </DialogActions>
    </Dialog>
  );
}
