// Numerical edge cases handled on purpose: directions with huge or tiny components.
import { describe, it, expect } from 'vitest';
import { Ray, Plane, Scene, Sphere, Box, PointLight, intersectQuadratic, intersectGeometric } from '../../lib/index.js';
import { trace } from '../../lib/tracing/trace.js';

describe('numerical edge cases', () => {
  it('a direction with huge components is normalised, not zeroed', () => {
    const ray = new Ray([0, 0, 0], [1e200, 1e200, 0]);
    expect(ray.direction.x).toBeCloseTo(Math.SQRT1_2, 15);
    expect(ray.direction.y).toBeCloseTo(Math.SQRT1_2, 15);
    expect(ray.direction.z).toBe(0);
  });

  it('a direction with tiny (non-zero) components is accepted', () => {
    expect(new Ray([0, 0, 0], [0, 0, -1e-170]).direction).toEqual({ x: 0, y: 0, z: -1 });
    expect(() => new Ray([0, 0, 0], [0, 0, 0])).toThrow(RangeError);
  });

  it('a plane normal with huge or tiny components is normalised', () => {
    expect(new Plane([0, 0, 0], [0, 1e300, 0]).normal).toEqual({ x: 0, y: 1, z: 0 });
    expect(new Plane([0, 0, 0], [0, 1e-300, 0]).normal).toEqual({ x: 0, y: 1, z: 0 });
    expect(() => new Plane([0, 0, 0], [0, 0, 0])).toThrow(/normal/);
  });

  it('the mirror depth is a whole number of bounces', () => {
    expect(() => new Scene({ maxDepth: 2.5 })).toThrow(/maxDepth must be a whole number/);
    expect(new Scene({ maxDepth: 3 }).maxDepth).toBe(3);
  });
});

describe('a light lying on a surface', () => {
  // A point light exactly on the top face of a box lights a sphere above it:
  // the shadow ray reaches the face at the light's own distance, a tie that
  // must not count as a blocker (else the lit side gets speckled).
  it('is not shadowed by the surface it lies on', () => {

    const scene = new Scene()
      .add(new Box([-1, -1, -6], [1, 1, -4], { color: [0.5, 0.5, 0.5] }))
      .add(new Sphere([0, 3, -5], 0.5, { color: [1, 1, 1] }))
      .add(new PointLight([0, 1, -5], [1, 1, 1]));
    // From beside the box, up at the sphere's underside, which faces the light.
    const steps = {};
    trace(scene, new Ray([1.5, 1.2, -5], [-1.5, 1.3, 0]), [0, 0, 0], steps);
    expect(steps.hit.object).toBeInstanceOf(Sphere);
    const [light] = steps.hit.lights;
    expect(light.facing).toBe(true);
    expect(light.inShadow).toBe(false);
  });
});

describe('a tangent ray to a tiny, far sphere', () => {
  // Rounding in L·L − tca² grows with |L|², not r²: the tangent band must too.
  it('is one root on both routes, and hit() agrees', () => {
    for (const [r, dist] of [[1e-3, 20], [1e-2, 300], [0.05, 1000]]) {
      const sphere = new Sphere([0, 0, -dist], r);
      for (const ray of [new Ray([r, 0, 0], [0, 0, -1]), new Ray([0, -r, 0], [0, 0, -1]), new Ray([-r, 0, 0], [0, 0, -1])]) {
        const q = intersectQuadratic(ray, sphere), g = intersectGeometric(ray, sphere);
        expect(q.roots, `quadratic r=${r}`).toBe(1);
        expect(g.roots, `geometric r=${r}`).toBe(1);
        expect(q.t).toBeCloseTo(dist, 6);
        expect(g.t).toBeCloseTo(dist, 6);
        expect(sphere.hit(ray)).toBeCloseTo(dist, 6);
      }
    }
  });
});

describe('shadow acne, on purpose', () => {
  // A floor lit from above: with both guards off (bias 0, epsilon 0) shadow
  // rays re-hit the surface they start on, at a rounding-error t.
  const floorScene = (options) => new Scene(options)
    .add(new Plane([0, -1.1, 0], [0.3, 1, 0.2], { color: [1, 1, 1] }))
    .add(new PointLight([0, 10, -10]));
  const shadowed = (scene) => {
    let count = 0;
    for (let i = 0; i < 400; i++) {
      const steps = {};
      trace(scene, new Ray([0, 0, 0], [(i % 20) / 20 - 0.5, -1, -(i / 20 | 0) / 20 - 0.5]), [0, 0, 0], steps);
      if (steps.hit?.lights[0].inShadow) count++;
    }
    return count;
  };

  it('appears with no offset and no epsilon, and not with the defaults', () => {
    expect(shadowed(floorScene({ bias: 0, epsilon: 0 }))).toBeGreaterThan(20);
    expect(shadowed(floorScene({}))).toBe(0);
  });

  it('epsilon is checked like every scene option', () => {
    expect(() => new Scene({ epsilon: -1 })).toThrow(/epsilon/);
    expect(new Scene().epsilon).toBe(1e-6);
  });
});
