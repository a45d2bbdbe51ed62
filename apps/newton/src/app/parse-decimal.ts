/** A typed number checked against its range: the value, or why it is not accepted. */
export type ParsedDecimal =
  | { readonly ok: true; readonly value: number }
  | { readonly ok: false; readonly reason: 'empty' | 'notANumber' | 'outOfRange' };

// Plain decimals only, with a point or a comma: no signs, exponents, hex or spaces inside
// ("1e9", "0x10", "-3" and "abc" are all refused, not reinterpreted).
const DECIMAL = /^\s*(\d+(?:[.,]\d*)?|[.,]\d+)\s*$/;

/** Reads what a learner typed into a number field with the range [min, max]. */
export function parseDecimal(text: string, min: number, max: number): ParsedDecimal {
  if (text.trim() === '') return { ok: false, reason: 'empty' };
  const match = DECIMAL.exec(text);
  if (match === null) return { ok: false, reason: 'notANumber' };
  const value = Number(match[1]!.replace(',', '.'));
  if (!Number.isFinite(value)) return { ok: false, reason: 'notANumber' };
  if (value < min || value > max) return { ok: false, reason: 'outOfRange' };
  return { ok: true, value };
}
