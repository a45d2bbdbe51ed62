import type { MessageKey } from '../../i18n/i18n.tsx';

const NAMES: readonly MessageKey[] = [
  'dir.right',
  'dir.upRight',
  'dir.up',
  'dir.upLeft',
  'dir.left',
  'dir.downLeft',
  'dir.down',
  'dir.downRight',
];

/** The message key naming the nearest of eight directions (degrees counter-clockwise from right). */
export function directionName(degrees: number): MessageKey {
  const index = ((Math.round(degrees / 45) % 8) + 8) % 8;
  return NAMES[index]!;
}
