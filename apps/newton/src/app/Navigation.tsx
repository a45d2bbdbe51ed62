import {
  BottomNavigation,
  BottomNavigationAction,
  Box,
  ButtonBase,
  Typography,
} from '@mui/material';
import type { ReactElement } from 'react';
import { useI18n } from '../i18n/i18n.tsx';
import { ForceIcon, InertiaIcon, ReactionIcon } from './icons.tsx';
import { SCREENS, type ScreenId } from './screens.ts';

const ICONS: Record<ScreenId, ReactElement> = {
  inertia: <InertiaIcon />,
  forces: <ForceIcon />,
  reactions: <ReactionIcon />,
};

/**
 * A label as its accessible name: without the soft hyphens (U+00AD) a message may hold where a
 * long word can break in the narrow rail ("Wechsel-wirkung" in German), so that a screen reader
 * and a search by name find the word whole.
 */
export function wholeWord(label: string): string {
  return label.replace(/\u00ad/g, '');
}

export interface NavigationProps {
  readonly current: ScreenId;
  readonly onChange: (screen: ScreenId) => void;
}

/** Bottom navigation on phones. */
export function BottomNav({ current, onChange }: NavigationProps) {
  const { t } = useI18n();
  return (
    <Box component="nav" aria-label={t('app.navigation')}>
      <BottomNavigation
        showLabels
        value={current}
        onChange={(_event, value: ScreenId) => onChange(value)}
        sx={{ bgcolor: '#1e1e1e', borderTop: '1px solid rgba(255, 255, 255, 0.08)', height: 60 }}
      >
        {SCREENS.map(({ id, label }) => (
          <BottomNavigationAction
            key={id}
            value={id}
            label={t(label)}
            aria-label={wholeWord(t(label))}
            icon={ICONS[id]}
            aria-current={current === id ? 'page' : undefined}
            href={`#${id}`}
            data-nav={id}
            sx={{
              '&.Mui-selected': { color: 'primary.main' },
              '& .MuiBottomNavigationAction-label, & .MuiBottomNavigationAction-label.Mui-selected':
                { fontSize: '0.875rem' },
            }}
          />
        ))}
      </BottomNavigation>
    </Box>
  );
}

/** A Material navigation rail on wide screens. */
export function NavRail({ current, onChange }: NavigationProps) {
  const { t } = useI18n();
  return (
    <Box
      component="nav"
      aria-label={t('app.navigation')}
      sx={{
        width: 80,
        flexShrink: 0,
        bgcolor: '#1e1e1e',
        borderRight: '1px solid rgba(255, 255, 255, 0.08)',
        display: 'flex',
        flexDirection: 'column',
        alignItems: 'center',
        gap: 1.5,
        pt: 2,
      }}
    >
      {SCREENS.map(({ id, label }) => {
        const selected = current === id;
        return (
          <ButtonBase
            key={id}
            href={`#${id}`}
            onClick={(event) => {
              event.preventDefault();
              onChange(id);
            }}
            aria-current={selected ? 'page' : undefined}
            aria-label={wholeWord(t(label))}
            data-nav={id}
            sx={{
              flexDirection: 'column',
              gap: 0.5,
              width: 72,
              py: 0.5,
              borderRadius: 2,
              color: selected ? 'primary.main' : 'text.secondary',
            }}
          >
            <Box
              sx={{
                width: 56,
                height: 32,
                borderRadius: 4,
                display: 'grid',
                placeItems: 'center',
                bgcolor: selected ? 'rgba(130, 177, 255, 0.16)' : 'transparent',
              }}
            >
              {ICONS[id]}
            </Box>
            {/* A long word breaks at its soft hyphen (shown as a hyphen) rather than run past. */}
            <Typography
              variant="caption"
              sx={{
                fontWeight: selected ? 700 : 500,
                maxWidth: '100%',
                textAlign: 'center',
                hyphens: 'manual',
                lineHeight: 1.25,
              }}
            >
              {t(label)}
            </Typography>
          </ButtonBase>
        );
      })}
    </Box>
  );
}
