import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { Camera } from '../../lib/index.js';
import { angles } from '../../lib/math/camera.js';

const DEG = Math.PI / 180;

/** DESIGN.md's formula for yaw = pitch = 0, normalised. */
function expectedDirection(x, y, W, H, fov) {
  const t = Math.tan((fov * DEG) / 2);
  const d = [(2 * (x + 0.5) / W - 1) * t * (W / H), (1 - 2 * (y + 0.5) / H) * t, -1];
  const len = Math.hypot(...d);
  return d.map((c) => c / len);
}

function expectDirection(actual, expected, digits = 12) {
  expect(actual.x).toBeCloseTo(expected[0], digits);
  expect(actual.y).toBeCloseTo(expected[1], digits);
  expect(actual.z).toBeCloseTo(expected[2], digits);
}

describe('Camera: rays through pixel centres', () => {
  it('defaults: fov 30, at the origin, looking toward −z', () => {
    const camera = new Camera({ width: 3, height: 3 });
    expect(camera.fov).toBe(30);
    expect(camera.position).toEqual({ x: 0, y: 0, z: 0 });
    const { ray, h, v } = camera.primaryRay(1, 1);
    expect(ray.origin).toEqual({ x: 0, y: 0, z: 0 });
    expectDirection(ray.direction, [0, 0, -1], 15);
    expect(h).toBeCloseTo(0, 12);
    expect(v).toBeCloseTo(0, 12);
  });

  it('every pixel follows the formula of the design (several sizes and fovs)', () => {
    for (const [W, H, fov] of [[64, 48, 30], [160, 120, 60], [5, 7, 90], [1, 1, 10], [32, 24, 170]]) {
      const camera = new Camera({ width: W, height: H, fov });
      for (let y = 0; y < H; y += Math.max(1, H >> 3)) {
        for (let x = 0; x < W; x += Math.max(1, W >> 3)) {
          expectDirection(camera.primaryRay(x, y).ray.direction, expectedDirection(x, y, W, H, fov));
        }
      }
    }
  });

  it('the corners: top-left is up and to the left, bottom-right down and to the right', () => {
    const W = 64, H = 48, fov = 30;
    const camera = new Camera({ width: W, height: H, fov });
    const corners = { tl: [0, 0], tr: [W - 1, 0], bl: [0, H - 1], br: [W - 1, H - 1] };
    for (const [x, y] of Object.values(corners)) {
      expectDirection(camera.primaryRay(x, y).ray.direction, expectedDirection(x, y, W, H, fov));
    }
    const tl = camera.primaryRay(0, 0), br = camera.primaryRay(W - 1, H - 1);
    expect(tl.h).toBeLessThan(0);
    expect(tl.v).toBeGreaterThan(0);
    expect(br.h).toBeCloseTo(-tl.h, 12);
    expect(br.v).toBeCloseTo(-tl.v, 12);
    // the top-left pixel's centre is half a pixel in from the edge: tan(v) just under tan(15°)
    const t = Math.tan(15 * DEG);
    const d = tl.ray.direction;
    expect(d.y / -d.z).toBeCloseTo(t * (1 - 1 / H), 12);
    expect(d.x / -d.z).toBeCloseTo(-t * (W / H) * (1 - 1 / W), 12);
  });

  it('an even-sized image: the four middle pixels are mirror images', () => {
    const camera = new Camera({ width: 64, height: 48 });
    const a = camera.primaryRay(31, 23).ray.direction, b = camera.primaryRay(32, 24).ray.direction;
    const c = camera.primaryRay(32, 23).ray.direction, d = camera.primaryRay(31, 24).ray.direction;
    expect(a.x).toBeCloseTo(-b.x, 14);
    expect(a.y).toBeCloseTo(-b.y, 14);
    expect(c.x).toBeCloseTo(-d.x, 14);
    expect(c.y).toBeCloseTo(-d.y, 14);
    expect(a.x).toBeCloseTo(-c.x, 14);
    expect(a.y).toBeCloseTo(c.y, 14);
    expect(a.x).toBeLessThan(0);
    expect(a.y).toBeGreaterThan(0);
  });

  it('the rays start at the camera position', () => {
    const camera = new Camera({ width: 4, height: 4, position: [1, 2, 3] });
    expect(camera.primaryRay(0, 3).ray.origin).toEqual({ x: 1, y: 2, z: 3 });
  });

  it('every ray is normalised', () => {
    const camera = new Camera({ width: 9, height: 5, fov: 120, yaw: 33, pitch: -71 });
    for (let y = 0; y < 5; y++) for (let x = 0; x < 9; x++) {
      const { x: dx, y: dy, z: dz } = camera.primaryRay(x, y).ray.direction;
      expect(dx * dx + dy * dy + dz * dz).toBeCloseTo(1, 14);
    }
  });
});

describe('Camera: H and V angles', () => {
  it('h = atan2(dx, −dz), v = asin(dy), in degrees', () => {
    expect(angles({ x: 0, y: 0, z: -1 })).toEqual({ h: 0, v: 0 });
    expect(angles({ x: 1, y: 0, z: 0 }).h).toBe(90);
    expect(angles({ x: -Math.SQRT1_2, y: 0, z: -Math.SQRT1_2 }).h).toBeCloseTo(-45, 12);
    expect(angles({ x: 0, y: -1, z: 0 }).v).toBe(-90);
    expect(angles({ x: 0, y: 0.5, z: -Math.sqrt(0.75) }).v).toBeCloseTo(30, 12);
  });

  it('the centre ray of an odd-sized image has h = yaw and v = pitch', () => {
    for (const [yaw, pitch] of [[0, 0], [30, -82], [-45, 10], [90, 0], [179, 45], [-120, -30], [10, 89]]) {
      const camera = new Camera({ width: 65, height: 49, fov: 40, yaw, pitch });
      const { h, v } = camera.primaryRay(32, 24);
      expect(h).toBeCloseTo(yaw, 9);
      expect(v).toBeCloseTo(pitch, 9);
    }
  });

  it('property: the centre ray has h = yaw, v = pitch for any yaw in (−180, 180) and pitch in (−90, 90)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -179.9, max: 179.9, noNaN: true }),
        fc.double({ min: -89.9, max: 89.9, noNaN: true }),
        fc.constantFrom(1, 3, 11, 101),
        (yaw, pitch, size) => {
          const camera = new Camera({ width: size, height: size + 2, fov: 50, yaw, pitch });
          const { h, v } = camera.primaryRay((size - 1) / 2, (size + 1) / 2);
          expect(h).toBeCloseTo(yaw, 7);
          expect(v).toBeCloseTo(pitch, 7);
        },
      ),
      { numRuns: 500, seed: 42 },
    );
  });

  it('yaw turns right, pitch looks up', () => {
    const right = new Camera({ width: 3, height: 3, yaw: 90 }).primaryRay(1, 1).ray.direction;
    expectDirection(right, [1, 0, 0]);
    const up = new Camera({ width: 3, height: 3, pitch: 90 }).primaryRay(1, 1).ray.direction;
    expectDirection(up, [0, 1, 0]);
    const back = new Camera({ width: 3, height: 3, yaw: 180 }).primaryRay(1, 1).ray.direction;
    expectDirection(back, [0, 0, 1]);
  });

  it('with yaw, the image is still upright and right is still right', () => {
    const camera = new Camera({ width: 11, height: 11, yaw: 40 });
    const left = camera.primaryRay(0, 5), right = camera.primaryRay(10, 5);
    expect(left.h).toBeLessThan(40);
    expect(right.h).toBeGreaterThan(40);
    expect(left.v).toBeCloseTo(0, 12);
    const top = camera.primaryRay(5, 0), bottom = camera.primaryRay(5, 10);
    expect(top.v).toBeGreaterThan(0);
    expect(bottom.v).toBeLessThan(0);
    expect(top.h).toBeCloseTo(40, 12);
  });

  it('with pitch, the middle column stays at h = yaw and v spans the fov around the pitch', () => {
    const camera = new Camera({ width: 11, height: 201, fov: 30, yaw: -20, pitch: 25 });
    for (const y of [0, 50, 100, 150, 200]) expect(camera.primaryRay(5, y).h).toBeCloseTo(-20, 9);
    const top = camera.primaryRay(5, 0).v, bottom = camera.primaryRay(5, 200).v;
    expect(top).toBeGreaterThan(25);
    expect(bottom).toBeLessThan(25);
    expect(top - bottom).toBeCloseTo(30 * (1 - 1 / 201), 1);
  });

  it('the vertical fov: the edge of the image is at ±fov/2', () => {
    // a tall image with many rows: the first row's centre is just under fov/2
    const camera = new Camera({ width: 1, height: 2001, fov: 60 });
    expect(camera.primaryRay(0, 0).v).toBeCloseTo(30, 1);
    expect(camera.primaryRay(0, 2000).v).toBeCloseTo(-30, 1);
  });
});

describe('Camera: project, the inverse of directionAt', () => {
  it('takes a point on any pixel\'s ray back to that pixel, whatever the camera', () => {
    fc.assert(fc.property(
      fc.integer({ min: 1, max: 200 }), fc.integer({ min: 1, max: 200 }), fc.double({ min: 5, max: 150, noNaN: true }),
      fc.double({ min: -180, max: 180, noNaN: true }), fc.double({ min: -89, max: 89, noNaN: true }),
      fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0.1, max: 1000, noNaN: true }),
      (width, height, fov, yaw, pitch, u, v, t) => {
        const camera = new Camera({ width, height, fov, yaw, pitch, position: [1, -2, 3] });
        const x = Math.floor(u * (width - 1)), y = Math.floor(v * (height - 1));
        const d = camera.directionAt(x, y);
        const p = camera.project([1 + d.x * t, -2 + d.y * t, 3 + d.z * t]);
        expect(p.x).toBeCloseTo(x, 6);
        expect(p.y).toBeCloseTo(y, 6);
        expect(p.depth).toBeGreaterThan(0);
      }));
  });

  it('puts a point straight ahead in the middle, and says when a point is behind the eye', () => {
    const camera = new Camera({ width: 64, height: 48 });
    expect(camera.project([0, 0, -10])).toEqual({ x: 31.5, y: 23.5, depth: 10 });
    expect(camera.project({ x: 0, y: 0, z: 5 }).depth).toBe(-5);
    const left = camera.project([-100, 0, -10]), high = camera.project([0, 100, -10]);
    expect(left.x).toBeLessThan(0);
    expect(high.y).toBeLessThan(0);
  });

  it('names the point when it is not one', () => {
    const camera = new Camera({ width: 4, height: 4 });
    expect(() => camera.project([0, 0])).toThrow(/^point must have 3 numbers/);
    expect(() => camera.project([0, NaN, 0])).toThrow(/point\.y/);
  });
});

describe('Camera: bad input names the field', () => {
  const cases = [
    [{ width: 0, height: 10 }, RangeError, /width/],
    [{ width: 1.5, height: 10 }, RangeError, /width/],
    [{ width: -3, height: 10 }, RangeError, /width/],
    [{ width: '10', height: 10 }, TypeError, /width/],
    [{ height: 10 }, TypeError, /width/],
    [{ width: 10, height: 0 }, RangeError, /height/],
    [{ width: 10, height: NaN }, TypeError, /height/],
    [{ width: 10, height: 10, fov: 0 }, RangeError, /fov/],
    [{ width: 10, height: 10, fov: 180 }, RangeError, /fov/],
    [{ width: 10, height: 10, fov: -30 }, RangeError, /fov/],
    [{ width: 10, height: 10, fov: NaN }, TypeError, /fov/],
    [{ width: 10, height: 10, fov: '30' }, TypeError, /fov/],
    [{ width: 10, height: 10, pitch: 95 }, RangeError, /pitch/],
    [{ width: 10, height: 10, pitch: -90.5 }, RangeError, /pitch/],
    [{ width: 10, height: 10, pitch: 'up' }, TypeError, /pitch/],
    [{ width: 10, height: 10, yaw: Infinity }, TypeError, /yaw/],
    [{ width: 10, height: 10, position: [0, 0] }, TypeError, /position/],
    [{ width: 10, height: 10, position: [0, NaN, 0] }, TypeError, /position\.y/],
  ];
  for (const [options, type, field] of cases) {
    it(`${JSON.stringify(options)} → ${type.name} ${field}`, () => {
      expect(() => new Camera(options)).toThrow(type);
      expect(() => new Camera(options)).toThrow(field);
    });
  }

  it('no options at all names width', () => {
    expect(() => new Camera()).toThrow(/width/);
  });

  it('primaryRay checks its coordinates are numbers', () => {
    const camera = new Camera({ width: 4, height: 4 });
    expect(() => camera.primaryRay('1', 2)).toThrow(TypeError);
    expect(() => camera.primaryRay('1', 2)).toThrow(/x/);
    expect(() => camera.primaryRay(1, NaN)).toThrow(/y/);
  });
});
