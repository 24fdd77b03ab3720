/**
 * The page side of `npm run bench:browser` (driven by bench/browser.js).
 *
 * ?part=progressive (default): a p5 sketch with one tracer view of the class
 *   scene at 640×480, coarse to fine, budget 8 ms, as a sketch would make it.
 *   Every draw() of the view is timed (its step(), and the rest: blit and
 *   progress bar). When the picture is done, window.bench.progressive holds
 *   the figures; then window.bench.changes() times view.setScene()/restart()
 *   to the first coarse preview and to the finished picture. With &workers=0
 *   the view traces on the page's thread alone (large frames go to workers otherwise).
 * ?part=workers: window.bench.workers() times ParallelRenderer with 1 and 2
 *   workers and render() on the main thread, side by side, and compares the
 *   pictures byte for byte; window.bench.workerGarbage() renders frames on 2
 *   workers between two marks, for the driver to count the workers' garbage
 *   collections in a trace.
 * ?part=animation: sketch 07's animated example (p.createAnimation in a
 *   320×240 tracer view, the class scene turning); window.bench.animation()
 *   plays it on the page's thread and on 2 workers, in turns, and counts the
 *   frames that reach the canvas per second.
 *
 * Nothing here asserts a time; the driver prints the figures.
 */
import p5 from 'p5';
import { Camera, classScene, classSceneAt, render } from '../../lib/index.js';
import '../../lib/p5/index.js';
import { ParallelRenderer } from '../../lib/tracing/workers/parallel.js';

const WIDTH = 640, HEIGHT = 480, BUDGET_MS = 8;
const params = new URLSearchParams(location.search);
const part = params.get('part') ?? 'progressive';
const viewWorkers = params.get('workers') === '0' ? false : 'auto'; // ?workers=0: the tracer view on the page's thread alone
const bench = (window.bench = { part });

const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));

function report(text) {
  document.getElementById('report').textContent += `${text}\n`;
}

/* ---------------- progressive rendering in a tracer view ---------------- */

/**
 * Wraps the view's draw() and its renderer's step() with timers. `onDraw`
 * hooks (set by changes()) see each frame's record right after its blit.
 */
function instrument(view) {
  const renderer = view.renderer;
  const step = renderer.step.bind(renderer), draw = view.draw.bind(view);
  const probe = { frames: [], stepMs: 0, onDraw: null };
  renderer.step = (budgetMs) => {
    const start = performance.now();
    const result = step(budgetMs);
    probe.stepMs = performance.now() - start;
    return result;
  };
  view.draw = () => {
    const start = performance.now();
    if (probe.frames.length === 0) performance.mark('bench:first-step'); // seen in the trace too
    probe.stepMs = 0;
    const tracedBefore = renderer.traced;
    draw();
    const end = performance.now();
    const frame = { start, end, step: probe.stepMs, draw: end - start, traced: renderer.traced - tracedBefore, shown: renderer.traced, blockSize: renderer.blockSize, done: renderer.done };
    probe.frames.push(frame);
    probe.onDraw?.(frame);
  };
  return probe;
}

function progressivePart() {
  const loaded = performance.now();
  new p5((p) => {
    let view, probe, setupMs;
    p.setup = () => {
      p.noCanvas();
      const start = performance.now();
      view = p.createTracerView({
        scene: classScene(), camera: new Camera({ width: WIDTH, height: HEIGHT }),
        budgetMs: BUDGET_MS, renderMode: 'coarse', scale: 1, parent: 'sketch', workers: viewWorkers,
      });
      setupMs = performance.now() - start;
      probe = instrument(view);
      bench.view = view;
      waitUntilDone(view).then(async () => {
        await nextFrame(); await nextTask(); // the last frame's paint lands in the long-task list too
        const frames = probe.frames.map(({ start, step, draw, traced, pass }) => ({ start, step, draw, traced, pass }));
        bench.progressive = {
          moduleLoaded: loaded, setupMs, firstStep: frames[0].start, doneAt: probe.frames.at(-1).end,
          frames, longTasks: [...window.longTasks], longTasksObserved: window.longTasksObserved,
          rendersPerSecond: view.renderer.raysPerSecond,
        };
        report(`progressive: ${frames.length} frames, done ${(bench.progressive.doneAt - frames[0].start).toFixed(0)} ms after the first step`);
        bench.changes = (options) => changes(view, probe, options);
      });
    };
    // A sketch usually has a draw(); the view runs on its own animation frames beside it.
    p.draw = () => { bench.sketchDraw?.(); };
  });
}

/** Resolves once the view's picture is done (polled each frame, outside the view's own work). */
async function waitUntilDone(view) {
  while (!view.done) await nextFrame();
}

/**
 * Times `n` changes from the change call to the first frame showing traced
 * pixels of the new render: `blit` when the view's draw() has put them into
 * the canvas, `painted` at the first task after that frame was painted (a
 * message posted from the frame runs after its paint). `from` says where the
 * change is made: 'task' = a timer, as an input box's event would;
 * 'draw' = inside the sketch's p5 draw(), as an animating sketch would.
 */
async function changes(view, probe, { n = 12, from = 'task', gapMs = 180 } = {}) {
  const results = [];
  const longTasksBefore = window.longTasks.length;
  for (let i = 0; i < n; i++) {
    await sleep(gapMs + Math.random() * 17); // any phase of the frame
    const kind = i % 2 === 0 ? 'setScene' : 'restart';
    const scene = kind === 'setScene' ? classScene() : null; // built before the clock starts
    const result = await new Promise((resolve) => {
      let t0 = 0, changeMs = 0;
      const onDraw = (frame) => {
        if (frame.shown === 0) return; // nothing of the new picture yet (with workers, rows may arrive between frames)
        probe.onDraw = null;
        const blit = frame.end - t0;
        const channel = new MessageChannel();
        channel.port1.onmessage = () => resolve({ kind, from, t0, changeMs, blit, painted: performance.now() - t0, step: frame.step, draw: frame.draw });
        channel.port2.postMessage(0);
      };
      const change = () => {
        probe.onDraw = onDraw; // from here on: frames of the old render must not count
        t0 = performance.now();
        if (kind === 'setScene') view.setScene(scene); else view.restart();
        changeMs = performance.now() - t0;
      };
      if (from === 'draw') bench.sketchDraw = () => { bench.sketchDraw = null; change(); };
      else change();
    });
    // Then the whole picture: the end of the draw() that finished it.
    const doneAt = view.done ? probe.frames.at(-1).end : await new Promise((resolve) => {
      probe.onDraw = (frame) => { if (frame.done) { probe.onDraw = null; resolve(frame.end); } };
    });
    result.done = doneAt - result.t0;
    results.push(result);
  }
  await waitUntilDone(view);
  return { results, longTasks: window.longTasks.slice(longTasksBefore) };
}

/* ---------------- workers ---------------- */

/**
 * Renders the class scene at 640×480 `runs` times per case after `warmup`
 * rounds, the cases taking turns (first case rotating) so they share the
 * machine's state. Returns each case's times and whether each picture equals
 * render()'s byte for byte.
 */
async function workersPart({ runs = 7, warmup = 2 } = {}) {
  const scene = classScene(), camera = new Camera({ width: WIDTH, height: HEIGHT });
  const reference = render(scene, camera);
  const one = new ParallelRenderer({ workers: 1 }).warm(), two = new ParallelRenderer({ workers: 2 }).warm();
  const moved = new ParallelRenderer({ workers: 2, shared: false }).warm();
  const how = one.shared ? 'one shared frame' : 'rows transferred';
  const cases = [
    { name: 'render(), main thread', run: async () => render(scene, camera) },
    { name: `1 worker, ${how}`, run: () => one.render(scene, camera) },
    { name: `2 workers, ${how}`, run: () => two.render(scene, camera) },
  ];
  if (two.shared) cases.push({ name: '2 workers, rows transferred', run: () => moved.render(scene, camera) });
  const timed = async (c) => {
    const start = performance.now();
    const buffer = await c.run();
    return { ms: performance.now() - start, buffer };
  };
  const differing = (buffer) => {
    if (buffer.length !== reference.length) return Math.max(buffer.length, reference.length);
    let count = 0;
    for (let i = 0; i < buffer.length; i++) if (buffer[i] !== reference[i]) count++;
    return count;
  };
  try {
    // The first render of each case: workers start, load their module and compile.
    const first = [];
    for (const c of cases) {
      const { ms, buffer } = await timed(c);
      first.push(ms);
      c.differing = differing(buffer);
      c.times = [];
    }
    for (let round = 0; round < warmup + runs; round++) {
      for (let k = 0; k < cases.length; k++) {
        const c = cases[(round + k) % cases.length];
        await nextTask();
        const { ms, buffer } = await timed(c);
        if (round >= warmup) c.times.push(ms);
        c.differing += differing(buffer);
      }
    }
    return {
      width: WIDTH, height: HEIGHT, runs, warmup, cores: navigator.hardwareConcurrency, isolated: crossOriginIsolated,
      cases: cases.map((c, k) => ({ name: c.name, first: first[k], times: c.times, differing: c.differing })),
    };
  } finally {
    for (const parallel of [one, two, moved]) parallel.terminate();
  }
}

/**
 * 2 workers (a shared frame where the page is isolated) rendering the class
 * scene `frames` times back to back after `warmup` frames, between the marks
 * bench:garbage-start and bench:garbage-end: the driver counts the workers'
 * garbage collections between them in a Chromium trace. The fast path should
 * allocate nothing per pixel; a number boxed per pixel shows here as several
 * collections a frame.
 */
async function workerGarbage({ frames = 10, warmup = 10 } = {}) {
  const scene = classScene(), camera = new Camera({ width: WIDTH, height: HEIGHT });
  const two = new ParallelRenderer({ workers: 2 }).warm();
  try {
    for (let i = 0; i < warmup; i++) await two.render(scene, camera);
    performance.mark('bench:garbage-start');
    for (let i = 0; i < frames; i++) await two.render(scene, camera);
    performance.mark('bench:garbage-end');
    return { frames, warmup };
  } finally {
    two.terminate();
  }
}

/* ---------------- the animated example ---------------- */

const MOVIE = { width: 320, height: 240 }, SECONDS_PER_TURN = 12; // as in sketch 07

/**
 * Sketch 07's animated example, as the sketch makes it: a tracer view, an
 * animation of the class scene over it, draw() moving it on. `animation()`
 * plays it `rounds` times on each thread in turns (first thread rotating),
 * each time `warmupMs` unmeasured then `seconds` counted, in two ways:
 *   display: draw() on p5's loop, once per display frame, as in class;
 *   uncapped: p5's loop stopped, and the animation's tick() called again as
 *     soon as a frame is on the canvas (on the page's thread: right after
 *     it; on the workers: when a frame is back, 2 frames kept under way), so
 *     the display's rate caps neither thread.
 * It returns the frames per second that reached the canvas each way, and what
 * a frame costs: on the page's thread, draw() (the whole frame traced, and
 * shown); on the workers, each frame from its request to its picture back
 * (ParallelRenderer.render, timed here).
 */
function animationPart() {
  const renders = [];
  const next = new MessageChannel(); // uncapped: the next tick, as a task of its own
  let uncapped = false, lastTick = 0, movie;
  const parallelRender = ParallelRenderer.prototype.render;
  ParallelRenderer.prototype.render = async function timedRender(...args) {
    const start = performance.now();
    const buffer = await parallelRender.apply(this, args);
    renders.push(performance.now() - start);
    if (uncapped) next.port2.postMessage(0); // runs after the animation has taken the frame
    return buffer;
  };
  next.port1.onmessage = () => {
    if (!uncapped) return;
    const now = performance.now();
    movie.tick(now - lastTick);
    lastTick = now;
    if (movie.thread === 'main') next.port2.postMessage(0); // traced and shown: the next one
  };
  new p5((p) => {
    let draws = [];
    p.setup = () => {
      p.noCanvas();
      const camera = new Camera(MOVIE);
      const view = p.createTracerView({ scene: classSceneAt(0, SECONDS_PER_TURN), camera, scale: 1, parent: 'sketch' });
      movie = p.createAnimation({ view, sceneAt: (t) => classSceneAt(t, SECONDS_PER_TURN), camera, workers: 2 });
      bench.animation = playInTurns;
      document.body.dataset.render = 'done';
    };
    p.draw = () => {
      const start = performance.now();
      movie?.tick(p.deltaTime);
      draws.push(performance.now() - start);
    };

    /** Plays on `thread` for warmupMs + seconds, p5's loop or uncapped; the counted part's figures. */
    async function play(thread, way, { seconds, warmupMs }) {
      movie.start(thread);
      if (way === 'uncapped') {
        p.noLoop();
        uncapped = true;
        lastTick = performance.now();
        next.port2.postMessage(0);
        if (thread === 'workers') next.port2.postMessage(0); // a second frame under way from the start
      }
      await sleep(warmupMs);
      const frames0 = movie.counter.frames, t0 = performance.now();
      draws = [];
      renders.length = 0;
      await sleep(seconds * 1000);
      const ms = performance.now() - t0;
      const result = { fps: ((movie.counter.frames - frames0) * 1000) / ms, drawRate: (draws.length * 1000) / ms, draws: [...draws], renders: [...renders] };
      uncapped = false;
      movie.stop();
      p.loop();
      await sleep(200);
      return result;
    }

    async function playInTurns({ rounds = 5, seconds = 3, warmupMs = 1000 } = {}) {
      const threads = ['main', 'workers'], each = () => ({ main: [], workers: [] });
      const fps = each(), uncappedFps = each(), drawRate = each(), frameMs = each(), drawMs = each();
      for (let round = 0; round < rounds; round++) {
        for (let k = 0; k < threads.length; k++) {
          const thread = threads[(round + k) % threads.length];
          const shown = await play(thread, 'display', { seconds, warmupMs });
          fps[thread].push(shown.fps);
          drawRate[thread].push(shown.drawRate);
          drawMs[thread].push(...shown.draws);
          frameMs[thread].push(...(thread === 'main' ? shown.draws : shown.renders));
          uncappedFps[thread].push((await play(thread, 'uncapped', { seconds, warmupMs: warmupMs / 2 })).fps);
        }
      }
      return { width: MOVIE.width, height: MOVIE.height, workers: movie.workers, rounds, seconds, fps, uncappedFps, drawRate, frameMs, drawMs };
    }
  });
}

if (part === 'workers') {
  bench.workers = workersPart;
  bench.workerGarbage = workerGarbage;
  document.body.dataset.render = 'done';
} else if (part === 'animation') {
  animationPart();
} else {
  progressivePart();
}
