import type { ReactNode } from 'react';

/** Props of {@link Switch}. */
export interface SwitchProps {
  readonly checked: boolean;
  readonly onChange: (checked: boolean) => void;
  readonly label: ReactNode;
  /** The input's `data-control`, naming it for tests and tools. */
  readonly control?: string;
}

/**
 * A Material switch with its label: a native checkbox in the switch role (the label's whole
 * row, 48 px tall, toggles it), drawn as a track and a thumb by `ui.css`.
 */
export function Switch({ checked, onChange, label, control }: SwitchProps) {
  return (
    <label className="ui-switch">
      <span className="ui-switch__box">
        <input
          type="checkbox"
          role="switch"
          className="ui-switch__input"
          checked={checked}
          onChange={(event) => onChange(event.currentTarget.checked)}
          data-control={control}
        />
        <span className="ui-switch__track" aria-hidden="true" />
        <span className="ui-switch__thumb" aria-hidden="true" />
      </span>
      <span className="ui-body2">{label}</span>
    </label>
  );
}
