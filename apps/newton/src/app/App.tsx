import {
  AppBar,
  Box,
  Button,
  CssBaseline,
  Dialog,
  DialogActions,
  DialogContent,
  DialogContentText,
  DialogTitle,
  IconButton,
  ThemeProvider,
  ToggleButton,
  ToggleButtonGroup,
  Toolbar,
  Tooltip,
  Typography,
  useMediaQuery,
} from '@mui/material';
import { useEffect, useState } from 'react';
import { I18nProvider, LOCALES, preferredLocale, useI18n, type Locale } from '../i18n/i18n.tsx';
import { ForcesScreen } from '../screens/forces/ForcesScreen.tsx';
import { InertiaScreen } from '../screens/inertia/InertiaScreen.tsx';
import { ReactionsScreen } from '../screens/reactions/ReactionsScreen.tsx';
import { HintIcon } from './icons.tsx';
import { BottomNav, NavRail } from './Navigation.tsx';
import { SCREENS, screenFromHash, type ScreenId } from './screens.ts';
import { theme } from './theme.ts';

const LOCALE_KEY = 'newton.locale';

function initialLocale(): Locale {
  try {
    const saved = localStorage.getItem(LOCALE_KEY);
    if (saved === 'en' || saved === 'de') return saved;
  } catch {
    // Storage may be blocked; fall back to the browser's languages.
  }
  return preferredLocale(navigator.languages ?? [navigator.language]);
}

/** The app: a top bar with the screen's name, the screens, and the navigation. */
export function App() {
  const [locale, setLocale] = useState<Locale>(initialLocale);
  useEffect(() => {
    document.documentElement.lang = locale;
    try {
      localStorage.setItem(LOCALE_KEY, locale);
    } catch {
      // Not saved: the choice lasts for this visit.
    }
  }, [locale]);
  return (
    <ThemeProvider theme={theme}>
      <CssBaseline />
      <I18nProvider locale={locale}>
        <Shell locale={locale} onLocale={setLocale} />
      </I18nProvider>
    </ThemeProvider>
  );
}

function Shell({ locale, onLocale }: { locale: Locale; onLocale: (locale: Locale) => void }) {
  const { t } = useI18n();
  const wide = useMediaQuery('(min-width: 600px)', { noSsr: true });
  const [screen, setScreen] = useState<ScreenId>(() => screenFromHash(location.hash));
  const [hintOpen, setHintOpen] = useState(false);
  const current = SCREENS.find((item) => item.id === screen)!;

  useEffect(() => {
    const onHash = (): void => setScreen(screenFromHash(location.hash));
    window.addEventListener('hashchange', onHash);
    return () => window.removeEventListener('hashchange', onHash);
  }, []);
  useEffect(() => {
    document.title = `${t(current.label)} · ${t('app.title')}`;
    document.documentElement.dataset['ready'] = 'true';
  }, [current, t]);

  const go = (id: ScreenId): void => {
    setScreen(id);
    history.replaceState(null, '', `#${id}`);
  };

  return (
    <Box sx={{ height: '100dvh', display: 'flex', flexDirection: 'column', overflow: 'hidden' }}>
      <AppBar position="static" elevation={0} color="transparent" sx={{ bgcolor: '#1e1e1e' }}>
        <Toolbar variant="dense" sx={{ gap: 1, minHeight: 52 }}>
          <Typography variant="h6" component="h1" sx={{ flex: 1, fontSize: '1.15rem' }} noWrap>
            <Box
              component="span"
              sx={{ color: 'text.secondary', fontWeight: 400, display: wide ? 'inline' : 'none' }}
            >
              {t('app.title')} ·{' '}
            </Box>
            {t(current.label)}
          </Typography>
          <Tooltip title={t('app.hint')}>
            <IconButton
              aria-label={t('app.hint')}
              onClick={() => setHintOpen(true)}
              data-action="hint"
              sx={{ width: 48, height: 48 }}
            >
              <HintIcon sx={{ color: '#ffd54f' }} />
            </IconButton>
          </Tooltip>
          <ToggleButtonGroup
            value={locale}
            exclusive
            size="small"
            aria-label={t('app.language')}
            onChange={(_event, value: Locale | null) => value !== null && onLocale(value)}
          >
            {LOCALES.map((item) => (
              <ToggleButton
                key={item}
                value={item}
                lang={item}
                sx={{ minWidth: 48, minHeight: 48, px: 1.25, py: 0.25 }}
                data-locale={item}
              >
                {item.toUpperCase()}
              </ToggleButton>
            ))}
          </ToggleButtonGroup>
        </Toolbar>
      </AppBar>
      <Box sx={{ flex: 1, minHeight: 0, display: 'flex' }}>
        {wide && <NavRail current={screen} onChange={go} />}
        <Box component="main" sx={{ flex: 1, minWidth: 0, minHeight: 0 }}>
          <InertiaScreen active={screen === 'inertia'} />
          <ForcesScreen active={screen === 'forces'} />
          <ReactionsScreen active={screen === 'reactions'} />
        </Box>
      </Box>
      {!wide && <BottomNav current={screen} onChange={go} />}
      <Dialog open={hintOpen} onClose={() => setHintOpen(false)} aria-labelledby="hint-title">
        <DialogTitle id="hint-title">
          {t('app.hint')}: {t(current.label)}
        </DialogTitle>
        <DialogContent>
          <DialogContentText>{t(current.hint)}</DialogContentText>
        </DialogContent>
        <DialogActions>
          <Button onClick={() => setHintOpen(false)}>{t('app.close')}</Button>
        </DialogActions>
      </Dialog>
    </Box>
  );
}
