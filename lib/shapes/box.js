/**
 * An axis-aligned box between corners `min` and `max` (the slab method).
 */
import { toVec3, Vec3, set } from '../vec3.js';
import { shapeOptions } from '../material.js';
import { EPSILON } from '../constants.js';

const AXES = ['x', 'y', 'z'];

export class Box {
  /**
   * @param {number[]|{x,y,z}} min the corner with the smallest x, y, z
   * @param {number[]|{x,y,z}} max the opposite corner; larger on every axis
   * @param {import('../material.js').Material|object} [material] a Material or its options, which may also give the shape a `name`
   * @example
   * const housing = new Box([-0.8, 3.4, -16.8], [0.8, 7.4, -16.2], { color: [0.15, 0.15, 0.16] }); // two opposite corners
   */
  constructor(min, max, material) {
    this.min = toVec3(min, 'min');
    this.max = toVec3(max, 'max');
    for (const a of AXES) {
      if (!(this.max[a] > this.min[a])) {
        throw new RangeError(`max.${a} must be greater than min.${a}, got ${this.max[a]} ≤ ${this.min[a]}`);
      }
    }
    const shape = shapeOptions(material);
    this.name = shape.name;
    this.material = shape.material;
  }

  /** Smallest t > tMin where the ray meets the box, or Infinity. */
  hit(ray, tMin = EPSILON) {
    let tNear = -Infinity, tFar = Infinity;
    for (let i = 0; i < 3; i++) {
      const a = AXES[i];
      const o = ray.origin[a], d = ray.direction[a];
      if (d === 0) {
        if (o < this.min[a] || o > this.max[a]) return Infinity; // parallel and outside this slab
        continue;
      }
      let t1 = (this.min[a] - o) / d, t2 = (this.max[a] - o) / d;
      if (t1 > t2) { const s = t1; t1 = t2; t2 = s; }
      if (t1 > tNear) tNear = t1;
      if (t2 < tFar) tFar = t2;
      if (tNear > tFar) return Infinity;
    }
    if (tNear > tMin) return tNear;
    return tFar > tMin ? tFar : Infinity; // the ray starts inside
  }

  /** The outward normal of the face nearest to `point`. */
  normalAt(point, out = new Vec3()) {
    let best = Infinity;
    set(out, 0, 1, 0);
    for (const a of AXES) {
      const toMin = Math.abs(point[a] - this.min[a]), toMax = Math.abs(point[a] - this.max[a]);
      if (toMin < best) { best = toMin; set(out, 0, 0, 0); out[a] = -1; }
      if (toMax < best) { best = toMax; set(out, 0, 0, 0); out[a] = 1; }
    }
    return out;
  }
}
