import { Box, Button, FormControlLabel, Switch, TextField, Typography } from '@mui/material';
import { useState } from 'react';
import { parseDecimal } from '../../app/parse-decimal.ts';
import { useI18n } from '../../i18n/i18n.tsx';
import { MAX_MASS, MIN_MASS } from './forces-scene.ts';

export interface MysteryMassProps {
  /** B's hidden mass (kg), or null while the mystery is off. */
  readonly mass: number | null;
  /** The learner found it: the mass is shown. */
  readonly found: boolean;
  readonly onToggle: (on: boolean) => void;
  /** A guess (kg), validated to the masses a square can have. */
  readonly onGuess: (guess: number) => void;
}

/**
 * PhET's mystery object: B gets a hidden mass and A's force; the learner measures B's
 * acceleration and types m = F / a, checked to 5 %.
 */
export function MysteryMass({ mass, found, onToggle, onGuess }: MysteryMassProps) {
  const { t, number, unit } = useI18n();
  const [text, setText] = useState('');
  const parsed = parseDecimal(text, MIN_MASS, MAX_MASS);
  const error =
    text.trim() === '' || parsed.ok
      ? null
      : parsed.reason === 'outOfRange'
        ? t('field.outOfRange', { min: number(MIN_MASS, 2), max: number(MAX_MASS, 2), unit: 'kg' })
        : t('field.notANumber');
  const submit = (): void => {
    if (parsed.ok) onGuess(parsed.value);
  };
  return (
    <Box sx={{ px: 0.5 }}>
      <FormControlLabel
        sx={{ minHeight: 48, mr: 0 }}
        control={
          <Switch
            checked={mass !== null}
            onChange={(_event, value) => {
              setText('');
              onToggle(value);
            }}
            slotProps={{ input: { 'data-control': 'mystery' } as object }}
          />
        }
        label={<Typography variant="body2">{t('forces.mystery')}</Typography>}
      />
      {mass !== null && (
        <Box
          component="form"
          onSubmit={(event) => {
            event.preventDefault();
            submit();
          }}
          sx={{ display: 'flex', gap: 1, alignItems: 'flex-start' }}
        >
          {found ? (
            <Typography variant="body2" data-readout="mystery-result" sx={{ py: 1.5 }}>
              {t('forces.mysteryRight', { mass: unit(mass, 'kg', 1) })}
            </Typography>
          ) : (
            <>
              <TextField
                id="mystery-guess"
                size="small"
                value={text}
                label={t('forces.mysteryGuess')}
                error={error !== null}
                helperText={error ?? t('forces.mysteryHelp')}
                onChange={(event) => setText(event.target.value)}
                sx={{ flex: 1 }}
                slotProps={{
                  htmlInput: { inputMode: 'decimal', 'aria-invalid': error !== null },
                  input: { endAdornment: <Typography variant="body2">kg</Typography> },
                }}
              />
              <Button
                type="submit"
                variant="outlined"
                disabled={!parsed.ok}
                sx={{ minHeight: 48 }}
                data-action="check-mystery"
              >
                {t('forces.mysteryCheck')}
              </Button>
            </>
          )}
        </Box>
      )}
    </Box>
  );
}
