import { useEffect, type ReactNode } from 'react';
import { SimControls, type SimControlsProps } from './SimControls.tsx';
import { useMediaQuery } from './use-media-query.ts';

/** Canvas and panel side by side: a wide screen, or any phone held sideways. */
export const SIDE_BY_SIDE = '(min-width: 960px), (orientation: landscape)';
// app.css shrinks the law's text to two lines on a small portrait phone (320x568 to 375x667)
// and to one on a short landscape phone.

export interface ScreenLayoutProps {
  readonly id: string;
  readonly active: boolean;
  /** The law's statement, shown on top. */
  readonly law: string;
  /** The simulation: takes the room that is left. */
  readonly stage: ReactNode;
  /** Readouts, graphs and the screen's own settings: they scroll when the phone is small. */
  readonly panel: ReactNode;
  /**
   * The screen's main buttons (Apply force, Start): always on the screen, below the panel,
   * never scrolled away.
   */
  readonly actions?: ReactNode;
  readonly controls: SimControlsProps;
}

/**
 * A screen: the law on top, the canvas filling the rest, then readouts and controls within thumb
 * reach. Side by side (canvas left, panel right) when the screen is wide or turned sideways. The
 * page itself never scrolls: on a small phone only the panel does, and the main buttons and the
 * simulation controls stay where the thumb is.
 */
export function ScreenLayout({
  id,
  active,
  law,
  stage,
  panel,
  actions,
  controls,
}: ScreenLayoutProps) {
  const sideBySide = useMediaQuery(SIDE_BY_SIDE);
  // The first screen is on the page (its code loaded on demand): the app is ready.
  useEffect(() => {
    if (active) document.documentElement.dataset['ready'] = 'true';
  }, [active]);
  const simControls = (
    <div className="screen__controls">
      <SimControls {...controls} />
    </div>
  );
  return (
    <section
      id={id}
      aria-labelledby={`${id}-law`}
      className={sideBySide ? 'screen screen--side' : 'screen'}
      style={active ? undefined : { display: 'none' }}
    >
      <p id={`${id}-law`} className="screen__law ui-body2" title={law}>
        {law}
      </p>
      <div className="screen__body">
        <div className="screen__stage-box">
          <div className="screen__stage">{stage}</div>
        </div>
        <div className="screen__side">
          <div data-panel={id} className="screen__panel">
            {panel}
          </div>
          {actions !== undefined && (
            <div data-actions={id} className="screen__actions">
              {actions}
            </div>
          )}
          {sideBySide && simControls}
        </div>
      </div>
      {!sideBySide && simControls}
    </section>
  );
}
