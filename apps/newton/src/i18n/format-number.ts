/** Decimal and group separators of the app's locales (CLDR's, as Intl.NumberFormat uses them). */
const SEPARATORS: Record<string, { decimal: string; group: string }> = {
  en: { decimal: '.', group: ',' },
  de: { decimal: ',', group: '.' },
};

/**
 * `size` (finite, 0 or more) rounded to `digits` decimals as ICU rounds it: its shortest decimal
 * form (what `String(size)` writes: 1.005, not the binary 1.00499...) rounded half away from
 * zero. Returns the whole digits and the fraction's `digits` digits.
 */
function roundDecimal(size: number, digits: number): { whole: string; fraction: string } {
  const [mantissa, exponent] = String(size).split('e') as [string, string | undefined];
  const point = mantissa.indexOf('.');
  const all = point < 0 ? mantissa : mantissa.slice(0, point) + mantissa.slice(point + 1);
  const at = (point < 0 ? mantissa.length : point) + Number(exponent ?? 0);
  // The digits with the point after `at` of them, padded with zeros on either side.
  const lead = at < 0 ? '0'.repeat(-at) : '';
  const padded = lead + all + '0'.repeat(Math.max(0, at - all.length));
  const wholeLength = Math.max(0, at);
  let kept = padded.slice(0, wholeLength + digits).padEnd(wholeLength + digits, '0');
  if ((padded.charCodeAt(wholeLength + digits) || 48) >= 53 /* 5 */) {
    // Add one at the last kept digit, carrying.
    const chars = kept.split('');
    let i = chars.length - 1;
    while (i >= 0 && chars[i] === '9') chars[i--] = '0';
    kept =
      i < 0 ? '1' + chars.join('') : ((chars[i] = String(Number(chars[i]) + 1)), chars.join(''));
  }
  const split = kept.length - digits;
  const whole = kept.slice(0, split).replace(/^0+(?=\d)/, '') || '0';
  return { whole, fraction: kept.slice(split) };
}

/**
 * Formats `value` as `Intl.NumberFormat(locale, { maximumFractionDigits: digits,
 * minimumFractionDigits: minDigits })` does for English and German, to the character (a test
 * compares them), without Intl: the first Intl formatter of a page loads the locale's ICU data,
 * which cost a slow phone tens of milliseconds before the first screen could answer. A negative
 * value that rounds to zero reads "-0", as Intl writes it. Not-finite values go to Intl.
 */
export function formatNumber(value: number, locale: string, digits = 2, minDigits = 0): string {
  const separators = SEPARATORS[locale];
  if (separators === undefined || !Number.isFinite(value)) {
    return new Intl.NumberFormat(locale, {
      maximumFractionDigits: digits,
      minimumFractionDigits: minDigits,
    }).format(value);
  }
  const { whole, fraction: full } = roundDecimal(Math.abs(value), digits);
  let end = full.length;
  while (end > minDigits && full.charCodeAt(end - 1) === 48 /* 0 */) end--;
  const fraction = full.slice(0, end);
  let grouped = whole;
  if (whole.length > 3) {
    grouped = '';
    for (let i = whole.length; i > 0; i -= 3) {
      const part = whole.slice(Math.max(0, i - 3), i);
      grouped = grouped === '' ? part : part + separators.group + grouped;
    }
  }
  const sign = value < 0 || Object.is(value, -0) ? '-' : '';
  return sign + grouped + (fraction === '' ? '' : separators.decimal + fraction);
}

/**
 * The plural form English and German give a number, as `Intl.PluralRules` picks it: "one" for a
 * number that reads 1 (or -1) at its default three decimals, "other" otherwise.
 */
export function pluralForm(value: number): 'one' | 'other' {
  if (!Number.isFinite(value)) return 'other';
  const { whole, fraction } = roundDecimal(Math.abs(value), 3);
  return whole === '1' && fraction === '000' ? 'one' : 'other';
}
