// The animation on workers, pipelined: while draw() shows frame n the workers trace frame n+1,
// at most PIPELINE frames under way, and what is shown is render()'s picture of its moment.
import { describe, it, expect, vi, afterEach } from 'vitest';
import { SceneAnimation, PIPELINE } from '../../lib/p5/controls/animation.js';
import { workerHandler } from '../../lib/tracing/workers/split.js';
import { render, Camera, classSceneAt } from '../../lib/index.js';

/** A Web Worker stand-in that holds its jobs until run() (the real worker code, on structured clones). */
class HeldWorker {
  static started = [];
  constructor() {
    this.handle = workerHandler({ now: () => 0 });
    this.jobs = [];
    this.onmessage = null;
    HeldWorker.started.push(this);
  }
  postMessage(job) { this.jobs.push(structuredClone(job)); }
  terminate() { this.terminated = true; }
  run() {
    for (const job of this.jobs.splice(0)) this.handle(job, (m, transfer) => this.onmessage({ data: structuredClone(m, { transfer }) }));
  }
}
const runWorkers = async () => {
  for (const w of HeldWorker.started) w.run();
  await new Promise((resolve) => setTimeout(resolve)); // the renders' promises settle
};

/** A tracer view stand-in: the scene it was given, its one-thread picture, and every buffer put on its canvas. */
function fakeView(camera) {
  const shown = [];
  return {
    shown, budgetMs: 8, scene: null, buffer: null,
    setCamera() { return this; },
    setScene(scene) { this.scene = scene; return this; },
    draw() { this.buffer = render(this.scene, camera); },
    canvas: { getContext: () => ({ putImageData: (image) => shown.push(image.data) }) },
  };
}

describe('SceneAnimation on workers', () => {
  afterEach(() => {
    vi.unstubAllGlobals();
    HeldWorker.started = [];
  });

  it('posts the frame for the next draw() while this one shows, at most PIPELINE under way, and shows the newest back', async () => {
    vi.stubGlobal('Worker', HeldWorker);
    vi.stubGlobal('ImageData', class { constructor(data) { this.data = data; } });
    const camera = new Camera({ width: 24, height: 16 }), sceneAt = (t) => classSceneAt(t, 12);
    const view = fakeView(camera), paused = [];
    const movie = new SceneAnimation(/** @type {any} */ (view), { sceneAt, camera, workers: 2, onPause: (info) => paused.push(info) });
    const jobs = () => HeldWorker.started.map((w) => w.jobs.length);

    movie.start('workers');
    expect(PIPELINE).toBe(2);
    movie.tick(20); // t = 0.02: nothing back yet; the frame for the next draw() (t = 0.04) goes to the workers
    expect(jobs()).toEqual([1, 1]);
    movie.tick(20); // t = 0.04: still nothing back; a second frame (t = 0.06) goes
    movie.tick(20); // t = 0.06: two under way: no third
    expect(jobs()).toEqual([2, 2]);
    expect(movie.counter.frames).toBe(0);

    await runWorkers();
    expect(movie.counter.frames).toBe(0); // frames back are shown by draw(), not as they arrive
    movie.tick(20); // t = 0.08: the newest back (t = 0.06) is shown, and the frame for t = 0.1 goes
    expect(movie.counter.frames).toBe(1);
    expect(movie.shown).toBeCloseTo(0.06);
    expect(view.shown.at(-1)).toEqual(render(sceneAt(movie.shown), camera));
    expect(jobs()).toEqual([1, 1]);

    // Paused with a frame under way: once it is back it is the one that stays, and one thread agrees with it.
    movie.play(false);
    expect(paused).toEqual([]);
    await runWorkers();
    expect(movie.shown).toBeCloseTo(0.1);
    expect(view.shown.at(-1)).toEqual(render(sceneAt(movie.shown), camera));
    expect(paused).toEqual([{ thread: 'workers', same: true }]);
    movie.tick(20); // paused: nothing moves
    expect(jobs()).toEqual([0, 0]);
  });

  it('drops frames of an earlier run: started again, it shows only frames posted since', async () => {
    vi.stubGlobal('Worker', HeldWorker);
    vi.stubGlobal('ImageData', class { constructor(data) { this.data = data; } });
    const camera = new Camera({ width: 20, height: 12 }), sceneAt = (t) => classSceneAt(t, 12);
    const view = fakeView(camera);
    const movie = new SceneAnimation(/** @type {any} */ (view), { sceneAt, camera, workers: 2 });
    movie.start('workers');
    movie.tick(500); // posts the frame for t = 1
    movie.start('main'); // a frame on the page's thread…
    movie.start('workers'); // …and the workers again, the old frame still under way
    await runWorkers();
    movie.tick(10);
    expect(movie.counter.frames).toBe(0); // the old frame (t = 1) was dropped
    await runWorkers();
    movie.tick(10);
    expect(movie.counter.frames).toBe(1);
    expect(movie.shown).toBeCloseTo(0.52); // posted by the first draw() of the new run (t = 0.51) for the next
  });
});
