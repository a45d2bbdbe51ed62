import { describe, expect, it } from 'vitest';
import { formatNumber, pluralForm } from '../src/i18n/format-number.ts';

// Values a screen shows: small and large, negative, halves at every decimal, and tricky binary
// fractions (1.005 is 1.00499999... in binary: it rounds down, in Intl as here).
const VALUES = [
  0,
  -0,
  1,
  -1,
  0.5,
  -0.5,
  0.125,
  -0.125,
  1.005,
  2.675,
  9.995,
  0.0049,
  -0.0049,
  0.005,
  -0.005,
  12.5,
  999.9999,
  1000,
  -1234.5678,
  98765.4321,
  1234567.891,
  1e20,
  -3,
  2.13,
  0.333333,
  2 / 3,
  Math.PI,
  -Math.E,
  59.94,
  1e-7,
  -1e-7,
  123456789.123,
  NaN,
  Infinity,
  -Infinity,
];
// Pseudo-random values over many magnitudes (a fixed sequence: the same every run).
let seed = 12345;
for (let i = 0; i < 400; i++) {
  seed = (seed * 1103515245 + 12345) % 2147483648;
  const magnitude = 10 ** ((seed % 12) - 5);
  VALUES.push(((seed / 2147483648) * 2 - 1) * magnitude);
}

describe('numbers are formatted as Intl.NumberFormat formats them, without Intl', () => {
  for (const locale of ['en', 'de']) {
    it(`matches Intl in ${locale} for every value and every digit setting the app uses`, () => {
      for (const [digits, minDigits] of [
        [0, 0],
        [1, 0],
        [2, 0],
        [2, 2],
        [3, 0],
        [3, 3],
        [1, 1],
        [4, 2],
      ] as const) {
        const intl = new Intl.NumberFormat(locale, {
          maximumFractionDigits: digits,
          minimumFractionDigits: minDigits,
        });
        for (const value of VALUES) {
          expect(
            formatNumber(value, locale, digits, minDigits),
            `${value} ${digits}/${minDigits}`,
          ).toBe(intl.format(value));
        }
      }
    });

    it(`picks the plural form Intl.PluralRules picks in ${locale}`, () => {
      const rules = new Intl.PluralRules(locale);
      for (const value of [...VALUES, 1.00001, 0.9999, 0.9995, -1.0004, 1.0005]) {
        expect(pluralForm(value), String(value)).toBe(
          rules.select(value) === 'one' ? 'one' : 'other',
        );
      }
    });
  }
});
