/**
 * Numbers as the kit prints them, one home for each way: the diagrams'
 * labels (`formatLabel`), the inspector's values (`formatNumber`, `formatVector`,
 * `formatAngle`), the legends' round numbers (`formatRounded`,
 * `formatPowerOfTen`) and the progress line's rate (`formatRate`). Each prints what a test or a
 * screenshot already expects: change one only on purpose.
 */

/**
 * A plain number as typed: 12, -3.5, .5, 1e-3. The dot and its digits come
 * as one optional group, so no two repeats compete for the same digits and
 * a test takes time in proportion to the text (`\d+\.?\d*` took 3 s on
 * 60,000 digits then a letter).
 */
export const PLAIN_NUMBER = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[+-]?\d+)?$/i;

const SUPERSCRIPT = '⁰¹²³⁴⁵⁶⁷⁸⁹';

/** A whole number of 0 and more in superscript digits: 12 → '¹²'. */
const superscript = (e) => [...String(e)].map((d) => SUPERSCRIPT[d]).join('');

/**
 * A number for a label: one decimal (or `digits`), '−' for minus, big ones as a×10ⁿ.
 * @example
 * formatLabel(-3.25);   // '−3.3' (rounded, with a real minus sign)
 */
export function formatLabel(n, digits = 1) {
  if (n === null || n === undefined || !Number.isFinite(n)) return '—';
  const minus = n < 0 ? '−' : '';
  const a = Math.abs(n);
  if (a >= 1e6) {
    const e = Math.floor(Math.log10(a));
    return `${minus}${(a / 10 ** e).toFixed(2)}×10${superscript(e)}`;
  }
  const text = a.toFixed(a >= 1000 ? 0 : digits);
  return Number(text) === 0 ? text : minus + text;
}

/** @deprecated the old name of formatLabel. */
export const fmt = formatLabel;

/** The sign between a formula's terms: '+' or '−'. */
export function sign(n) {
  return n < 0 ? '−' : '+';
}

/**
 * A number as the inspector panel shows it: 4 significant digits (whole
 * numbers of 1000 and more in full), powers of ten for the very large and
 * very small, "—" for null (no value: no root, no hit).
 */
export function formatNumber(n) {
  if (n === null || n === undefined || Number.isNaN(n)) return '—';
  if (n === Infinity) return '∞';
  if (n === -Infinity) return '-∞';
  if (n === 0) return '0';
  const a = Math.abs(n);
  if (a >= 1e7 || a < 1e-4) return n.toExponential(3).replace(/\.?0+e/, 'e').replace('e+', 'e');
  if (a >= 1000) return String(Math.round(n));
  return String(Number(n.toPrecision(4)));
}

/** A vector `{x, y, z}` as "(x, y, z)". */
export function formatVector(v) {
  return v ? `(${formatNumber(v.x)}, ${formatNumber(v.y)}, ${formatNumber(v.z)})` : '—';
}

/**
 * An angle with one decimal, as in the answer line ("−0.0" shown as "0.0").
 * @example
 * formatAngle(-0.04); // '0.0'
 * formatAngle(30);    // '30.0'
 */
export function formatAngle(degrees) {
  const text = degrees.toFixed(1);
  return text === '-0.0' ? '0.0' : text;
}

/** A number for a legend: whole from 10 up, else to one decimal ('2.5', '40'). */
export function formatRounded(n) {
  return Math.abs(n) >= 10 ? String(Math.round(n)) : String(Math.round(n * 10) / 10);
}

/** The power of ten nearest a positive value, for a legend: '0.01', '1', '100', '10³'. */
export function formatPowerOfTen(value) {
  const e = Math.round(Math.log10(value));
  return e <= 2 ? String(10 ** e) : '10' + superscript(e);
}

/** A rate for the progress line: '850', '35k', '1.2M'. */
export function formatRate(n) {
  if (n >= 1e6) return `${(n / 1e6).toFixed(1)}M`;
  if (n >= 1e3) return `${Math.round(n / 1e3)}k`;
  return String(Math.round(n));
}
