/** Numbers as the diagrams print them. */

/**
 * A number for a label: one decimal (or `digits`), '−' for minus, big ones as a×10ⁿ.
 * @example
 * fmt(-3.25);   // '−3.3' (rounded, with a real minus sign)
 */
export function fmt(n, digits = 1) {
  if (n === null || n === undefined || !Number.isFinite(n)) return '—';
  const minus = n < 0 ? '−' : '';
  const a = Math.abs(n);
  if (a >= 1e6) {
    const e = Math.floor(Math.log10(a));
    return `${minus}${(a / 10 ** e).toFixed(2)}×10${[...String(e)].map((d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d]).join('')}`;
  }
  const text = a.toFixed(a >= 1000 ? 0 : digits);
  return Number(text) === 0 ? text : minus + text;
}

/** The sign between a formula's terms: '+' or '−'. */
export function sign(n) {
  return n < 0 ? '−' : '+';
}

/** About `count` round tick values between lo and hi (steps of 1, 2 or 5 × 10ⁿ). */
export function niceTicks(lo, hi, count) {
  const raw = (hi - lo) / count, mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw) ?? 10 * mag;
  const ticks = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi; t += step) ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
  return ticks;
}
