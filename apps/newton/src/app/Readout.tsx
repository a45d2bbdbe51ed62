import type { ReactNode } from 'react';

/**
 * A labelled live value: "Speed / 0.734 m/s". The value is a text, or a `LiveText` that
 * rewrites itself without a render.
 */
export function Readout({ label, value, name }: { label: string; value: ReactNode; name: string }) {
  return (
    <div className="readout">
      <div className="ui-caption ui-secondary readout__label">{label}</div>
      <div className="ui-body2 ui-numbers readout__value" data-readout={name}>
        {value}
      </div>
    </div>
  );
}
