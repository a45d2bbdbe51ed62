import { useI18n } from '../i18n/i18n.tsx';
import { Slider } from '../ui/Slider.tsx';

/** Props of {@link ElasticitySlider}. */
export interface ElasticitySliderProps {
  /** Id of the label element (unique on the page). */
  readonly id: string;
  /** The label, without the value. */
  readonly label: string;
  /** Coefficient of restitution, 0 to 1. */
  readonly value: number;
  /** Called with the new coefficient, 0 to 1, in steps of 0.05. */
  readonly onChange: (elasticity: number) => void;
}

/**
 * The elasticity (coefficient of restitution) slider that Inertia and Reactions share: shown in
 * per cent, in steps of 5 %, labelled for screen readers.
 */
export function ElasticitySlider({ id, label, value, onChange }: ElasticitySliderProps) {
  const { number } = useI18n();
  return (
    <div className="elasticity">
      <div id={id} className="ui-caption">
        {label}: {number(value * 100, 0)} %
      </div>
      <Slider
        value={Math.round(value * 100)}
        min={0}
        max={100}
        step={5}
        onChange={(percent) => onChange(percent / 100)}
        aria-labelledby={id}
        valueText={(percent) => `${percent} %`}
        control="elasticity"
      />
    </div>
  );
}
