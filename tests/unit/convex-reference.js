/**
 * A slow, obviously correct reference for closed convex solids, for the
 * shape tests: a solid given by g(P) < 0 inside, with g convex, so g along a
 * ray, g(Ro + Rd·t), is a convex function of t. Its minimum (a ternary
 * search) tells whether the ray meets the solid at all; each side of it, g
 * crosses zero once (bisection): where the ray goes in and where it comes out.
 * No quadratic, no discriminant: nothing shared with the code under test.
 */

/** The kit's seeded PRNG (mulberry32, lib/tracing/photons.js): the same "random" rays every run. It is not under test here. */
export { seededRandom as seeded } from '../../lib/tracing/photons.js';

/** The t where a convex `g` first and last is ≤ 0 along the ray, within ±span, or null when it never is. */
export function convexInterval(g, ray, span = 1e4) {
  const o = ray.origin, d = ray.direction;
  const at = (t) => g(o.x + d.x * t, o.y + d.y * t, o.z + d.z * t);
  let lo = -span, hi = span;
  for (let i = 0; i < 400 && hi - lo > 0; i++) { // ternary search for the minimum of a convex function
    const m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (at(m1) < at(m2)) hi = m2; else lo = m1;
  }
  const tMid = (lo + hi) / 2;
  if (!(at(tMid) < 0)) return null;
  return { tIn: bisect(at, -span, tMid), tOut: bisect(at, span, tMid) };
}

/** The zero crossing between `outside` (g > 0) and `inside` (g < 0), to the last bit. */
function bisect(at, outside, inside) {
  for (let i = 0; i < 2000; i++) {
    const mid = (outside + inside) / 2;
    if (mid === outside || mid === inside) break;
    if (at(mid) < 0) inside = mid; else outside = mid;
  }
  return (outside + inside) / 2;
}

/** The nearest hit past `epsilon` of a ray with a solid whose interval is `interval`: where it enters, or where it leaves from inside. */
export function nearestOf(interval, epsilon) {
  if (interval === null) return Infinity;
  if (interval.tIn > epsilon) return interval.tIn;
  return interval.tOut > epsilon ? interval.tOut : Infinity;
}

/** A random unit vector (from three normal deviates: no direction favoured). */
export function randomDirection(random) {
  const gauss = () => Math.sqrt(-2 * Math.log(1 - random())) * Math.cos(2 * Math.PI * random());
  for (;;) {
    const x = gauss(), y = gauss(), z = gauss(), l = Math.hypot(x, y, z);
    if (l > 1e-3) return [x / l, y / l, z / l];
  }
}
