/**
 * What the cylinder and the cone share: both stand on a vertical axis through
 * `center`, from center.y − height/2 to center.y + height/2, both are the
 * lesson's quadratic At² + Bt + C = 0 with y treated apart, and both may be
 * closed by flat discs (caps).
 */
import { toVec3, Vec3 } from '../math/vec3.js';
import { finiteNumber, bool } from '../text/check.js';
import { Material, shapeOptions, materialOptions } from './material.js';
import { vector, materialToJSON } from './json.js';
import { axialTriangles } from './tessellate.js';
import { P, N } from './packed.js';

/**
 * A discriminant this small, relative to the terms it is the difference of
 * (B² and 4AC), counts as zero: the ray grazes the surface (as for the sphere).
 */
export const TANGENT = 1e-12;

/**
 * The packed form (lib/shapes/packed.js) of a Cylinder or a Cone, six numbers:
 * cx cy cz radius height capped (1 or 0); `hit` and `normal` are its
 * numbers-only test and normal (cylinderHit/cylinderNormal, coneHit/coneNormal).
 */
export function axialPacked(hit, normal) {
  return Object.freeze({
    pack(shape, shapes, at) {
      const c = shape.center;
      shapes.set([c.x, c.y, c.z, shape.radius, shape.height, shape.capped ? 1 : 0], at);
    },
    hit(s, b, ox, oy, oz, dx, dy, dz, tMin) {
      return hit(s[b], s[b + 1], s[b + 2], s[b + 3], s[b + 4], s[b + 5] === 1, ox, oy, oz, dx, dy, dz, tMin);
    },
    normal(s, b, surface) {
      normal(s[b], s[b + 1], s[b + 2], s[b + 3], s[b + 4], s[b + 5] === 1, surface[P], surface[P + 1], surface[P + 2], surface, N);
    },
  });
}

/**
 * The checked arguments of a Cylinder or a Cone: `center`, `radius` > 0,
 * `height` > 0, and the options: `capped` (default true) plus a sphere's
 * material options and `name`.
 */
export function axialArguments(center, radius, height, options) {
  const c = toVec3(center, 'center');
  positive(radius, 'radius');
  positive(height, 'height');
  let capped = true, rest = options;
  if (options && typeof options === 'object' && !(options instanceof Material) && Object.hasOwn(options, 'capped')) {
    ({ capped, ...rest } = options);
    bool(capped, 'capped');
  }
  const { name, material } = shapeOptions(rest);
  return { center: c, radius, height, capped, name, material };
}

/**
 * The largest radius, height or cone slope (radius / height): past it a square
 * in the quadratic (k²·B², r²) overflows to Infinity, and Infinity − Infinity
 * is a NaN, a black pixel with no message (a cone of radius 1e308 drew one).
 */
export const MAX_SIZE = 1e30;

/** A finite number greater than 0 and at most MAX_SIZE, else an error naming `field`. */
function positive(value, field) {
  finiteNumber(value, field);
  if (value <= 0) throw new RangeError(`${field} must be greater than 0, got ${value}`);
  if (value > MAX_SIZE) throw new RangeError(`${field} must be at most ${MAX_SIZE}, got ${value}`);
}

/**
 * Solves At² + Bt + C = 0 into `out` (a Float64Array of 2, t0 ≤ t1) and
 * returns how many real roots there are: 0, 1 or 2. A = 0 is a line, not a
 * parabola: one root −C/B, or none when B = 0 too (the ray runs along the
 * surface, never crossing it).
 */
export function solveQuadratic(A, B, C, out) {
  if (A === 0) {
    if (B === 0) return 0;
    out[0] = out[1] = -C / B;
    return 1;
  }
  const discriminant = B * B - 4 * A * C;
  if (Math.abs(discriminant) <= TANGENT * (B * B + 4 * Math.abs(A * C))) {
    out[0] = out[1] = -B / (2 * A); // tangent
    return 1;
  }
  if (discriminant < 0) return 0;
  // (−B ± √disc) / 2A, written so the two terms never cancel each other out.
  const q = -0.5 * (B + (B < 0 ? -1 : 1) * Math.sqrt(discriminant));
  const ta = q / A, tb = C / q;
  out[0] = Math.min(ta, tb);
  out[1] = Math.max(ta, tb);
  return 2;
}

/** The record's `roots`, `t0`, `t1` (from `solveQuadratic`) and their heights `y0`, `y1`; null when there are none. */
export function recordSide(target, count, roots, oy, dy) {
  target.roots = count;
  target.t0 = count ? roots[0] : null;
  target.t1 = count ? roots[1] : null;
  target.y0 = count ? oy + dy * roots[0] : null;
  target.y1 = count ? oy + dy * roots[1] : null;
}

/**
 * t where the ray (x, z: the origin relative to the axis) crosses the plane
 * y = yPlane inside the disc of radius² `r2` around the axis, or NaN: a ray
 * parallel to the plane, or one crossing it outside the disc.
 */
export function capCrossing(yPlane, r2, x, oy, z, dx, dy, dz) {
  if (dy === 0) return NaN;
  const t = (yPlane - oy) / dy;
  const px = x + dx * t, pz = z + dz * t;
  return px * px + pz * pz <= r2 ? t : NaN;
}

/** Is y within the side's span: above `lo`, below `hi` (or at it, when `closedTop`)? */
export function withinSpan(y, lo, hi, closedTop) {
  return y > lo && (y < hi || (closedTop && y === hi));
}

/** A number, or null when it is NaN (the record's "none"). */
export function orNull(value) {
  return Number.isNaN(value) ? null : value;
}

/** The box around a shape of `radius` on the axis from `bottom` to `top`. */
export function axialBounds(center, radius, height) {
  return {
    min: new Vec3(center.x - radius, center.y - height / 2, center.z - radius),
    max: new Vec3(center.x + radius, center.y + height / 2, center.z + radius),
  };
}

/**
 * A Cylinder's or Cone's options from scene JSON: its Material (or none) and
 * `capped`, as the constructor takes them.
 */
export function withCapped(material, capped) {
  if (capped === undefined) return material;
  return material === undefined ? { capped } : { ...materialOptions(material), capped };
}

/**
 * What a Cylinder and a Cone share: their checked arguments, their box,
 * their JSON and scene code, and their 3D view (a cone is a cylinder whose
 * top radius is 0). Each gives its own `hit`, `intersect`, `normalAt`,
 * `recordRows` and static `type`.
 */
export class AxialShape {
  constructor(center, radius, height, options) {
    const checked = axialArguments(center, radius, height, options);
    this.center = checked.center;
    this.radius = checked.radius;
    this.height = checked.height;
    this.capped = checked.capped;
    this.name = checked.name;
    this.material = checked.material;
  }

  /** What its drawing in the 3D view depends on (the view's mesh cache, lib/p5/scene-view/mesh.js). */
  viewKey() {
    const c = this.center;
    return `${c.x},${c.y},${c.z},${this.radius},${this.height},${this.capped}`;
  }

  /** The world-space box around it. */
  bounds() {
    return axialBounds(this.center, this.radius, this.height);
  }

  /** Draws itself into a 3D view's mesh with the view's own tools (lib/p5/scene-view/mesh.js). */
  drawIn3D(kit, into, rgb) {
    kit.triangles(into, axialTriangles(this.center, this.radius, this.topRadius, this.height, this.capped), rgb);
  }

  /** The radius at its top: the cylinder's own, a cone's 0. */
  get topRadius() { return this.radius; }

  /** Its scene JSON (lib/scene/json.js). */
  toJSON() {
    return { type: /** @type {any} */ (this.constructor).type, name: this.name ?? '', center: vector(this.center), radius: this.radius, height: this.height, capped: this.capped, material: materialToJSON(this.material) };
  }

  /** Its JSON fields. */
  static get fields() { return ['center', 'radius', 'height', 'capped', 'material']; }

  /** One from its fields (checked by the constructor). */
  static build(o, material) {
    return new this(o.center, o.radius, o.height, withCapped(material, o.capped));
  }

  /** Its constructor's arguments in scene code: `capped` goes with the material's options, and only when false. */
  static codeArguments(o, material) {
    const options = o.capped === false ? { ...material, capped: false } : material;
    return [o.center, o.radius, o.height, options];
  }
}
