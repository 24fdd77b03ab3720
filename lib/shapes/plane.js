/**
 * An infinite plane through `point` with unit `normal` (a floor, a wall).
 */
import { toVec3, toUnit, Vec3, copy } from '../vec3.js';
import { shapeOptions } from '../material.js';
import { EPSILON } from '../constants.js';

/** |n·d| below this: the ray runs along the plane and misses it. */
const PARALLEL = 1e-12;

export class Plane {
  /**
   * @param {number[]|{x,y,z}} point any point on the plane
   * @param {number[]|{x,y,z}} normal the side it faces; normalised here, not zero-length
   * @param {import('../material.js').Material|object} [material] a Material or its options, which may also give the shape a `name`
   * @example
   * const ground = new Plane([0, -4, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] }); // a point on it, the way it faces
   * const scene = new Scene().add(ground);
   */
  constructor(point = [0, 0, 0], normal = [0, 1, 0], material) {
    this.point = toVec3(point, 'point');
    const n = toVec3(normal, 'normal');
    this.normal = toUnit(n, n, 'normal');
    const shape = shapeOptions(material);
    this.name = shape.name;
    this.material = shape.material;
  }

  /** t where the ray meets the plane (t > tMin), or Infinity; a ray along the plane misses. */
  hit(ray, tMin = EPSILON) {
    const n = this.normal, d = ray.direction, o = ray.origin, p = this.point;
    return planeHit(p.x, p.y, p.z, n.x, n.y, n.z, o.x, o.y, o.z, d.x, d.y, d.z, tMin);
  }

  /** The plane's normal (the same everywhere). */
  normalAt(point, out = new Vec3()) {
    return copy(out, this.normal);
  }
}

/** The ray–plane test in numbers only (Plane#hit, and lib/kernel.js): t > tMin where the ray meets the plane, or Infinity. */
export function planeHit(px, py, pz, nx, ny, nz, ox, oy, oz, dx, dy, dz, tMin) {
  const denom = nx * dx + ny * dy + nz * dz;
  if (Math.abs(denom) < PARALLEL) return Infinity;
  const t = ((px - ox) * nx + (py - oy) * ny + (pz - oz) * nz) / denom;
  return t > tMin ? t : Infinity;
}
