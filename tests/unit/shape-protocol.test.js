import { describe, it, expect } from 'vitest';
import { Ray } from '../../lib/math/ray.js';
import { Sphere, Plane, Box, shapeClasses, shapeClass, kindOf, isShape, ballOf, middleOf, registerShape } from '../../lib/shapes/index.js';
import { EPSILON } from '../../lib/math/constants.js';

const ray = new Ray([0, 0, 0], [0, 0, -1]);

describe('every listed shape has the protocol', () => {
  const examples = [new Sphere([0, 0, -20], 4), new Plane([0, -1, 0], [0, 1, 0]), new Box([-1, -1, -12], [1, 1, -10])];
  for (const shape of examples) {
    it(`${kindOf(shape)}: intersect's t is hit's, bounds, JSON by type`, () => {
      const record = shape.intersect(new Ray([0.3, 0.2, 0], [0.01, -0.2, -1]));
      const t = shape.hit(new Ray([0.3, 0.2, 0], [0.01, -0.2, -1]), EPSILON);
      if (t === Infinity) expect(record.t).toBe(null);
      else expect(record.t).toBeCloseTo(t, 9); // a sphere's record is the quadratic route's, its hit the geometric one's
      expect(isShape(shape)).toBe(true);
      const json = shape.toJSON();
      expect(json.type).toBe(kindOf(shape));
      const Shape = shapeClass(json.type);
      expect(Shape.fields.every((f) => f in json)).toBe(true);
      expect(Shape.build(json, shape.material).toJSON()).toEqual(json);
      for (const [label] of shape.recordRows(record)) expect(typeof label).toBe('string');
    });
  }
  it('lists the sphere, the plane and the box, in the lesson\'s order', () => {
    expect(shapeClasses().slice(0, 3)).toEqual([Sphere, Plane, Box]);
  });
});

describe('each shape\'s own record', () => {
  it('a sphere: the quadratic route, with the geometric route beside it', () => {
    const r = new Sphere([0, 0, -20], 4).intersect(ray);
    expect([r.A, r.B, r.C, r.discriminant, r.roots, r.t0, r.t1, r.t]).toEqual([1, -40, 384, 64, 2, 16, 24, 16]);
    expect([r.geometric.tca, r.geometric.d2, r.geometric.thc, r.geometric.t]).toEqual([20, 0, 4, 16]);
  });
  it('a plane: Rd·n, (P0 − Ro)·n and t = their quotient; a ray along it has no t', () => {
    const r = new Plane([0, 0, -5], [0, 0, 1]).intersect(ray);
    expect([r.denominator, r.numerator, r.t]).toEqual([-1, -5, 5]);
    const along = new Plane([0, -1, 0], [0, 1, 0]).intersect(ray);
    expect([along.denominator, along.t]).toEqual([0, null]);
  });
  it('a box: each slab\'s entry and exit, the latest entry and the earliest exit', () => {
    const r = new Box([-1, -2, -12], [1, 2, -10]).intersect(new Ray([0, 0, 0], [0, 0, -1]));
    expect(r.slabs).toEqual([{ axis: 'x', tmin: -Infinity, tmax: Infinity }, { axis: 'y', tmin: -Infinity, tmax: Infinity }, { axis: 'z', tmin: 10, tmax: 12 }]);
    expect([r.tNear, r.tFar, r.t]).toEqual([10, 12, 10]);
    const past = new Box([5, -2, -12], [6, 2, -10]).intersect(new Ray([0, 0, 0], [0, 0, -1]));
    expect([past.slabs[0].tmin, past.tNear, past.t]).toEqual([null, null, null]);
  });
});

describe('bounds, balls and middles', () => {
  it('a sphere is bounded by Sc ∓ r and is a ball; a box by its corners; a plane not at all', () => {
    const s = new Sphere([1, 2, 3], 2);
    expect(s.bounds()).toEqual({ min: { x: -1, y: 0, z: 1 }, max: { x: 3, y: 4, z: 5 } });
    expect(ballOf(s)).toBe(s);
    expect(new Box([0, 0, 0], [2, 4, 6]).bounds()).toEqual({ min: { x: 0, y: 0, z: 0 }, max: { x: 2, y: 4, z: 6 } });
    expect(ballOf(new Box([0, 0, 0], [2, 4, 6]))).toBe(null);
    expect(new Plane().bounds()).toBe(null);
    expect(middleOf(new Box([0, 0, 0], [2, 4, 6]))).toEqual({ x: 1, y: 2, z: 3 });
  });
});

describe('registerShape', () => {
  it('refuses a class without type, fields and build, and a type already taken', () => {
    expect(() => registerShape(class {})).toThrow(/static type, fields and build/);
    class Other { static get type() { return 'sphere'; } static get fields() { return []; } static build() { return null; } }
    expect(() => registerShape(Other)).toThrow(/"sphere" is taken/);
    expect(registerShape(Sphere)).toBe(Sphere);
  });
});

describe('shapeNames', () => {
  it("is shapeName of each shape, a shape added twice and a sketch's own object too", async () => {
    const { shapeName, shapeNames } = await import('../../lib/scene/scene.js');
    const a = new Sphere([0, 0, -5], 1), b = new Box([0, 0, 0], [1, 1, 1]), own = { hit: () => Infinity };
    const objects = [a, new Plane(), a, b, new Sphere([0, 0, -9], 1, { name: 'moon' }), own, new Sphere([1, 0, -5], 1)];
    expect(shapeNames(objects)).toEqual(objects.map((o) => shapeName(o, objects)));
    expect(shapeNames(objects)).toEqual(['sphere 1', 'plane 1', 'sphere 1', 'box 1', 'moon', 'object 6', 'sphere 4']);
  });
});
