import { describe, it, expect } from 'vitest';
import { Box, Ray } from '../../lib/index.js';

describe('Box (slabs)', () => {
  const box = new Box([-1, -1, -12], [1, 1, -8]);

  it('a ray along −z meets the front face at t = 8, normal +z', () => {
    const ray = new Ray([0, 0, 0], [0, 0, -1]);
    expect(box.hit(ray)).toBe(8);
    expect(box.normalAt(ray.at(8))).toEqual({ x: 0, y: 0, z: 1 });
  });

  it('normals of every face', () => {
    expect(box.normalAt({ x: -1, y: 0, z: -10 })).toEqual({ x: -1, y: 0, z: 0 });
    expect(box.normalAt({ x: 1, y: 0.2, z: -9 })).toEqual({ x: 1, y: 0, z: 0 });
    expect(box.normalAt({ x: 0, y: 1, z: -10 })).toEqual({ x: 0, y: 1, z: 0 });
    expect(box.normalAt({ x: 0, y: -1, z: -10 })).toEqual({ x: 0, y: -1, z: 0 });
    expect(box.normalAt({ x: 0, y: 0, z: -12 })).toEqual({ x: 0, y: 0, z: -1 });
  });

  it('hits from the side and at an angle', () => {
    expect(box.hit(new Ray([5, 0, -10], [-1, 0, 0]))).toBe(4);
    // from (0, 5, −10) straight down: top face at y = 1, t = 4
    expect(box.hit(new Ray([0, 5, -10], [0, -1, 0]))).toBe(4);
    // diagonal in x and z: enters through the front face z = −8 at t = 8√2
    expect(box.hit(new Ray([-8.5, 0, 0], [1, 0, -1]))).toBeCloseTo(8 * Math.SQRT2, 12);
  });

  it('misses: beside it, behind the eye, parallel outside a slab', () => {
    expect(box.hit(new Ray([3, 0, 0], [0, 0, -1]))).toBe(Infinity);
    expect(box.hit(new Ray([0, 0, 0], [0, 0, 1]))).toBe(Infinity);
    expect(box.hit(new Ray([0, 2, -10], [1, 0, 0]))).toBe(Infinity);
    expect(box.hit(new Ray([0, 0, 0], [1, 0, -1]))).toBe(Infinity);
  });

  it('from inside, the ray meets the far face', () => {
    expect(box.hit(new Ray([0, 0, -10], [0, 0, -1]))).toBe(2);
    expect(box.hit(new Ray([0, 0, -10], [1, 0, 0]))).toBe(1);
  });

  it('bad input names the field', () => {
    expect(() => new Box([0, 0, 0], [1, 0, 1])).toThrow(RangeError);
    expect(() => new Box([0, 0, 0], [1, 0, 1])).toThrow(/max\.y/);
    expect(() => new Box([2, 0, 0], [1, 1, 1])).toThrow(/max\.x/);
    expect(() => new Box([0, 0, 0])).toThrow(TypeError);
    expect(() => new Box([0, 0, 0])).toThrow(/max/);
    expect(() => new Box([0, 0, NaN], [1, 1, 1])).toThrow(/min\.z/);
    expect(() => new Box([0, 0, 0], [1, 1, 1], { transparency: 3 })).toThrow(/transparency/);
  });
});
