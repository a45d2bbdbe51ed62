import type { ButtonHTMLAttributes } from 'react';

/** Props of {@link IconButton}: a native button's; `aria-label` is required (it has no text). */
export interface IconButtonProps extends ButtonHTMLAttributes<HTMLButtonElement> {
  readonly 'aria-label': string;
  readonly color?: 'default' | 'primary';
  /** A tooltip on hover (a mouse); the name screen readers say is `aria-label`. */
  readonly tip?: string;
  readonly [data: `data-${string}`]: string | undefined;
}

/** A round 48 px icon button, as MUI's `IconButton size="large"`. */
export function IconButton({
  color = 'default',
  tip,
  className,
  type = 'button',
  ...rest
}: IconButtonProps) {
  const classes = ['ui-icon-button'];
  if (color === 'primary') classes.push('ui-icon-button--primary');
  if (className !== undefined) classes.push(className);
  return <button type={type} className={classes.join(' ')} title={tip} {...rest} />;
}
