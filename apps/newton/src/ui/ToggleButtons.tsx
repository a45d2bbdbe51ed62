import type { ReactNode } from 'react';

/** One choice of a {@link ToggleButtons} group. */
export interface ToggleChoice<T extends string> {
  readonly value: T;
  readonly label: ReactNode;
  /** Attributes for the choice's button (`data-surface`, `lang`). */
  readonly attributes?: Record<`data-${string}`, string> & { lang?: string };
}

/** Props of {@link ToggleButtons}. */
export interface ToggleButtonsProps<T extends string> {
  readonly label: string;
  readonly value: T;
  readonly choices: readonly ToggleChoice<T>[];
  readonly onChange: (value: T) => void;
  readonly className?: string;
}

/**
 * Exclusive toggle buttons, as MUI's `ToggleButtonGroup exclusive`: a labelled group of buttons,
 * the chosen one pressed (`aria-pressed`).
 */
export function ToggleButtons<T extends string>({
  label,
  value,
  choices,
  onChange,
  className,
}: ToggleButtonsProps<T>) {
  return (
    <div
      role="group"
      aria-label={label}
      className={className === undefined ? 'ui-toggles' : `ui-toggles ${className}`}
    >
      {choices.map((choice) => (
        <button
          key={choice.value}
          type="button"
          className="ui-toggle"
          aria-pressed={choice.value === value}
          onClick={() => choice.value !== value && onChange(choice.value)}
          {...choice.attributes}
        >
          {choice.label}
        </button>
      ))}
    </div>
  );
}
