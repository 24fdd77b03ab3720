import { describe, it, expect } from 'vitest';
import { Ray, EPSILON } from '../../lib/index.js';
import { Vec3 } from '../../lib/math/vec3.js';
import { Cylinder } from '../../lib/shapes/cylinder.js';
import { seeded, convexInterval, nearestOf, randomDirection } from './convex-reference.js';

/**
 * The Ray Tracer Challenge (Buck, 2019), ch. 13 "Cylinders": its cylinder has
 * radius 1 around the y axis, is infinite unless given y ∈ (minimum, maximum),
 * and open unless "closed". Ours has a center and a height, so its scenarios
 * become: infinite → Cylinder([0, 0, 0], 1, 1e6, { capped: false });
 * minimum 1, maximum 2 → Cylinder([0, 1.5, 0], 1, 1, …). The book counts
 * every intersection, behind the origin too; `hits` counts the same from our
 * record: the side's roots within the height, and each cap crossed.
 */
const infinite = new Cylinder([0, 0, 0], 1, 1e6, { capped: false });
const from1to2 = (capped) => new Cylinder([0, 1.5, 0], 1, 1, { capped });

function hits(cylinder, ray) {
  const r = cylinder.intersect(ray);
  const bottom = cylinder.center.y - cylinder.height / 2, top = cylinder.center.y + cylinder.height / 2;
  const roots = r.roots === 2 ? [r.t0, r.t1] : r.roots === 1 ? [r.t0] : [];
  const y = (t) => ray.origin.y + ray.direction.y * t;
  return roots.filter((t) => y(t) > bottom && y(t) < top).length + (r.tTop !== null) + (r.tBottom !== null);
}

describe('the book\'s scenarios (ch. 13)', () => {
  it.each([
    [[1, 0, 0], [0, 1, 0]], // along the surface: A = 0, no root
    [[0, 0, 0], [0, 1, 0]], // inside, along the axis: A = 0
    [[0, 0, -5], [1, 1, 1]],
  ])('a ray from %j along %j misses', (origin, direction) => {
    const r = infinite.intersect(new Ray(origin, direction));
    expect(r.t).toBeNull();
    expect(infinite.hit(new Ray(origin, direction))).toBe(Infinity);
  });

  it('a ray along the axis has A = 0, so no roots at all', () => {
    const r = infinite.intersect(new Ray([0, 0, 0], [0, 1, 0]));
    expect(r.A).toBe(0);
    expect(r.roots).toBe(0);
    expect(r.t0).toBeNull();
  });

  it.each([
    [[1, 0, -5], [0, 0, 1], 5, 5], // tangent
    [[0, 0, -5], [0, 0, 1], 4, 6],
    [[0.5, 0, -5], [0.1, 1, 1], 6.80798, 7.08872],
  ])('a ray from %j along %j hits at t0 = %d, t1 = %d', (origin, direction, t0, t1) => {
    const ray = new Ray(origin, direction);
    const r = infinite.intersect(ray);
    expect(r.t0).toBeCloseTo(t0, 5);
    expect(r.t1).toBeCloseTo(t1, 5);
    expect(r.t).toBeCloseTo(t0, 5);
    expect(r.part).toBe('side');
    expect(infinite.hit(ray)).toBeCloseTo(t0, 5);
  });

  it('by hand: (0, 0, −5) along +z', () => {
    // x = 0, z = −5; A = Xd² + Zd² = 0 + 1 = 1; B = 2(x·Xd + z·Zd) = 2(−5) = −10
    // C = x² + z² − r² = 25 − 1 = 24; B² − 4AC = 100 − 96 = 4 → t = (10 ± 2) / 2 = 4, 6
    const r = infinite.intersect(new Ray([0, 0, -5], [0, 0, 1]));
    expect(r).toMatchObject({ A: 1, B: -10, C: 24, discriminant: 4, roots: 2, t0: 4, t1: 6, t: 4, part: 'side' });
  });

  it('the lesson\'s point: A is Xd² + Zd², not 1', () => {
    // Rd = (0.1, 1, 1) / √2.01: A = (0.01 + 1) / 2.01 = 1.01 / 2.01
    expect(infinite.intersect(new Ray([0.5, 0, -5], [0.1, 1, 1])).A).toBeCloseTo(1.01 / 2.01, 12);
  });

  it.each([
    [[1, 0, 0], [1, 0, 0]],
    [[0, 5, -1], [0, 0, -1]],
    [[0, -2, 1], [0, 0, 1]],
    [[-1, 1, 0], [-1, 0, 0]],
  ])('the normal at %j is %j', (point, normal) => {
    const n = infinite.normalAt(new Vec3(...point));
    expect([n.x, n.y, n.z]).toEqual(normal);
  });

  it.each([
    [[0, 1.5, 0], [0.1, 1, 0], 0], // from inside, out through the top's opening
    [[0, 3, -5], [0, 0, 1], 0], // above
    [[0, 0, -5], [0, 0, 1], 0], // below
    [[0, 2, -5], [0, 0, 1], 0], // at the top's height: y < maximum is strict
    [[0, 1, -5], [0, 0, 1], 0], // at the bottom's height
    [[0, 1.5, -2], [0, 0, 1], 2], // through the middle
  ])('the cylinder from y = 1 to 2, open: a ray from %j along %j meets it %d times', (origin, direction, count) => {
    expect(hits(from1to2(false), new Ray(origin, direction))).toBe(count);
  });

  it.each([
    [[0, 3, 0], [0, -1, 0]],
    [[0, 3, -2], [0, -1, 2]],
    [[0, 4, -2], [0, -1, 1]], // the corner case: out through the bottom cap's rim
    [[0, 0, -2], [0, 1, 2]],
    [[0, -1, -2], [0, 1, 1]], // in through the bottom cap's rim
  ])('the cylinder from y = 1 to 2, capped: a ray from %j along %j meets it twice', (origin, direction) => {
    expect(hits(from1to2(true), new Ray(origin, direction))).toBe(2);
  });

  it.each([
    [[0, 1, 0], [0, -1, 0]],
    [[0.5, 1, 0], [0, -1, 0]],
    [[0, 1, 0.5], [0, -1, 0]],
    [[0, 2, 0], [0, 1, 0]],
    [[0.5, 2, 0], [0, 1, 0]],
    [[0, 2, 0.5], [0, 1, 0]],
  ])('the capped cylinder\'s normal at %j is %j', (point, normal) => {
    const n = from1to2(true).normalAt(new Vec3(...point));
    expect([n.x, n.y, n.z]).toEqual(normal);
  });
});

describe('the book\'s bounding boxes (the bonus chapter "Bounding boxes and hierarchies")', () => {
  it('"A bounded cylinder has a bounding box": minimum −5, maximum 3 → (−1, −5, −1) to (1, 3, 1)', () => {
    // ours: center y = (−5 + 3) / 2 = −1, height 8
    expect(new Cylinder([0, -1, 0], 1, 8).bounds()).toEqual({ min: { x: -1, y: -5, z: -1 }, max: { x: 1, y: 3, z: 1 } });
  });
});

describe('the record names the part hit', () => {
  const can = new Cylinder([0, 0, -10], 2, 4); // y from −2 to 2
  it('straight down onto the top: the top cap at t = 8 − 2 = 6; the bottom at 10', () => {
    const r = can.intersect(new Ray([0, 8, -10], [0, -1, 0]));
    expect(r).toMatchObject({ tTop: 6, tBottom: 10, part: 'top', t: 6, roots: 0 });
  });
  it('from below, the bottom cap', () => {
    expect(can.intersect(new Ray([1, -5, -10], [0, 1, 0]))).toMatchObject({ part: 'bottom', t: 3 });
  });
  it('a ray crossing a cap\'s plane outside its disc leaves that cap\'s t null', () => {
    const r = can.intersect(new Ray([0, 0, 0], [0, 0, -1]));
    expect(r).toMatchObject({ tTop: null, tBottom: null, part: 'side', t: 8, t0: 8, t1: 12, y0: 0, y1: 0 });
  });
  it('uncapped, a ray down the axis goes through', () => {
    const pipe = new Cylinder([0, 0, -10], 2, 4, { capped: false });
    expect(pipe.intersect(new Ray([0, 8, -10], [0, -1, 0]))).toMatchObject({ tTop: null, t: null, part: null });
  });
  it('bounds', () => {
    expect(can.bounds()).toEqual({ min: { x: -2, y: -2, z: -12 }, max: { x: 2, y: 2, z: -8 } });
  });
});

describe('bad values are refused, naming the field', () => {
  it.each([
    [() => new Cylinder([0, 0, 0], 1, 0), RangeError, /height must be greater than 0/],
    [() => new Cylinder([0, 0, 0], 0, 1), RangeError, /radius must be greater than 0/],
    [() => new Cylinder([0, 0, 0], 1, NaN), TypeError, /height must be a finite number/],
    [() => new Cylinder([0, 0, 0], 1e308, 1), RangeError, /^radius must be at most 1e\+30, got 1e\+308$/],
    [() => new Cylinder([0, Infinity, 0], 1, 1), TypeError, /center\.y must be a finite number/],
    [() => new Cylinder([0, 0, 0], 1, 1, { capped: 'yes' }), TypeError, /capped must be true or false/],
    [() => new Cylinder([0, 0, 0], 1, 1, { colour: 'red' }), TypeError, /colour/],
  ])('%#', (make, type, message) => {
    expect(make).toThrow(type);
    expect(make).toThrow(message);
  });
  it('takes a name and material options beside capped', () => {
    const c = new Cylinder([0, 0, 0], 1, 1, { capped: false, name: 'pipe', color: [1, 0, 0] });
    expect([c.capped, c.name, c.material.color]).toEqual([false, 'pipe', [1, 0, 0]]);
  });
});

describe('against a reference with no quadratic in it (seeded random rays)', () => {
  it('capped cylinders: the same t within 1e-9, from hit and from intersect', () => {
    const random = seeded(13);
    let compared = 0, hitsSeen = 0;
    for (let s = 0; s < 40; s++) {
      const center = [random() * 10 - 5, random() * 10 - 5, random() * 10 - 15];
      const radius = 0.2 + random() * 3, height = 0.2 + random() * 6;
      const cylinder = new Cylinder(center, radius, height);
      const bottom = center[1] - height / 2, top = center[1] + height / 2;
      const g = (x, y, z) => Math.max(Math.hypot(x - center[0], z - center[2]) - radius, bottom - y, y - top);
      for (let i = 0; i < 100; i++) {
        // from anywhere near it (inside too), toward a point in its box: most rays hit
        const origin = center.map((c) => c + (random() - 0.5) * 4 * (radius + height));
        const aim = center.map((c, k) => c + (random() - 0.5) * (k === 1 ? height : 2 * radius));
        const ray = i % 5 ? new Ray(origin, aim.map((a, k) => a - origin[k])) : new Ray(origin, randomDirection(random));
        const expected = nearestOf(convexInterval(g, ray), EPSILON);
        const t = cylinder.hit(ray), record = cylinder.intersect(ray).t ?? Infinity;
        if (expected === Infinity) {
          expect(t).toBe(Infinity);
          expect(record).toBe(Infinity);
        } else {
          expect(Math.abs(t - expected)).toBeLessThanOrEqual(1e-9 * expected);
          expect(record).toBe(t);
          hitsSeen++;
        }
        compared++;
      }
    }
    expect(compared).toBe(4000);
    expect(hitsSeen).toBeGreaterThan(1500);
  });
});

describe('open cylinders against the same reference', () => {
  it('the side\'s hits are where the ray enters and leaves the infinite solid cylinder, kept when within the height', () => {
    const random = seeded(31);
    let hitsSeen = 0;
    for (let s = 0; s < 30; s++) {
      const center = [random() * 10 - 5, random() * 10 - 5, random() * 10 - 15];
      const radius = 0.2 + random() * 3, height = 0.2 + random() * 6;
      const pipe = new Cylinder(center, radius, height, { capped: false });
      const bottom = center[1] - height / 2, top = center[1] + height / 2;
      const g = (x, y, z) => Math.hypot(x - center[0], z - center[2]) - radius; // infinite along y: convex
      for (let i = 0; i < 60; i++) {
        const origin = center.map((c) => c + (random() - 0.5) * 4 * (radius + height));
        const aim = center.map((c, k) => c + (random() - 0.5) * (k === 1 ? height : 2 * radius));
        const ray = new Ray(origin, aim.map((a, k) => a - origin[k]));
        const interval = convexInterval(g, ray, 1e6);
        const y = (t) => ray.origin.y + ray.direction.y * t;
        const side = interval ? [interval.tIn, interval.tOut].filter((t) => t > EPSILON && y(t) > bottom && y(t) < top) : [];
        const expected = side.length ? side[0] : Infinity;
        const t = pipe.hit(ray);
        if (expected === Infinity) expect(t).toBe(Infinity);
        else {
          expect(Math.abs(t - expected)).toBeLessThanOrEqual(1e-9 * expected);
          hitsSeen++;
        }
        expect(pipe.intersect(ray).t ?? Infinity).toBe(t);
      }
    }
    expect(hitsSeen).toBeGreaterThan(500);
  });
});
