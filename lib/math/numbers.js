/**
 * Small number helpers shared by the library and the p5 adapter.
 */

/** `v` held within lo ≤ v ≤ hi. */
export function clamp(v, lo, hi) {
  return Math.min(hi, Math.max(lo, v));
}

/** About `count` round tick values between lo and hi (steps of 1, 2 or 5 × 10ⁿ). */
export function niceTicks(lo, hi, count) {
  const raw = (hi - lo) / count, mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw) ?? 10 * mag;
  const ticks = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi; t += step) ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
  return ticks;
}
