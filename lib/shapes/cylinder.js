/**
 * A cylinder standing on the y axis through `center` (a can, a pillar): the
 * sphere's quadratic with y left out of it, (Xo + Xd·t − Xc)² + (Zo + Zd·t − Zc)² = r²,
 * so A = Xd² + Zd², not 1. A ray straight along the axis has A = 0 and never
 * meets the curved side; only the caps can stop it.
 */
import { Vec3, set } from '../math/vec3.js';
import { EPSILON } from '../math/constants.js';
import { AxialShape, axialPacked, solveQuadratic, recordSide, capCrossing, withinSpan, orNull } from './axial.js';

const _roots = new Float64Array(2);
const _normal = new Float64Array(3);

export class Cylinder extends AxialShape {
  /**
   * @param {number[]|{x,y,z}} center the middle of the axis
   * @param {number} radius > 0
   * @param {number} height > 0: from center.y − height/2 to center.y + height/2
   * @param {object} [options] `capped` (default true: closed by two discs), and a sphere's material options and `name`
   * @example
   * const can = new Cylinder([0, -2, -20], 2, 4, { color: [0.8, 0.2, 0.2] });
   * const pipe = new Cylinder([4, 0, -20], 1, 6, { capped: false });
   */
  constructor(center, radius, height, options) {
    super(center, radius, height, options);
  }

  /** Smallest t > tMin where the ray meets the cylinder, or Infinity. */
  hit(ray, tMin = EPSILON) {
    const o = ray.origin, d = ray.direction, c = this.center;
    return cylinderHit(c.x, c.y, c.z, this.radius, this.height, this.capped, o.x, o.y, o.z, d.x, d.y, d.z, tMin);
  }

  /**
   * The lesson's record, written into `target`: the curved side's
   * `A, B, C, discriminant, roots, t0, t1` (the infinite cylinder's roots)
   * and `y0, y1` (their heights: a root above the top or below the bottom
   * is cut off), each cap's `tTop`, `tBottom` (null when the ray crosses
   * its plane outside the disc, or there is no cap), and `part` ('side',
   * 'top', 'bottom' or null) with `t`, the nearest hit past EPSILON or null.
   */
  intersect(ray, target = {}) {
    const o = ray.origin, d = ray.direction, c = this.center, r = this.radius;
    const x = o.x - c.x, z = o.z - c.z; // Ro − center, sideways
    const bottom = c.y - this.height / 2, top = c.y + this.height / 2;
    const A = d.x * d.x + d.z * d.z;
    const B = 2 * (x * d.x + z * d.z);
    const C = x * x + z * z - r * r;
    Object.assign(target, { A, B, C, discriminant: B * B - 4 * A * C });
    recordSide(target, solveQuadratic(A, B, C, _roots), _roots, o.y, d.y);
    target.tTop = this.capped ? orNull(capCrossing(top, r * r, x, o.y, z, d.x, d.y, d.z)) : null;
    target.tBottom = this.capped ? orNull(capCrossing(bottom, r * r, x, o.y, z, d.x, d.y, d.z)) : null;
    target.t = null;
    target.part = null;
    for (const [t, part] of [[target.t0, 'side'], [target.t1, 'side'], [target.tTop, 'top'], [target.tBottom, 'bottom']]) {
      const ok = t !== null && t > EPSILON && (target.t === null || t < target.t) &&
        (part !== 'side' || withinSpan(o.y + d.y * t, bottom, top, false));
      if (ok) { target.t = t; target.part = part; }
    }
    return target;
  }

  /** The outward unit normal at a surface point: up or down on a cap, straight out from the axis on the side. */
  normalAt(point, out = new Vec3()) {
    const c = this.center;
    cylinderNormal(c.x, c.y, c.z, this.radius, this.height, this.capped, point.x, point.y, point.z, _normal, 0);
    return set(out, _normal[0], _normal[1], _normal[2]);
  }

  /** The record's lines for the inspector: the quadratic of the side, the caps' crossings, the nearest hit and the part it is on. */
  recordRows(record) {
    return [['A', record.A], ['B', record.B], ['C', record.C], ['B² − 4AC', record.discriminant], ['t0', record.t0], ['t1', record.t1],
      ['top cap t', record.tTop], ['bottom cap t', record.tBottom],
      [`t (${record.part ?? 'no hit'})`, record.t]];
  }

  /** Its type in scene JSON. */
  static get type() { return 'cylinder'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Cylinder'; }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): cx cy cz radius height capped (1 or 0). */
  static get packed() { return PACKED; }
}

const PACKED = axialPacked(cylinderHit, cylinderNormal);

/**
 * Cylinder#normalAt in numbers only (and the kernel's): the outward unit
 * normal at point (px, py, pz) into out[at…at+2].
 */
export function cylinderNormal(cx, cy, cz, radius, height, capped, px, py, pz, out, at) {
  const x = px - cx, z = pz - cz;
  const rho = Math.sqrt(x * x + z * z);
  const toSide = Math.abs(rho - radius);
  const toTop = Math.abs(py - (cy + height / 2)), toBottom = Math.abs(py - (cy - height / 2));
  if (capped && toTop < toSide && toTop <= toBottom) { out[at] = 0; out[at + 1] = 1; out[at + 2] = 0; return; }
  if (capped && toBottom < toSide) { out[at] = 0; out[at + 1] = -1; out[at + 2] = 0; return; }
  if (rho > 0) { out[at] = x / rho; out[at + 1] = 0; out[at + 2] = z / rho; return; }
  out[at] = 1; out[at + 1] = 0; out[at + 2] = 0;
}

/**
 * The ray–cylinder test in numbers only (Cylinder#hit; a packed scene's
 * kernel may call it too): the nearest of the side's roots within the
 * height and the caps' crossings greater than tMin, or Infinity.
 */
export function cylinderHit(cx, cy, cz, radius, height, capped, ox, oy, oz, dx, dy, dz, tMin) {
  const x = ox - cx, z = oz - cz, bottom = cy - height / 2, top = cy + height / 2, r2 = radius * radius;
  let best = Infinity;
  const roots = solveQuadratic(dx * dx + dz * dz, 2 * (x * dx + z * dz), x * x + z * z - r2, _roots);
  for (let i = 0; i < roots; i++) {
    const t = _roots[i];
    if (t > tMin && t < best && withinSpan(oy + dy * t, bottom, top, false)) best = t;
  }
  if (capped) {
    const tTop = capCrossing(top, r2, x, oy, z, dx, dy, dz), tBottom = capCrossing(bottom, r2, x, oy, z, dx, dy, dz);
    if (tTop > tMin && tTop < best) best = tTop;
    if (tBottom > tMin && tBottom < best) best = tBottom;
  }
  return best;
}
