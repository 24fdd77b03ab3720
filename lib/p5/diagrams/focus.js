/** Which sphere a pixel's diagrams explain. */

/**
 * The sphere test of a record worth explaining: the sphere the ray hits,
 * else its closest miss (largest discriminant, skipping spheres wholly
 * behind the eye) — the same choice as the discriminant mode. Null when the
 * record has no sphere tests.
 */
export function focusTest(record) {
  const tests = record?.tests ?? [];
  const hit = tests.find((t) => t.sphere === record.hit?.object);
  if (hit) return hit;
  const ahead = tests.filter((t) => t.quadratic.roots === 0);
  const pool = ahead.length ? ahead : tests;
  return pool.reduce((best, t) => (!best || t.quadratic.discriminant > best.quadratic.discriminant ? t : best), null);
}
