import {
  Button,
  Dialog,
  DialogActions,
  DialogContent,
  DialogContentText,
  DialogTitle,
} from '@mui/material';
import { useI18n, type MessageKey } from '../i18n/i18n.tsx';
import { MuiTheme } from './MuiTheme.tsx';

/** Props of {@link HintDialog}. */
export interface HintDialogProps {
  readonly open: boolean;
  readonly onClose: () => void;
  /** The screen's name and hint. */
  readonly label: MessageKey;
  readonly hint: MessageKey;
}

/**
 * The hint of the screen shown, and the link to the teacher page: an MUI dialog, loaded with MUI
 * the first time the learner asks for it (not on the first screen's way).
 */
export function HintDialog({ open, onClose, label, hint }: HintDialogProps) {
  const { t } = useI18n();
  return (
    <MuiTheme>
      <Dialog open={open} onClose={onClose} aria-labelledby="hint-title">
        <DialogTitle id="hint-title">
          {t('app.hint')}: {t(label)}
        </DialogTitle>
        <DialogContent>
          <DialogContentText>{t(hint)}</DialogContentText>
          <DialogContentText sx={{ mt: 2 }}>
            <a
              href={t('app.teacherPage')}
              style={{ color: 'var(--color-primary)' }}
              data-action="teacher"
            >
              {t('app.teacher')}
            </a>
          </DialogContentText>
        </DialogContent>
        <DialogActions>
          <Button onClick={onClose}>{t('app.close')}</Button>
        </DialogActions>
      </Dialog>
    </MuiTheme>
  );
}
