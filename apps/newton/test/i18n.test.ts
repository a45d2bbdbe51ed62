import { describe, expect, it } from 'vitest';
import de from '../src/i18n/messages/de.json';
import en from '../src/i18n/messages/en.json';
import { createI18n, preferredLocale } from '../src/i18n/i18n.tsx';

describe('messages', () => {
  it('German has exactly the English keys, none empty', () => {
    expect(Object.keys(de).sort()).toEqual(Object.keys(en).sort());
    for (const text of [...Object.values(en), ...Object.values(de)])
      expect(text.trim()).not.toBe('');
  });

  it('fills placeholders and formats numbers with units per locale', () => {
    expect(createI18n('en').t('forces.dialogTitle', { name: 'A' })).toBe('Square A');
    expect(createI18n('de').unit(0.5, 'm/s', 2, 2)).toBe('0,50\u00a0m/s');
    expect(createI18n('en').unit(4, 'N')).toBe('4\u00a0N');
    expect(createI18n('en').number(-0.0001, 2)).toBe('0');
  });

  it("chooses the plural form by the locale's rules: 1 particle, 2 particles", () => {
    const english = createI18n('en');
    expect(english.t('reactions.added', { mass: '1 kg', count: 1 })).toBe(
      'Particle added, 1 kg. 1 particle.',
    );
    expect(english.t('reactions.added', { mass: '1 kg', count: 2 })).toBe(
      'Particle added, 1 kg. 2 particles.',
    );
    expect(createI18n('de').t('reactions.added', { mass: '1 kg', count: 1 })).toBe(
      'Teilchen hinzugefügt, 1 kg. 1 Teilchen.',
    );
    for (const text of [...Object.values(en), ...Object.values(de)]) {
      // A plural left unfilled would show its braces to the learner.
      if (text.includes('plural')) {
        expect(text).toMatch(/\{\w+, plural, one \{[^{}]*\} other \{[^{}]*\}\}/);
      }
    }
  });

  it('picks the browser language when the app has it', () => {
    expect(preferredLocale(['de-AT', 'en'])).toBe('de');
    expect(preferredLocale(['fr-FR'])).toBe('en');
  });
});
