import { createContext, useContext, useMemo, type ReactNode } from 'react';
import de from './messages/de.json';
import en from './messages/en.json';
import { formatNumber, pluralForm } from './format-number.ts';

/** A message key: every key of the English file (the German file has the same keys). */
export type MessageKey = keyof typeof en;
export type Locale = 'en' | 'de';

export const LOCALES: readonly Locale[] = ['en', 'de'];
const MESSAGES: Record<Locale, Record<MessageKey, string>> = { en, de };

/**
 * Translates a key, filling `{name}` placeholders from `values`, and choosing a plural's form
 * (`{count, plural, one {# particle} other {# particles}}`) by the locale's plural rules.
 */
export type Translate = (key: MessageKey, values?: Record<string, string | number>) => string;

export interface I18n {
  readonly locale: Locale;
  readonly t: Translate;
  /** Formats a number for the locale with at most `digits` decimals (and at least `minDigits`). */
  readonly number: (value: number, digits?: number, minDigits?: number) => string;
  /** A value with its SI unit, separated by a no-break space: "2 N", "0,50 m/s". */
  readonly unit: (value: number, unit: string, digits?: number, minDigits?: number) => string;
}

/** A plural in a message: `{name, plural, one {...} other {...}}` (ICU's form, these two cases). */
const PLURAL = /\{(\w+), plural, one \{([^{}]*)\} other \{([^{}]*)\}\}/g;

/** Builds the translator and formatters of a locale (pure; used by the provider and tests). */
export function createI18n(locale: Locale): I18n {
  const messages = MESSAGES[locale];
  // Formatted without Intl (formatNumber): the first Intl formatter loads the locale's data.
  const number = (value: number, digits = 2, minDigits = 0): string =>
    // Avoid "-0".
    formatNumber(Math.abs(value) < 0.5 * 10 ** -digits ? 0 : value, locale, digits, minDigits);
  return {
    locale,
    t: (key, values) =>
      messages[key]
        // "{count, plural, one {# particle} other {# particles}}": the form the locale's plural
        // rules pick for the number, with # as the number ("1 particle", "2 particles").
        .replace(PLURAL, (match, name: string, one: string, other: string) => {
          const value = values?.[name];
          if (typeof value !== 'number') return match;
          const form = pluralForm(value) === 'one' ? one : other;
          return form.replace(/#/g, number(value, 2));
        })
        .replace(/\{(\w+)\}/g, (match, name: string) =>
          values !== undefined && name in values ? String(values[name]) : match,
        ),
    number,
    unit: (value, unit, digits, minDigits) => `${number(value, digits, minDigits)}\u00a0${unit}`,
  };
}

/** The locale the browser prefers, if the app has it; English otherwise. */
export function preferredLocale(languages: readonly string[]): Locale {
  for (const language of languages) {
    const base = language.toLowerCase().split('-')[0];
    if (base === 'de' || base === 'en') return base;
  }
  return 'en';
}

const I18nContext = createContext<I18n>(createI18n('en'));

export function I18nProvider({ locale, children }: { locale: Locale; children: ReactNode }) {
  const value = useMemo(() => createI18n(locale), [locale]);
  return <I18nContext.Provider value={value}>{children}</I18nContext.Provider>;
}

/** The current locale's translator and formatters. */
export function useI18n(): I18n {
  return useContext(I18nContext);
}
