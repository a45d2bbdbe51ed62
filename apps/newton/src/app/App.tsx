import { Suspense, lazy, useEffect, useState, type LazyExoticComponent } from 'react';
import { I18nProvider, LOCALES, preferredLocale, useI18n, type Locale } from '../i18n/i18n.tsx';
import { IconButton } from '../ui/IconButton.tsx';
import { ToggleButtons } from '../ui/ToggleButtons.tsx';
import { HintIcon, SoundOffIcon, SoundOnIcon } from './icons.tsx';
import { onSoundChange, setSoundEnabled, soundEnabled } from './sound.ts';
import { BottomNav, NavRail } from './Navigation.tsx';
import { SCREEN_MODULES, type FirstScreen, type ScreenComponent } from './screen-modules.ts';
import { SCREENS, screenFromHash, type ScreenId } from './screens.ts';
import { useMediaQuery } from './use-media-query.ts';
import '../ui/ui.css';
import './app.css';

const LOCALE_KEY = 'newton.locale';
/** The other screens' code is fetched this long after the start if nothing was tapped (ms). */
const PREFETCH_AFTER_MS = 8000;

// Each screen is its own chunk, fetched the first time it is shown (the first one by main.tsx,
// before the first render).
const LAZY_SCREENS = Object.fromEntries(
  SCREENS.map(({ id }) => [
    id,
    lazy(() => SCREEN_MODULES[id]().then((Component) => ({ default: Component }))),
  ]),
) as Record<ScreenId, ScreenComponent | LazyExoticComponent<ScreenComponent>>;
// The hint's dialog is MUI's: it loads with MUI the first time it is asked for.
const HintDialog = lazy(() =>
  import('./HintDialog.tsx').then((module) => ({ default: module.HintDialog })),
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

/**
 * The app: a top bar with the screen's name, the screens, and the navigation. `first` is the
 * screen it opens with, its code already loaded (main.tsx): shown at once, with no fallback.
 */
export function App({ first }: { first?: FirstScreen | undefined }) {
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
    <I18nProvider locale={locale}>
      <Shell locale={locale} onLocale={setLocale} first={first} />
    </I18nProvider>
  );
}

function Shell({
  locale,
  onLocale,
  first,
}: {
  locale: Locale;
  onLocale: (locale: Locale) => void;
  first: FirstScreen | undefined;
}) {
  const { t } = useI18n();
  // The first screen's component as loaded, the others lazily: a lazy component suspends on its
  // first render even when its code is here, and React holds a reveal back until 300 ms after
  // the fallback it replaces was shown.
  const [screens] = useState(() =>
    first === undefined ? LAZY_SCREENS : { ...LAZY_SCREENS, [first.id]: first.Component },
  );
  const { inertia: InertiaScreen, forces: ForcesScreen, reactions: ReactionsScreen } = screens;
  // The rail on the side when there is room beside the screen: a tablet, or a phone turned
  // sideways (a bar below would take a fifth of its height).
  const wide = useMediaQuery('(min-width: 600px), (orientation: landscape)');
  const [screen, setScreen] = useState<ScreenId>(() => screenFromHash(location.hash));
  const [hintOpen, setHintOpen] = useState(false);
  // The hint's dialog (and MUI with it) loads the first time it is opened.
  const [hintShown, setHintShown] = useState(false);
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
        for (const module of Object.values(SCREEN_MODULES)) void module();
        void import('./HintDialog.tsx');
        void import('../screens/inertia/ForceDialog.tsx');
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
    <div className="app">
      <header className="app-bar">
        <h1 className={wide ? 'app-bar__title' : 'app-bar__title app-bar__title--narrow'}>
          {wide && <span className="app-bar__app">{t('app.title')} · </span>}
          {t(current.label)}
        </h1>
        <IconButton
          aria-label={t('app.hint')}
          tip={t('app.hint')}
          onClick={() => {
            setHintOpen(true);
            setHintShown(true);
          }}
          data-action="hint"
        >
          <HintIcon color="var(--color-hint)" />
        </IconButton>
        <SoundToggle />
        <ToggleButtons
          label={t('app.language')}
          value={locale}
          onChange={onLocale}
          className="app-bar__locales"
          choices={LOCALES.map((item) => ({
            value: item,
            label: item.toUpperCase(),
            attributes: { lang: item, 'data-locale': item },
          }))}
        />
      </header>
      <div className="app-body">
        {wide && <NavRail current={screen} onChange={go} />}
        <main className="app-main">
          <Suspense fallback={<ScreenLoading />}>
            {visited.has('inertia') && <InertiaScreen active={screen === 'inertia'} />}
            {visited.has('forces') && <ForcesScreen active={screen === 'forces'} />}
            {visited.has('reactions') && <ReactionsScreen active={screen === 'reactions'} />}
          </Suspense>
        </main>
      </div>
      {!wide && <BottomNav current={screen} onChange={go} />}
      {hintShown && (
        <Suspense fallback={null}>
          <HintDialog
            open={hintOpen}
            onClose={() => setHintOpen(false)}
            label={current.label}
            hint={current.hint}
          />
        </Suspense>
      )}
    </div>
  );
}

/** Shown while a screen's code arrives; marks the app ready once it has. */
function ScreenLoading() {
  const { t } = useI18n();
  return (
    <div role="progressbar" aria-label={t('app.loading')} aria-busy="true" className="app-loading">
      …
    </div>
  );
}

/** Sound on events: off until the learner turns it on. */
function SoundToggle() {
  const { t } = useI18n();
  const [on, setOn] = useState(soundEnabled);
  useEffect(() => onSoundChange(() => setOn(soundEnabled())), []);
  const label = on ? t('app.soundOff') : t('app.soundOn');
  return (
    <IconButton
      aria-label={t('app.sound')}
      tip={label}
      aria-pressed={on}
      onClick={() => setSoundEnabled(!on)}
      data-action="sound"
    >
      {on ? <SoundOnIcon /> : <SoundOffIcon />}
    </IconButton>
  );
}
