// The class scene, and the class scene t seconds into the original animated example.
import { describe, it, expect } from 'vitest';
import { classScene, classSceneAt } from '../../lib/index.js';

const centers = (scene) => Object.fromEntries(scene.objects.map((o) => [o.name, [o.center.x, o.center.y, o.center.z]]));
const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

describe('classSceneAt', () => {
  it('is the class scene at t = 0 and again after a whole turn', () => {
    expect(centers(classSceneAt(0))).toEqual(centers(classScene()));
    const turned = centers(classSceneAt(12)), start = centers(classScene());
    for (const name of Object.keys(start)) start[name].forEach((v, i) => expect(turned[name][i]).toBeCloseTo(v, 9));
  });

  it('turns yellow, blue and white about the pink sphere, a quarter turn in a quarter of secondsPerTurn', () => {
    const now = centers(classSceneAt(3)); // 12 s a turn: 90°
    expect(now.yellow[0]).toBeCloseTo(-5, 9); // (5, -1, -15) is (+5, +5) from pink's (0, -20) in x, z
    expect(now.yellow[1]).toBe(-1);           // heights stay
    expect(now.yellow[2]).toBeCloseTo(-15, 9);
    expect(centers(classSceneAt(1.5, 6)).yellow[0]).toBeCloseTo(-5, 9); // the same quarter turn, faster
  });

  it('keeps every circling sphere at its distance from the pink one, and the rest in place', () => {
    const start = centers(classScene());
    for (const t of [0.7, 4.2, 10]) {
      const now = centers(classSceneAt(t));
      for (const name of ['yellow', 'blue', 'white']) expect(distance(now[name], now.pink)).toBeCloseTo(distance(start[name], start.pink), 9);
      for (const name of ['ground', 'pink', 'light 1', 'light 2']) expect(now[name]).toEqual(start[name]);
    }
  });

  it('names a bad time or speed', () => {
    expect(() => classSceneAt(NaN)).toThrow(/^t must be a finite number/);
    expect(() => classSceneAt(1, 0)).toThrow(/^secondsPerTurn must be greater than 0/);
  });
});
