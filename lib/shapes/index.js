/**
 * The list of shapes: every shape class of the kit, and what the rest of the
 * library asks of a shape without knowing its class.
 *
 * The shape protocol (docs/ARCHITECTURE.md, "A new shape"): a shape has
 * `hit(ray, tMin)`, `normalAt(point, out)`, `intersect(ray, target)` (the
 * lesson's record, `t` the nearest hit past EPSILON or null), `bounds()`
 * (null when unbounded), `material` and `name`; it may also have
 * `recordRows(record)` (its record's lines in the inspector), `middle()`
 * (where its light shines from), `drawIn3D(kit, into, rgb)` (the 3D view),
 * `ball()` (only a ball: its `{ center, radius }`) and `toJSON()`. Its class
 * gives `type`, `fields` and `build(fields, material)` for scene JSON, and
 * may give `packed` (lib/shapes/packed.js) for render()'s kernel.
 */
import { Sphere } from './sphere.js';
import { Plane } from './plane.js';
import { Box } from './box.js';
import { Cylinder } from './cylinder.js';
import { Cone } from './cone.js';
import { Triangle } from './triangle.js';
import { Mesh } from './mesh.js';
import { Material } from './material.js';
import { show } from '../text/check.js';

/**
 * A shape class as the list knows it.
 * @typedef {Function & { type: string, fields: string[], build: (fields: object, material?: Material) => object, check?: (shape: object, material?: Material) => void, packed?: object, workOf?: (json: any) => { triangles: number, field: string }, form?: { title: string, what: string, columns: object[] } }} ShapeClass
 */

/**
 * Every shape class, in the order the lesson meets them. A new shape is one more entry here.
 * @type {ShapeClass[]}
 */
const SHAPES = [Sphere, Plane, Box, Cylinder, Cone, Triangle, Mesh];

/** Each listed class's own `hit` and `normalAt`, as listed (a sketch may replace them later). */
const METHODS = new Map();
const remember = (Shape) => METHODS.set(Shape, { hit: Shape.prototype.hit, normalAt: Shape.prototype.normalAt });
SHAPES.forEach(remember);

/** The methods every shape has (the protocol's core). */
const CORE = ['hit', 'normalAt', 'intersect', 'bounds'];

/**
 * Adds a shape class to the list (a sketch's or a test's own shape): it can
 * then be read from scene JSON by its `type`. Returns the class.
 * @param {any} Shape a class with static `type`, `fields` and `build`
 * @example
 * class Dot extends Sphere { static get type() { return 'dot'; } static build(o, m) { return new Dot(o.center, o.radius, m); } }
 * registerShape(Dot); // a shape of the sketch's own (docs/ARCHITECTURE.md, "A new shape")
 * sceneFromJSON({ objects: [{ type: 'dot', center: [0, 0, -10], radius: 1 }] }).objects[0] instanceof Dot; // true
 */
export function registerShape(Shape) {
  if (typeof Shape !== 'function' || typeof Shape.type !== 'string' || !Array.isArray(Shape.fields) || typeof Shape.build !== 'function') {
    throw new TypeError(`registerShape takes a shape class with static type, fields and build, got ${show(Shape)}`);
  }
  const taken = shapeClass(Shape.type);
  if (taken === Shape) return Shape;
  if (taken) throw new TypeError(`the shape type ${show(Shape.type)} is taken`);
  SHAPES.push(Shape);
  remember(Shape);
  return Shape;
}

/** The shape classes, in order (read only). */
export function shapeClasses() {
  return SHAPES;
}

/** The shape class of a scene JSON `type` ('sphere'), or undefined. */
export function shapeClass(type) {
  return SHAPES.find((Shape) => Shape.type === type);
}

/**
 * The triangles a shape's JSON makes (its class's `workOf`, read before any check), and
 * the field that says so ('' for the shape itself); none for a shape without it.
 * @param {any} o the shape's JSON (not checked yet)
 * @returns {{ triangles: number, field: string }}
 */
export function shapeWork(o) {
  const Shape = shapeClass(o.type);
  return typeof Shape?.workOf === 'function' ? Shape.workOf(o) : { triangles: 0, field: '' };
}

/**
 * The listed class that made `shape` itself (not a subclass) when the shape's
 * `hit` and `normalAt` are still that class's, as listed; else undefined.
 */
export function plainClassOf(shape) {
  const methods = METHODS.get(shape?.constructor);
  return methods && shape.hit === methods.hit && shape.normalAt === methods.normalAt ? shape.constructor : undefined;
}

/** The listed class a shape is made by (a subclass's parent too), or undefined. */
export function classOf(shape) {
  return SHAPES.find((Shape) => shape instanceof Shape);
}

/** The word for a shape's kind: its class's type ('sphere', 'box'), or 'object' for one not listed. */
export function kindOf(shape) {
  return classOf(shape)?.type ?? 'object';
}

/**
 * The name the code builds a shape or light class by (`new Sphere(…)`): its own
 * static `codeName`, else the class's own name (a subclass does not take its parent's).
 * @param {Function & { codeName?: string }} Class
 */
export function codeNameOf(Class) {
  return Object.hasOwn(Class, 'codeName') ? Class.codeName : Class.name;
}

/** True when `item` implements the shape protocol: its core methods and a Material. */
export function isShape(item) {
  return item !== null && typeof item === 'object' && CORE.every((m) => typeof item[m] === 'function') && item.material instanceof Material;
}

/** The shape as a ball `{ center, radius }` when it is one (a sphere), else null. */
export function ballOf(shape) {
  return typeof shape.ball === 'function' ? shape.ball() : null;
}

/** Where a light of this shape shines from: its `middle()`, else the middle of its bounds. */
export function middleOf(shape) {
  if (typeof shape.middle === 'function') return shape.middle();
  const b = shape.bounds();
  return b ? { x: (b.min.x + b.max.x) / 2, y: (b.min.y + b.max.y) / 2, z: (b.min.z + b.max.z) / 2 } : { x: 0, y: 0, z: 0 };
}

export { Sphere, Plane, Box, Cylinder, Cone, Triangle, Mesh };
