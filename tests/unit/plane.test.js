import { describe, it, expect } from 'vitest';
import { Plane, Ray } from '../../lib/index.js';

describe('Plane', () => {
  const floor = new Plane([0, -2, 0], [0, 1, 0]);

  it('normalises its normal', () => {
    const p = new Plane([0, 0, 0], [0, 0, 5]);
    expect(p.normal).toEqual({ x: 0, y: 0, z: 1 });
    expect(p.normalAt({ x: 3, y: 4, z: 0 })).toEqual({ x: 0, y: 0, z: 1 });
  });

  it('normalises a normal too short for 1/|n| (5e-324), not into NaN', () => {
    expect(new Plane([0, 0, 0], [0, 5e-324, 0]).normal).toEqual({ x: 0, y: 1, z: 0 });
    expect(new Plane([0, 0, 0], [-5e-324, 0, 5e-324]).normal).toEqual(new Plane([0, 0, 0], [-1, 0, 1]).normal);
  });

  it('a ray straight down meets the floor at t = height (hand-checked: 2)', () => {
    expect(floor.hit(new Ray([0, 0, 0], [0, -1, 0]))).toBe(2);
    expect(floor.hit(new Ray([5, 10, -3], [0, -1, 0]))).toBe(12);
  });

  it('a ray at 45° down meets it at t = 2√2', () => {
    expect(floor.hit(new Ray([0, 0, 0], [0, -1, -1]))).toBeCloseTo(2 * Math.SQRT2, 12);
  });

  it('the plane is hit from below too', () => {
    expect(floor.hit(new Ray([0, -5, 0], [0, 1, 0]))).toBe(3);
  });

  it('misses: a ray going away, a ray along the plane, a ray starting on it', () => {
    expect(floor.hit(new Ray([0, 0, 0], [0, 1, 0]))).toBe(Infinity);
    expect(floor.hit(new Ray([0, 0, 0], [1, 0, -1]))).toBe(Infinity);
    expect(floor.hit(new Ray([0, -2, 0], [1, 0, 0]))).toBe(Infinity);
    expect(floor.hit(new Ray([0, -2, 0], [0, 1, 1]))).toBe(Infinity);
  });

  it('bad input names the field', () => {
    expect(() => new Plane([0, 0, 0], [0, 0, 0])).toThrow(RangeError);
    expect(() => new Plane([0, 0, 0], [0, 0, 0])).toThrow(/normal/);
    expect(() => new Plane([0, 'a', 0], [0, 1, 0])).toThrow(TypeError);
    expect(() => new Plane([0, 'a', 0], [0, 1, 0])).toThrow(/point\.y/);
    expect(() => new Plane([0, 0, 0], [0, 1])).toThrow(/normal/);
    expect(() => new Plane([0, 0, 0], [0, 1, 0], { reflection: 9 })).toThrow(/reflection/);
  });
});
