/** A typed number checked against its range: the value, or why it is not accepted. */
export type ParsedDecimal =
  | { readonly ok: true; readonly value: number }
  | { readonly ok: false; readonly reason: 'empty' | 'notANumber' | 'outOfRange' };

// Plain decimals only, with a point or a comma, and an optional minus (ASCII or U+2212): no
// exponents, hex, plus signs or spaces inside ("1e9", "0x10" and "abc" are refused, not
// reinterpreted). A negative number is a number: "-3" is out of the range, not "not a number".
const DECIMAL = /^\s*([-\u2212]?)(\d+(?:[.,]\d*)?|[.,]\d+)\s*$/;

/** Reads what a learner typed into a number field with the range [min, max]. */
export function parseDecimal(text: string, min: number, max: number): ParsedDecimal {
  if (text.trim() === '') return { ok: false, reason: 'empty' };
  const match = DECIMAL.exec(text);
  if (match === null) return { ok: false, reason: 'notANumber' };
  const value = (match[1] === '' ? 1 : -1) * Number(match[2]!.replace(',', '.'));
  if (!Number.isFinite(value)) return { ok: false, reason: 'notANumber' };
  if (value < min || value > max) return { ok: false, reason: 'outOfRange' };
  return { ok: true, value };
}
