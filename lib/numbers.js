/**
 * Small number helpers shared by the library and the p5 adapter.
 */

/** `v` held within lo ≤ v ≤ hi. */
export function clamp(v, lo, hi) {
  return Math.min(hi, Math.max(lo, v));
}
