import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { Ray, Sphere, intersectQuadratic, intersectGeometric, EPSILON } from '../../lib/index.js';

const both = (ray, sphere) => [intersectQuadratic(ray, sphere), intersectGeometric(ray, sphere)];

describe('the worksheet: eye at the origin looking along −z, sphere at (0, 0, −20), r = 4', () => {
  const ray = new Ray([0, 0, 0], [0, 0, -1]);
  const sphere = new Sphere([0, 0, -20], 4);

  it('quadratic route, by hand', () => {
    // Ro − Sc = (0, 0, 20), Rd = (0, 0, −1)
    // A = 0² + 0² + (−1)² = 1
    // B = 2[(0)(0) + (0)(0) + (20)(−1)] = −40   (negative: the sphere is ahead)
    // C = 0² + 0² + 20² − 4² = 400 − 16 = 384
    // B² − 4AC = 1600 − 1536 = 64 > 0 → two solutions
    // t = (40 ± √64) / 2 = (40 ± 8) / 2 → 16 and 24
    expect(intersectQuadratic(ray, sphere)).toEqual({
      A: 1, B: -40, C: 384, discriminant: 64, roots: 2, t0: 16, t1: 24, t: 16,
    });
  });

  it('geometric route, by hand', () => {
    // L = Sc − Ro = (0, 0, −20); tca = L·Rd = 20
    // d² = L·L − tca² = 400 − 400 = 0; thc = √(16 − 0) = 4
    // t = 20 ∓ 4 → 16 and 24
    expect(intersectGeometric(ray, sphere)).toEqual({
      L: { x: 0, y: 0, z: -20 }, tca: 20, d2: 0, thc: 4, roots: 2, t0: 16, t1: 24, t: 16,
    });
  });

  it('the renderer\'s hit() agrees: t = 16', () => {
    expect(sphere.hit(ray)).toBe(16);
  });

  it('the normal at the hit point faces the eye', () => {
    expect(sphere.normalAt(ray.at(16))).toEqual({ x: 0, y: 0, z: 1 });
  });
});

describe('tangent, miss, behind, inside', () => {
  const sphere = new Sphere([0, 0, -20], 4);

  it('tangent: one root, t0 = t1 (a ray 4 units to the side grazes the sphere)', () => {
    // Ro − Sc = (4, 0, 20): B = −40, C = 16 + 400 − 16 = 400, B² − 4AC = 0
    const [q, g] = both(new Ray([4, 0, 0], [0, 0, -1]), sphere);
    expect(q).toMatchObject({ A: 1, B: -40, C: 400, discriminant: 0, roots: 1, t0: 20, t1: 20, t: 20 });
    // L = (−4, 0, −20), tca = 20, d² = 416 − 400 = 16 = r²
    expect(g).toMatchObject({ tca: 20, d2: 16, thc: 0, roots: 1, t0: 20, t1: 20, t: 20 });
    expect(sphere.hit(new Ray([4, 0, 0], [0, 0, -1]))).toBe(20);
  });

  it('tangent from any side and at an angle', () => {
    // from (0, 0, 0) toward the top point of a sphere: the ray along +x at height 4
    const ray = new Ray([-10, 4, -20], [1, 0, 0]);
    for (const r of both(ray, sphere)) expect(r).toMatchObject({ roots: 1, t0: 10, t1: 10, t: 10 });
  });

  it('miss: no roots, t0, t1, t and thc are null', () => {
    // Ro − Sc = (5, 0, 20): C = 25 + 400 − 16 = 409, B² − 4AC = 1600 − 1636 = −36
    const [q, g] = both(new Ray([5, 0, 0], [0, 0, -1]), sphere);
    expect(q).toMatchObject({ B: -40, C: 409, discriminant: -36, roots: 0, t0: null, t1: null, t: null });
    // d² = 425 − 400 = 25 > 16
    expect(g).toMatchObject({ tca: 20, d2: 25, thc: null, roots: 0, t0: null, t1: null, t: null });
    expect(sphere.hit(new Ray([5, 0, 0], [0, 0, -1]))).toBe(Infinity);
  });

  it('a sphere behind the eye: two roots, both negative, no hit', () => {
    // looking along +z: B = 2(20·1) = +40, t = (−40 ± 8)/2 → −24, −16
    const ray = new Ray([0, 0, 0], [0, 0, 1]);
    const [q, g] = both(ray, sphere);
    expect(q).toMatchObject({ B: 40, C: 384, discriminant: 64, roots: 2, t0: -24, t1: -16, t: null });
    expect(g).toMatchObject({ tca: -20, roots: 2, thc: 4, t0: -24, t1: -16, t: null });
    expect(sphere.hit(ray)).toBe(Infinity);
  });

  it('origin at the centre: t is the far root (t0 = −4, t1 = 4)', () => {
    const ray = new Ray([0, 0, -20], [0, 0, -1]);
    const [q, g] = both(ray, sphere);
    expect(q).toMatchObject({ C: -16, roots: 2, t0: -4, t1: 4, t: 4 });
    expect(g).toMatchObject({ tca: 0, roots: 2, t0: -4, t1: 4, t: 4 });
    expect(sphere.hit(ray)).toBe(4);
  });

  it('origin inside with tca < 0 is still a hit (the far root is ahead)', () => {
    // origin 2 past the centre, still looking along −z: L = (0, 0, 2), tca = −2,
    // d² = 4 − 4 = 0, thc = 4 → t = −6 or 2; quadratic: B = 4, C = −12, disc = 64
    const ray = new Ray([0, 0, -22], [0, 0, -1]);
    const [q, g] = both(ray, sphere);
    expect(g).toMatchObject({ tca: -2, d2: 0, thc: 4, roots: 2, t0: -6, t1: 2, t: 2 });
    expect(q).toMatchObject({ B: 4, C: -12, discriminant: 64, roots: 2, t0: -6, t1: 2, t: 2 });
    expect(sphere.hit(ray)).toBe(2);
  });

  it('origin inside, off-axis, tca < 0', () => {
    const ray = new Ray([1, 2, -21], [0.2, -0.1, -1]);
    const [q, g] = both(ray, sphere);
    expect(g.tca).toBeLessThan(0);
    expect(g.roots).toBe(2);
    expect(g.t).toBeGreaterThan(0);
    expect(q.t).toBeCloseTo(g.t, 12);
    const p = ray.at(g.t);
    expect(Math.hypot(p.x, p.y, p.z + 20)).toBeCloseTo(4, 12);
  });

  it('a ray starting on the surface finds the other side, not itself', () => {
    const inward = new Ray([0, 0, -16], [0, 0, -1]);
    for (const r of both(inward, sphere)) expect(r.t).toBeCloseTo(8, 12);
    expect(sphere.hit(inward)).toBeCloseTo(8, 12);
    const outward = new Ray([0, 0, -16], [0, 0, 1]);
    for (const r of both(outward, sphere)) expect(r.t).toBeNull();
    expect(sphere.hit(outward)).toBe(Infinity);
  });

  it('t is the smallest root greater than EPSILON', () => {
    // A sphere of radius 5 whose near surface is at z = 0; the ray goes −z from just in front of it.
    const s = new Sphere([0, 0, -5], 5);
    // t0 = EPSILON / 3 is the surface the ray starts on: t skips it for the far side, t1 ≈ 10.
    const onSurface = new Ray([0, 0, EPSILON / 3], [0, 0, -1]);
    for (const r of both(onSurface, s)) {
      expect(r.t0).toBeCloseTo(EPSILON / 3, 9);
      expect(r.t).toBe(r.t1);
      expect(r.t).toBeCloseTo(10, 5);
    }
    expect(s.hit(onSurface)).toBeCloseTo(10, 5);
    // t0 = 3·EPSILON is already a new hit: t is t0.
    const justAhead = new Ray([0, 0, 3 * EPSILON], [0, 0, -1]);
    for (const r of both(justAhead, s)) {
      expect(r.t).toBe(r.t0);
      expect(r.t).toBeCloseTo(3 * EPSILON, 9);
    }
    expect(s.hit(justAhead)).toBeCloseTo(3 * EPSILON, 9);
  });

  it('writes into the given target and returns it', () => {
    const ray = new Ray([0, 0, 0], [0, 0, -1]);
    const q = {}, g = {};
    expect(intersectQuadratic(ray, sphere, q)).toBe(q);
    expect(intersectGeometric(ray, sphere, g)).toBe(g);
    expect(g.t).toBe(16);
    intersectGeometric(new Ray([5, 0, 0], [0, 0, -1]), sphere, g); // reuse: a miss now
    expect(g).toMatchObject({ roots: 0, thc: null, t: null, L: { x: -5, y: 0, z: -20 } });
  });
});

describe('huge and tiny radii', () => {
  it('a ground sphere of radius 10000: straight down hits its top at t = 4', () => {
    const ground = new Sphere([0, -10004, -20], 10000);
    const down = new Ray([0, 0, -20], [0, -1, 0]);
    for (const r of both(down, ground)) {
      expect(r.roots).toBe(2);
      expect(r.t).toBeCloseTo(4, 9);
      expect(r.t1).toBeCloseTo(20004, 8);
    }
    expect(ground.hit(down)).toBeCloseTo(4, 9);
  });

  it('radius 10000: a slanted ray hits the top point (0, −4, −20) at t = √416', () => {
    const ground = new Sphere([0, -10004, -20], 10000);
    const ray = new Ray([0, 0, 0], [0, -4, -20]);
    for (const r of both(ray, ground)) expect(r.t).toBeCloseTo(Math.sqrt(416), 8);
  });

  it('radius 10000: many rays land on its surface', () => {
    const ground = new Sphere([0, -10004, -20], 10000);
    for (let i = 0; i < 200; i++) {
      const ray = new Ray([0, 0, 0], [Math.sin(i) * 0.5, -0.25 - (i % 17) / 20, -1]);
      for (const r of both(ray, ground)) {
        expect(r.roots).toBe(2);
        const p = ray.at(r.t);
        expect(Math.hypot(p.x, p.y + 10004, p.z + 20) / 10000).toBeCloseTo(1, 12);
      }
    }
  });

  it('a sphere of radius 0.001 at distance 20 is hit at 20 ∓ 0.001', () => {
    const tiny = new Sphere([0, 0, -20], 1e-3);
    const ray = new Ray([0, 0, 0], [0, 0, -1]);
    for (const r of both(ray, tiny)) {
      expect(r.roots).toBe(2);
      // thc is only as exact as L·L − tca² (or C) allows: ~1e-11 here, 1e-8 of the radius
      expect(r.t0).toBeCloseTo(20 - 1e-3, 10);
      expect(r.t1).toBeCloseTo(20 + 1e-3, 10);
      expect(r.t).toBe(r.t0);
    }
    expect(tiny.hit(ray)).toBeCloseTo(20 - 1e-3, 10);
  });

  it('radius 0.001: a ray off by half the radius hits, off by twice misses', () => {
    const tiny = new Sphere([0, 0, -20], 1e-3);
    const near = new Ray([5e-4, 0, 0], [0, 0, -1]);
    const far = new Ray([2e-3, 0, 0], [0, 0, -1]);
    const halfChord = Math.sqrt(1e-6 - 25e-8);
    for (const r of both(near, tiny)) {
      expect(r.roots).toBe(2);
      expect(r.t0).toBeCloseTo(20 - halfChord, 9);
    }
    for (const r of both(far, tiny)) expect(r).toMatchObject({ roots: 0, t: null });
    expect(tiny.hit(far)).toBe(Infinity);
  });

  it('a tiny sphere near the eye (radius 1e-6 at distance 1e-3)', () => {
    const speck = new Sphere([0, 0, -1e-3], 1e-6);
    const ray = new Ray([0, 0, 0], [0, 0, -1]);
    for (const r of both(ray, speck)) {
      expect(r.roots).toBe(2);
      expect(r.t0 / (1e-3 - 1e-6)).toBeCloseTo(1, 9);
    }
  });
});

describe('both routes agree on many random rays (property)', () => {
  const coord = fc.double({ min: -50, max: 50, noNaN: true });
  const point = fc.tuple(coord, coord, coord);
  const direction = point.filter(([x, y, z]) => Math.hypot(x, y, z) > 1e-3);
  const radius = fc.double({ min: 0.01, max: 40, noNaN: true });

  it('roots away from the tangent band, t0, t1 and t within a relative tolerance, hit() the same', () => {
    fc.assert(
      fc.property(point, radius, point, direction, (c, r, o, d) => {
        const sphere = new Sphere(c, r);
        const ray = new Ray(o, d);
        const [q, g] = both(ray, sphere);
        // d² computed without cancellation: |L − tca·Rd|²
        const Rd = ray.direction;
        const L = { x: c[0] - o[0], y: c[1] - o[1], z: c[2] - o[2] };
        const tca = L.x * Rd.x + L.y * Rd.y + L.z * Rd.z;
        const perp = Math.hypot(L.x - tca * Rd.x, L.y - tca * Rd.y, L.z - tca * Rd.z);
        const scale = Math.hypot(L.x, L.y, L.z) + r;
        const gap = r * r - perp * perp;
        if (Math.abs(gap) < 1e-9 * scale * scale) return; // the tangent band: either answer is fair
        const expectedRoots = gap > 0 ? 2 : 0;
        expect(q.roots).toBe(expectedRoots);
        expect(g.roots).toBe(expectedRoots);
        if (expectedRoots === 0) {
          expect([q.t0, q.t1, q.t, g.t0, g.t1, g.t, g.thc]).toEqual([null, null, null, null, null, null, null]);
          expect(sphere.hit(ray)).toBe(Infinity);
          return;
        }
        const tol = 1e-9 * scale;
        expect(Math.abs(q.t0 - g.t0)).toBeLessThan(tol);
        expect(Math.abs(q.t1 - g.t1)).toBeLessThan(tol);
        expect(q.t0).toBeLessThanOrEqual(q.t1);
        expect(g.t0).toBeLessThanOrEqual(g.t1);
        // Both roots lie on the sphere.
        for (const t of [g.t0, g.t1]) {
          const p = ray.at(t);
          expect(Math.abs(Math.hypot(p.x - c[0], p.y - c[1], p.z - c[2]) - r)).toBeLessThan(tol);
        }
        // t: the nearest root in front, unless a root sits right at EPSILON.
        if ([g.t0, g.t1].some((t) => Math.abs(t - EPSILON) < tol)) return;
        const ahead = [g.t0, g.t1].filter((t) => t > EPSILON);
        if (ahead.length === 0) {
          expect(q.t).toBeNull();
          expect(g.t).toBeNull();
          expect(sphere.hit(ray)).toBe(Infinity);
        } else {
          expect(g.t).toBe(ahead[0]);
          expect(Math.abs(q.t - g.t)).toBeLessThan(tol);
          expect(Math.abs(sphere.hit(ray) - g.t)).toBeLessThan(tol);
        }
      }),
      { numRuns: 1500, seed: 20240611 },
    );
  });

  it('rays aimed at random points inside the sphere always hit it, from outside and inside', () => {
    fc.assert(
      fc.property(point, radius, point, fc.tuple(coord, coord, coord), (c, r, o, u) => {
        const sphere = new Sphere(c, r);
        // a target strictly inside: the centre plus up to 0.9 r
        const len = Math.hypot(...u) || 1;
        const target = c.map((ci, i) => ci + (u[i] / len) * 0.9 * r * Math.min(1, len / 50));
        const dir = target.map((ti, i) => ti - o[i]);
        fc.pre(Math.hypot(...dir) > 1e-6);
        const ray = new Ray(o, dir);
        const [q, g] = both(ray, sphere);
        expect(q.roots).toBe(2);
        expect(g.roots).toBe(2);
        expect(g.t).not.toBeNull();
        expect(q.t).not.toBeNull();
        expect(sphere.hit(ray)).toBeLessThan(Infinity);
      }),
      { numRuns: 500, seed: 7 },
    );
  });
});

describe('Sphere: bad input names the field', () => {
  const cases = [
    [[[0, 0, 0], 0], RangeError, /radius/],
    [[[0, 0, 0], -4], RangeError, /radius/],
    [[[0, 0, 0], NaN], TypeError, /radius/],
    [[[0, 0, 0], Infinity], TypeError, /radius/],
    [[[0, 0, 0], '4'], TypeError, /radius/],
    [[[0, 0, 0]], TypeError, /radius/],
    [[[0, 0], 4], TypeError, /center/],
    [[[0, 0, 'z'], 4], TypeError, /center\.z/],
    [[undefined, 4], TypeError, /center/],
    [[[0, 0, 0], 4, { color: 'blurple' }], TypeError, /color/],
  ];
  for (const [args, type, field] of cases) {
    it(`new Sphere(${args.map((a) => JSON.stringify(a) ?? 'undefined').join(', ')}) → ${type.name} ${field}`, () => {
      expect(() => new Sphere(...args)).toThrow(type);
      expect(() => new Sphere(...args)).toThrow(field);
    });
  }
});
