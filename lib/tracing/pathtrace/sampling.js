/**
 * Directions drawn at random, each written into a caller's Float64Array
 * (`out[at …]`), nothing allocated: a diffuse bounce's cosine-weighted
 * direction over the hemisphere around a normal, and a point in the unit
 * ball for a metal's fuzz.
 */

const TWO_PI = 2 * Math.PI;

/**
 * Cosine-weighted direction around the unit normal `normal[n …]` (Malley's
 * method: a uniform point on the unit disc lifted onto the hemisphere), from
 * two uniform numbers `u[first]`, `u[first + 1]` in [0, 1), into `out[at …]`, and its
 * cos θ to the normal into `out[at + 3]`. Its density over the hemisphere is
 * cos θ / π (cosinePdf). Numbers come and go in arrays: docs/performance.md.
 */
export function cosineHemisphere(out, at, normal, n, u, first) {
  const Nx = normal[n], Ny = normal[n + 1], Nz = normal[n + 2], u1 = u[first], u2 = u[first + 1];
  const r = Math.sqrt(u1), phi = TWO_PI * u2;
  const a = r * Math.cos(phi), b = r * Math.sin(phi), cos = Math.sqrt(1 - u1);
  // An orthonormal basis (T, B, N) from N alone, without a branch on its size (Duff et al., 2017).
  const sign = Nz >= 0 ? 1 : -1, k = -1 / (sign + Nz), m = Nx * Ny * k;
  const Tx = 1 + sign * Nx * Nx * k, Ty = sign * m, Tz = -sign * Nx;
  const Bx = m, By = sign + Ny * Ny * k, Bz = -Ny;
  out[at] = a * Tx + b * Bx + cos * Nx;
  out[at + 1] = a * Ty + b * By + cos * Ny;
  out[at + 2] = a * Tz + b * Bz + cos * Nz;
  out[at + 3] = cos;
}

/** The density of cosineHemisphere's direction at cos θ to the normal: cos θ / π (0 below the surface). */
export function cosinePdf(cos) {
  return cos > 0 ? cos / Math.PI : 0;
}

/** A point uniform in the unit ball into `out[at …]`, from three uniform numbers `u[first …]`: a direction on the sphere, at radius ∛u3. */
export function inUnitBall(out, at, u, first) {
  const u1 = u[first], u2 = u[first + 1], u3 = u[first + 2];
  const z = 1 - 2 * u1, ring = Math.sqrt(Math.max(0, 1 - z * z)), phi = TWO_PI * u2, radius = Math.cbrt(u3);
  out[at] = radius * ring * Math.cos(phi);
  out[at + 1] = radius * ring * Math.sin(phi);
  out[at + 2] = radius * z;
}
