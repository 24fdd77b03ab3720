/**
 * A sphere, and the lesson's two ways to intersect a ray with it:
 * the quadratic (A, B, C, discriminant) and the geometric route (L, tca, d², thc).
 */
import { toVec3, Vec3, sub, normalize } from '../math/vec3.js';
import { finiteNumber } from '../text/check.js';
import { shapeOptions } from './material.js';
import { EPSILON } from '../math/constants.js';
import { vector, materialToJSON } from './json.js';
import { xyz, share, SURFACE } from './form.js';
import * as layout from './packed.js';

/** lib/shapes/packed.js's P and N, as literals for the numbers-only normal below (checkCopies says why). */
const P = 0, N = 3;
layout.checkCopies({ P, N }, layout, 'lib/shapes/packed.js');

// Re-exported: EPSILON's public path (lib/index.js) has always been this module.
export { EPSILON };

/**
 * r² − d² (or discriminant / 4A) this small counts as tangent, relative to
 * r² + L·L: the size of the terms whose difference it is, so rounding never
 * makes the two routes disagree, for a tiny far sphere as for a huge one.
 */
const TANGENT = 1e-12;

export class Sphere {
  /**
   * @param {number[]|{x,y,z}} center Sc
   * @param {number} radius Sr, > 0
   * @param {import('./material.js').Material|object} [material] a Material or its options, which may also give the shape a `name`
   * @example
   * const ball = new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] });             // center, radius, material
   * const lamp = new Sphere([0, 20, -30], 3, { color: [0, 0, 0], emission: 1.2 }); // a light you can see
   */
  constructor(center, radius, material) {
    this.center = toVec3(center, 'center');
    finiteNumber(radius, 'radius');
    if (radius <= 0) throw new RangeError(`radius must be greater than 0, got ${radius}`);
    this.radius = radius;
    const shape = shapeOptions(material);
    this.name = shape.name;
    this.material = shape.material;
  }

  /**
   * Smallest t > tMin where the ray meets the sphere, or Infinity: the
   * geometric route of `intersectGeometric` in numbers only, with no record
   * written, because the renderer calls it for every ray and every sphere.
   */
  hit(ray, tMin = EPSILON) {
    const o = ray.origin, d = ray.direction, c = this.center;
    return sphereHit(c.x, c.y, c.z, this.radius, o.x, o.y, o.z, d.x, d.y, d.z, tMin);
  }

  /** The outward unit normal at a surface point. */
  normalAt(point, out = new Vec3()) {
    return normalize(out, sub(out, point, this.center));
  }

  /**
   * The lesson's record: the quadratic route's `{ A, B, C, discriminant, roots, t0, t1, t }`
   * (intersectQuadratic) with the geometric route's record beside it as `geometric`.
   */
  intersect(ray, target = {}) {
    intersectQuadratic(ray, this, target);
    target.geometric = intersectGeometric(ray, this, target.geometric ?? {});
    return target;
  }

  /** The record's lines for the inspector: `[label, value]`. */
  recordRows(record) {
    return [['A', record.A], ['B', record.B], ['C', record.C], ['B² − 4AC', record.discriminant], ['t', record.t]];
  }

  /** The box from Sc − r to Sc + r. */
  bounds() {
    const { center: c, radius: r } = this;
    return { min: new Vec3(c.x - r, c.y - r, c.z - r), max: new Vec3(c.x + r, c.y + r, c.z + r) };
  }

  /** A sphere is a ball: its `center` and `radius` (itself). Shapes that are not a ball have no `ball`. */
  ball() {
    return this;
  }

  /** Where a light of this shape shines from: its centre. */
  middle() {
    return this.center;
  }

  /** Draws itself into a 3D view's mesh with the view's own tools (lib/p5/scene-view/view.js). */
  drawIn3D(kit, into, rgb) {
    kit.ball(into, this.center, this.radius, rgb, !this.material.isEmissive);
  }

  /** Its scene JSON (lib/scene/json.js). */
  toJSON() {
    return { type: 'sphere', name: this.name ?? '', center: vector(this.center), radius: this.radius, material: materialToJSON(this.material) };
  }

  /** Its type in scene JSON. */
  static get type() { return 'sphere'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Sphere'; }
  /** What its drawing in the 3D view depends on (the view's mesh cache, lib/p5/scene-view/mesh.js). */
  viewKey() { const c = this.center; return `${c.x},${c.y},${c.z},${this.radius}`; }
  /** Built again from its JSON, the same to the bit (lib/scene/edits.js need not build it twice). */
  static get roundTrips() { return true; }

  /** Its JSON fields, in the order the constructor takes them. */
  static get fields() { return ['center', 'radius', 'material']; }

  /** A sphere from its fields (checked by the constructor). */
  static build(o, material) {
    return new Sphere(o.center, o.radius, material);
  }

  /**
   * Its fields checked again as they are now (lib/scene/check.js, before every
   * trace): a quick look, nothing built, while they are what the constructor
   * makes; else the constructor's checks, which throw naming the field, or
   * take a centre given as [x, y, z] as the constructor does.
   */
  static check(sphere, material) {
    const c = sphere.center, r = sphere.radius;
    if (c instanceof Vec3 && Number.isFinite(c.x) && Number.isFinite(c.y) && Number.isFinite(c.z) && Number.isFinite(r) && r > 0) return;
    sphere.center = Sphere.build(sphere, material).center;
  }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): cx cy cz radius. */
  static get packed() { return PACKED; }

  /** Its table in the scene form (lib/shapes/form.js). */
  static get form() { return FORM; }
}

const FORM = Object.freeze({
  title: 'Spheres', what: 'Sphere',
  columns: [...xyz('center', 'centre'), { path: ['radius'], label: 'radius', head: 'radius', kind: 'number', rule: { above: 0 } },
    SURFACE, share('reflection'), share('transparency'),
    { path: ['material', 'emission'], label: 'emission', head: 'emission', kind: 'color', grey: true }],
});

const PACKED = Object.freeze({
  pack(sphere, shapes, at) {
    shapes.set([sphere.center.x, sphere.center.y, sphere.center.z, sphere.radius], at);
  },
  hit(s, b, ox, oy, oz, dx, dy, dz, tMin) {
    return sphereHit(s[b], s[b + 1], s[b + 2], s[b + 3], ox, oy, oz, dx, dy, dz, tMin);
  },
  /** normalAt in numbers: (P − Sc) / |P − Sc|, as vec3.js normalize. */
  normal(s, b, surface) {
    const x = surface[P] - s[b], y = surface[P + 1] - s[b + 1], z = surface[P + 2] - s[b + 2];
    const length = Math.sqrt(x * x + y * y + z * z), scale = length > 0 ? 1 / length : 0;
    surface[N] = x * scale; surface[N + 1] = y * scale; surface[N + 2] = z * scale;
  },
});

/**
 * The ray–sphere test in numbers only (Sphere#hit, and render()'s fast path
 * over packed scenes, lib/tracing/kernel.js): the geometric route, L = Sc − Ro,
 * tca = L·Rd, d² = L·L − tca², thc = √(r² − d²); the smallest t = tca ∓ thc
 * greater than tMin, or Infinity.
 */
export function sphereHit(cx, cy, cz, radius, ox, oy, oz, dx, dy, dz, tMin) {
  const r2 = radius * radius;
  const Lx = cx - ox, Ly = cy - oy, Lz = cz - oz;
  const tca = Lx * dx + Ly * dy + Lz * dz;
  const LL = Lx * Lx + Ly * Ly + Lz * Lz;
  const gap = r2 - (LL - tca * tca); // r² − d²
  const band = TANGENT * (r2 + LL);
  if (gap < -band) return Infinity; // d > r: a miss
  const thc = gap <= band ? 0 : Math.sqrt(gap);
  if (tca - thc > tMin) return tca - thc;
  return tca + thc > tMin ? tca + thc : Infinity;
}

/**
 * The quadratic route: At² + Bt + C = 0 (slide "An implicit form describing a
 * sphere"). Writes `{ A, B, C, discriminant, roots, t0, t1, t }` into `target`.
 * @example
 * const ray = new Ray([0, 0, 0], [0, 0, -1]);
 * const { A, B, C, discriminant, t0, t1, t } = intersectQuadratic(ray, new Sphere([0, 0, -20], 4));
 * // A = 1, B = -40, C = 384, discriminant = 64 > 0: two hits, t0 = 16, t1 = 24; t = 16, the nearest
 */
export function intersectQuadratic(ray, sphere, target = {}) {
  const o = ray.origin, d = ray.direction, c = sphere.center, r = sphere.radius;
  const ox = o.x - c.x, oy = o.y - c.y, oz = o.z - c.z; // Ro − Sc
  const A = d.x * d.x + d.y * d.y + d.z * d.z;
  const B = 2 * (ox * d.x + oy * d.y + oz * d.z);
  const C = ox * ox + oy * oy + oz * oz - r * r;
  const discriminant = B * B - 4 * A * C;
  target.A = A; target.B = B; target.C = C; target.discriminant = discriminant;
  if (Math.abs(discriminant) <= TANGENT * 4 * A * (C + 2 * r * r)) { // C + 2r² = L·L + r²
    target.roots = 1; // tangent: the ray grazes the sphere
    target.t0 = target.t1 = -B / (2 * A);
  } else if (discriminant < 0) {
    target.roots = 0; // t would be imaginary: no intersection
    target.t0 = target.t1 = null;
  } else {
    // (−B ± √disc) / 2A, written so the two terms never cancel each other out.
    const q = -0.5 * (B + (B < 0 ? -1 : 1) * Math.sqrt(discriminant));
    const ta = q / A, tb = C / q;
    target.roots = 2;
    target.t0 = Math.min(ta, tb);
    target.t1 = Math.max(ta, tb);
  }
  target.t = nearestPositive(target.t0, target.t1);
  return target;
}

/**
 * The geometric route (slides "Geometric approach"): L = Sc − Ro, tca = L·Rd,
 * d² = L·L − tca², thc = √(r² − d²), t = tca ∓ thc. Writes
 * `{ L, tca, d2, thc, roots, t0, t1, t }` into `target` (`L` is a number triple
 * `{x, y, z}`, reused). A ray starting inside the sphere is never rejected:
 * there tca < 0 is fine, the far root is still ahead.
 * @example
 * const ray = new Ray([0, 0, 0], [0, 0, -1]);
 * const { L, tca, d2, thc, t } = intersectGeometric(ray, new Sphere([0, 0, -20], 4));
 * // L = (0, 0, -20), tca = 20, d² = 0, thc = 4: t = tca − thc = 16, as the quadratic says
 */
export function intersectGeometric(ray, sphere, target = {}) {
  const o = ray.origin, d = ray.direction, c = sphere.center, r = sphere.radius;
  const L = target.L ?? (target.L = new Vec3());
  L.x = c.x - o.x; L.y = c.y - o.y; L.z = c.z - o.z;
  const tca = L.x * d.x + L.y * d.y + L.z * d.z;
  const LL = L.x * L.x + L.y * L.y + L.z * L.z;
  const d2 = LL - tca * tca;
  const r2 = r * r;
  target.tca = tca; target.d2 = d2;
  if (Math.abs(r2 - d2) <= TANGENT * (r2 + LL)) {
    target.roots = 1; // d = r: tangent
    target.thc = 0;
    target.t0 = target.t1 = tca;
  } else if (d2 > r2) {
    target.roots = 0; // d > r: the ray passes the sphere by
    target.thc = target.t0 = target.t1 = null;
  } else {
    const thc = Math.sqrt(r2 - d2);
    target.roots = 2;
    target.thc = thc;
    target.t0 = tca - thc;
    target.t1 = tca + thc;
  }
  target.t = nearestPositive(target.t0, target.t1);
  return target;
}

/** The smallest of t0 ≤ t1 greater than EPSILON (a hit in front of the eye), or null. */
function nearestPositive(t0, t1) {
  if (t0 === null) return null;
  if (t0 > EPSILON) return t0;
  if (t1 > EPSILON) return t1;
  return null;
}

