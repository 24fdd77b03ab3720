import { describe, it, expect } from 'vitest';
import { WorkerProgressiveRenderer, MIN_PIXELS } from '../../lib/tracing/workers/worker-frames.js';
import { ProgressiveRenderer } from '../../lib/tracing/frames.js';
import { render } from '../../lib/tracing/render.js';
import { modeShader } from '../../lib/tracing/modes.js';
import { Camera, classScene, classSceneAt } from '../../lib/index.js';
import { fakeWorkers, silentWorker } from './fake-workers.js';

// Frames of MIN_PIXELS or more go to the workers; the tests lower the bar to keep Node quick.
const MIN = { minPixels: 10_000 };
const LARGE = new Camera({ width: 160, height: 120 });
const SMALL = new Camera({ width: 64, height: 48 });
const tick = () => new Promise((resolve) => setTimeout(resolve, 1));

/** Steps like a tracer view's frames until done; returns what each step saw. */
async function runToDone(r, { budgetMs = 8, maxSteps = 5000 } = {}) {
  const steps = [];
  for (let i = 0; i < maxSteps && !r.done; i++) {
    const before = r.traced;
    const { changed, done } = r.step(budgetMs);
    steps.push({ changed, done, pass: r.blockSize, traced: r.traced, before, progress: r.progress });
    if (!done) await tick();
  }
  return steps;
}

describe('WorkerProgressiveRenderer', () => {
  it('a large frame: coarse passes here first, then the workers\' rows; the final buffer is render()\'s', async () => {
    expect(MIN_PIXELS).toBe(100_000); // 640×480 goes to the workers, 320×240 not
    const fake = fakeWorkers();
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: LARGE, workers: 2, createWorker: fake.create, ...MIN });
    expect(r.usingWorkers).toBe(true);
    const steps = await runToDone(r);
    expect(r.done).toBe(true);
    expect(r.buffer).toEqual(render(classScene(), LARGE));
    expect(steps[0].pass).toBeLessThanOrEqual(16); // the first step shows a 16 px preview at least
    expect(steps[0].traced).toBeGreaterThan(0);
    // Coarse to fine: the pass never grows back; progress never goes back; 100 % only at the end.
    for (let i = 1; i < steps.length; i++) {
      expect(steps[i].pass).toBeLessThanOrEqual(steps[i - 1].pass);
      expect(steps[i].progress).toBeGreaterThanOrEqual(steps[i - 1].progress);
    }
    expect(steps.slice(0, -1).every((s) => s.progress < 1)).toBe(true);
    expect(r.progress).toBe(1);
    // The main thread traced the coarse passes only: 16 and 8 px blocks, about 1/64 of the pixels.
    expect(fake.started.length).toBe(2);
    expect(r.raysPerSecond).toBeGreaterThan(0);
  });

  it('starts no worker before its first step: a renderer made and thrown away (a view that starts on the GPU) costs no worker', async () => {
    const fake = fakeWorkers();
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: LARGE, workers: 2, createWorker: fake.create, ...MIN });
    expect(r.usingWorkers).toBe(true);
    r.restart({ scene: classSceneAt(1) });
    expect(fake.started.length).toBe(0);
    r.terminate();
    const used = new WorkerProgressiveRenderer({ scene: classScene(), camera: LARGE, workers: 2, createWorker: fake.create, ...MIN });
    used.step(8);
    expect(fake.started.length).toBe(2);
    await runToDone(used);
    expect(used.buffer).toEqual(render(classScene(), LARGE));
  });

  it('a change while the workers are busy: only the newest frame is posted next, and it ends as render()\'s', async () => {
    const fake = fakeWorkers();
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: LARGE, workers: 2, createWorker: fake.create, ...MIN });
    r.step(8);
    r.restart({ scene: classSceneAt(1) });
    r.restart({ scene: classSceneAt(2) });
    await runToDone(r);
    expect(r.buffer).toEqual(render(classSceneAt(2), LARGE));
    const posted = new Set(fake.received.map((m) => m.id));
    expect(posted.size).toBe(2); // the first frame, then the newest: frame 1 s never went out
  });

  it('small frames, other visual modes and other orders stay on this thread, as a ProgressiveRenderer', async () => {
    for (const options of [
      { camera: SMALL },
      { camera: LARGE, shader: modeShader('discriminant') },
      { camera: LARGE, mode: 'scanline' },
      { camera: LARGE, workers: false },
      { camera: LARGE, minPixels: 160 * 120 + 1 },
    ]) {
      const fake = fakeWorkers();
      const r = new WorkerProgressiveRenderer({ scene: classScene(), createWorker: fake.create, workers: 2, ...MIN, ...options });
      expect(r.usingWorkers).toBe(false);
      const plain = new ProgressiveRenderer({ scene: classScene(), camera: options.camera, shader: options.shader, mode: options.mode });
      await runToDone(r, { budgetMs: 1000 });
      while (!plain.step(1000).done);
      expect(r.buffer).toEqual(plain.buffer);
      expect(fake.started.length).toBe(0);
    }
  }, 30_000);

  it('workers that fail: the frame is finished here, time-sliced, the same bytes; later frames stay here', async () => {
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: LARGE, workers: 2, ...MIN, createWorker: () => {
      const w = { terminate() {}, postMessage() { setTimeout(() => w.onerror({ message: 'SyntaxError' })); } };
      return w;
    } });
    expect(r.usingWorkers).toBe(true);
    await runToDone(r);
    expect(r.buffer).toEqual(render(classScene(), LARGE));
    expect(r.problem).toBe('render worker 1 failed (SyntaxError)');
    r.restart({ scene: classSceneAt(3) });
    expect(r.usingWorkers).toBe(false);
    await runToDone(r);
    expect(r.buffer).toEqual(render(classSceneAt(3), LARGE));
  });

  it('a worker that never answers: after the timeout this thread finishes the frame', async () => {
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: LARGE, workers: 1, ...MIN, createWorker: silentWorker });
    await runToDone(r, { maxSteps: 20000 });
    expect(r.done).toBe(true);
    expect(r.buffer).toEqual(render(classScene(), LARGE));
  }, 20_000);

  it('a scene that cannot travel as JSON is traced here', async () => {
    const scene = classScene();
    const sphere = scene.objects[1];
    scene.objects.push({ hit: () => Infinity, normalAt: () => {}, material: sphere.material });
    const fake = fakeWorkers();
    const r = new WorkerProgressiveRenderer({ scene, camera: LARGE, workers: 2, createWorker: fake.create, ...MIN });
    await runToDone(r);
    expect(r.buffer).toEqual(render(scene, LARGE));
  });

  it('slow motion by the clock: slowRaysPerSecond reaches the renderer doing the work (Shoot\'s speed)', () => {
    let t = 0;
    const r = new WorkerProgressiveRenderer({ scene: classScene(), camera: SMALL, mode: 'slow', workers: false, now: () => t });
    expect(r.slowRaysPerSecond).toBe(0);
    r.slowRaysPerSecond = 4; // one ray every 250 ms
    expect(r.slowRaysPerSecond).toBe(4);
    r.step();
    expect(r.traced).toBe(1);
    t += 100;
    r.step();
    expect(r.traced).toBe(1); // not yet owed: without the setter, one ray would go every step
    t += 160;
    r.step();
    expect(r.traced).toBe(2);
    expect(() => { r.slowRaysPerSecond = -1; }).toThrow(new RangeError('slowRaysPerSecond must not be negative, got -1'));
  });

  it('checks its workers option, and passes the rest to ProgressiveRenderer', () => {
    expect(() => new WorkerProgressiveRenderer({ scene: classScene(), camera: SMALL, workers: 0 })).toThrow(/workers must be 'auto', false or a positive whole number, got 0/);
    expect(() => new WorkerProgressiveRenderer({ scene: classScene(), camera: SMALL, mode: 'fast' })).toThrow(/mode must be one of/);
  });
});
