import { describe, it, expect } from 'vitest';
import { Ray } from '../../lib/index.js';
import { Vec3 } from '../../lib/math/vec3.js';
import { Triangle } from '../../lib/shapes/triangle.js';
import { seeded, randomDirection } from './convex-reference.js';

/**
 * The Ray Tracer Challenge (Buck, 2019), ch. 15 "Triangles": the triangle
 * p1 = (0, 1, 0), p2 = (−1, 0, 0), p3 = (1, 0, 0), rays from z = −2 along +z.
 * The book's normal is normalize(e2 × e1) = (0, 0, −1); ours is e1 × e2
 * (a, b, c counterclockwise seen from the front in our right-handed frame),
 * so its sign is the other: (0, 0, 1). The renderer turns a normal to face
 * the ray either way.
 */
const triangle = new Triangle([0, 1, 0], [-1, 0, 0], [1, 0, 0]);
const plain = (v) => ({ x: v.x + 0, y: v.y + 0, z: v.z + 0 }); // −0 as 0


describe('the book\'s scenarios (ch. 15)', () => {
  it('constructing a triangle: e1 = (−1, −1, 0), e2 = (1, −1, 0)', () => {
    const r = triangle.intersect(new Ray([0, 0.5, -2], [0, 0, 1]));
    expect(r.e1).toEqual({ x: -1, y: -1, z: 0 });
    expect(r.e2).toEqual({ x: 1, y: -1, z: 0 });
  });

  it.each([[0, 0.5, 0], [-0.5, 0.75, 0], [0.5, 0.25, 0]])('the normal at (%d, %d, %d) is the same everywhere', (x, y, z) => {
    expect(triangle.normalAt(new Vec3(x, y, z))).toEqual({ x: 0, y: 0, z: 1 });
  });

  it('a ray parallel to the triangle: P = Rd × e2 = (0, 0, −1), determinant e1·P = 0', () => {
    const ray = new Ray([0, -1, -2], [0, 1, 0]);
    const r = triangle.intersect(ray);
    expect(plain(r.P)).toEqual({ x: 0, y: 0, z: -1 });
    expect(r.determinant + 0).toBe(0);
    expect(r.parallel).toBe(true);
    expect(r.t).toBeNull();
    expect(triangle.hit(ray)).toBe(Infinity);
  });

  it.each([
    ['p1–p3', [1, 1, -2]],
    ['p1–p2', [-1, 1, -2]],
    ['p2–p3', [0, -1, -2]],
  ])('a ray misses the %s edge', (edge, origin) => {
    const ray = new Ray(origin, [0, 0, 1]);
    expect(triangle.intersect(ray).t).toBeNull();
    expect(triangle.hit(ray)).toBe(Infinity);
  });

  it('a ray strikes the triangle at t = 2, by hand', () => {
    // P = (0, 0, 1) × (1, −1, 0) = (1, 1, 0); det = e1·P = −1 − 1 = −2
    // S = Ro − p1 = (0, −0.5, −2); u = S·P / det = −0.5 / −2 = 0.25
    // Q = S × e1 = (−2, 2, −0.5); v = Rd·Q / det = −0.5 / −2 = 0.25; t = e2·Q / det = (−2 − 2) / −2 = 2
    const ray = new Ray([0, 0.5, -2], [0, 0, 1]);
    const r = triangle.intersect(ray);
    expect(r).toMatchObject({ determinant: -2, u: 0.25, v: 0.25, t: 2, parallel: false });
    expect([r.P, r.S, r.Q].map(plain)).toEqual([{ x: 1, y: 1, z: 0 }, { x: 0, y: -0.5, z: -2 }, { x: -2, y: 2, z: -0.5 }]);
    expect(triangle.hit(ray)).toBe(2);
  });

  it('ch. 15, smooth triangles: the ray from (−0.2, 0.3, −2) meets it at u = 0.45, v = 0.25', () => {
    // S = (−0.2, −0.7, −2): u = S·(1, 1, 0) / −2 = −0.9 / −2 = 0.45; Q = S × e1 = (−2, 2, −0.5): v = −0.5 / −2 = 0.25
    const r = triangle.intersect(new Ray([-0.2, 0.3, -2], [0, 0, 1]));
    expect(r.u).toBeCloseTo(0.45, 12);
    expect(r.v).toBeCloseTo(0.25, 12);
    expect(r.t).toBeCloseTo(2, 12);
  });
});

describe('the book\'s bounding box (the bonus chapter "Bounding boxes and hierarchies")', () => {
  it('"A triangle has a bounding box": (−3, 7, 2), (6, 2, −4), (2, −1, −1) → (−3, −1, −4) to (6, 7, 2)', () => {
    expect(new Triangle([-3, 7, 2], [6, 2, -4], [2, -1, -1]).bounds()).toEqual({ min: { x: -3, y: -1, z: -4 }, max: { x: 6, y: 7, z: 2 } });
  });
});

describe('bad values are refused, naming the field', () => {
  it.each([
    [() => new Triangle([0, 0, 0], [1, 1, 1], [2, 2, 2]), RangeError, /a, b, c must not lie on one line: the triangle has zero area/],
    [() => new Triangle([0, 0, 0], [0, 0, 0], [1, 0, 0]), RangeError, /zero area/],
    [() => new Triangle([0, 0, 0], [1, 0, NaN], [0, 1, 0]), TypeError, /b\.z must be a finite number/],
    [() => new Triangle([0, 0, 0], [1, 0, 0]), TypeError, /c must be \[x, y, z\]/],
  ])('%#', (make, type, message) => {
    expect(make).toThrow(type);
    expect(make).toThrow(message);
  });
});

describe('against the plane and the inside test, on seeded random rays', () => {
  it('t puts the hit on the triangle\'s plane, inside it; a miss is outside or parallel', () => {
    const random = seeded(22);
    let hits = 0;
    for (let i = 0; i < 2000; i++) {
      const corner = () => [random() * 4 - 2, random() * 4 - 2, random() * 4 - 12];
      const [a, b, c] = [corner(), corner(), corner()];
      const tri = new Triangle(a, b, c);
      const origin = [random() - 0.5, random() - 0.5, 0];
      const aim = [0, 1, 2].map((k) => (a[k] + b[k] + c[k]) / 3 + random() - 0.5 - origin[k]); // near its middle
      const ray = new Ray(origin, i % 4 ? aim : randomDirection(random));
      // the reference: the plane's t, then barycentric areas of the point (no Möller–Trumbore)
      const n = tri.normalAt(new Vec3());
      const denominator = n.x * ray.direction.x + n.y * ray.direction.y + n.z * ray.direction.z;
      const tPlane = ((a[0] - ray.origin.x) * n.x + (a[1] - ray.origin.y) * n.y + (a[2] - ray.origin.z) * n.z) / denominator;
      const p = [0, 1, 2].map((k) => ray.origin['xyz'[k]] + ray.direction['xyz'[k]] * tPlane);
      const areaTowards = (q, r) => { // signed area of (p, q, r) along n
        const u = q.map((x, k) => x - p[k]), v = r.map((x, k) => x - p[k]);
        return (u[1] * v[2] - u[2] * v[1]) * n.x + (u[2] * v[0] - u[0] * v[2]) * n.y + (u[0] * v[1] - u[1] * v[0]) * n.z;
      };
      const inside = [areaTowards(a, b), areaTowards(b, c), areaTowards(c, a)];
      const clearlyIn = inside.every((s) => s > 1e-9), clearlyOut = inside.some((s) => s < -1e-9);
      const t = tri.hit(ray);
      if (clearlyIn && tPlane > 1e-6) {
        expect(Math.abs(t - tPlane)).toBeLessThanOrEqual(1e-9 * tPlane);
        hits++;
      } else if (clearlyOut || tPlane < 0) {
        expect(t).toBe(Infinity);
      }
      expect(tri.intersect(ray).t ?? Infinity).toBe(t);
    }
    expect(hits).toBeGreaterThan(500);
  });
});
