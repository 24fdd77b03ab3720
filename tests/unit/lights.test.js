import { describe, it, expect } from 'vitest';
import { PointLight, SpotLight, AreaLight, Scene, Sphere, Box, Plane, Camera, Ray, render, sceneToJSON, sceneFromJSON, sceneToCode } from '../../lib/index.js';
import { trace } from '../../lib/tracing/trace.js';
import { falloff } from '../../lib/tracing/optics.js';

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

describe('attenuation: a light fades with distance d by 1 / (1 + attenuation·d²)', () => {
  const makers = {
    PointLight: (attenuation) => new PointLight([0, 10, 0], { attenuation }),
    SpotLight: (attenuation) => new SpotLight([0, 10, 0], [0, 0, 0], { angle: 40, attenuation }),
    AreaLight: (attenuation) => new AreaLight([0, 10, 0], 1, { samples: 1, attenuation }),
  };
  /** A white floor under the light, and the inspector's record of the point right below it, 10 away. */
  const below = (light) => {
    const scene = new Scene().add(new Plane([0, 0, 0], [0, 1, 0])).add(light), steps = {};
    trace(scene, new Ray([0, 5, 0], [0, -1, 0]), [0, 0, 0], steps);
    return steps.hit.lights[0];
  };

  it.each(Object.keys(makers))('%s: 0 by default; a negative or non-number attenuation names the field', (name) => {
    expect(makers[name](undefined).attenuation).toBe(0);
    expect(makers[name](0.5).attenuation).toBe(0.5);
    expect(() => makers[name](-0.1)).toThrow(RangeError);
    expect(() => makers[name](-0.1)).toThrow(/attenuation/);
    for (const bad of ['0.1', NaN, Infinity, null, [0.1]]) {
      expect(() => makers[name](bad)).toThrow(TypeError);
      expect(() => makers[name](bad)).toThrow(/attenuation/);
    }
  });

  it('the formula: 1 / (1 + k·d²), exactly 1 at k = 0', () => {
    expect(falloff(0.04, 10)).toBeCloseTo(1 / 5, 15); // 1 + 0.04·100 = 5
    expect(falloff(1, 0)).toBe(1);
    expect(falloff(0, 123.4)).toBe(1);
    expect(falloff(0.01, 10)).toBe(0.5); // half as strong at d = 1/√k
  });

  it.each(Object.keys(makers))('%s: a floor point 10 below it gets a fifth of the light at k = 0.04; the record says so', (name) => {
    const lit = below(makers[name](0.04)), plain = below(makers[name](0));
    expect(lit.distance).toBe(10);
    expect(lit.falloff).toBeCloseTo(0.2, 15);
    expect(plain.falloff).toBe(1);
    expect(plain.contribution).toEqual([1, 1, 1]); // cos 1, white on white
    lit.contribution.forEach((c) => expect(c).toBeCloseTo(0.2, 15));
    expect(lit.inShadow).toBe(false); // fading is not a shadow
  });

  it('attenuation 0 leaves the picture byte for byte; any other darkens it', () => {
    const camera = new Camera({ width: 24, height: 18, position: [0, 6, 8], pitch: -30 });
    const picture = (options) => render(new Scene({ ambient: 0.1 }).add(new Plane([0, -2, 0], [0, 1, 0])).add(new Sphere([0, 0, -10], 2))
      .add(new PointLight([4, 8, -4], options)), camera);
    const plain = picture({}), none = picture({ attenuation: 0 }), fading = picture({ attenuation: 0.02 });
    expect(none).toEqual(plain);
    expect(fading).not.toEqual(plain);
    let darker = 0;
    for (let i = 0; i < plain.length; i += 4) if (fading[i] < plain[i]) darker++;
    expect(darker).toBeGreaterThan(0);
  });

  it('round-trips through scene JSON and scene code; lights that do not fade are written as before', () => {
    const scene = new Scene().add(new Plane([0, -2, 0], [0, 1, 0]))
      .add(new PointLight([1, 8, 0], { color: [1, 0.5, 0.25], attenuation: 0.03 }))
      .add(new SpotLight([0, 9, -5], [0, -2, -5], { angle: 20, attenuation: 0.1 }))
      .add(new AreaLight([3, 9, -5], 2, { samples: 4, attenuation: 0.25 }))
      .add(new PointLight([5, 5, 5]));
    const json = sceneToJSON(scene);
    expect(json.objects.slice(1).map((o) => o.attenuation)).toEqual([0.03, 0.1, 0.25, undefined]);
    expect(Object.keys(json.objects[4])).not.toContain('attenuation');
    const back = sceneFromJSON(JSON.parse(JSON.stringify(json)));
    expect(back.lights.map((l) => l.attenuation)).toEqual(scene.lights.map((l) => l.attenuation));
    expect(sceneToJSON(back)).toEqual(json);
    const code = sceneToCode(scene);
    expect(code).toContain('new PointLight([1, 8, 0], { color: [1, 0.5, 0.25], attenuation: 0.03 })');
    expect(code).toContain('attenuation: 0.1 }');
    expect(code).toContain('attenuation: 0.25 }');
    expect(code).toContain('new PointLight([5, 5, 5])');
    expect(() => sceneFromJSON({ objects: [{ type: 'pointLight', position: [0, 0, 0], attenuation: -1 }] })).toThrow(/objects\[0\]\.attenuation/);
  });
});
