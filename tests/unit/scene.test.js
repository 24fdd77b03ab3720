import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Box, PointLight, classScene } from '../../lib/index.js';

describe('Scene', () => {
  it('defaults: black background, no ambient, shadows on, 5 bounces', () => {
    const scene = new Scene();
    expect(scene.background).toEqual([0, 0, 0]);
    expect(scene.ambient).toBe(0);
    expect(scene.shadows).toBe(true);
    expect(scene.maxDepth).toBe(5);
    expect(scene.objects).toEqual([]);
    expect(scene.lights).toEqual([]);
  });

  it('takes a background as a string', () => {
    expect(new Scene({ background: 'white' }).background).toEqual([1, 1, 1]);
  });

  it('add is chainable and keeps the order; spheres lists only spheres', () => {
    const a = new Sphere([0, 0, -5], 1), p = new Plane(), b = new Box([0, 0, 0], [1, 1, 1]), c = new Sphere([2, 0, -5], 1);
    const light = new PointLight([0, 5, 0]);
    const scene = new Scene();
    expect(scene.add(a).add(p).add(b).add(c).add(light)).toBe(scene);
    expect(scene.objects).toEqual([a, p, b, c]);
    expect(scene.spheres).toEqual([a, c]);
    expect(scene.lights.map((l) => l.source)).toEqual([light]);
  });

  it('remove takes a shape and its light away', () => {
    const lamp = new Sphere([0, 5, 0], 1, { emission: 1 }), ball = new Sphere([0, 0, -5], 1);
    const light = new PointLight([1, 1, 1]);
    const scene = new Scene().add(lamp).add(ball).add(light);
    expect(scene.lights).toHaveLength(2);
    scene.remove(lamp);
    expect(scene.objects).toEqual([ball]);
    expect(scene.lights.map((l) => l.source)).toEqual([light]);
    scene.remove(light);
    expect(scene.lights).toEqual([]);
  });

  it("the class's example scene: ground, four spheres, two emissive lights", () => {
    const scene = classScene();
    expect(scene.objects).toHaveLength(7);
    expect(scene.spheres).toHaveLength(7);
    expect(scene.lights).toHaveLength(2);
    const pink = scene.objects.find((o) => o.name === 'pink');
    expect(pink.center).toEqual({ x: 0, y: 0, z: -20 });
    expect(pink.radius).toBe(4);
    expect(pink.material.reflection).toBe(0);
    const full = classScene({ full: true }).objects.find((o) => o.name === 'pink');
    expect(full.material.reflection).toBeGreaterThan(0);
    expect(full.material.transparency).toBeGreaterThan(0);
  });
});

describe('Scene: bad input names the field', () => {
  const cases = [
    [{ background: 'sky' }, TypeError, /background/],
    [{ background: [1, 1] }, TypeError, /background/],
    [{ ambient: 2 }, RangeError, /ambient/],
    [{ ambient: '0.1' }, TypeError, /ambient/],
    [{ shadows: 'yes' }, TypeError, /shadows/],
    [{ shadows: 1 }, TypeError, /shadows/],
    [{ bias: -1 }, RangeError, /bias/],
    [{ maxDepth: 17 }, RangeError, /maxDepth/],
    [{ maxDepth: -1 }, RangeError, /maxDepth/],
    [{ maxDepth: NaN }, TypeError, /maxDepth/],
    [{ specular: 'on' }, TypeError, /specular/],
  ];
  for (const [options, type, field] of cases) {
    it(`${JSON.stringify(options)} → ${type.name} ${field}`, () => {
      expect(() => new Scene(options)).toThrow(type);
      expect(() => new Scene(options)).toThrow(field);
    });
  }

  it('add refuses anything but shapes and lights', () => {
    const scene = new Scene();
    for (const bad of [null, undefined, 'sphere', { center: [0, 0, 0], radius: 1 }, 42]) {
      expect(() => scene.add(bad)).toThrow(TypeError);
      expect(() => scene.add(bad)).toThrow(/scene\.add/);
    }
    expect(scene.objects).toEqual([]);
  });
});

describe('shapeName: what an unnamed shape is called on the page', () => {
  it('its own name, else its kind and its number among that kind, from 1', async () => {
    const { shapeName } = await import('../../lib/scene/scene.js');
    const scene = new Scene()
      .add(new Plane([0, -1, 0], [0, 1, 0]))
      .add(new Sphere([0, 0, -20], 4))
      .add(new Sphere([5, 0, -20], 1, { name: 'moon' }))
      .add(new Box([-1, -1, -9], [1, 1, -7]))
      .add(new Sphere([-5, 0, -20], 1));
    expect(scene.objects.map((o) => shapeName(o, scene.objects))).toEqual(['plane 1', 'sphere 1', 'moon', 'box 1', 'sphere 3']);
    expect(shapeName(new Sphere([0, 0, 0], 1), [])).toBe('sphere'); // not in the list: its kind alone
  });
});
