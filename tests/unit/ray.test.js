import { describe, it, expect } from 'vitest';
import { Ray } from '../../lib/index.js';

describe('Ray: R(t) = Ro + Rd·t', () => {
  it('normalises the direction (slide: Xd² + Yd² + Zd² = 1)', () => {
    const ray = new Ray([1, 2, 3], [0, 3, -4]);
    expect(ray.origin).toEqual({ x: 1, y: 2, z: 3 });
    expect(ray.direction).toEqual({ x: 0, y: expect.closeTo(0.6, 15), z: expect.closeTo(-0.8, 15) });
    const { x, y, z } = ray.direction;
    expect(x * x + y * y + z * z).toBeCloseTo(1, 15);
  });

  it('takes {x, y, z} objects too', () => {
    const ray = new Ray({ x: 0, y: 0, z: 0 }, { x: 0, y: 0, z: -7 });
    expect(ray.direction).toEqual({ x: 0, y: 0, z: -1 });
  });

  it('does not keep a reference to the caller\'s arrays or objects', () => {
    const o = { x: 1, y: 1, z: 1 };
    const ray = new Ray(o, [0, 0, -2]);
    o.x = 100;
    expect(ray.origin.x).toBe(1);
  });

  it('at(t) is the point t along the ray', () => {
    const ray = new Ray([1, 2, 3], [0, 3, -4]);
    const p = ray.at(10);
    expect(p.x).toBe(1);
    expect(p.y).toBeCloseTo(8, 12);
    expect(p.z).toBeCloseTo(-5, 12);
    const out = { x: 0, y: 0, z: 0 };
    expect(ray.at(0, out)).toBe(out);
    expect(out).toEqual({ x: 1, y: 2, z: 3 });
  });

  it('defaults to the eye at the origin looking toward −z', () => {
    const ray = new Ray();
    expect(ray.origin).toEqual({ x: 0, y: 0, z: 0 });
    expect(ray.direction).toEqual({ x: 0, y: 0, z: -1 });
  });
});

describe('Ray: bad input', () => {
  it('a zero-length direction is a RangeError naming direction', () => {
    expect(() => new Ray([0, 0, 0], [0, 0, 0])).toThrow(RangeError);
    expect(() => new Ray([0, 0, 0], [0, 0, 0])).toThrow(/direction/);
  });

  it('bad origins and directions are TypeErrors naming the field', () => {
    expect(() => new Ray([0, 0], [0, 0, -1])).toThrow(TypeError);
    expect(() => new Ray([0, 0], [0, 0, -1])).toThrow(/origin/);
    expect(() => new Ray([0, 0, 0], [0, NaN, -1])).toThrow(/direction\.y/);
    expect(() => new Ray([0, 0, 0], 'down')).toThrow(/direction/);
    expect(() => new Ray([0, 0, 0], 'down')).toThrow(TypeError);
    expect(() => new Ray(null, [0, 0, -1])).toThrow(/origin/);
  });
});
