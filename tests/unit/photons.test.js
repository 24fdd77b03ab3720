import { describe, it, expect } from 'vitest';
import { PhotonTracer, seededRandom } from '../../lib/tracing/photons.js';
import { classScene } from '../../lib/scene/examples.js';
import { Camera } from '../../lib/math/camera.js';
import { Scene } from '../../lib/scene/scene.js';
import { Sphere } from '../../lib/shapes/sphere.js';
import { PointLight } from '../../lib/lights/point-light.js';

const camera = () => new Camera({ width: 16, height: 12 });

describe('seededRandom', () => {
  it('repeats with its seed, differs with another, stays in [0, 1)', () => {
    const a = seededRandom(7), b = seededRandom(7), c = seededRandom(8);
    const xs = Array.from({ length: 1000 }, a);
    expect(Array.from({ length: 1000 }, b)).toEqual(xs);
    expect(Array.from({ length: 1000 }, c)).not.toEqual(xs);
    expect(xs.every((x) => x >= 0 && x < 1)).toBe(true);
    expect(xs.reduce((s, x) => s + x, 0) / 1000).toBeCloseTo(0.5, 1);
  });
});

describe('PhotonTracer', () => {
  it('is deterministic: the same seed gives the same picture, however the photons are split into steps', () => {
    const one = new PhotonTracer({ scene: classScene(), camera: camera(), seed: 3, eyeRadius: 3 });
    one.emit(60000);
    const steps = new PhotonTracer({ scene: classScene(), camera: camera(), seed: 3, eyeRadius: 3 });
    for (let i = 0; i < 6; i++) steps.emit(10000);
    expect(steps.reached).toBe(one.reached);
    expect(steps.light).toEqual(one.light);
    expect(one.reached).toBeGreaterThan(0);
    const other = new PhotonTracer({ scene: classScene(), camera: camera(), seed: 4, eyeRadius: 3 });
    other.emit(60000);
    expect(other.light).not.toEqual(one.light);
  });

  it('only a small share of the photons reaches the eye, and a bigger eye catches more', () => {
    const small = new PhotonTracer({ scene: classScene(), camera: camera(), seed: 1, eyeRadius: 1 });
    const big = new PhotonTracer({ scene: classScene(), camera: camera(), seed: 1, eyeRadius: 4 });
    small.emit(50000); big.emit(50000);
    expect(small.emitted).toBe(50000);
    expect(small.share).toBeLessThan(0.01);
    expect(big.reached).toBeGreaterThan(small.reached);
  });

  it('a photon lands on the pixel that looks back along it: a light straight ahead lights the middle pixel', () => {
    const scene = new Scene();
    scene.add(new Sphere([0, 0, -3], 0.05, { emission: 1 }));
    const tracer = new PhotonTracer({ scene, camera: new Camera({ width: 9, height: 9, fov: 40 }), seed: 1, eyeRadius: 0.05 });
    tracer.emit(60000);
    expect(tracer.reached).toBeGreaterThan(0);
    const lit = [];
    for (let i = 0; i < 81; i++) if (tracer.light[i * 3] > 0) lit.push([i % 9, Math.floor(i / 9)]);
    expect(lit).toEqual([[4, 4]]); // the sphere and the eye are small: every photon arrives within the middle pixel's 4.4°
  });

  it('photons take the colour of what they bounce off; the picture is opaque RGBA', () => {
    const scene = new Scene();
    scene.add(new Sphere([0, -1003, -10], 1000, { color: [1, 0, 0] }));
    scene.add(new PointLight([0, 5, 5])); // behind the eye: no photon comes straight from it
    const tracer = new PhotonTracer({ scene, camera: new Camera({ width: 8, height: 8, fov: 60 }), seed: 2, eyeRadius: 2.5 });
    tracer.emit(50000);
    expect(tracer.reached).toBeGreaterThan(0);
    for (let i = 0; i < 64; i++) { expect(tracer.light[i * 3 + 1]).toBe(0); expect(tracer.light[i * 3 + 2]).toBe(0); }
    const rgba = tracer.writePicture(new Uint8ClampedArray(64 * 4));
    expect(rgba.some((v, i) => i % 4 === 0 && v > 100)).toBe(true);
    expect(rgba.every((v, i) => i % 4 !== 3 || v === 255)).toBe(true);
  });

  it('keeps sample paths from a light, and says clearly what it needs', () => {
    const tracer = new PhotonTracer({ scene: classScene(), camera: camera(), seed: 1, eyeRadius: 3, samplePaths: 5 });
    tracer.emit(30000);
    expect(tracer.paths.filter((p) => !p.reached).length).toBe(5);
    expect(tracer.paths.filter((p) => p.reached).length).toBeLessThanOrEqual(5);
    for (const { points } of tracer.paths) expect(points.length).toBeGreaterThanOrEqual(2);
    expect(() => new PhotonTracer({ scene: new Scene(), camera: camera() })).toThrow(/no light/);
    expect(() => new PhotonTracer({ scene: classScene(), camera: camera(), eyeRadius: 0 })).toThrow(RangeError);
    expect(() => new PhotonTracer({ scene: classScene(), camera: camera(), eyRadius: 1 })).toThrow(/did you mean "eyeRadius"/);
  });
});
