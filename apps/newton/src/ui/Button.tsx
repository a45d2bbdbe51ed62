import type { ButtonHTMLAttributes, ReactNode } from 'react';

/** Props of {@link Button}: a native button's, and Material's look. */
export interface ButtonProps extends ButtonHTMLAttributes<HTMLButtonElement> {
  /** Material's three kinds: filled, outlined, or text only. Default text. */
  readonly variant?: 'contained' | 'outlined' | 'text';
  readonly color?: 'primary' | 'secondary';
  /** An icon before the label. */
  readonly startIcon?: ReactNode;
  /** Grows to share the row with its neighbours. */
  readonly grow?: boolean;
  /** Data attributes pass through (`data-action` names a control for tests and tools). */
  readonly [data: `data-${string}`]: string | undefined;
}

/** A Material button as a plain `<button>`, styled by `ui.css`. */
export function Button({
  variant = 'text',
  color = 'primary',
  startIcon,
  grow = false,
  className,
  children,
  type = 'button',
  ...rest
}: ButtonProps) {
  const classes = ['ui-button', `ui-button--${variant}`, `ui-button--${color}`];
  if (grow) classes.push('ui-grow');
  if (className !== undefined) classes.push(className);
  return (
    <button type={type} className={classes.join(' ')} {...rest}>
      {startIcon !== undefined && <span className="ui-button__icon">{startIcon}</span>}
      {children}
    </button>
  );
}
