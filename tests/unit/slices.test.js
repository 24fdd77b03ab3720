// Long text built in slices (lib/text/slices.js): the same text as built at once,
// with a wait whenever a slice has taken its time.
import { describe, it, expect } from 'vitest';
import { joinInSlices, SLICE_MS } from '../../lib/text/slices.js';
import { Scene, Sphere, PointLight, classScene } from '../../lib/index.js';
import { sceneToCode, sceneCodeLines } from '../../lib/scene/json.js';

/** 2,000 spheres, named and not, and a point light among them. */
function bigScene() {
  const scene = new Scene({ background: [0.9, 0.9, 1], ambient: 0.1 });
  for (let i = 0; i < 2000; i++) {
    const ball = new Sphere([i % 40, Math.floor(i / 40), -50], 0.25, { color: [i / 2000, 0.5, 0.25] });
    if (i % 3) ball.name = `ball ${i}`;
    scene.add(ball);
    if (i === 1000) scene.add(new PointLight([0, 10, 0], [1, 0.9, 0.8], 2));
  }
  return scene;
}

describe('joinInSlices', () => {
  it('joins the lines, waiting once per slice of sliceMs on its clock', async () => {
    const clock = { t: 0 };
    let waits = 0;
    function* lines() {
      for (let i = 0; i < 100; i++) { clock.t += 1; yield `${i}\n`; } // each line costs 1 ms
    }
    const text = await joinInSlices(lines(), { sliceMs: 10, now: () => clock.t, pause: async () => { waits++; } });
    expect(text).toBe(Array.from({ length: 100 }, (_, i) => `${i}\n`).join(''));
    expect(waits).toBe(10);
  });

  it('waits for a task of its own by default (a timer, not a microtask)', async () => {
    let timerRan = false;
    setTimeout(() => { timerRan = true; }, 0);
    const clock = { t: 0 };
    const text = await joinInSlices((function* () { clock.t += SLICE_MS; yield 'a'; yield 'b'; })(), { now: () => clock.t });
    expect(text).toBe('ab');
    expect(timerRan).toBe(true); // the timer set before had its turn during the wait
  });
});

describe('sceneCodeLines', () => {
  it('makes sceneToCode\'s text, a line at a time', async () => {
    for (const scene of [classScene(), bigScene(), new Scene()]) {
      const lines = [...sceneCodeLines(scene, { importFrom: 'raytracing-sketchbook' })];
      expect(lines.every((line) => line.endsWith('\n'))).toBe(true);
      expect(lines.join('')).toBe(sceneToCode(scene, { importFrom: 'raytracing-sketchbook' }));
      expect(await joinInSlices(sceneCodeLines(scene), { sliceMs: 0 })).toBe(sceneToCode(scene));
    }
    expect(sceneToCode(new Scene())).toBe("import { Scene } from '../lib/index.js';\n\nconst scene = new Scene({});\n");
  });

  it('refuses what is not a scene, as sceneToCode did', () => {
    expect(() => [...sceneCodeLines({ objects: [] })]).toThrow(new TypeError('scene must be a Scene, got {"objects":[]}'));
  });
});
