/**
 * The leaf formulas of the lesson's shading, written once: Lambert's cos term,
 * Phong's highlight, a spot light's cone, the fall of light with distance,
 * one light's share of the colour, the mirror direction,
 * Snell's law, Schlick's Fresnel share and the mirror/glass mix. trace.js (the
 * readable tracer) and kernel.js (render()'s fast path) both call them, so the
 * two cannot tell the story apart.
 *
 * Each takes numbers and returns a number, or writes a direction into a
 * caller's Float64Array (as vec3.js's reflectInto does for the mirror ray):
 * nothing allocates, and each is small enough that V8 inlines it, so no
 * number is boxed on the way (docs/performance.md, "Notes on V8").
 */

/** Lambert: how squarely light from the unit direction L falls on the unit normal N, cos θ = N·L (≤ 0: from behind). */
export function lambert(Nx, Ny, Nz, Lx, Ly, Lz) {
  return Nx * Lx + Ny * Ly + Nz * Lz;
}

/**
 * Phong's highlight toward the unit direction L: specular·(R·V)^shininess, R
 * the light's ray mirrored about the normal N, V = −D the way back along the
 * ray D; `cos` is N·L (lambert). L mirrored about N, L − 2(N·L)N (vec3.js's
 * reflect), is −R, so R·V is that mirror dotted with D, here in numbers: a
 * mirror written into a vector and read back cost 3 % of a full-shading frame.
 */
export function specular(strength, shininess, cos, Lx, Ly, Lz, Nx, Ny, Nz, Dx, Dy, Dz) {
  if (!(strength > 0)) return 0;
  const twice = 2 * cos;
  const rv = (Lx - twice * Nx) * Dx + (Ly - twice * Ny) * Dy + (Lz - twice * Nz) * Dz;
  return rv > 0 ? strength * Math.pow(rv, shininess) : 0;
}

/**
 * How much of a spot light reaches a point, 0–1, from the unit direction L
 * from the point toward the light: with cos = −L·axis (the angle off the
 * axis), 1 inside cosInner, 0 outside cosOuter, smoothstep between.
 */
export function spotShare(axisX, axisY, axisZ, cosOuter, cosInner, Lx, Ly, Lz) {
  const cos = -(Lx * axisX + Ly * axisY + Lz * axisZ);
  if (cos >= cosInner) return 1;
  if (cos <= cosOuter) return 0;
  const s = (cos - cosOuter) / (cosInner - cosOuter);
  return s * s * (3 - 2 * s);
}

/**
 * The fall of a light's strength with distance d: 1 / (1 + k·d²), k the
 * light's `attenuation`. One number, not OpenGL's three (constant, linear,
 * quadratic): the d² is the lesson (light spreads over a sphere's surface,
 * 4πd²), the 1 + keeps a light up close from blowing up to infinity, and k
 * says at what distance the light is half as strong (d = 1/√k). k = 0 gives
 * exactly 1: no falloff, the same picture as before.
 */
export function falloff(attenuation, distance) {
  return 1 / (1 + attenuation * distance * distance);
}

/**
 * One colour channel of one light's share: the light's colour times the
 * surface's under it (`diffuse`, Lambert's cos times what the shadow ray let
 * through) plus the highlight, which takes the light's colour only.
 */
export function lightShare(light, surface, diffuse, highlight) {
  return light * (surface * diffuse + highlight);
}

/**
 * Snell's law: the refracted unit direction T = eta·D + s·N of the unit
 * direction D through the unit normal N that faces it, into `out[at …]` (a
 * Float64Array: the kernel's ray, or trace.js's frame); cosi = −D·N, eta the
 * ratio of the indices (the side it comes from over the side it enters).
 * False on total internal reflection, where nothing goes through (a NaN is not).
 */
export function refract(out, at, Dx, Dy, Dz, Nx, Ny, Nz, cosi, eta) {
  const k = 1 - eta * eta * (1 - cosi * cosi);
  if (k < 0) return false;
  const s = eta * cosi - Math.sqrt(k);
  out[at] = eta * Dx + s * Nx; out[at + 1] = eta * Dy + s * Ny; out[at + 2] = eta * Dz + s * Nz;
  return true;
}

/**
 * Schlick's approximation of the Fresnel reflectance at cos θ for index `ior`:
 * r0 + (1 − r0)(1 − cos θ)⁵. The fifth power by multiplying: Math.pow took a
 * fifth of a full-shading frame (it differs in F's last bit, never in a byte seen).
 */
export function schlick(cosi, ior) {
  const r0 = ((1 - ior) / (1 + ior)) ** 2;
  const k = 1 - cosi, k2 = k * k;
  return r0 + (1 - r0) * k2 * k2 * k;
}

/**
 * The share of light glass reflects (F): none without glass, all of it on
 * total internal reflection, else Schlick's.
 */
export function fresnel(transparency, refracts, cosi, ior) {
  if (!(transparency > 0)) return 0;
  return refracts ? schlick(cosi, ior) : 1;
}

/**
 * One colour channel of the mirror and glass mix:
 * opaque = (1 − reflection)·local + reflection·colour·mirrored,
 * result = (1 − transparency)·opaque + transparency·(F·mirrored + (1 − F)·colour·through).
 */
export function mix(local, mirror, through, color, reflection, transparency, F) {
  const opaque = (1 - reflection) * local + reflection * color * mirror;
  return (1 - transparency) * opaque + transparency * (F * mirror + (1 - F) * color * through);
}
