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

/**
 * The screens as links (`#inertia`...), the current one marked: a bottom bar on phones, a
 * Material navigation rail on wide screens (`kind`). Plain elements styled by app.css.
 */
function ScreenLinks({ current, onChange, kind }: NavigationProps & { kind: 'bar' | 'rail' }) {
  const { t } = useI18n();
  return (
    <nav aria-label={t('app.navigation')} className={`app-nav app-nav--${kind}`}>
      {SCREENS.map(({ id, label }) => (
        <a
          key={id}
          href={`#${id}`}
          className="app-nav__link"
          onClick={(event) => {
            event.preventDefault();
            onChange(id);
          }}
          aria-current={current === id ? 'page' : undefined}
          aria-label={wholeWord(t(label))}
          data-nav={id}
        >
          <span className="app-nav__icon">{ICONS[id]}</span>
          {/* A long word breaks at its soft hyphen (shown as a hyphen) rather than run past. */}
          <span className="app-nav__label">{t(label)}</span>
        </a>
      ))}
    </nav>
  );
}

/** Bottom navigation on phones. */
export function BottomNav(props: NavigationProps) {
  return <ScreenLinks {...props} kind="bar" />;
}

/** A Material navigation rail on wide screens. */
export function NavRail(props: NavigationProps) {
  return <ScreenLinks {...props} kind="rail" />;
}
