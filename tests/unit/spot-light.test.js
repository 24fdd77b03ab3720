import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, PointLight, SpotLight, AreaLight, Camera, render, inspectPixel, sceneToJSON, sceneFromJSON, sceneToCode } from '../../lib/index.js';
import * as lib from '../../lib/index.js';
import { spotShare } from '../../lib/tracing/optics.js';
import { packScene } from '../../lib/tracing/kernel.js';

const camera = new Camera({ width: 48, height: 36, position: [0, 8, 6], pitch: -30 });
const floorScene = (...lights) => lights.reduce((scene, light) => scene.add(light), new Scene({ background: [0.1, 0.1, 0.15], ambient: 0.05 })
  .add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.9, 0.9, 0.9] }))
  .add(new Sphere([0, -1, -20], 3, { color: [1, 0.32, 0.36] })));
const floorHits = (scene) => {
  const out = [];
  for (let y = 0; y < camera.height; y++) for (let x = 0; x < camera.width; x++) {
    const r = inspectPixel(scene, camera, x, y);
    if (r.hit?.object === scene.objects[0]) out.push(r);
  }
  return out;
};

describe('SpotLight: a cone of light with a smooth edge', () => {
  it.each([
    [() => new SpotLight([0, 10, 0], [0, 0, 0], { angle: 0 }), /angle must be between 0 and 90/],
    [() => new SpotLight([0, 10, 0], [0, 0, 0], { angle: 90 }), /angle must be between 0 and 90/],
    [() => new SpotLight([0, 10, 0], [0, 0, 0], { angle: -5 }), /angle must be between 0 and 90/],
    [() => new SpotLight([0, 10, 0], [0, 10, 0]), /target must not be the light's own position/],
    [() => new SpotLight([0, 10, 0], [0, 0, 0], { angle: 'wide' }), /angle/],
    [() => new SpotLight([0, 10, 0], [0, 0, 0], { intensity: -1 }), 'intensity must not be negative, got -1'],
    [() => new SpotLight([0, 10, 0], null), /target/],
  ])('refuses bad values, naming the field (%#)', (make, message) => {
    expect(make).toThrow(message);
  });

  it('lets all its light through inside, none outside, and fades smoothly between', () => {
    const spot = new SpotLight([0, 10, 0], [0, 0, 0], { angle: 30 });
    const share = (deg) => { // toLight for a point `deg` off the axis, seen from below
      const a = (deg * Math.PI) / 180;
      return spotShare(spot.axis.x, spot.axis.y, spot.axis.z, spot.cosOuter, spot.cosInner, -Math.sin(a), Math.cos(a), 0);
    };
    expect(share(0)).toBe(1);
    expect(share(23)).toBe(1); // inside the inner 80 %
    expect(share(31)).toBe(0);
    const edge = [24.5, 25, 26, 27, 28, 29.5].map(share);
    for (let i = 1; i < edge.length; i++) expect(edge[i]).toBeLessThan(edge[i - 1]);
    for (const s of edge) { expect(s).toBeGreaterThan(0); expect(s).toBeLessThan(1); }
  });

  it('lights a circle of the floor: dark outside it, a soft rim, the point light\'s light inside', () => {
    const spot = new SpotLight([0, 10, -20], [0, -4, -20], { angle: 25 });
    const beams = floorHits(floorScene(spot)).map((r) => r.hit.lights[0].beam);
    expect(beams.some((b) => b === 1)).toBe(true);
    expect(beams.some((b) => b === 0)).toBe(true);
    expect(beams.some((b) => b > 0 && b < 1)).toBe(true);
    // Inside the inner cone a spot is the point light at its place: the same colour, byte for byte.
    const withSpot = floorScene(spot), withPoint = floorScene(new PointLight([0, 10, -20]));
    for (let y = 0; y < camera.height; y++) for (let x = 0; x < camera.width; x++) {
      const r = inspectPixel(withSpot, camera, x, y);
      if (r.hit && r.hit.lights[0]?.beam === 1) expect(r.color).toEqual(inspectPixel(withPoint, camera, x, y).color);
    }
  });

  it('renders through the kernel (its cone packed with the light), as the inspector says', () => {
    const scene = floorScene(new SpotLight([0, 10, -20], [0, -4, -20], { angle: 25 }));
    expect(packScene(scene)).not.toBe(null);
    const picture = render(scene, camera);
    for (const [x, y] of [[24, 18], [5, 30], [40, 10]]) {
      const i = (y * camera.width + x) * 4;
      expect(inspectPixel(scene, camera, x, y).color).toEqual([picture[i], picture[i + 1], picture[i + 2]]);
    }
  });
});

describe('a spot light through the kernel', () => {
  it('gives trace.js\'s bytes with its cone, fading or not, shadows on or off', () => {
    for (const attenuation of [0, 0.02]) for (const shadows of [true, false]) {
      const scene = floorScene(new SpotLight([3, 10, -16], [0, -4, -20], { angle: 20, attenuation }), new PointLight([-8, 6, 0], [0.3, 0.3, 0.6]));
      scene.shadows = shadows;
      expect(packScene(scene)).not.toBe(null);
      const picture = render(scene, camera);
      for (let y = 0; y < camera.height; y++) for (let x = 0; x < camera.width; x++) {
        const i = (y * camera.width + x) * 4;
        expect([picture[i], picture[i + 1], picture[i + 2]]).toEqual(inspectPixel(scene, camera, x, y).color);
      }
    }
  });

  it('fades the circle of light with distance: the factor is the record\'s, and farther is dimmer', () => {
    const records = floorHits(floorScene(new SpotLight([0, 10, -20], [0, -4, -20], { angle: 25, attenuation: 0.05 })))
      .map((r) => r.hit.lights[0]).filter((l) => l.beam === 1);
    expect(records.length).toBeGreaterThan(1);
    for (const l of records) expect(l.falloff).toBe(1 / (1 + 0.05 * l.distance * l.distance));
    const [near, far] = [...records].sort((a, b) => a.distance - b.distance).filter((_, i, all) => i === 0 || i === all.length - 1);
    expect(far.falloff).toBeLessThan(near.falloff);
  });
});

describe('spot and area lights in scene JSON and code', () => {
  const scene = () => floorScene(new SpotLight([0, 10, -20], [0, -4, -20], { angle: 25, color: [1, 0.9, 0.7] }),
    new AreaLight([-6, 14, -14], 3, { samples: 9, intensity: 0.6 }), new PointLight([10, 10, 0], [1, 1, 1], 0.3));

  it('round-trip to the same picture, an area light written once', () => {
    const s = scene(), picture = render(s, camera), json = sceneToJSON(s);
    expect(json.objects.map((o) => o.type)).toEqual(['plane', 'sphere', 'spotLight', 'areaLight', 'pointLight']);
    const back = sceneFromJSON(JSON.parse(JSON.stringify(json)));
    expect(back.lights).toHaveLength(s.lights.length);
    expect(render(back, camera)).toEqual(picture);
    const code = sceneToCode(s, { importFrom: 'lib' });
    expect(code).toMatch(/^import \{ Scene, Sphere, Plane, PointLight, AreaLight, SpotLight \} from/);
    const built = new Function(...Object.keys(lib), code.replace(/^import .*$/m, '') + '\nreturn scene;')(...Object.values(lib));
    expect(render(built, camera)).toEqual(picture);
  });

  it('bad fields are named', () => {
    expect(() => sceneFromJSON({ objects: [{ type: 'spotLight', position: [0, 1, 0], target: [0, 0, 0], angle: 95 }] })).toThrow(/objects\[0\]\.angle must be between 0 and 90/);
    expect(() => sceneFromJSON({ objects: [{ type: 'areaLight', center: [0, 1, 0], radius: 1, samples: 7 }] })).toThrow(/objects\[0\]\.samples must be a square number/);
  });
});
