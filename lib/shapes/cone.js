/**
 * A cone standing on the y axis through `center`: its base, a circle of
 * `radius`, at center.y − height/2, its apex at center.y + height/2. Its
 * radius shrinks by k = radius / height per unit up, so a point is on it when
 * (X − Xc)² + (Z − Zc)² = k²·(apex − Y)²; along the ray that is the lesson's
 * At² + Bt + C = 0 again, with A = Xd² + Zd² − k²·Yd², which may be 0 or
 * negative: a ray parallel to the cone's slope meets it once.
 */
import { Vec3, set } from '../math/vec3.js';
import { EPSILON } from '../math/constants.js';
import { AxialShape, MAX_SIZE, axialPacked, solveQuadratic, recordSide, capCrossing, withinSpan, orNull } from './axial.js';

const _roots = new Float64Array(2);
const _normal = new Float64Array(3);

export class Cone extends AxialShape {
  /**
   * @param {number[]|{x,y,z}} center the middle of the axis
   * @param {number} radius > 0, the base circle's
   * @param {number} height > 0: base at center.y − height/2, apex at center.y + height/2
   * @param {object} [options] `capped` (default true: the base closed by a disc), and a sphere's material options and `name`
   * @example
   * const hat = new Cone([0, 2, -20], 3, 4, { color: 'orange' });
   */
  constructor(center, radius, height, options) {
    super(center, radius, height, options);
    if (radius / height > MAX_SIZE) throw new RangeError(`radius / height must be at most ${MAX_SIZE} (a cone this flat is a disc), got ${radius / height}`);
  }

  /** Smallest t > tMin where the ray meets the cone, or Infinity. */
  hit(ray, tMin = EPSILON) {
    const o = ray.origin, d = ray.direction, c = this.center;
    return coneHit(c.x, c.y, c.z, this.radius, this.height, this.capped, o.x, o.y, o.z, d.x, d.y, d.z, tMin);
  }

  /**
   * The lesson's record, written into `target`: the sloped side's
   * `A, B, C, discriminant, roots, t0, t1` (the roots of the double cone,
   * tip to tip), `y0, y1` (their heights: a root above the apex, on the
   * upper half, or below the base is cut off), the base's `tBase` (null when
   * the ray crosses its plane outside the disc, or it has no cap), and
   * `part` ('side', 'base' or null) with `t`, the nearest hit past EPSILON or null.
   */
  intersect(ray, target = {}) {
    const o = ray.origin, d = ray.direction, c = this.center, r = this.radius;
    const k2 = (r / this.height) * (r / this.height);
    const x = o.x - c.x, z = o.z - c.z; // Ro − center, sideways
    const base = c.y - this.height / 2, apex = c.y + this.height / 2, below = apex - o.y;
    const A = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
    const B = 2 * (x * d.x + z * d.z + k2 * below * d.y);
    const C = x * x + z * z - k2 * below * below;
    Object.assign(target, { A, B, C, discriminant: B * B - 4 * A * C });
    recordSide(target, solveQuadratic(A, B, C, _roots), _roots, o.y, d.y);
    target.tBase = this.capped ? orNull(capCrossing(base, r * r, x, o.y, z, d.x, d.y, d.z)) : null;
    target.t = null;
    target.part = null;
    for (const [t, part] of [[target.t0, 'side'], [target.t1, 'side'], [target.tBase, 'base']]) {
      const ok = t !== null && t > EPSILON && (target.t === null || t < target.t) &&
        (part !== 'side' || withinSpan(o.y + d.y * t, base, apex, true));
      if (ok) { target.t = t; target.part = part; }
    }
    return target;
  }

  /**
   * The outward unit normal at a surface point: down on the base; on the
   * side, out from the axis and up by the slope k, ∝ (X − Xc, k·ρ, Z − Zc)
   * where ρ is the distance from the axis; straight up at the apex.
   */
  normalAt(point, out = new Vec3()) {
    const c = this.center;
    coneNormal(c.x, c.y, c.z, this.radius, this.height, this.capped, point.x, point.y, point.z, _normal, 0);
    return set(out, _normal[0], _normal[1], _normal[2]);
  }

  /** The record's lines for the inspector: the quadratic of the side, the caps' crossings, the nearest hit and the part it is on. */
  recordRows(record) {
    return [['A', record.A], ['B', record.B], ['C', record.C], ['B² − 4AC', record.discriminant], ['t0', record.t0], ['t1', record.t1],
      ['base t', record.tBase],
      [`t (${record.part ?? 'no hit'})`, record.t]];
  }

  /** A cone's top is its apex: radius 0. */
  get topRadius() { return 0; }

  /** Its type in scene JSON. */
  static get type() { return 'cone'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Cone'; }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): cx cy cz radius height capped (1 or 0). */
  static get packed() { return PACKED; }
}

const PACKED = axialPacked(coneHit, coneNormal);

/**
 * Cone#normalAt in numbers only (and the kernel's): the outward unit normal
 * at point (px, py, pz) into out[at…at+2].
 */
export function coneNormal(cx, cy, cz, radius, height, capped, px, py, pz, out, at) {
  const k = radius / height, x = px - cx, z = pz - cz;
  const rho = Math.sqrt(x * x + z * z);
  const toSide = Math.abs(rho - k * (cy + height / 2 - py)) / Math.sqrt(1 + k * k);
  if (capped && Math.abs(py - (cy - height / 2)) < toSide) { out[at] = 0; out[at + 1] = -1; out[at + 2] = 0; return; }
  if (rho === 0) { out[at] = 0; out[at + 1] = 1; out[at + 2] = 0; return; }
  const length = rho * Math.sqrt(1 + k * k); // |(x, kρ, z)|
  out[at] = x / length; out[at + 1] = (k * rho) / length; out[at + 2] = z / length;
}

/**
 * The ray–cone test in numbers only (Cone#hit; a packed scene's kernel may
 * call it too): the nearest of the side's roots between base and apex and
 * the base's crossing greater than tMin, or Infinity.
 */
export function coneHit(cx, cy, cz, radius, height, capped, ox, oy, oz, dx, dy, dz, tMin) {
  const k2 = (radius / height) * (radius / height);
  const x = ox - cx, z = oz - cz, base = cy - height / 2, apex = cy + height / 2, below = apex - oy;
  const A = dx * dx + dz * dz - k2 * dy * dy;
  const B = 2 * (x * dx + z * dz + k2 * below * dy);
  const C = x * x + z * z - k2 * below * below;
  let best = Infinity;
  const roots = solveQuadratic(A, B, C, _roots);
  for (let i = 0; i < roots; i++) {
    const t = _roots[i];
    if (t > tMin && t < best && withinSpan(oy + dy * t, base, apex, true)) best = t;
  }
  if (capped) {
    const tBase = capCrossing(base, radius * radius, x, oy, z, dx, dy, dz);
    if (tBase > tMin && tBase < best) best = tBase;
  }
  return best;
}
