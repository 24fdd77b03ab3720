import { describe, it, expect } from 'vitest';
import { Ray, EPSILON } from '../../lib/index.js';
import { Vec3 } from '../../lib/math/vec3.js';
import { Cone } from '../../lib/shapes/cone.js';
import { seeded, convexInterval, nearestOf, randomDirection } from './convex-reference.js';

/**
 * The Ray Tracer Challenge (Buck, 2019), ch. 13 "Cones": its cone is double,
 * x² + z² = y², two halves tip to tip at the origin, infinite unless given
 * y ∈ (minimum, maximum). Ours is one half, apex at the top: the book's lower
 * half is our Cone([0, −h/2, 0], h, h) (slope k = radius / height = 1).
 * A scenario on the book's upper half is mirrored (y → −y maps its cone onto
 * itself) to land on ours; `hits` counts the book's way, behind the origin
 * too: the side's roots between base and apex, and the base if crossed.
 */
const lowerHalf = new Cone([0, -50, 0], 100, 100, { capped: false });
const lowerHalfOf05 = new Cone([0, -0.25, 0], 0.5, 0.5); // the book's cone from y = −0.5 to 0.5, closed: its lower half

function hits(cone, ray) {
  const r = cone.intersect(ray);
  const base = cone.center.y - cone.height / 2, apex = cone.center.y + cone.height / 2;
  const roots = r.roots === 2 ? [r.t0, r.t1] : r.roots === 1 ? [r.t0] : [];
  const y = (t) => ray.origin.y + ray.direction.y * t;
  return roots.filter((t) => y(t) > base && y(t) <= apex).length + (r.tBase !== null);
}

describe('the book\'s scenarios (ch. 13)', () => {
  it('a ray from (0, 0, −5) along +z touches the apex: t0 = t1 = 5', () => {
    // x = 0, z = −5, apex − Yo = 0; A = 0 + 1 − 0 = 1, B = 2(−5) = −10, C = 25: B² − 4AC = 0
    const r = lowerHalf.intersect(new Ray([0, 0, -5], [0, 0, 1]));
    expect(r).toMatchObject({ A: 1, B: -10, C: 25, discriminant: 0, roots: 1, t0: 5, t1: 5, t: 5, part: 'side' });
  });

  it('a ray from (0, 0, −5) along (1, 1, 1) touches the upper half at t = 8.66025: not on ours', () => {
    // Rd = (1, 1, 1)/√3: A = 1/3 + 1/3 − 1/3, B = −10/√3, C = 25: B² − 4AC = 100/3 − 100/3 = 0,
    // t = −B / 2A = 5√3 = 8.66025 at y = 5, above our apex
    const r = lowerHalf.intersect(new Ray([0, 0, -5], [1, 1, 1]));
    expect(r.roots).toBe(1);
    expect(r.t0).toBeCloseTo(8.66025, 5);
    expect(r.y0).toBeCloseTo(5, 9);
    expect(r.t).toBeNull();
  });

  it('a ray from (1, 1, −5) along (−0.5, −1, 1) hits at 4.55006 and 49.44994, both on the lower half', () => {
    const ray = new Ray([1, 1, -5], [-0.5, -1, 1]);
    const r = lowerHalf.intersect(ray);
    expect(r.t0).toBeCloseTo(4.55006, 5);
    expect(r.t1).toBeCloseTo(49.44994, 5);
    expect(r.t).toBeCloseTo(4.55006, 5);
    expect(lowerHalf.hit(ray)).toBeCloseTo(4.55006, 5);
  });

  it('a ray parallel to one of its halves: A = 0, one root, t = −C/B', () => {
    // The book's ray from (0, 0, −1) along (0, 1, 1), mirrored: along (0, −1, 1)/√2.
    // A = 0 + ½ − ½ = 0; B = 2(z·Zd + k²(apex − Yo)·Yd) = 2(−1·√2/2 + 0) = −√2; C = 0 + 1 − 0 = 1
    // t = −C/B = 1/√2 = 0.70711 → (0, −0.5, −0.5): ρ = 0.5 = apex − y, on the cone.
    // (The book prints 0.35355, from its formula t = −c/2b; at that t the point
    // (0, −0.25, −0.75) has ρ = 0.75 ≠ 0.25: it is not on the cone.)
    const r = lowerHalf.intersect(new Ray([0, 0, -1], [0, -1, 1]));
    expect(r.A).toBe(0);
    expect(r.roots).toBe(1);
    expect(r.t).toBeCloseTo(Math.SQRT1_2, 12);
    // unmirrored, the same root lands on the upper half, which ours has not
    const up = lowerHalf.intersect(new Ray([0, 0, -1], [0, 1, 1]));
    expect(up.t0).toBeCloseTo(Math.SQRT1_2, 12);
    expect(up.t).toBeNull();
  });

  it.each([
    [[0, 0, -5], [0, 1, 0], 0], // beside it, straight up
    [[0, 0, -0.25], [0, -1, 1], 2], // mirrored from the book's (0, 1, 1): the side at y = −0.125 and the base
    [[0, 0, -0.25], [0, 1, 0], 2], // the book's 4, two on each half: the base (y = −0.5) and the side (y = −0.25)
  ])('the book\'s closed cone from y = −0.5 to 0.5, its lower half: a ray from %j along %j meets it %d times', (origin, direction, count) => {
    expect(hits(lowerHalfOf05, new Ray(origin, direction))).toBe(count);
  });

  it('normals: the book\'s (−1, −1, 0) → (−1, 1, 0) and, mirrored, (1, 1, 1) → (1, −√2, 1), made unit', () => {
    const cone = new Cone([0, -1, 0], 2, 2); // apex at the origin, k = 1
    const a = cone.normalAt(new Vec3(-1, -1, 0)), b = cone.normalAt(new Vec3(1, -1, 1));
    [[a, [-Math.SQRT1_2, Math.SQRT1_2, 0]], [b, [0.5, Math.SQRT2 / 2, 0.5]]].forEach(([n, expected]) => {
      [n.x, n.y, n.z].forEach((value, i) => expect(value).toBeCloseTo(expected[i], 12));
    });
    expect(cone.normalAt(new Vec3(0, 0, 0))).toEqual({ x: 0, y: 1, z: 0 }); // the apex: the book's (0, 0, 0) is no unit vector; ours points up
    expect(cone.normalAt(new Vec3(0.5, -2, 0.5))).toEqual({ x: 0, y: -1, z: 0 }); // the base
  });
});

describe('the book\'s bounding boxes (the bonus chapter "Bounding boxes and hierarchies")', () => {
  it('"A bounded cone has a bounding box", minimum −5, maximum 3: its lower half from y = −5 to the apex at 0', () => {
    // The book's double cone has radius |y|: (−5, −5, −5) to (5, 3, 5), the upper half
    // (radius 3 at y = 3) inside the lower's width. Ours is the lower half alone, so its top is the apex, y = 0.
    expect(new Cone([0, -2.5, 0], 5, 5).bounds()).toEqual({ min: { x: -5, y: -5, z: -5 }, max: { x: 5, y: 0, z: 5 } });
  });
});

describe('the record names the part hit', () => {
  const hat = new Cone([0, 0, -10], 2, 4); // base y = −2, apex y = 2
  it('from below, the base', () => {
    expect(hat.intersect(new Ray([0.5, -6, -10], [0, 1, 0]))).toMatchObject({ tBase: 4, part: 'base', t: 4 });
  });
  it('from the side, the side; the base plane crossed outside its disc is null', () => {
    const r = hat.intersect(new Ray([0, 0, 0], [0, 0, -1])); // at y = 0 the radius is 1: t = 9
    expect(r).toMatchObject({ tBase: null, part: 'side', t: 9, t0: 9, t1: 11 });
  });
  it('bounds', () => {
    expect(hat.bounds()).toEqual({ min: { x: -2, y: -2, z: -12 }, max: { x: 2, y: 2, z: -8 } });
  });
});

describe('bad values are refused, naming the field', () => {
  it.each([
    [() => new Cone([0, 0, 0], 0, 1), RangeError, /radius must be greater than 0, got 0/],
    [() => new Cone([0, 0, 0], 1, 0), RangeError, /height must be greater than 0/],
    [() => new Cone([0, 0, 0], 1, -2), RangeError, /height must be greater than 0/],
    [() => new Cone([0, 0], 1, 1), TypeError, /center must have 3 numbers/],
    [() => new Cone([0, 0, 0], '1', 1), TypeError, /radius must be a finite number/],
  ])('%#', (make, type, message) => {
    expect(make).toThrow(type);
    expect(make).toThrow(message);
  });
});

describe('against a reference with no quadratic in it (seeded random rays)', () => {
  it('capped cones: the same t within 1e-9, from hit and from intersect', () => {
    const random = seeded(15);
    let hitsSeen = 0;
    for (let s = 0; s < 40; s++) {
      const center = [random() * 10 - 5, random() * 10 - 5, random() * 10 - 15];
      const radius = 0.2 + random() * 3, height = 0.2 + random() * 6;
      const cone = new Cone(center, radius, height);
      const base = center[1] - height / 2, apex = center[1] + height / 2, k = radius / height;
      const g = (x, y, z) => Math.max(Math.hypot(x - center[0], z - center[2]) - k * (apex - y), base - y);
      for (let i = 0; i < 100; i++) {
        const origin = center.map((c) => c + (random() - 0.5) * 4 * (radius + height));
        const aim = center.map((c, j) => c + (random() - 0.5) * (j === 1 ? height : radius));
        const ray = i % 5 ? new Ray(origin, aim.map((a, j) => a - origin[j])) : new Ray(origin, randomDirection(random));
        const expected = nearestOf(convexInterval(g, ray), EPSILON);
        const t = cone.hit(ray), record = cone.intersect(ray).t ?? Infinity;
        if (expected === Infinity) {
          expect(t).toBe(Infinity);
        } else {
          expect(Math.abs(t - expected)).toBeLessThanOrEqual(1e-9 * expected);
          hitsSeen++;
        }
        expect(record).toBe(t);
      }
    }
    expect(hitsSeen).toBeGreaterThan(1500);
  });
});

describe('open cones against the same reference', () => {
  it('the side\'s hits are where the ray enters and leaves the solid below the apex (one half, convex), kept above the base', () => {
    const random = seeded(33);
    let hitsSeen = 0;
    for (let s = 0; s < 30; s++) {
      const center = [random() * 10 - 5, random() * 10 - 5, random() * 10 - 15];
      const radius = 0.2 + random() * 3, height = 0.2 + random() * 6;
      const funnel = new Cone(center, radius, height, { capped: false });
      const base = center[1] - height / 2, apex = center[1] + height / 2, k = radius / height;
      const g = (x, y, z) => Math.hypot(x - center[0], z - center[2]) - k * (apex - y);
      for (let i = 0; i < 60; i++) {
        const origin = center.map((c) => c + (random() - 0.5) * 4 * (radius + height));
        const aim = center.map((c, j) => c + (random() - 0.5) * (j === 1 ? height : radius));
        const ray = new Ray(origin, aim.map((a, j) => a - origin[j]));
        const interval = convexInterval(g, ray, 1e6);
        const y = (t) => ray.origin.y + ray.direction.y * t;
        const side = interval ? [interval.tIn, interval.tOut].filter((t) => Math.abs(t) < 1e5 && t > EPSILON && y(t) > base) : [];
        const expected = side.length ? side[0] : Infinity;
        const t = funnel.hit(ray);
        if (expected === Infinity) expect(t).toBe(Infinity);
        else {
          expect(Math.abs(t - expected)).toBeLessThanOrEqual(1e-9 * expected);
          hitsSeen++;
        }
        expect(funnel.intersect(ray).t ?? Infinity).toBe(t);
      }
    }
    expect(hitsSeen).toBeGreaterThan(500);
  });
});

describe('huge and flat cones: refused past the limit with a message, no NaN within it', () => {
  it('a radius of 1e308 and a cone flatter than the limit are refused, naming the field', () => {
    expect(() => new Cone([0, 0, -20], 1e308, 1)).toThrow(/^radius must be at most 1e\+30, got 1e\+308$/);
    expect(() => new Cone([0, 0, -20], 1, 1e31)).toThrow(/^height must be at most 1e\+30/);
    expect(() => new Cone([0, 0, -20], 1e10, 1e-25)).toThrow(/^radius \/ height must be at most 1e\+30 \(a cone this flat is a disc\), got 1e\+35$/);
  });

  it.each([[1e30, 1], [1e30, 1e30], [1e-5, 1e-30], [1, 1e-29], [1e-300, 1]])('radius %s, height %s: every t finite, every normal a unit vector, no NaN in the record', (radius, height) => {
    const cone = new Cone([0, 0, -20], radius, height);
    const random = seeded(7);
    for (let i = 0; i < 200; i++) {
      const ray = new Ray([0, 0, 0], randomDirection(random));
      const record = cone.intersect(ray);
      for (const [key, value] of Object.entries(record)) if (typeof value === 'number') expect(value, key).not.toBeNaN();
      const t = cone.hit(ray);
      if (!Number.isFinite(t)) continue;
      const n = cone.normalAt(new Vec3(ray.direction.x * t, ray.direction.y * t, ray.direction.z * t));
      expect(Math.hypot(n.x, n.y, n.z)).toBeCloseTo(1, 9);
    }
  });
});
