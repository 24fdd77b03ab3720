import { describe, it, expect } from 'vitest';
import { PointLight, Scene, Sphere, Box } from '../../lib/index.js';

describe('PointLight', () => {
  it('has a position, a colour and an intensity; emits colour × intensity', () => {
    const light = new PointLight([1, 2, 3], [1, 0.5, 0], 2);
    expect(light.position).toEqual({ x: 1, y: 2, z: 3 });
    expect(light.color).toEqual([1, 0.5, 0]);
    expect(light.emission).toEqual([2, 1, 0]);
  });

  it('defaults to white with intensity 1; colour strings work', () => {
    expect(new PointLight([0, 0, 0]).emission).toEqual([1, 1, 1]);
    expect(new PointLight([0, 0, 0], 'red').emission).toEqual([1, 0, 0]);
  });

  it('bad input names the field', () => {
    expect(() => new PointLight()).toThrow(TypeError);
    expect(() => new PointLight()).toThrow(/position/);
    expect(() => new PointLight([0, NaN, 0])).toThrow(/position\.y/);
    expect(() => new PointLight([0, 0, 0], 'glow')).toThrow(/color/);
    expect(() => new PointLight([0, 0, 0], [1, 1, 1], -1)).toThrow(RangeError);
    expect(() => new PointLight([0, 0, 0], [1, 1, 1], -1)).toThrow(/intensity/);
    expect(() => new PointLight([0, 0, 0], [1, 1, 1], '2')).toThrow(TypeError);
    expect(() => new PointLight([0, 0, 0], [1, 1, 1], '2')).toThrow(/intensity/);
  });
});

describe('light sources of a scene', () => {
  it('a point light is a light at its position', () => {
    const light = new PointLight([0, 5, 0], [1, 1, 1], 0.5);
    const scene = new Scene().add(light);
    expect(scene.lights).toHaveLength(1);
    expect(scene.lights[0]).toMatchObject({ position: { x: 0, y: 5, z: 0 }, emission: [0.5, 0.5, 0.5], object: null, source: light });
    expect(scene.objects).toHaveLength(0);
  });

  it('an emissive sphere is both a shape and a light at its centre', () => {
    const sun = new Sphere([0, 20, -30], 3, { color: [0, 0, 0], emission: 1.2 });
    const scene = new Scene().add(sun);
    expect(scene.objects).toEqual([sun]);
    expect(scene.lights).toHaveLength(1);
    expect(scene.lights[0]).toMatchObject({ position: { x: 0, y: 20, z: -30 }, emission: [1.2, 1.2, 1.2], object: sun });
  });

  it('an emissive box is a light at its middle', () => {
    const lamp = new Box([0, 0, 0], [2, 4, 6], { emission: 1 });
    const scene = new Scene().add(lamp);
    expect(scene.lights[0].position).toEqual({ x: 1, y: 2, z: 3 });
  });

  it('a non-emissive sphere is not a light', () => {
    const scene = new Scene().add(new Sphere([0, 0, -5], 1, { color: 'red' }));
    expect(scene.lights).toHaveLength(0);
  });
});
