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
import { Suspense, lazy, useEffect, useState } from 'react';
import { I18nProvider, LOCALES, preferredLocale, useI18n, type Locale } from '../i18n/i18n.tsx';
import { HintIcon, SoundOffIcon, SoundOnIcon } from './icons.tsx';
import { onSoundChange, setSoundEnabled, soundEnabled } from './sound.ts';
import { BottomNav, NavRail } from './Navigation.tsx';
import { SCREENS, screenFromHash, type ScreenId } from './screens.ts';
import { theme } from './theme.ts';

const LOCALE_KEY = 'newton.locale';
/** The other screens' code is fetched this long after the start if nothing was tapped (ms). */
const PREFETCH_AFTER_MS = 8000;

// Each screen is its own chunk, fetched the first time it is shown: the first screen paints
// without the code of the other two.
const InertiaScreen = lazy(() =>
  import('../screens/inertia/InertiaScreen.tsx').then((module) => ({
    default: module.InertiaScreen,
  })),
);
const ForcesScreen = lazy(() =>
  import('../screens/forces/ForcesScreen.tsx').then((module) => ({
    default: module.ForcesScreen,
  })),
);
const ReactionsScreen = lazy(() =>
  import('../screens/reactions/ReactionsScreen.tsx').then((module) => ({
    default: module.ReactionsScreen,
  })),
);

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
  // The rail on the side when there is room beside the screen: a tablet, or a phone turned
  // sideways (a bar below would take a fifth of its height).
  const wide = useMediaQuery('(min-width: 600px), (orientation: landscape)', { noSsr: true });
  const [screen, setScreen] = useState<ScreenId>(() => screenFromHash(location.hash));
  const [hintOpen, setHintOpen] = useState(false);
  // Screens stay mounted once shown (their worlds keep their state), hidden when not current.
  const [visited, setVisited] = useState<ReadonlySet<ScreenId>>(() => new Set([screen]));
  useEffect(() => {
    setVisited((old) => (old.has(screen) ? old : new Set([...old, screen])));
  }, [screen]);
  const current = SCREENS.find((item) => item.id === screen)!;
  // Once the learner has used the first screen (or after a while), fetch the others' code while
  // idle: switching is then instant. Not sooner: on a slow phone, parsing two screens' code
  // while the first one starts delayed its first tap.
  useEffect(() => {
    let idle = 0;
    const prefetch = (): void => {
      stop();
      const load = (): void => {
        void import('../screens/inertia/InertiaScreen.tsx');
        void import('../screens/forces/ForcesScreen.tsx');
        void import('../screens/reactions/ReactionsScreen.tsx');
      };
      if (typeof requestIdleCallback === 'function')
        idle = requestIdleCallback(load, { timeout: 3000 });
      else load();
    };
    const timer = setTimeout(prefetch, PREFETCH_AFTER_MS);
    const stop = (): void => {
      clearTimeout(timer);
      window.removeEventListener('pointerup', prefetch);
      window.removeEventListener('keyup', prefetch);
    };
    window.addEventListener('pointerup', prefetch);
    window.addEventListener('keyup', prefetch);
    return () => {
      stop();
      if (idle !== 0) cancelIdleCallback(idle);
    };
  }, []);

  useEffect(() => {
    const onHash = (): void => setScreen(screenFromHash(location.hash));
    window.addEventListener('hashchange', onHash);
    return () => window.removeEventListener('hashchange', onHash);
  }, []);
  useEffect(() => {
    document.title = `${t(current.label)} · ${t('app.title')}`;
  }, [current, t]);

  const go = (id: ScreenId): void => {
    setScreen(id);
    history.replaceState(null, '', `#${id}`);
  };

  return (
    <Box sx={{ height: '100dvh', display: 'flex', flexDirection: 'column', overflow: 'hidden' }}>
      <AppBar position="static" elevation={0} color="transparent" sx={{ bgcolor: '#1e1e1e' }}>
        <Toolbar variant="dense" sx={{ gap: 0.5, minHeight: 52, px: { xs: 1.5, sm: 2 } }}>
          <Typography
            variant="h6"
            component="h1"
            sx={{ flex: 1, minWidth: 0, fontSize: wide ? '1.15rem' : '1.05rem' }}
            noWrap
          >
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
          <SoundToggle />
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
          <Suspense fallback={<ScreenLoading />}>
            {visited.has('inertia') && <InertiaScreen active={screen === 'inertia'} />}
            {visited.has('forces') && <ForcesScreen active={screen === 'forces'} />}
            {visited.has('reactions') && <ReactionsScreen active={screen === 'reactions'} />}
          </Suspense>
        </Box>
      </Box>
      {!wide && <BottomNav current={screen} onChange={go} />}
      <Dialog open={hintOpen} onClose={() => setHintOpen(false)} aria-labelledby="hint-title">
        <DialogTitle id="hint-title">
          {t('app.hint')}: {t(current.label)}
        </DialogTitle>
        <DialogContent>
          <DialogContentText>{t(current.hint)}</DialogContentText>
          <DialogContentText sx={{ mt: 2 }}>
            <a href={t('app.teacherPage')} style={{ color: '#82b1ff' }} data-action="teacher">
              {t('app.teacher')}
            </a>
          </DialogContentText>
        </DialogContent>
        <DialogActions>
          <Button onClick={() => setHintOpen(false)}>{t('app.close')}</Button>
        </DialogActions>
      </Dialog>
    </Box>
  );
}

/** Shown while a screen's code arrives; marks the app ready once it has. */
function ScreenLoading() {
  const { t } = useI18n();
  return (
    <Box
      role="progressbar"
      aria-label={t('app.loading')}
      aria-busy="true"
      sx={{ height: '100%', display: 'grid', placeItems: 'center', color: 'text.secondary' }}
    >
      …
    </Box>
  );
}

/** Sound on events: off until the learner turns it on. */
function SoundToggle() {
  const { t } = useI18n();
  const [on, setOn] = useState(soundEnabled);
  useEffect(() => onSoundChange(() => setOn(soundEnabled())), []);
  const label = on ? t('app.soundOff') : t('app.soundOn');
  return (
    <Tooltip title={label}>
      <IconButton
        aria-label={t('app.sound')}
        aria-pressed={on}
        onClick={() => setSoundEnabled(!on)}
        data-action="sound"
        sx={{ width: 48, height: 48 }}
      >
        {on ? <SoundOnIcon /> : <SoundOffIcon />}
      </IconButton>
    </Tooltip>
  );
}
