/**
 * An infinite plane through `point` with unit `normal` (a floor, a wall).
 */
import { toVec3, toUnit, Vec3, copy } from '../math/vec3.js';
import { shapeOptions } from './material.js';
import { EPSILON } from '../math/constants.js';
import { vector, materialToJSON } from './json.js';
import { xyz, share, SURFACE } from './form.js';
import { N } from './packed.js';

/** |n·d| below this: the ray runs along the plane and misses it. */
const PARALLEL = 1e-12;

export class Plane {
  /**
   * @param {number[]|{x,y,z}} point any point on the plane
   * @param {number[]|{x,y,z}} normal the side it faces; normalised here, not zero-length
   * @param {import('./material.js').Material|object} [material] a Material or its options, which may also give the shape a `name`
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

  /**
   * The lesson's record: `{ denominator, numerator, t }`, denominator = Rd·n
   * (0: the ray runs along the plane), numerator = (P0 − Ro)·n, and
   * t = numerator / denominator when that is past EPSILON, else null.
   */
  intersect(ray, target = {}) {
    const n = this.normal, d = ray.direction, o = ray.origin, p = this.point;
    target.denominator = n.x * d.x + n.y * d.y + n.z * d.z;
    target.numerator = (p.x - o.x) * n.x + (p.y - o.y) * n.y + (p.z - o.z) * n.z;
    const t = this.hit(ray, EPSILON);
    target.t = t === Infinity ? null : t;
    return target;
  }

  /** The record's lines for the inspector: `[label, value]`. */
  recordRows(record) {
    return [['Rd·n', record.denominator], ['(P0 − Ro)·n', record.numerator], ['t', record.t]];
  }

  /** A plane has no bounds: it may be anywhere in the picture. */
  bounds() {
    return null;
  }

  /** Where a light of this shape shines from: its point. */
  middle() {
    return this.point;
  }

  /** Draws itself into a 3D view's mesh with the view's own tools (lib/p5/scene-view/view.js). */
  drawIn3D(kit, into, rgb) {
    kit.ground(into, this.point, this.normal, 0, rgb);
  }

  /** Its scene JSON (lib/scene/json.js). */
  toJSON() {
    return { type: 'plane', name: this.name ?? '', point: vector(this.point), normal: vector(this.normal), material: materialToJSON(this.material) };
  }

  /** Its type in scene JSON. */
  static get type() { return 'plane'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Plane'; }
  /** What its drawing in the 3D view depends on (the view's mesh cache, lib/p5/scene-view/mesh.js). */
  viewKey() { const p = this.point, n = this.normal; return `${p.x},${p.y},${p.z},${n.x},${n.y},${n.z}`; }

  /** Its JSON fields, in the order the constructor takes them. */
  static get fields() { return ['point', 'normal', 'material']; }

  /** A plane from its fields (checked by the constructor). */
  static build(o, material) {
    return new Plane(o.point, o.normal, material);
  }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): px py pz nx ny nz. */
  static get packed() { return PACKED; }

  /** Its table in the scene form (lib/shapes/form.js). */
  static get form() { return FORM; }
}

const FORM = Object.freeze({ title: 'Planes', what: 'Plane', columns: [...xyz('point', 'point'), ...xyz('normal', 'normal'), SURFACE, share('reflection')] });

const PACKED = Object.freeze({
  pack(plane, shapes, at) {
    shapes.set([plane.point.x, plane.point.y, plane.point.z, plane.normal.x, plane.normal.y, plane.normal.z], at);
  },
  hit(s, b, ox, oy, oz, dx, dy, dz, tMin) {
    return planeHit(s[b], s[b + 1], s[b + 2], s[b + 3], s[b + 4], s[b + 5], ox, oy, oz, dx, dy, dz, tMin);
  },
  normal(s, b, surface) {
    surface[N] = s[b + 3]; surface[N + 1] = s[b + 4]; surface[N + 2] = s[b + 5];
  },
});

/** The ray–plane test in numbers only (Plane#hit, and lib/tracing/kernel.js): t > tMin where the ray meets the plane, or Infinity. */
export function planeHit(px, py, pz, nx, ny, nz, ox, oy, oz, dx, dy, dz, tMin) {
  const denom = nx * dx + ny * dy + nz * dz;
  if (Math.abs(denom) < PARALLEL) return Infinity;
  const t = ((px - ox) * nx + (py - oy) * ny + (pz - oz) * nz) / denom;
  return t > tMin ? t : Infinity;
}
