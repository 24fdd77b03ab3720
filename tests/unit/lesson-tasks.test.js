// The lesson pages' tasks: their shape, and the predicates against real scenes and records.
import { describe, it, expect } from 'vitest';
import { Camera, Scene, Sphere, Plane, PointLight, classScene, inspectPixel } from '../../lib/index.js';
import { LESSONS, lessonOf, sphereTest, nearZeroDiscriminant, eyeInside, hasAcne, inShadowOf, shadowsOnOthers } from '../../lib/lesson-tasks.js';

const select = (scene, camera, x, y) => ({ type: 'select', record: inspectPixel(scene, camera, x, y), scene, camera, parts: {}, mode: 'shaded', order: 'coarse' });
const task = (page, id) => lessonOf(page).tasks.find((t) => t.id === id);

describe('the lessons', () => {
  it('pages 00–09 and 16 each have three to seven tasks with an id, a text and a hint', () => {
    expect(LESSONS.map((l) => l.page)).toEqual(['00', '01', '02', '03', '04', '05', '06', '07', '08', '09', '16']);
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
