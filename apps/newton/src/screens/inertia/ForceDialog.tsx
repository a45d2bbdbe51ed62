import {
  Box,
  Button,
  Dialog,
  DialogActions,
  DialogContent,
  DialogTitle,
  Slider,
  Typography,
} from '@mui/material';
import { useEffect, useState } from 'react';
import { MuiTheme } from '../../app/MuiTheme.tsx';
import { useI18n } from '../../i18n/i18n.tsx';
import { AngleDial } from './AngleDial.tsx';
import { directionName } from './direction-name.ts';
import { MAX_FORCE, MIN_FORCE } from './inertia-scene.ts';

export interface ForceDialogProps {
  readonly open: boolean;
  readonly angle: number;
  readonly magnitude: number;
  readonly sides: number;
  readonly onClose: () => void;
  readonly onConfirm: (angle: number, magnitude: number) => void;
}

/**
 * "Change force": turn an arrow around a picture of the object and set its magnitude. An MUI
 * dialog, loaded (with MUI) the first time it opens: the Inertia screen paints without it.
 */
export function ForceDialog({
  open,
  angle,
  magnitude,
  sides,
  onClose,
  onConfirm,
}: ForceDialogProps) {
  const { t, unit } = useI18n();
  const [draftAngle, setDraftAngle] = useState(angle);
  const [draftMagnitude, setDraftMagnitude] = useState(magnitude);
  useEffect(() => {
    if (open) {
      setDraftAngle(angle);
      setDraftMagnitude(magnitude);
    }
  }, [open, angle, magnitude]);

  const valueText = t('inertia.angleValue', {
    value: draftAngle,
    name: t(directionName(draftAngle)),
  });
  return (
    <MuiTheme>
      <Dialog
        open={open}
        onClose={onClose}
        aria-labelledby="force-dialog-title"
        fullWidth
        maxWidth="xs"
      >
        <DialogTitle id="force-dialog-title">{t('inertia.dialogTitle')}</DialogTitle>
        <DialogContent>
          <Typography variant="body2" sx={{ color: 'text.secondary', mb: 1 }}>
            {t('inertia.dialogHelp')}
          </Typography>
          <AngleDial
            angle={draftAngle}
            onChange={setDraftAngle}
            sides={sides}
            label={t('inertia.angle')}
            valueText={valueText}
          />
          <Typography align="center" variant="body2" sx={{ mt: 1 }} data-readout="dialog-angle">
            {valueText}
          </Typography>
          <Box sx={{ mt: 2, px: 1 }}>
            <Typography id="force-magnitude-label" variant="body2" gutterBottom>
              {t('inertia.magnitude')}: <b>{unit(draftMagnitude, 'N', 1)}</b>
            </Typography>
            <Slider
              value={draftMagnitude}
              min={MIN_FORCE}
              max={MAX_FORCE}
              step={0.1}
              onChange={(_event, value) => setDraftMagnitude(value as number)}
              aria-labelledby="force-magnitude-label"
              getAriaValueText={(value) => unit(value, 'N', 1)}
            />
          </Box>
        </DialogContent>
        <DialogActions>
          <Button onClick={onClose}>{t('app.cancel')}</Button>
          <Button variant="contained" onClick={() => onConfirm(draftAngle, draftMagnitude)}>
            {t('app.ok')}
          </Button>
        </DialogActions>
      </Dialog>
    </MuiTheme>
  );
}
