// Screen bounds must be conservative: a shape left out of a pixel's list is
// one its ray cannot hit, so render()'s tiles give the very same picture.
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { Camera, Scene, Sphere, Box, Plane, render, classScene } from '../../lib/index.js';
import { renderPixel } from '../../lib/tracing/render.js';
import { screenBounds, tileCandidates, TILE } from '../../lib/tracing/bounds.js';

const coord = fc.double({ min: -30, max: 30, noNaN: true });

/** Every pixel whose primary ray hits `object` (by its own hit()). */
function hitPixels(object, camera) {
  const pixels = [];
  for (let y = 0; y < camera.height; y++) {
    for (let x = 0; x < camera.width; x++) {
      if (object.hit(camera.primaryRay(x, y).ray) < Infinity) pixels.push([x, y]);
    }
  }
  return pixels;
}

describe('screenBounds', () => {
  it('holds every pixel whose ray hits the sphere, for any sphere and camera (property)', () => {
    fc.assert(fc.property(
      coord, coord, coord, fc.double({ min: 0.05, max: 20, noNaN: true }),
      fc.double({ min: -180, max: 180, noNaN: true }), fc.double({ min: -80, max: 80, noNaN: true }),
      fc.double({ min: 10, max: 120, noNaN: true }),
      (x, y, z, r, yaw, pitch, fov) => {
        const camera = new Camera({ width: 24, height: 18, fov, yaw, pitch, position: [1, 2, 3] });
        const sphere = new Sphere([x, y, z], r);
        const rect = {};
        const some = screenBounds(sphere, camera, rect);
        for (const [px, py] of hitPixels(sphere, camera)) {
          expect(some).toBe(true);
          expect(px).toBeGreaterThanOrEqual(rect.x0);
          expect(px).toBeLessThanOrEqual(rect.x1);
          expect(py).toBeGreaterThanOrEqual(rect.y0);
          expect(py).toBeLessThanOrEqual(rect.y1);
        }
      },
    ), { seed: 7, numRuns: 150 });
  });

  it('is tight for a small sphere straight ahead, and empty for one behind the eye', () => {
    const camera = new Camera({ width: 64, height: 48 });
    const rect = {};
    expect(screenBounds(new Sphere([0, 0, -20], 1), camera, rect)).toBe(true);
    expect(rect.x1 - rect.x0).toBeLessThan(16);
    expect(rect.y1 - rect.y0).toBeLessThan(16);
    expect(screenBounds(new Sphere([0, 0, 20], 1), camera, rect)).toBe(false);
  });

  it('covers everything for a plane and for a sphere around the eye', () => {
    const camera = new Camera({ width: 64, height: 48 });
    const rect = {};
    for (const shape of [new Plane([0, -1, 0], [0, 1, 0]), new Sphere([0, 0, 0], 5)]) {
      expect(screenBounds(shape, camera, rect)).toBe(true);
      expect(rect).toEqual({ x0: 0, y0: 0, x1: 63, y1: 47 });
    }
  });

  it('holds every pixel of a box', () => {
    const camera = new Camera({ width: 40, height: 30, yaw: 10 });
    const box = new Box([-1, -2, -12], [3, 1, -9]);
    const rect = {};
    expect(screenBounds(box, camera, rect)).toBe(true);
    for (const [px, py] of hitPixels(box, camera)) {
      expect(px >= rect.x0 && px <= rect.x1 && py >= rect.y0 && py <= rect.y1).toBe(true);
    }
  });
});

describe('render by tiles', () => {
  /** The picture pixel by pixel, every ray against every shape. */
  const untiled = (scene, camera) => {
    const out = new Uint8ClampedArray(camera.width * camera.height * 4);
    for (let y = 0; y < camera.height; y++) for (let x = 0; x < camera.width; x++) renderPixel(scene, camera, x, y, out);
    return out;
  };

  it('gives the untiled picture byte for byte, at sizes that are not whole tiles', () => {
    const room = new Scene({ background: [0.2, 0.3, 0.5] })
      .add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.8, 0.8, 0.8] }))
      .add(new Box([-3, -1, -12], [-1, 1, -10], { color: [1, 0.3, 0.3] }))
      .add(new Sphere([1.5, 0, -9], 1, { color: [0.3, 0.6, 1], reflection: 0.3 }))
      .add(new Sphere([0, 8, -5], 1, { emission: 1 }));
    for (const [scene, camera] of [
      [classScene(), new Camera({ width: 67, height: 41 })],
      [classScene({ full: true }), new Camera({ width: 50, height: 37, yaw: 20, pitch: -5 })],
      [room, new Camera({ width: 45, height: 33, position: [0, 1, 0] })],
    ]) {
      expect(Buffer.from(render(scene, camera)).equals(Buffer.from(untiled(scene, camera)))).toBe(true);
    }
  });

  it('renders only the rows asked for', () => {
    const camera = new Camera({ width: 40, height: 30 });
    const band = render(classScene(), camera, undefined, { y0: 7, y1: 19 });
    const whole = render(classScene(), camera);
    const row = (buf, y) => Buffer.from(buf.subarray(y * 160, (y + 1) * 160));
    expect(row(band, 6).every((v) => v === 0)).toBe(true);
    expect(row(band, 7).equals(row(whole, 7))).toBe(true);
    expect(row(band, 18).equals(row(whole, 18))).toBe(true);
    expect(row(band, 19).every((v) => v === 0)).toBe(true);
  });

  it('lists shapes per tile in the scene order', () => {
    const scene = classScene();
    const camera = new Camera({ width: 64, height: 48 });
    const { columns, lists } = tileCandidates(scene, camera);
    expect(columns).toBe(64 / TILE);
    for (const list of lists) {
      const order = list.map((o) => scene.objects.indexOf(o));
      expect(order).toEqual([...order].sort((a, b) => a - b));
    }
  });
});
