/**
 * A triangle between corners a, b, c, intersected by Möller and Trumbore
 * (1997): the hit point written as a + u·e1 + v·e2 (e1 = b − a, e2 = c − a)
 * and as Ro + Rd·t, solved for t, u, v at once by Cramer's rule. The
 * determinant of that system is e1·P with P = Rd × e2; it is 0 when the ray
 * runs parallel to the triangle's plane, the zero discriminant of the
 * sphere again: no single answer. The ray is inside when u ≥ 0, v ≥ 0 and
 * u + v ≤ 1.
 */
import { toVec3, Vec3, sub, cross, dot, length, normalize, scale } from '../math/vec3.js';
import { shapeOptions } from './material.js';
import { EPSILON } from '../math/constants.js';
import { vector, materialToJSON } from './json.js';
import { N, sideTables } from './packed.js';

/**
 * A determinant this small, relative to |e1|·|e2|·|Rd| (its size when the
 * ray is square to the triangle), counts as 0: the ray is parallel.
 */
export const PARALLEL = 1e-12;

/** |e1 × e2| this small relative to |e1|·|e2|: the corners are on one line. */
export const FLAT = 1e-12;

/**
 * The longest side a triangle may have: past about 1e77 the determinant's
 * square overflows and the triangle is taken as parallel to every ray.
 */
export const MAX_SIDE = 1e30;

/**
 * A power of two that brings the largest of six numbers (two edges) near 1.
 * Scaling by it is exact, so the area test is relative to the triangle's size
 * (sides of 1e-200 do not square to 0) and a normal keeps its bits.
 */
export function edgeScale(e1x, e1y, e1z, e2x, e2y, e2z) {
  const largest = Math.max(Math.abs(e1x), Math.abs(e1y), Math.abs(e1z), Math.abs(e2x), Math.abs(e2y), Math.abs(e2z));
  return largest > 0 ? 2 ** Math.min(1000, -Math.floor(Math.log2(largest))) : 1;
}

export class Triangle {
  /**
   * @param {number[]|{x,y,z}} a a corner
   * @param {number[]|{x,y,z}} b the next corner
   * @param {number[]|{x,y,z}} c the last; a, b, c counterclockwise as seen from the front (the normal's side)
   * @param {import('./material.js').Material|object} [options] a Material or its options, which may also give the shape a `name`
   * @example
   * const sail = new Triangle([-2, 0, -20], [2, 0, -20], [0, 4, -20], { color: 'white' });
   */
  constructor(a, b, c, options) {
    this.a = toVec3(a, 'a');
    this.b = toVec3(b, 'b');
    this.c = toVec3(c, 'c');
    checkArea(this.a, this.b, this.c, '');
    const shape = shapeOptions(options);
    this.name = shape.name;
    this.material = shape.material;
  }

  /** Smallest t > tMin where the ray meets the triangle, or Infinity. */
  hit(ray, tMin = EPSILON) {
    const o = ray.origin, d = ray.direction, a = this.a, b = this.b, c = this.c;
    return triangleHit(a.x, a.y, a.z, b.x - a.x, b.y - a.y, b.z - a.z, c.x - a.x, c.y - a.y, c.z - a.z,
      o.x, o.y, o.z, d.x, d.y, d.z, tMin);
  }

  /**
   * Möller–Trumbore with its steps, written into `target`: `e1`, `e2`,
   * `P` = Rd × e2, `determinant` = e1·P, `S` = Ro − a, `u` = S·P / det,
   * `Q` = S × e1, `v` = Rd·Q / det, and `t` = e2·Q / det when the ray is
   * inside (else null, as are u, v, t once a step has ruled it out), and
   * `parallel` when the determinant is 0.
   */
  intersect(ray, target = {}) {
    return intersectTriangle(ray, this.a, this.b, this.c, target);
  }

  /** The unit normal of the front, e1 × e2 (the same everywhere on it). */
  normalAt(point, out = new Vec3()) {
    const e1 = sub(new Vec3(), this.b, this.a), e2 = sub(new Vec3(), this.c, this.a);
    const k = edgeScale(e1.x, e1.y, e1.z, e2.x, e2.y, e2.z);
    return normalize(out, cross(out, scale(e1, e1, k), scale(e2, e2, k)));
  }

  /** The world-space box around the triangle. */
  bounds() {
    const { a, b, c } = this;
    return {
      min: new Vec3(Math.min(a.x, b.x, c.x), Math.min(a.y, b.y, c.y), Math.min(a.z, b.z, c.z)),
      max: new Vec3(Math.max(a.x, b.x, c.x), Math.max(a.y, b.y, c.y), Math.max(a.z, b.z, c.z)),
    };
  }
  /** The record's lines for the inspector: Möller–Trumbore's determinant, u, v and t. */
  recordRows(record) {
    return [['det', record.determinant], ['u', record.u], ['v', record.v], ['t', record.t]];
  }

  /** Draws itself into a 3D view's mesh with the view's own tools (lib/p5/scene-view/mesh.js). */
  drawIn3D(kit, into, rgb) {
    const { a, b, c } = this;
    kit.triangles(into, [a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z], rgb);
  }

  /** Its scene JSON (lib/scene/json.js). */
  toJSON() {
    return { type: 'triangle', name: this.name ?? '', a: vector(this.a), b: vector(this.b), c: vector(this.c), material: materialToJSON(this.material) };
  }

  /** Its type in scene JSON. */
  static get type() { return 'triangle'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Triangle'; }
  /** What its drawing in the 3D view depends on (the view's mesh cache, lib/p5/scene-view/mesh.js). */
  viewKey() { return [this.a, this.b, this.c].map((p) => `${p.x},${p.y},${p.z}`).join(','); }

  /** Its JSON fields, in the order the constructor takes them. */
  static get fields() { return ['a', 'b', 'c', 'material']; }
  /** The triangles its JSON makes (lib/scene/work.js). */
  static workOf() { return { triangles: 1, field: '' }; }

  /** A triangle from its fields (checked by the constructor). */
  static build(o, material) {
    return new Triangle(o.a, o.b, o.c, material);
  }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): its side table's index (corner a, edges e1 e2, its normal). */
  static get packed() { return PACKED; }
}

const PACKED = Object.freeze({
  pack(triangle, shapes, at, tables) {
    const { a, b, c } = triangle, n = triangle.normalAt(a); // the same normal everywhere, normalAt's to the last bit
    shapes[at] = tables.push(Float64Array.of(a.x, a.y, a.z, b.x - a.x, b.y - a.y, b.z - a.z, c.x - a.x, c.y - a.y, c.z - a.z, n.x, n.y, n.z)) - 1;
  },
  hit(s, b, ox, oy, oz, dx, dy, dz, tMin) {
    const t = sideTables.current[s[b]];
    return triangleHit(t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8], ox, oy, oz, dx, dy, dz, tMin);
  },
  normal(s, b, surface) {
    const t = sideTables.current[s[b]];
    surface[N] = t[9]; surface[N + 1] = t[10]; surface[N + 2] = t[11];
  },
});

/** A RangeError when a, b, c have (next to) no area; `where` says which triangle ("cells[3] " or ""). */
export function checkArea(a, b, c, where) {
  const e1 = sub(new Vec3(), b, a), e2 = sub(new Vec3(), c, a);
  checkSides(e1.x, e1.y, e1.z, e2.x, e2.y, e2.z, where);
  const k = edgeScale(e1.x, e1.y, e1.z, e2.x, e2.y, e2.z);
  scale(e1, e1, k);
  scale(e2, e2, k);
  const area2 = length(cross(new Vec3(), e1, e2));
  if (!(area2 > FLAT * length(e1) * length(e2))) {
    throw new RangeError(`${where}a, b, c must not lie on one line: the triangle has zero area`);
  }
}

/** A RangeError when an edge from a is longer than MAX_SIDE along an axis. */
export function checkSides(e1x, e1y, e1z, e2x, e2y, e2z, where) {
  if (Math.max(Math.abs(e1x), Math.abs(e1y), Math.abs(e1z), Math.abs(e2x), Math.abs(e2y), Math.abs(e2z)) > MAX_SIDE) {
    throw new RangeError(`${where}a side is longer than ${MAX_SIDE}: too big to trace (its determinant overflows)`);
  }
}

/** The record of `Triangle#intersect` for corners a, b, c (also a mesh's triangle hit). */
export function intersectTriangle(ray, a, b, c, target = {}) {
  const o = ray.origin, d = ray.direction;
  const e1 = sub(new Vec3(), b, a), e2 = sub(new Vec3(), c, a);
  const P = cross(new Vec3(), d, e2);
  const determinant = e1.x * P.x + e1.y * P.y + e1.z * P.z;
  Object.assign(target, { e1, e2, P, determinant, S: null, u: null, Q: null, v: null, t: null });
  const size2 = dot(e1, e1) * dot(e2, e2) * dot(d, d); // as triangleHit has it, to the last bit
  target.parallel = determinant * determinant <= PARALLEL * PARALLEL * size2;
  if (target.parallel) return target;
  const S = sub(new Vec3(), o, a);
  target.S = S;
  target.u = (S.x * P.x + S.y * P.y + S.z * P.z) / determinant;
  if (target.u < 0 || target.u > 1) return target; // outside, beyond the edge a–c or b–c
  const Q = cross(new Vec3(), S, e1);
  target.Q = Q;
  target.v = (d.x * Q.x + d.y * Q.y + d.z * Q.z) / determinant;
  if (target.v < 0 || target.u + target.v > 1) return target; // outside, beyond a–b or b–c
  const t = (e2.x * Q.x + e2.y * Q.y + e2.z * Q.z) / determinant;
  target.t = t > EPSILON ? t : null;
  return target;
}

/**
 * The ray–triangle test in numbers only (Triangle#hit, and every triangle
 * of a Mesh): corner a, edges e1 = b − a and e2 = c − a; t > tMin or Infinity.
 */
export function triangleHit(ax, ay, az, e1x, e1y, e1z, e2x, e2y, e2z, ox, oy, oz, dx, dy, dz, tMin) {
  const Px = dy * e2z - dz * e2y, Py = dz * e2x - dx * e2z, Pz = dx * e2y - dy * e2x; // P = Rd × e2
  const determinant = e1x * Px + e1y * Py + e1z * Pz;
  const size2 = (e1x * e1x + e1y * e1y + e1z * e1z) * (e2x * e2x + e2y * e2y + e2z * e2z) * (dx * dx + dy * dy + dz * dz);
  if (determinant * determinant <= PARALLEL * PARALLEL * size2) return Infinity; // parallel
  const Sx = ox - ax, Sy = oy - ay, Sz = oz - az; // S = Ro − a
  const u = (Sx * Px + Sy * Py + Sz * Pz) / determinant;
  if (u < 0 || u > 1) return Infinity;
  const Qx = Sy * e1z - Sz * e1y, Qy = Sz * e1x - Sx * e1z, Qz = Sx * e1y - Sy * e1x; // Q = S × e1
  const v = (dx * Qx + dy * Qy + dz * Qz) / determinant;
  if (v < 0 || u + v > 1) return Infinity;
  const t = (e2x * Qx + e2y * Qy + e2z * Qz) / determinant;
  return t > tMin ? t : Infinity;
}
