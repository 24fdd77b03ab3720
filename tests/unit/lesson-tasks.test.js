// The lesson pages' tasks: their shape, and the predicates against real scenes and records.
import { describe, it, expect } from 'vitest';
import { Camera, Scene, Sphere, Plane, Cylinder, Cone, Triangle, Mesh, PointLight, AreaLight, SpotLight, classScene, inspectPixel } from '../../lib/index.js';
import { LESSONS, lessonOf, sphereTest, nearZeroDiscriminant, eyeInside, hasAcne, inShadowOf, shadowsOnOthers } from '../../lib/lesson/tasks.js';

const select = (scene, camera, x, y) => ({ type: 'select', record: inspectPixel(scene, camera, x, y), scene, camera, parts: {}, mode: 'shaded', order: 'coarse' });
const task = (page, id) => lessonOf(page).tasks.find((t) => t.id === id);

describe('the lessons', () => {
  it('pages 00–14, 16 and 17 each have three to seven tasks with an id, a text and a hint', () => {
    expect(LESSONS.map((l) => l.page)).toEqual(['00', '01', '02', '03', '04', '05', '06', '07', '08', '09', '10', '11', '12', '13', '14', '16', '17']);
    for (const lesson of LESSONS) {
      expect(lesson.tasks.length, lesson.page).toBeGreaterThanOrEqual(3);
      expect(lesson.tasks.length, lesson.page).toBeLessThanOrEqual(7);
      expect(new Set(lesson.tasks.map((t) => t.id)).size).toBe(lesson.tasks.length);
      for (const t of lesson.tasks) expect([typeof t.text, typeof t.hint, typeof t.done], `${lesson.page} ${t.id}`).toEqual(['string', 'string', 'function']);
    }
    expect(lessonOf('01').tasks[0].text).toMatch(/^Select any pixel/);
    expect(LESSONS.filter((l) => l.homework).map((l) => l.page)).toEqual(['08', '09']);
  });
});

describe('the predicates', () => {
  const ball = () => new Scene().add(new Sphere([0, 0, -20], 4, { color: 'pink', name: 'pink' })).add(new PointLight([-10, 10, 10]));
  const camera = new Camera({ width: 64, height: 48 });

  it('sketch 01\'s slow motion is done by the render order being slow', () => {
    const state = (order) => ({ type: 'state', scene: ball(), camera, parts: {}, mode: 'shaded', order });
    expect(task('01', 'slow').done(state('slow'), {})).toBe(true);
    expect(task('01', 'slow').done(state('scanline'), {})).toBe(false);
  });

  it('a discriminant "about 0" is a band around the sphere\'s edge, not its middle or the sky', () => {
    const at = (x, y) => sphereTest(inspectPixel(ball(), camera, x, y));
    expect(nearZeroDiscriminant(at(32, 24))).toBe(false); // through the centre: 4r²
    expect(nearZeroDiscriminant(at(0, 0))).toBe(false);
    const band = [];
    for (let x = 32; x < 64; x++) if (nearZeroDiscriminant(at(x, 24))) band.push(x);
    expect(band.length).toBeGreaterThanOrEqual(1);
    expect(band.length).toBeLessThanOrEqual(3);
    expect(task('02', 'zero').done(select(ball(), camera, band[0], 24), {})).toBe(true);
    expect(task('02', 'negative').done(select(ball(), camera, 0, 0), {})).toBe(true);
    expect(task('02', 'positive').done(select(ball(), camera, 32, 24), {})).toBe(true);
    expect(task('02', 'positive').done({ type: 'state', scene: ball(), camera }, {})).toBe(false); // found by a selection only
  });

  it('02: pixel 10,12 hits the sphere once its radius is big enough', () => {
    const grown = (r) => ({ type: 'state', scene: new Scene().add(new Sphere([0, 0, -20], r)), camera });
    expect(task('02', 'grow').done(grown(4), {})).toBe(false);
    expect(task('02', 'grow').done(grown(6), {})).toBe(true);
  });

  it('03: tca < 0 and still a hit, only with the eye inside', () => {
    const inside = new Camera({ width: 64, height: 48, position: [0, 1.5, -22.5], fov: 90 });
    expect(eyeInside(sphereTest(inspectPixel(ball(), inside, 32, 24)))).toBe(true);
    expect(task('03', 'tca-negative').done(select(ball(), inside, 32, 24), {})).toBe(true);
    expect(task('03', 'tca-negative').done(select(ball(), camera, 32, 24), {})).toBe(false);
    expect(task('03', 'inside').done({ type: 'state', scene: ball(), camera: inside }, {})).toBe(true);
  });

  it('acne: a surface shadowing itself only without the shadow-ray offset; a real shadow is no acne', () => {
    const floor = (bias) => {
      const scene = new Scene({ bias }).add(new Plane([0, -1, 0], [0, 1, 0], { name: 'floor' })).add(new Sphere([0, 0, -10], 1, { name: 'ball' })).add(new PointLight([4, 8, -3]));
      scene.epsilon = bias === 0 ? 0 : scene.epsilon;
      return scene;
    };
    const cam = new Camera({ width: 80, height: 60, position: [0, 1.6, 2], pitch: -9 });
    const count = (scene, test) => {
      let n = 0;
      for (let y = 0; y < 60; y++) for (let x = 0; x < 80; x++) if (test(inspectPixel(scene, cam, x, y), scene)) n++;
      return n;
    };
    expect(count(floor(1e-4), hasAcne)).toBe(0);
    expect(count(floor(0), hasAcne)).toBeGreaterThan(0);
    expect(count(floor(1e-4), (r, s) => inShadowOf(r, s, 'ball'))).toBeGreaterThan(0); // the ball's shadow on the floor
  });

  it('05: a sphere moved over another throws a new shadow on it', () => {
    const eye = new Camera({ width: 160, height: 120 }).position;
    const start = shadowsOnOthers(classScene(), eye);
    expect(start).not.toContain('yellow→pink');
    const moved = classScene();
    Object.assign(moved.objects.find((o) => o.name === 'yellow').center, { x: 0, y: 7, z: -20 });
    expect(shadowsOnOthers(moved, eye)).toContain('yellow→pink');
    const memory = {};
    expect(task('05', 'shadow').done({ type: 'state', scene: classScene(), camera: new Camera({ width: 160, height: 120 }) }, memory)).toBe(false);
    expect(task('05', 'shadow').done({ type: 'state', scene: moved, camera: new Camera({ width: 160, height: 120 }) }, memory)).toBe(true);
  });

  it('04: two different right answers, and a turned camera read from the answer line', () => {
    const memory = {};
    const answer = (ok, line) => ({ type: 'answer', ok, answer: line });
    expect(task('04', 'two').done(answer(true, 'Pixel: 16,12; H: 0; V: 0'), memory)).toBe(false);
    expect(task('04', 'two').done(answer(true, 'Pixel: 16,12; H: 0; V: 0'), memory)).toBe(false);
    expect(task('04', 'two').done(answer(false, 'Pixel: 0,0; H: 0; V: 0'), memory)).toBe(false);
    expect(task('04', 'two').done(answer(true, 'Pixel: 17,12; H: 0; V: 0'), memory)).toBe(true);
    expect(task('04', 'turned').done(answer(true, 'Pixel: 16,12; H: 0; V: 0'), {})).toBe(false);
    expect(task('04', 'turned').done(answer(true, 'Pixel: 10,12; H: 30; V: -82'), {})).toBe(true);
  });
});

describe('the predicates of pages 10–14, on the sketches\' scenes', () => {
  const state = (scene, camera) => ({ type: 'state', scene, camera, parts: {} });

  it('10: a sphere of one\'s own, a glowing sphere, a mirror showing another shape', () => {
    const start = () => new Scene({ background: [0.85, 0.92, 1] }).add(new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] })).add(new PointLight([-10, 20, 0]));
    const camera = new Camera({ width: 64, height: 48 });
    expect(task('10', 'own').done(select(start(), camera, 32, 24), {})).toBe(false); // the starter's sphere
    const more = start().add(new Sphere([6, 1, -26], 2, { color: [0.3, 0.6, 1] }));
    const x = [...Array(64).keys()].find((i) => inspectPixel(more, camera, i, 22).hit?.object === more.objects[1]);
    expect(task('10', 'own').done(select(more, camera, x, 22), {})).toBe(true);
    expect(task('10', 'glow').done(state(more, camera), {})).toBe(false);
    expect(task('10', 'glow').done(state(start().add(new Sphere([6, 1, -26], 2, { color: [0, 0, 0], emission: 1 })), camera), {})).toBe(true);
    const mirror = new Scene({ background: [0.85, 0.92, 1] }).add(new Sphere([0, 0, -20], 4, { reflection: 0.8 }))
      .add(new Sphere([0, 0, 10], 4, { color: 'pink' })).add(new PointLight([-10, 20, 0]));
    expect(task('10', 'mirror').done(select(mirror, camera, 32, 24), {})).toBe(true); // the pink sphere behind the eye, in the mirror
    expect(task('10', 'mirror').done(select(start(), camera, 32, 24), {})).toBe(false);
  });

  it('11: an edge pixel is one whose rays hit different things; the rays per pixel are the camera\'s', () => {
    const scene = classScene(), four = new Camera({ width: 64, height: 48, samples: 4 });
    expect(task('11', 'edge').done(select(scene, four, 24, 7), {})).toBe(true); // the pink sphere's top edge
    expect(task('11', 'edge').done(select(scene, four, 32, 24), {})).toBe(false); // its middle: every ray on it
    expect(task('11', 'edge').done(select(scene, new Camera({ width: 64, height: 48 }), 24, 7), {})).toBe(false); // one ray: no edge to see
    expect(task('11', 'sixteen').done(state(scene, new Camera({ width: 64, height: 48, samples: 16 })), {})).toBe(true);
    expect(task('11', 'one').done(state(scene, four), {})).toBe(false);
  });

  it('12: the cylinder\'s side, the cone, the triangle, and a ray just beside the triangle (not far from it)', () => {
    const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.12 })
      .add(new Plane([0, -4, 0], [0, 1, 0], { name: 'floor' }))
      .add(new Cylinder([-6, -1, -24], 2.5, 6, { name: 'pink cylinder' }))
      .add(new Cone([1, -1, -26], 3, 6, { name: 'yellow cone' }))
      .add(new Triangle([5, -4, -22], [10, -4, -24], [7.5, 3, -23], { name: 'green triangle' }))
      .add(new PointLight([-10, 20, 0]));
    const camera = new Camera({ width: 64, height: 48, fov: 35, position: [0, 2, 0], pitch: -8 });
    const done = (id, x, y) => task('12', id).done(select(scene, camera, x, y), {});
    expect([done('side', 8, 20), done('side', 34, 14)]).toEqual([true, false]);
    expect([done('cone', 34, 14), done('cone', 8, 20)]).toEqual([true, false]);
    expect([done('triangle', 56, 20), done('triangle', 52, 20)]).toEqual([true, false]);
    expect([done('beside', 52, 20), done('beside', 60, 20), done('beside', 56, 20), done('beside', 8, 20)]).toEqual([true, true, false, false]);
  });

  it('13: the bunny, a ray its boxes let in that misses it, a ray no box let in, the bunny\'s shadow', () => {
    // A small mesh stands in for the bunny: a tetrahedron whose box it does not fill.
    const mesh = new Mesh({ positions: [[-2, 0, -20], [2, 0, -20], [0, 0, -23], [0, 3, -21]], cells: [[0, 1, 3], [1, 2, 3], [2, 0, 3], [0, 2, 1]] }, { name: 'bunny' });
    const scene = new Scene().add(new Plane([0, -0.01, 0], [0, 1, 0], { name: 'floor' })).add(mesh).add(new PointLight([20, 10, -21]));
    const camera = new Camera({ width: 64, height: 48, position: [0, 1.5, 0] });
    const done = (id, x, y) => task('13', id).done(select(scene, camera, x, y), {});
    const pixels = [];
    for (let y = 0; y < 48; y++) for (let x = 0; x < 64; x++) pixels.push([x, y]);
    const bunny = pixels.find(([x, y]) => inspectPixel(scene, camera, x, y).hit?.object === mesh);
    expect(done('bunny', ...bunny)).toBe(true);
    expect(done('skip', 0, 0)).toBe(true);
    expect(done('skip', ...bunny)).toBe(false);
    expect(pixels.some(([x, y]) => done('loose', x, y))).toBe(true); // beside a sloping face, inside the box
    expect(done('loose', ...bunny)).toBe(false);
    expect(done('loose', 0, 0)).toBe(false);
    expect(pixels.some(([x, y]) => done('shadow', x, y))).toBe(true); // the floor beside it, away from a low light
  });

  it('14: the penumbra, the full shadow, outside the spot\'s cone, one shadow ray', () => {
    const scene = (samples) => new Scene({ background: [0.82, 0.9, 1], ambient: 0.1 })
      .add(new Plane([0, -4, 0], [0, 1, 0], { name: 'floor' }))
      .add(new Sphere([2, -1, -20], 3, { name: 'pink ball' }))
      .add(new SpotLight([-7, 12, -18], [-7, -4, -23], { angle: 20, intensity: 0.7, name: 'spot' }))
      .add(new AreaLight([-7, 12, -13], 5, { samples, intensity: 0.8, name: 'disc' }));
    const camera = new Camera({ width: 96, height: 72, fov: 45, position: [0, 5, 2], pitch: -20 });
    const done = (id, x, y, samples = 16) => task('14', id).done(select(scene(samples), camera, x, y), {});
    expect([done('penumbra', 64, 21), done('penumbra', 66, 27), done('penumbra', 0, 70)]).toEqual([true, false, false]);
    expect([done('umbra', 66, 27), done('umbra', 64, 21), done('umbra', 66, 27, 1)]).toEqual([true, false, false]);
    expect([done('cone', 0, 70), done('cone', 20, 50)].includes(true)).toBe(true);
    expect(done('one-ray', 0, 70, 1)).toBe(true);
    expect(done('one-ray', 0, 70, 16)).toBe(false);
  });
});
