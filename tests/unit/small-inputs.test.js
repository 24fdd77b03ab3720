// Small hostile inputs, each refused with a named TypeError/RangeError or
// handled: an array for a type, NaN colours, an endless ray rate, a huge
// option key, options inherited from Object.prototype.
import { describe, it, expect } from 'vitest';
import { sceneFromJSON, toHex, colorName, Material, Sphere, Scene, Camera, PointLight, classScene } from '../../lib/index.js';
import { ProgressiveRenderer } from '../../lib/tracing/frames.js';
import { WorkerProgressiveRenderer } from '../../lib/tracing/workers/worker-frames.js';
import { cameraFromJSON } from '../../lib/scene/json.js';
import { checkOptions, OPTION_KEY_MAX } from '../../lib/text/check.js';
import { shapeClasses } from '../../lib/shapes/index.js';
import { lightClasses } from '../../lib/lights/index.js';

describe('scene JSON', () => {
  it('refuses an array for a type ("sphere" in a list is not "sphere")', () => {
    const o = { type: ['sphere'], center: [0, 0, -5], radius: 1 };
    const types = [...shapeClasses(), ...lightClasses()].map((Kind) => `"${Kind.type}"`).join(', '); // the listed shapes and lights
    expect(types).toMatch(/^"sphere", "plane", .*"pointLight"/);
    expect(() => sceneFromJSON({ objects: [o] })).toThrow(new TypeError(`objects[0].type must be one of ${types}, got ["sphere"]`));
    expect(sceneFromJSON({ objects: [{ ...o, type: 'sphere' }] }).objects).toHaveLength(1);
  });
});

describe('toHex and colorName', () => {
  it('name what is wrong instead of #NaN0000, "purple" or "not iterable"', () => {
    expect(() => toHex([NaN, 0, 0])).toThrow(new TypeError('toHex takes [r, g, b], three finite numbers, got [NaN, 0, 0]'));
    expect(() => colorName([NaN, NaN, NaN])).toThrow(new TypeError('colorName takes [r, g, b], three finite numbers, got [NaN, NaN, NaN]'));
    expect(() => toHex(null)).toThrow(new TypeError('toHex takes [r, g, b], got null'));
    expect(() => colorName([1, 2])).toThrow(TypeError);
    expect(() => toHex(['255', 0, 0])).toThrow(TypeError);
    expect(toHex([255, 81, 96])).toBe('#ff5160');
    expect(toHex(new Uint8ClampedArray([255, 81, 96, 255]))).toBe('#ff5160'); // a pixel of a buffer
    expect(colorName([255, 81, 96])).toBe('pink');
  });
});

describe('slowRaysPerSecond', () => {
  it('is a finite number ≥ 0: Infinity traced nothing forever', () => {
    const r = new ProgressiveRenderer({ scene: classScene(), camera: new Camera({ width: 8, height: 6 }), mode: 'slow' });
    expect(() => { r.slowRaysPerSecond = Infinity; }).toThrow(new TypeError('slowRaysPerSecond must be a finite number, got Infinity'));
    expect(() => { r.slowRaysPerSecond = -1; }).toThrow(new RangeError('slowRaysPerSecond must not be negative, got -1'));
    expect(() => { r.slowRaysPerSecond = '4'; }).toThrow(TypeError);
    expect(r.slowRaysPerSecond).toBe(0);
    r.slowRaysPerSecond = 4;
    expect(r.slowRaysPerSecond).toBe(4);
  });

  it('is checked and used through the worker renderer too (the tracer view\'s, which Shoot sets)', () => {
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: new Camera({ width: 8, height: 6 }), mode: 'slow', workers: false, now: () => 0 });
    expect(() => { r.slowRaysPerSecond = Infinity; }).toThrow(new TypeError('slowRaysPerSecond must be a finite number, got Infinity'));
    expect(() => { r.slowRaysPerSecond = -1; }).toThrow(RangeError);
    expect(Object.hasOwn(r, 'slowRaysPerSecond')).toBe(false);
    r.slowRaysPerSecond = 4;
    expect(r.slowRaysPerSecond).toBe(4);
    r.step();
    const first = r.traced;
    r.step(); // no time has passed on its clock: no ray is owed at 4 a second
    expect(r.traced).toBe(first);
  });
});

describe('option keys', () => {
  it('a megabyte-long unknown key is named at once, cut, with the known options', () => {
    const key = 'x'.repeat(1e6);
    let message = '';
    try { new Material({ [key]: 1 }); } catch (error) { message = error.message; } // the closest key took 2 s and 270 MB
    expect(message).toMatch(/^unknown material option "x+…/);
    expect(message).toContain('known options: color, emission');
    expect(message.length).toBeLessThan(300);
    expect(() => checkOptions({ ['c'.repeat(OPTION_KEY_MAX)]: 1 }, ['color'], 'material')).toThrow(/did you mean "color"/);
  });

  it('options are read from own keys: a key set on Object.prototype is no option of a new material, shape, scene, light or camera', () => {
    const keys = { reflection: 0.9, color: 'red', radius: 7, ambient: 0.5, intensity: 3, fov: 90, name: 'polluted', objects: [{ type: 'sphere', center: [0, 0, 0], radius: 1 }] };
    try {
      for (const [k, v] of Object.entries(keys)) Object.prototype[k] = v;
      expect(new Material().reflection).toBe(0);
      expect(new Material({}).color).toEqual([1, 1, 1]);
      const ball = new Sphere([0, 0, -5], 1, { specular: 0.5 });
      expect(ball.material.reflection).toBe(0);
      expect(ball.name).toBe('');
      expect(new Scene().ambient).toBe(0);
      expect(new PointLight([0, 1, 0], {}).intensity).toBe(1);
      expect(new Camera({ width: 4, height: 3 }).fov).toBe(30);
      expect(cameraFromJSON({ width: 4, height: 3 }).fov).toBe(30);
      const scene = sceneFromJSON({ objects: [{ type: 'sphere', center: [0, 0, -5], radius: 1, material: {} }] });
      expect(scene.ambient).toBe(0);
      expect(scene.objects[0].material.reflection).toBe(0);
      expect(sceneFromJSON({}).objects).toHaveLength(0);
    } finally {
      for (const k of Object.keys(keys)) delete Object.prototype[k];
    }
    expect({}.reflection).toBeUndefined();
  });
});
