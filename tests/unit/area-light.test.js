import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, PointLight, Camera, render, inspectPixel } from '../../lib/index.js';
import { AreaLight, concentric } from '../../lib/lights/area-light.js';

const floorScene = (light) => new Scene({ background: [0.8, 0.9, 1], ambient: 0.1 })
  .add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.9, 0.9, 0.9] }))
  .add(new Sphere([0, 0, -20], 3, { color: [1, 0.32, 0.36] }))
  .add(light);
const camera = new Camera({ width: 48, height: 36, position: [0, 6, 8], pitch: -25 });

describe('AreaLight: a disc of light, sampled at fixed points', () => {
  it.each([
    [() => new AreaLight([0, 10, 0], 0), /radius must be greater than 0/],
    [() => new AreaLight([0, 10, 0], -1), /radius must be greater than 0/],
    [() => new AreaLight([0, 10, 0], 2, { samples: 3 }), /samples must be a square number/],
    [() => new AreaLight([0, 10, 0], 2, { samples: 100 }), /samples must be a square number/],
    [() => new AreaLight([0, 10, 0], 2, { normal: [0, 0, 0] }), /normal must not be \(0, 0, 0\)/],
    [() => new AreaLight([0, 10, 0], 2, { intensity: -1 }), 'intensity must not be negative, got -1'],
    [() => new AreaLight([0, 10, 0], 2, { colour: 'red' }), /colour/],
    [() => new AreaLight([0, NaN, 0], 2), /center/],
  ])('refuses bad values, naming the field (%#)', (make, message) => {
    expect(make).toThrow(message);
  });

  it('the concentric map takes the square\'s edge to the circle and its centre to the centre', () => {
    for (const b of [-1, -0.3, 0, 0.6, 1]) {
      for (const [x, y] of [concentric(1, b), concentric(-1, b), concentric(b, 1), concentric(b, -1)]) expect(Math.hypot(x, y)).toBeCloseTo(1, 12);
    }
    expect(concentric(0, 0)).toEqual([0, 0]);
  });

  it('puts its points on the disc, one per cell, spread evenly around the centre', () => {
    const light = new AreaLight([2, 10, -5], 3, { samples: 25, normal: [0, -1, 1] });
    const points = light.points();
    expect(points).toHaveLength(25);
    const n = light.normal, mean = { x: 0, y: 0, z: 0 };
    for (const p of points) {
      const d = { x: p.x - 2, y: p.y - 10, z: p.z + 5 };
      expect(Math.hypot(d.x, d.y, d.z)).toBeLessThanOrEqual(3 + 1e-12); // inside the disc
      expect(Math.abs(d.x * n.x + d.y * n.y + d.z * n.z)).toBeLessThan(1e-12); // in its plane
      mean.x += p.x / 25; mean.y += p.y / 25; mean.z += p.z / 25;
    }
    expect(mean.x).toBeCloseTo(2, 10); expect(mean.y).toBeCloseTo(10, 10); expect(mean.z).toBeCloseTo(-5, 10);
    expect(new Set(points.map((p) => `${p.x},${p.y},${p.z}`)).size).toBe(25); // no two the same
    expect(light.points()).toEqual(points); // fixed: the same points every time
  });

  it('with one sample it is the point light at its centre: the same bytes', () => {
    const area = render(floorScene(new AreaLight([-6, 14, -14], 3, { samples: 1, color: [1, 0.9, 0.8], intensity: 0.9 })), camera);
    const point = render(floorScene(new PointLight([-6, 14, -14], [1, 0.9, 0.8], 0.9)), camera);
    expect(area).toEqual(point);
  });

  it('fades each of its points by that point\'s own distance', () => {
    const scene = floorScene(new AreaLight([-6, 14, -14], 4, { samples: 9, attenuation: 0.01 }));
    const fading = inspectPixel(scene, camera, 24, 30), { hit } = fading;
    expect(hit.object).toBe(scene.objects[0]); // the floor
    expect(hit.lights).toHaveLength(9);
    const distances = new Set(hit.lights.map((l) => l.distance));
    expect(distances.size).toBeGreaterThan(1);
    for (const l of hit.lights) expect(l.falloff).toBe(1 / (1 + 0.01 * l.distance * l.distance));
    const plain = inspectPixel(floorScene(new AreaLight([-6, 14, -14], 4, { samples: 9 })), camera, 24, 30);
    expect(fading.color.every((c, i) => c <= plain.color[i])).toBe(true);
    expect(fading.color).not.toEqual(plain.color);
  });

  it('casts a shadow with a penumbra: floor points that reach some of its shadow rays, not all', () => {
    const scene = floorScene(new AreaLight([-6, 14, -14], 4, { samples: 16 }));
    const reached = new Set();
    for (let y = 0; y < camera.height; y++) {
      for (let x = 0; x < camera.width; x++) {
        const { hit } = inspectPixel(scene, camera, x, y);
        if (!hit || hit.object !== scene.objects[0]) continue; // the floor
        reached.add(hit.lights.filter((l) => l.transmission > 0).length);
      }
    }
    expect(reached.has(16)).toBe(true); // fully lit
    expect(reached.has(0)).toBe(true); // the umbra
    expect([...reached].some((n) => n > 0 && n < 16)).toBe(true); // the penumbra between
  });

  it('is the same picture twice, and render() agrees with the inspector', () => {
    const scene = floorScene(new AreaLight([-6, 14, -14], 4, { samples: 9 }));
    const a = render(scene, camera), b = render(scene, camera);
    expect(a).toEqual(b);
    for (const [x, y] of [[3, 30], [24, 18], [40, 33], [10, 5]]) {
      const i = (y * camera.width + x) * 4;
      expect(inspectPixel(scene, camera, x, y).color).toEqual([a[i], a[i + 1], a[i + 2]]);
    }
  });

  it('is removed from the scene with all its points', () => {
    const light = new AreaLight([0, 10, 0], 2, { samples: 4 });
    const scene = floorScene(light);
    expect(scene.lights.filter((l) => l.source === light)).toHaveLength(4);
    scene.remove(light);
    expect(scene.lights).toHaveLength(0);
  });
});
