/**
 * An axis-aligned box between corners `min` and `max` (the slab method).
 */
import { toVec3, Vec3, set } from '../math/vec3.js';
import { shapeOptions } from './material.js';
import { EPSILON } from '../math/constants.js';
import { vector, materialToJSON } from './json.js';
import { xyz, share, SURFACE } from './form.js';
import { P, N, scratchNumbers } from './packed.js';

const AXES = ['x', 'y', 'z'];

export class Box {
  /**
   * @param {number[]|{x,y,z}} min the corner with the smallest x, y, z
   * @param {number[]|{x,y,z}} max the opposite corner; larger on every axis
   * @param {import('./material.js').Material|object} [material] a Material or its options, which may also give the shape a `name`
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

  /**
   * The lesson's record: each slab's `{ axis, tmin, tmax }` (where the ray
   * enters and leaves it; for a ray parallel to it −∞…∞ inside, null outside),
   * `tNear` the latest entry, `tFar` the earliest exit, and `t` the nearest
   * hit past EPSILON or null.
   */
  intersect(ray, target = {}) {
    let tNear = -Infinity, tFar = Infinity;
    target.slabs = AXES.map((axis) => {
      const o = ray.origin[axis], d = ray.direction[axis], min = this.min[axis], max = this.max[axis];
      if (d === 0) return o < min || o > max ? { axis, tmin: null, tmax: null } : { axis, tmin: -Infinity, tmax: Infinity };
      const t1 = (min - o) / d, t2 = (max - o) / d;
      const slab = { axis, tmin: Math.min(t1, t2), tmax: Math.max(t1, t2) };
      tNear = Math.max(tNear, slab.tmin); tFar = Math.min(tFar, slab.tmax);
      return slab;
    });
    const outside = target.slabs.some((slab) => slab.tmin === null);
    target.tNear = outside ? null : tNear;
    target.tFar = outside ? null : tFar;
    const t = this.hit(ray, EPSILON);
    target.t = t === Infinity ? null : t;
    return target;
  }

  /** The record's lines for the inspector: `[label, value]`. */
  recordRows(record) {
    return [...record.slabs.flatMap(({ axis, tmin, tmax }) => [[`${axis} slab tmin`, tmin], [`${axis} slab tmax`, tmax]]),
      ['tNear', record.tNear], ['tFar', record.tFar], ['t', record.t]];
  }

  /** Its two corners. */
  bounds() {
    return { min: this.min, max: this.max };
  }

  /** Where a light of this shape shines from: halfway between its corners. */
  middle() {
    const { min, max } = this;
    return new Vec3((min.x + max.x) / 2, (min.y + max.y) / 2, (min.z + max.z) / 2);
  }

  /** Draws itself into a 3D view's mesh with the view's own tools (lib/p5/scene-view/view.js). */
  drawIn3D(kit, into, rgb) {
    kit.box(into, this.min, this.max, rgb);
  }

  /** Its scene JSON (lib/scene/json.js). */
  toJSON() {
    return { type: 'box', name: this.name ?? '', min: vector(this.min), max: vector(this.max), material: materialToJSON(this.material) };
  }

  /** Its type in scene JSON. */
  static get type() { return 'box'; }
  /** The class's name in the code that builds it (lib/scene/json.js, sceneToCode). */
  static get codeName() { return 'Box'; }
  /** What its drawing in the 3D view depends on (the view's mesh cache, lib/p5/scene-view/mesh.js). */
  viewKey() { const a = this.min, b = this.max; return `${a.x},${a.y},${a.z},${b.x},${b.y},${b.z}`; }
  /** Built again from its JSON, the same to the bit (lib/scene/edits.js need not build it twice). */
  static get roundTrips() { return true; }

  /** Its JSON fields, in the order the constructor takes them. */
  static get fields() { return ['min', 'max', 'material']; }

  /** A box from its fields (checked by the constructor). */
  static build(o, material) {
    return new Box(o.min, o.max, material);
  }

  /** Its packed form for render()'s kernel (lib/shapes/packed.js): min xyz, max xyz. */
  static get packed() { return PACKED; }

  /** Its table in the scene form (lib/shapes/form.js). */
  static get form() { return FORM; }
}

const FORM = Object.freeze({ title: 'Boxes', what: 'Box', columns: [...xyz('min', 'min'), ...xyz('max', 'max'), SURFACE, share('reflection')] });

/** [tNear, tFar] of the packed box's slabs so far. */
const slab = scratchNumbers(2);

/** Narrows `slab` by one axis' slab min…max; false when the ray misses it. */
function clipSlab(min, max, o, d) {
  if (d === 0) return !(o < min || o > max); // parallel: inside this slab or never
  let t1 = (min - o) / d, t2 = (max - o) / d;
  if (t1 > t2) { const swap = t1; t1 = t2; t2 = swap; }
  if (t1 > slab[0]) slab[0] = t1;
  if (t2 < slab[1]) slab[1] = t2;
  return !(slab[0] > slab[1]);
}

const PACKED = Object.freeze({
  pack(box, shapes, at) {
    shapes.set([box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z], at);
  },
  /** Box#hit in numbers: the slabs, x then y then z. */
  hit(s, b, ox, oy, oz, dx, dy, dz, tMin) {
    slab[0] = -Infinity; slab[1] = Infinity;
    if (!clipSlab(s[b], s[b + 3], ox, dx) || !clipSlab(s[b + 1], s[b + 4], oy, dy) || !clipSlab(s[b + 2], s[b + 5], oz, dz)) return Infinity;
    const tNear = slab[0], tFar = slab[1];
    if (tNear > tMin) return tNear;
    return tFar > tMin ? tFar : Infinity; // the ray starts inside
  },
  /** Box#normalAt in numbers: the axis of the nearest face, x then y then z, min face before max face. */
  normal(s, b, surface) {
    let best = Infinity;
    surface[N] = 0; surface[N + 1] = 1; surface[N + 2] = 0;
    for (let a = 0; a < 3; a++) {
      const toMin = Math.abs(surface[P + a] - s[b + a]), toMax = Math.abs(surface[P + a] - s[b + 3 + a]);
      if (toMin < best) { best = toMin; surface[N] = 0; surface[N + 1] = 0; surface[N + 2] = 0; surface[N + a] = -1; }
      if (toMax < best) { best = toMax; surface[N] = 0; surface[N + 1] = 0; surface[N + 2] = 0; surface[N + a] = 1; }
    }
  },
});
