/**
 * 3-vectors as objects with x, y, z (Vec3), gl-matrix style: every function that
 * makes a vector writes into an `out` argument, so hot loops allocate nothing.
 */
import { finiteNumber, show } from '../text/check.js';

/** A vector's fields: a class, not a `{ x, y, z }` literal, on purpose (docs/performance.md, "Vectors are a class"). */
export class Vec3 {
  constructor(x = 0, y = 0, z = 0) {
    this.x = x; this.y = y; this.z = z;
  }
}

/** A new vector (gl-matrix's name; modules write `new Vec3(x, y, z)`). */
export function create(x = 0, y = 0, z = 0) {
  return new Vec3(x, y, z);
}

/** out = (x, y, z). */
export function set(out, x, y, z) {
  out.x = x; out.y = y; out.z = z;
  return out;
}

/** out = a. */
export function copy(out, a) {
  out.x = a.x; out.y = a.y; out.z = a.z;
  return out;
}

/** out = a + b. */
export function add(out, a, b) {
  out.x = a.x + b.x; out.y = a.y + b.y; out.z = a.z + b.z;
  return out;
}

/** out = a − b. */
export function sub(out, a, b) {
  out.x = a.x - b.x; out.y = a.y - b.y; out.z = a.z - b.z;
  return out;
}

/** out = a·s. */
export function scale(out, a, s) {
  out.x = a.x * s; out.y = a.y * s; out.z = a.z * s;
  return out;
}

/** out = a + b·s (a point along a ray: origin + direction·t). */
export function scaleAndAdd(out, a, b, s) {
  out.x = a.x + b.x * s; out.y = a.y + b.y * s; out.z = a.z + b.z * s;
  return out;
}

/** a·b. */
export function dot(a, b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/** out = a × b. */
export function cross(out, a, b) {
  const x = a.y * b.z - a.z * b.y;
  const y = a.z * b.x - a.x * b.z;
  const z = a.x * b.y - a.y * b.x;
  out.x = x; out.y = y; out.z = z;
  return out;
}

/** |a|. */
export function length(a) {
  return Math.sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

/** |a − b|. */
export function distance(a, b) {
  const dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return Math.sqrt(dx * dx + dy * dy + dz * dz);
}

/** out = a / |a|; a zero vector stays zero (callers that care check first). */
export function normalize(out, a) {
  const len = length(a);
  const s = len > 0 ? 1 / len : 0;
  out.x = a.x * s; out.y = a.y * s; out.z = a.z * s;
  return out;
}

/** reflect()'s numbers on their way into a Vec3. */
const mirror = new Float64Array(3);

/** out = d − 2(d·n)n: the mirror direction of d about the unit normal n. */
export function reflect(out, d, n) {
  reflectInto(mirror, 0, d.x, d.y, d.z, n.x, n.y, n.z);
  out.x = mirror[0]; out.y = mirror[1]; out.z = mirror[2];
  return out;
}

/**
 * reflect() in numbers, into `out[at …]` (a Float64Array): d = (dx, dy, dz),
 * n = (nx, ny, nz). lib/tracing/kernel.js writes its mirror ray's direction so, where
 * the ray is traced from (a Vec3 written and read back cost about 1 %).
 */
export function reflectInto(out, at, dx, dy, dz, nx, ny, nz) {
  const k = 2 * (dx * nx + dy * ny + dz * nz);
  out[at] = dx - k * nx; out[at + 1] = dy - k * ny; out[at + 2] = dz - k * nz;
}

/**
 * `out` = the unit vector along `a`, scaled by its largest component first so
 * |a| neither overflows (1e200) nor underflows (1e-170); throws a RangeError
 * naming `field` when `a` is zero. Below about 1e-308, 1/m is Infinity (and
 * 0 · Infinity NaN): such a vector is divided by m instead.
 */
export function toUnit(out, a, field) {
  const m = Math.max(Math.abs(a.x), Math.abs(a.y), Math.abs(a.z));
  if (!(m > 0)) throw new RangeError(`${field} must not be zero-length, got [0, 0, 0]`);
  const s = 1 / m;
  if (Number.isFinite(s)) return normalize(out, scale(out, a, s));
  out.x = a.x / m; out.y = a.y / m; out.z = a.z / m;
  return normalize(out, out);
}

/**
 * A vector from `[x, y, z]` or `{x, y, z}`, checked: every component must be a
 * finite number, else a TypeError naming `field` (and the component).
 */
export function toVec3(value, field) {
  let x, y, z;
  if (Array.isArray(value) || ArrayBuffer.isView(value)) {
    const list = /** @type {ArrayLike<number>} */ (value);
    if (list.length !== 3) throw new TypeError(`${field} must have 3 numbers [x, y, z], got ${show(value)}`);
    [x, y, z] = [list[0], list[1], list[2]];
  } else if (value && typeof value === 'object') {
    ({ x, y, z } = value);
  } else {
    throw new TypeError(`${field} must be [x, y, z] or {x, y, z}, got ${show(value)}`);
  }
  return new Vec3(finiteNumber(x, `${field}.x`), finiteNumber(y, `${field}.y`), finiteNumber(z, `${field}.z`));
}
