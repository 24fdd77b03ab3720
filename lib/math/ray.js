/**
 * A ray R(t) = Ro + Rd·t, t > 0, with Rd normalised (the lesson's slide 2).
 */
import { toVec3, toUnit, scaleAndAdd, Vec3 } from './vec3.js';

export class Ray {
  /**
   * @param {number[]|{x,y,z}} origin Ro
   * @param {number[]|{x,y,z}} direction Rd, normalised here; must not be zero-length
   * @example
   * const ray = new Ray([0, 0, 0], [0, 3, -4]);
   * ray.direction; // { x: 0, y: 0.6, z: -0.8 }: normalised
   */
  constructor(origin = [0, 0, 0], direction = [0, 0, -1]) {
    this.origin = toVec3(origin, 'origin');
    const d = toVec3(direction, 'direction');
    this.direction = toUnit(d, d, 'direction');
  }

  /** The point R(t), written into `out`. */
  at(t, out = new Vec3()) {
    return scaleAndAdd(out, this.origin, this.direction, t);
  }
}
