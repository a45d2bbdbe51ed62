import type { CSSProperties } from 'react';

/** Props of an {@link icon}: its size in CSS px (24 by default) and an optional colour. */
export interface IconProps {
  readonly size?: number;
  readonly color?: string;
  readonly className?: string;
  readonly style?: CSSProperties;
}

/**
 * A Material Design icon (paths under Apache 2.0) as a plain inline SVG: no icon package and no
 * styling engine. Decorative: the control around it carries the name.
 */
export function icon(path: string) {
  return function Icon({ size = 24, color, className, style }: IconProps) {
    return (
      <svg
        className={className === undefined ? 'ui-icon' : `ui-icon ${className}`}
        viewBox="0 0 24 24"
        width={size}
        height={size}
        aria-hidden="true"
        focusable="false"
        style={color === undefined ? style : { ...style, color }}
      >
        <path d={path} />
      </svg>
    );
  };
}
