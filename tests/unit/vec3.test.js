import { describe, it, expect } from 'vitest';
import * as vec3 from '../../lib/math/vec3.js';

const V = vec3.create;

describe('vec3: hand-checkable numbers', () => {
  const a = V(1, 2, 3), b = V(4, -5, 6);

  it('adds, subtracts and scales into out', () => {
    expect(vec3.add(V(), a, b)).toEqual({ x: 5, y: -3, z: 9 });
    expect(vec3.sub(V(), a, b)).toEqual({ x: -3, y: 7, z: -3 });
    expect(vec3.scale(V(), a, 2)).toEqual({ x: 2, y: 4, z: 6 });
    // a point along a ray: Ro + Rd·t with Ro = (1,2,3), Rd = (4,−5,6), t = 0.5
    expect(vec3.scaleAndAdd(V(), a, b, 0.5)).toEqual({ x: 3, y: -0.5, z: 6 });
  });

  it('dot and cross products (worksheet: 1·4 + 2·(−5) + 3·6 = 12)', () => {
    expect(vec3.dot(a, b)).toBe(12);
    // (2·6 − 3·(−5), 3·4 − 1·6, 1·(−5) − 2·4) = (27, 6, −13)
    expect(vec3.cross(V(), a, b)).toEqual({ x: 27, y: 6, z: -13 });
    expect(vec3.cross(V(), V(1, 0, 0), V(0, 1, 0))).toEqual({ x: 0, y: 0, z: 1 });
  });

  it('cross may write into one of its inputs', () => {
    const out = V(1, 2, 3);
    expect(vec3.cross(out, out, b)).toEqual({ x: 27, y: 6, z: -13 });
  });

  it('length, distance and normalize (3-4-5 triangle)', () => {
    expect(vec3.length(V(3, 4, 0))).toBe(5);
    expect(vec3.distance(V(1, 1, 1), V(4, 5, 1))).toBe(5);
    expect(vec3.normalize(V(), V(0, 3, -4))).toEqual({ x: 0, y: expect.closeTo(0.6, 15), z: expect.closeTo(-0.8, 15) });
    expect(vec3.normalize(V(), V(0, 0, 0))).toEqual({ x: 0, y: 0, z: 0 });
  });

  it('reflect mirrors about the normal', () => {
    // a ray going down-right bounces off a floor: (1, −1, 0) → (1, 1, 0)
    expect(vec3.reflect(V(), V(1, -1, 0), V(0, 1, 0))).toEqual({ x: 1, y: 1, z: 0 });
    expect(vec3.reflect(V(), V(0, 0, -1), V(0, 0, 1))).toEqual({ x: 0, y: 0, z: 1 });
  });

  it('set and copy; functions return out', () => {
    const out = V();
    expect(vec3.set(out, 7, 8, 9)).toBe(out);
    expect(out).toEqual({ x: 7, y: 8, z: 9 });
    const c = vec3.copy(V(), out);
    expect(c).toEqual(out);
    expect(c).not.toBe(out);
  });
});

describe('toVec3 checks its input', () => {
  it('accepts arrays, typed arrays and {x, y, z}', () => {
    expect(vec3.toVec3([1, 2, 3], 'p')).toEqual({ x: 1, y: 2, z: 3 });
    expect(vec3.toVec3(new Float64Array([1, 2, 3]), 'p')).toEqual({ x: 1, y: 2, z: 3 });
    expect(vec3.toVec3({ x: -1, y: 0, z: 5 }, 'p')).toEqual({ x: -1, y: 0, z: 5 });
  });

  it('rejects wrong shapes with a TypeError naming the field', () => {
    expect(() => vec3.toVec3([1, 2], 'center')).toThrow(TypeError);
    expect(() => vec3.toVec3([1, 2], 'center')).toThrow(/center/);
    expect(() => vec3.toVec3([1, 2, 3, 4], 'center')).toThrow(/center/);
    expect(() => vec3.toVec3('1,2,3', 'center')).toThrow(TypeError);
    expect(() => vec3.toVec3(null, 'center')).toThrow(/center/);
    expect(() => vec3.toVec3(undefined, 'center')).toThrow(/center/);
  });

  it('rejects non-finite components naming the component', () => {
    expect(() => vec3.toVec3([1, NaN, 3], 'center')).toThrow(/center\.y/);
    expect(() => vec3.toVec3([1, 2, Infinity], 'center')).toThrow(/center\.z/);
    expect(() => vec3.toVec3(['1', 2, 3], 'center')).toThrow(/center\.x/);
    expect(() => vec3.toVec3({ x: 1, y: 2 }, 'center')).toThrow(/center\.z/);
    expect(() => vec3.toVec3([1, NaN, 3], 'center')).toThrow(TypeError);
  });
});
