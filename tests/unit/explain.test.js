import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Box, PointLight, Camera, classScene, inspectPixel, colorName, render } from '../../lib/index.js';
import { angles } from '../../lib/math/camera.js';
import { penumbraScene, penumbraCamera, pointsSeen, penumbraPixel } from './penumbra-scene.js';

describe('inspectPixel: the full record of one pixel', () => {
  // Odd size: the centre pixel's ray is exactly (0, 0, −1), the worksheet's ray.
  const camera = new Camera({ width: 65, height: 49 });
  const scene = classScene();

  it('the centre pixel of the class scene: the worksheet numbers for the pink sphere', () => {
    const info = inspectPixel(scene, camera, 32, 24);
    expect(info).toMatchObject({ x: 32, y: 24, h: 0, v: 0 });
    expect(info.ray.direction).toEqual({ x: 0, y: 0, z: -1 });
    expect(info.tests).toHaveLength(7);
    const pink = info.tests.find((t) => t.sphere.name === 'pink');
    expect(pink.index).toBe(1);
    expect(pink.quadratic).toEqual({ A: 1, B: -40, C: 384, discriminant: 64, roots: 2, t0: 16, t1: 24, t: 16 });
    expect(pink.geometric).toMatchObject({ tca: 20, d2: 0, thc: 4, roots: 2, t0: 16, t1: 24, t: 16 });
    expect(info.hit.object.name).toBe('pink');
    expect(info.hit).toMatchObject({ t: 16, point: { x: 0, y: 0, z: -16 }, normal: { x: 0, y: 0, z: 1 } });
    expect(info.hit.incidence).toBe(0);
    expect(colorName(info.color)).toBe('pink');
  });

  it('one test per sphere, with both routes, in scene order', () => {
    const info = inspectPixel(scene, camera, 10, 12);
    expect(info.tests.map((t) => t.index)).toEqual([0, 1, 2, 3, 4, 5, 6]);
    for (const t of info.tests) {
      expect(t.sphere).toBe(scene.objects[t.index]);
      expect(t.quadratic).toHaveProperty('discriminant');
      expect(t.geometric).toHaveProperty('tca');
      expect(t.quadratic.roots).toBe(t.geometric.roots);
    }
  });

  it('its h and v are the ray\'s angles, and the camera\'s', () => {
    const info = inspectPixel(scene, camera, 3, 40);
    expect(angles(info.ray.direction)).toEqual({ h: info.h, v: info.v });
    const { h, v } = camera.primaryRay(3, 40);
    expect([info.h, info.v]).toEqual([h, v]);
    expect(info.h).toBeLessThan(0);
    expect(info.v).toBeLessThan(0);
  });

  it('a miss: hit null, the background colour, no t in front for any sphere', () => {
    const info = inspectPixel(scene, camera, 0, 0);
    expect(info.hit).toBeNull();
    expect(info.color).toEqual([255, 255, 255]);
    expect(info.tests.every((t) => t.quadratic.t === null && t.geometric.t === null)).toBe(true);
    // the ray's line, behind the eye, still meets the huge ground sphere: two roots, both negative
    const ground = info.tests.find((t) => t.sphere.name === 'ground');
    expect(ground.quadratic.roots).toBe(2);
    expect(ground.quadratic.t1).toBeLessThan(0);
  });

  it('per-light contributions: one entry per light, shadowed or not, adding up to the colour', () => {
    const info = inspectPixel(scene, camera, 32, 24);
    expect(info.hit.lights).toHaveLength(2);
    expect(info.hit.lights.map((l) => l.light.name)).toEqual(['light 1', 'light 2']);
    // light 1 is above and behind the sphere: it does not see the sphere's front
    expect(info.hit.lights[0].facing).toBe(false);
    expect(info.hit.lights[1]).toMatchObject({ facing: true, inShadow: false });
    const sum = [0, 1, 2].map((i) => info.hit.emission[i] + info.hit.ambient[i]
      + info.hit.lights.reduce((s, l) => s + l.contribution[i], 0));
    expect(sum.map((c) => Math.round(Math.min(1, c) * 255))).toEqual(info.color);
  });

  it('only spheres are tested; the index is the position among all objects', () => {
    const s = new Sphere([0, 0, -10], 1);
    const scene2 = new Scene().add(new Plane([0, -2, 0])).add(new Box([3, 0, -10], [4, 1, -9])).add(s).add(new PointLight([0, 5, 0]));
    const info = inspectPixel(scene2, new Camera({ width: 5, height: 5 }), 2, 2);
    expect(info.tests).toHaveLength(1);
    expect(info.tests[0]).toMatchObject({ sphere: s, index: 2 });
    expect(info.hit.object).toBe(s);
  });

  it('the records are fresh objects: inspecting again does not change an earlier answer', () => {
    const a = inspectPixel(scene, camera, 32, 24);
    const saved = JSON.stringify({ tests: a.tests.map((t) => [t.quadratic, t.geometric]), t: a.hit.t, color: a.color });
    inspectPixel(scene, camera, 0, 0);
    inspectPixel(scene, camera, 60, 45);
    expect(JSON.stringify({ tests: a.tests.map((t) => [t.quadratic, t.geometric]), t: a.hit.t, color: a.color })).toBe(saved);
  });
});

describe('the activity: which pixel, H and V render a PINK pixel?', () => {
  it('pink pixels exist in the class scene; every one is on the pink sphere', () => {
    const scene = classScene(), camera = new Camera({ width: 64, height: 48 });
    const pixels = render(scene, camera);
    const answers = [];
    for (let y = 0; y < 48; y++) for (let x = 0; x < 64; x++) {
      const i = (y * 64 + x) * 4;
      if (colorName([pixels[i], pixels[i + 1], pixels[i + 2]]) === 'pink') answers.push([x, y]);
    }
    expect(answers.length).toBeGreaterThan(50); // more than one right answer
    for (const [x, y] of answers) {
      const info = inspectPixel(scene, camera, x, y);
      expect(info.hit.object.name, `pixel ${x},${y}`).toBe('pink');
      expect(Math.abs(info.h)).toBeLessThan(15);
      expect(Math.abs(info.v)).toBeLessThan(15);
    }
  });

  it('the ground under the pink sphere is in the shadow of light 1', () => {
    const scene = classScene(), camera = new Camera({ width: 64, height: 48 });
    let shadowed = 0;
    for (let x = 0; x < 64; x++) {
      const info = inspectPixel(scene, camera, x, 47);
      if (info.hit?.object.name === 'ground' && info.hit.lights[0].inShadow) shadowed++;
    }
    expect(shadowed).toBeGreaterThan(0);
  });
});

describe('inspectPixel: bad coordinates name the field', () => {
  const camera = new Camera({ width: 64, height: 48 });
  const scene = classScene();
  const cases = [
    [64, 0, RangeError, /x/],
    [-1, 0, RangeError, /x/],
    [1.5, 0, RangeError, /x/],
    ['3', 0, TypeError, /x/],
    [NaN, 0, TypeError, /x/],
    [0, 48, RangeError, /y/],
    [0, -2, RangeError, /y/],
    [0, undefined, TypeError, /y/],
  ];
  for (const [x, y, type, field] of cases) {
    it(`(${JSON.stringify(x)}, ${JSON.stringify(y)}) → ${type.name} ${field}`, () => {
      expect(() => inspectPixel(scene, camera, x, y)).toThrow(type);
      expect(() => inspectPixel(scene, camera, x, y)).toThrow(field);
    });
  }
});

describe('the names in the record', () => {
  it('each test and the hit name their shape: its own name, else "sphere 1", "plane 1"', () => {
    const scene = new Scene({ background: [0, 0, 0] })
      .add(new Plane([0, -4, 0], [0, 1, 0]))
      .add(new Sphere([0, 0, -20], 4))
      .add(new Sphere([8, 0, -20], 1, { name: 'moon' }))
      .add(new PointLight([0, 20, 0]));
    const camera = new Camera({ width: 32, height: 24 });
    const centre = inspectPixel(scene, camera, 16, 12);
    expect(centre.tests.map((t) => t.name)).toEqual(['sphere 1', 'moon']);
    expect(centre.hit.name).toBe('sphere 1');
    expect(inspectPixel(scene, camera, 16, 23).hit.name).toBe('plane 1'); // the bottom row: the ground
  });
});

describe('inspectPixel: every shape by its own test', () => {
  it("a plane's Rd·n and t, a box's slabs, a sphere's quadratic: each shape's record and lines", () => {
    const camera = new Camera({ width: 65, height: 49 }); // the centre ray is (0, 0, −1)
    const scene = new Scene()
      .add(new Plane([0, 0, -30], [0, 0, 1]))
      .add(new Box([-1, -1, -12], [1, 1, -10]))
      .add(new Sphere([0, 0, -20], 4));
    const { records, hit } = inspectPixel(scene, camera, 32, 24);
    expect(records.map((r) => r.name)).toEqual(['plane 1', 'box 1', 'sphere 1']);
    const [plane, box, sphere] = records;
    expect(plane.record).toMatchObject({ denominator: -1, t: 30 });
    expect(plane.rows).toEqual([['Rd·n', -1], ['(P0 − Ro)·n', -30], ['t', 30]]);
    expect(box.record.slabs[2]).toEqual({ axis: 'z', tmin: 10, tmax: 12 });
    expect(box.rows.at(-1)).toEqual(['t', 10]);
    expect(sphere.record).toMatchObject({ discriminant: 64, t: 16 });
    expect(hit.object).toBe(box.object); // the nearest of the three records' t
  });
});

describe('inspectPixel: an area light\'s shadow rays, grouped', () => {
  const { scene, lamp } = penumbraScene();
  const camera = penumbraCamera();

  it('counts the shadow rays that reach the disc, as our own shadow rays do', () => {
    let penumbra = 0;
    for (let y = 0; y < camera.height; y += 3) {
      for (let x = 0; x < camera.width; x += 2) {
        const { hit } = inspectPixel(scene, camera, x, y);
        if (hit?.object !== scene.objects[0]) continue;
        expect(hit.areaLights).toHaveLength(1);
        const [g] = hit.areaLights;
        const seen = pointsSeen(hit.point, hit.normal, lamp, scene.bias);
        expect(g.light).toBe(lamp);
        expect(g.samples).toBe(16);
        expect(g.reached).toBe(seen);
        if (seen > 0 && seen < 16) penumbra++;
      }
    }
    expect(penumbra).toBeGreaterThan(0); // the scene does have a penumbra
  });

  it('sums its points\' transmission and what they added, and keeps them in hit.lights', () => {
    const { record } = penumbraPixel(scene, camera, lamp);
    const [g] = record.hit.areaLights;
    expect(g.rays).toHaveLength(16);
    expect(g.indices.map((i) => record.hit.lights[i])).toEqual(g.rays);
    expect(record.hit.lights).toHaveLength(16); // the per-point entries stay for their readers
    expect(g.transmission).toBeCloseTo(g.rays.reduce((sum, l) => sum + l.transmission, 0), 12);
    for (let c = 0; c < 3; c++) expect(g.contribution[c]).toBeCloseTo(g.rays.reduce((sum, l) => sum + l.contribution[c], 0), 12);
    expect(g.reached).toBeGreaterThan(0);
    expect(g.reached).toBeLessThan(16);
  });

  it('point lights are not grouped', () => {
    const { hit } = inspectPixel(classScene(), new Camera({ width: 64, height: 48 }), 32, 24);
    expect(hit.areaLights).toEqual([]);
  });
});
