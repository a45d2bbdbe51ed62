import type { MessageKey } from '../i18n/i18n.tsx';

export type ScreenId = 'inertia' | 'forces' | 'reactions';

/** The three screens in order, with their navigation label and hint. */
export const SCREENS: readonly { id: ScreenId; label: MessageKey; hint: MessageKey }[] = [
  { id: 'inertia', label: 'nav.inertia', hint: 'inertia.hint' },
  { id: 'forces', label: 'nav.forces', hint: 'forces.hint' },
  { id: 'reactions', label: 'nav.reactions', hint: 'reactions.hint' },
];

/** The screen named by a location hash ("#forces", or a preset link "#forces?mA=1"), or the first. */
export function screenFromHash(hash: string): ScreenId {
  const id = hash.replace(/^#/, '').split('?')[0];
  return SCREENS.find((screen) => screen.id === id)?.id ?? 'inertia';
}
