/**
 * The browser benchmark: `npm run bench:browser` (add `-- --dev` to time the
 * Vite dev server's unbundled modules instead of a production build).
 *
 * Builds bench/browser/bench.html with `vite build` into a temporary folder,
 * serves it with `vite preview` on port 5178, or BENCH_PORT / `--port N`
 * (stopped at the end by its PID),
 * and drives headless Chromium (@playwright/test, the browser that
 * scripts/find-browser.js finds) through these measurements:
 *   1. the class scene at 640×480 traced progressively in a tracer view
 *      (coarse to fine, budget 8 ms): main-thread tasks over 16 ms, from a
 *      Chromium trace (every task) and from the Long Tasks API (over 50 ms
 *      only), split into page load and rendering (from the first step on);
 *      the distribution of the per-frame step() and draw() times;
 *   2. time from view.setScene()/restart() to the first coarse preview;
 *   3. the class scene at 640×480 by ParallelRenderer with 1 and 2 workers
 *      (one shared frame, and rows transferred) and by render() on the main
 *      thread, side by side; each worker picture must equal render()'s byte
 *      for byte; then, in a Chromium trace of a page of its own, the 2
 *      workers' garbage collections per frame (a number boxed per pixel
 *      shows as several a frame);
 *   4. a save while a sketch is open in the Vite dev server (a second server,
 *      on --save-port N or BENCH_SAVE_PORT, default the port + 1): the time
 *      from writing the sketch file to the first coarse preview, the sketch
 *      swapped in place and, side by side, the page reloaded; and whether
 *      the selected pixel came back (see saves());
 *   5. the 3D scene view's frame rate and cost (see view3d());
 *   6. sketch 07's animated example at 320×240 on the page's thread and on 2
 *      workers in turns: frames per second on the canvas, and what a frame
 *      costs on each (see bench/browser/bench.js);
 *   7. the GPU engine: the class scene with full shading at 640×480 (or
 *      --gpu-size 1280x720), frames per second on the GPU and on one Web
 *      Worker per core, and their ratio, in one run (see bench/browser/gpu.js).
 *      Headless Chromium here draws WebGL with SwiftShader, on the CPU; on a
 *      machine with a GPU, add --headed (docs/gpu.md).
 *   8. the path tracer: sketch 16's Cornell box at 320×240 (or --paths-size),
 *      samples (paths) per second on the GPU engine (pathTraceGPU), on the
 *      page's thread and on one Web Worker per core, in one run (see
 *      bench/browser/paths.js); --headed for a real GPU, as in 7.
 * Times are printed, never asserted; the exit code is 1 only when something
 * is broken (a page error, a picture that differs, no browser).
 *
 * Options: --dev (the dev server instead of build + preview); --runs N (worker
 * timings per case, default 15); --rounds N (animation rounds per thread,
 * default 5); --only progressive, workers, animation, saves, view3d, gpu or paths (one part
 * alone); --port N or BENCH_PORT=N (the server's port, default 5178);
 * BENCH_TRACE=file writes the Chromium trace of part 1 (open it in
 * ui.perfetto.dev), and BENCH_TRACE_CATEGORIES=devtools.timeline,v8 adds
 * detail to it.
 *
 * Today's figures, with the conditions they were measured in, and how to read
 * them: docs/performance.md. (Figures age; that page says when they were taken.)
 */
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync, readFileSync } from 'node:fs';
import { tmpdir, loadavg, availableParallelism } from 'node:os';
import { join, resolve } from 'node:path';
import { chromium } from '@playwright/test';
import { findBrowser, HOW_TO_GET_ONE } from '../scripts/find-browser.js';

const PORT = port(option('--port') ?? process.env.BENCH_PORT);
const ROOT = resolve(import.meta.dirname, '..');
const PAGE = 'bench/browser/bench.html';
const VIEW3D_PAGE = 'bench/browser/view3d.html';
const GPU_PAGE = 'bench/browser/gpu.html';
const PATHS_PAGE = 'bench/browser/paths.html';
const PATHS_SIZE = (option('--paths-size') ?? '320x240').split('x').map(Number); // `-- --paths-size 640x480`
const GPU_SIZE = (option('--gpu-size') ?? '640x480').split('x').map(Number); // `-- --gpu-size 1280x720`
const HEADED = process.argv.includes('--headed'); // a real GPU: a headed browser (headless Chromium draws WebGL in software)
const ONLY_VIEW3D = option('--only') === 'view3d'; // `npm run bench:browser -- --only view3d`: section 5 alone
const DEV = process.argv.includes('--dev');
const ONLY = option('--only'); // 'progressive', 'workers', 'animation', 'saves' or 'view3d': one part alone
const TASK_LIMIT_MS = 16;
const CHANGES = 12;           // per way of making a change
const RUNS = Number(option('--runs') ?? 15), WARMUP = 3;   // worker timings (--runs N)

const median = (values) => {
  if (values.length === 0) return NaN;
  const sorted = [...values].sort((a, b) => a - b), mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};
const quantile = (values, q) => {
  if (values.length === 0) return NaN;
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
};
/** The value after `name` on the command line, or undefined. */
function option(name) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : undefined;
}
/** The server's port: the one asked for (a whole number 1–65535), else 5178. */
function port(asked) {
  if (asked === undefined || asked === '') return 5178;
  const n = Number(asked);
  if (!Number.isInteger(n) || n < 1 || n > 65535) throw new RangeError(`port must be a whole number from 1 to 65535, got ${JSON.stringify(asked)}`);
  return n;
}
const ms = (value) => (Number.isFinite(value) ? value.toFixed(1) : '–');

/* ---------------- server ---------------- */

/** `vite build` of the bench page alone into a temporary folder (the project's own config, minus its inputs). */
async function buildPage() {
  const outDir = mkdtempSync(join(tmpdir(), 'rt-bench-browser-'));
  const { build } = await import('vite');
  await build({
    root: ROOT, configFile: false, base: './', logLevel: 'warn',
    build: { target: 'es2022', outDir, emptyOutDir: true, rolldownOptions: { input: [resolve(ROOT, PAGE), resolve(ROOT, VIEW3D_PAGE), resolve(ROOT, GPU_PAGE), resolve(ROOT, PATHS_PAGE)] } },
    worker: { format: 'es' },
  });
  return outDir;
}

/** Starts vite (dev server, or preview of outDir) on `at` (PORT); resolves once it answers. */
async function startServer(outDir, at = PORT) {
  const args = outDir ? ['preview', '--outDir', outDir, '--port', String(at), '--strictPort'] : ['--port', String(at), '--strictPort'];
  const server = spawn(join(ROOT, 'node_modules/.bin/vite'), args, { cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '';
  server.stdout.on('data', (d) => { output += d; });
  server.stderr.on('data', (d) => { output += d; });
  const url = `http://localhost:${at}/`;
  for (let i = 0; i < 150; i++) {
    if (server.exitCode !== null) throw new Error(`vite exited (${server.exitCode}):\n${output}`);
    try {
      await fetch(url);
      return server;
    } catch { await new Promise((r) => setTimeout(r, 200)); }
  }
  server.kill();
  throw new Error(`vite did not answer on ${url} within 30 s:\n${output}`);
}

/* ---------------- trace: every main-thread task ---------------- */

/**
 * Top-level tasks of the page's main thread from a Chromium trace, as
 * { start, duration } in ms on the trace clock, and the trace time of the
 * `bench:first-step` mark.
 */
function mainThreadTasks(traceBuffer) {
  const events = JSON.parse(traceBuffer.toString()).traceEvents ?? [];
  const mark = events.find((e) => e.name === 'bench:first-step');
  const mains = new Set(events.filter((e) => e.ph === 'M' && e.name === 'thread_name' && e.args?.name === 'CrRendererMain').map((e) => `${e.pid}:${e.tid}`));
  // The page's main thread: the one that set the mark (other renderers may exist).
  const key = mark ? `${mark.pid}:${mark.tid}` : null;
  const tasks = events
    .filter((e) => e.ph === 'X' && /RunTask$/.test(e.name) && (key ? `${e.pid}:${e.tid}` === key : mains.has(`${e.pid}:${e.tid}`)))
    .map((e) => ({ start: e.ts / 1000, duration: (e.dur ?? 0) / 1000, cpu: e.tdur === undefined ? NaN : e.tdur / 1000 }))
    .sort((a, b) => a.start - b.start);
  const topLevel = [];
  for (const t of tasks) {
    const last = topLevel.at(-1);
    if (last && t.start < last.start + last.duration) continue; // nested in the one before
    topLevel.push(t);
  }
  return { tasks: topLevel, firstStep: mark ? mark.ts / 1000 : null };
}

/* ---------------- the three measurements ---------------- */

function watch(page, errors) {
  page.on('pageerror', (error) => errors.push(`page error: ${error.message}`));
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(`console: ${msg.text()}`); });
}

async function progressive(browser, base, errors, query = '') {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  watch(page, errors);
  const categories = ['toplevel', 'blink.user_timing', '__metadata', ...(process.env.BENCH_TRACE_CATEGORIES?.split(',') ?? [])];
  await browser.startTracing(page, { categories });
  await page.goto(`${base}${PAGE}?part=progressive${query}`);
  await page.waitForFunction(() => window.bench?.progressive, null, { timeout: 60_000, polling: 100 });
  const result = await page.evaluate(() => window.bench.progressive);
  const traceBuffer = await browser.stopTracing();
  if (process.env.BENCH_TRACE) writeFileSync(process.env.BENCH_TRACE, traceBuffer); // open in ui.perfetto.dev
  const trace = mainThreadTasks(traceBuffer);
  await page.close();
  // A fresh page for the changes: once a trace that saw the view's workers stops,
  // Playwright counts the traced page as closed.
  const again = await browser.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  watch(again, errors);
  await again.goto(`${base}${PAGE}?part=progressive${query}`);
  await again.waitForFunction(() => window.bench?.changes, null, { timeout: 60_000, polling: 100 });
  const changes = [];
  for (const from of ['task', 'draw']) {
    changes.push(await again.evaluate((options) => window.bench.changes(options), { n: CHANGES, from }));
  }
  await again.close();
  return { result, trace, changes };
}

const ANIMATION_ROUNDS = Number(option('--rounds') ?? 5), ANIMATION_SECONDS = 3;

/** Sketch 07's animated example at 320×240, on the page's thread and on 2 workers in turns: frames per second. */
async function animation(browser, base, errors) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  watch(page, errors);
  await page.goto(`${base}${PAGE}?part=animation`);
  await page.waitForFunction(() => window.bench?.animation, null, { timeout: 60_000, polling: 100 });
  const result = await page.evaluate((options) => window.bench.animation(options), { rounds: ANIMATION_ROUNDS, seconds: ANIMATION_SECONDS });
  await page.close();
  return result;
}

function reportAnimation(result) {
  const { fps, uncappedFps, drawRate, frameMs, drawMs, workers: n } = result;
  console.log(`\n6. Sketch 07's animated example, ${result.width}×${result.height}: ${result.rounds} rounds of ${result.seconds} s per thread and way, in turns`);
  const column = (label, values, digits = 1) => [label, median(values).toFixed(digits), Math.min(...values).toFixed(digits), Math.max(...values).toFixed(digits)];
  table(['', 'median', 'min', 'max'], [
    column("frames per second on the canvas, page's thread", fps.main),
    column(`frames per second on the canvas, ${n} workers`, fps.workers),
    column("  uncapped (no display in the loop), page's thread", uncappedFps.main),
    column(`  uncapped (no display in the loop), ${n} workers`, uncappedFps.workers),
    column("draw() calls per second, page's thread", drawRate.main),
    column(`draw() calls per second, ${n} workers`, drawRate.workers),
    column("ms a frame costs, page's thread (draw(): trace + show)", frameMs.main),
    column(`ms a frame costs, ${n} workers (request to picture back)`, frameMs.workers),
    column(`ms of the page's thread per draw(), ${n} workers`, drawMs.workers, 2),
  ], [58, 8, 8, 8]);
  const ratio = (a, b) => `ratio of medians ${(median(a) / median(b)).toFixed(2)}×, median of per-round ratios ${median(a.map((x, i) => x / b[i])).toFixed(2)}×`;
  console.log(`   frames per second, ${n} workers over the page's thread: on the display ${ratio(fps.workers, fps.main)}`);
  console.log(`                                                    uncapped ${ratio(uncappedFps.workers, uncappedFps.main)}`);
  console.log('   (draw() runs once per display frame at most: a thread that keeps up shows the display\'s rate;');
  console.log('    uncapped, the animation is ticked again as soon as a frame is on the canvas, 2 frames under way on the workers)');
}

async function workers(browser, base, errors) {
  const page = await browser.newPage();
  watch(page, errors);
  await page.goto(`${base}${PAGE}?part=workers`);
  await page.waitForFunction(() => window.bench?.workers);
  const result = await page.evaluate((options) => window.bench.workers(options), { runs: RUNS, warmup: WARMUP });
  await page.close();
  result.garbage = await workerGarbage(browser, base, errors);
  return result;
}

/**
 * The render workers' garbage collections while 2 of them render the class
 * scene, from a Chromium trace of a page of its own (tracing slows the
 * workers, so never during the timed runs): per frame, minor and major, and
 * their time.
 */
async function workerGarbage(browser, base, errors) {
  const page = await browser.newPage();
  watch(page, errors);
  await page.goto(`${base}${PAGE}?part=workers`);
  await page.waitForFunction(() => window.bench?.workerGarbage);
  await browser.startTracing(page, { categories: ['devtools.timeline', 'v8', '__metadata', 'blink.user_timing'] });
  const { frames, warmup } = await page.evaluate(() => window.bench.workerGarbage());
  const events = JSON.parse((await browser.stopTracing()).toString()).traceEvents ?? [];
  await page.close();
  const at = (name) => events.find((e) => e.name === name)?.ts;
  const start = at('bench:garbage-start'), end = at('bench:garbage-end');
  const workerThreads = new Set(events.filter((e) => e.ph === 'M' && e.name === 'thread_name' && e.args?.name === 'DedicatedWorker thread').map((e) => `${e.pid}:${e.tid}`));
  const collections = events.filter((e) => e.ph === 'X' && (e.name === 'MinorGC' || e.name === 'MajorGC') && workerThreads.has(`${e.pid}:${e.tid}`) && e.ts >= start && e.ts < end);
  const count = (name) => collections.filter((e) => e.name === name).length;
  const milliseconds = collections.reduce((sum, e) => sum + (e.dur ?? 0) / 1000, 0);
  return { frames, warmup, found: start !== undefined && end !== undefined, minor: count('MinorGC'), major: count('MajorGC'), ms: milliseconds };
}

/* ---------------- 4. a save: the file written → the first coarse preview ---------------- */

const SAVES = 9, SAVE_WARMUP = 2;
const SAVE_PORT = port(option('--save-port') ?? process.env.BENCH_SAVE_PORT ?? String(PORT + 1));
const LIVE = 'bench/browser/live-save'; // .html and .js, written here and removed after (ignored by git)
/** A call outside p5: the dev server does not swap a script that holds one, so a save of this copy reloads its page. */
const RELOADS = '\nsetTimeout(() => {}, 0); // a timer: saves of this copy reload the page\n';

/**
 * Sketch 10 (the playground) copied beside the bench page and opened in the
 * dev server; a pixel is selected; then the file is saved SAVES times (a
 * comment changes), as an editor does: swapped in place (lib/p5/page/hot-swap.js),
 * or, for the copy `how` = 'reload' (a timer in it), by a reload of the page.
 * Each time: Node's clock when the file is written; in the page (an init
 * script), the clock when the dev server's message arrives on its socket and
 * at the first putImageData of traced pixels into the tracer canvas (the
 * first coarse preview); and whether the selected pixel came back. Both
 * clocks are the epoch in ms on one machine.
 */
async function saves(browser, base, errors, how) {
  const js = readFileSync(resolve(ROOT, 'sketches/10-playground.js'), 'utf8').replaceAll("'../lib/", "'../../lib/") + (how === 'reload' ? RELOADS : '');
  const html = readFileSync(resolve(ROOT, 'sketches/10-playground.html'), 'utf8')
    .replace('./sketch.css', '../../sketches/sketch.css').replace('./10-playground.js', './live-save.js');
  writeFileSync(resolve(ROOT, `${LIVE}.html`), html);
  writeFileSync(resolve(ROOT, `${LIVE}.js`), js);
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  try {
    await context.addInitScript(() => {
      const put = CanvasRenderingContext2D.prototype.putImageData;
      CanvasRenderingContext2D.prototype.putImageData = function (imageData, ...rest) {
        put.call(this, imageData, ...rest);
        if (!window.firstPreview && this.canvas.hasAttribute('data-tracer') && imageData.data[3] !== 0) {
          window.firstPreview = performance.timeOrigin + performance.now();
        }
      };
      // The dev server's word that the file changed: a 'full-reload' or an 'update' message on Vite's socket.
      const NativeSocket = window.WebSocket;
      window.WebSocket = class extends NativeSocket {
        constructor(...args) {
          super(...args);
          this.addEventListener('message', (event) => {
            if (/"(full-reload|update)"/.test(String(event.data))) sessionStorage.setItem('bench:arrived', String(performance.timeOrigin + performance.now()));
          });
        }
      };
    });
    const page = await context.newPage();
    watch(page, errors);
    await page.goto(`${base}${LIVE}.html`);
    await page.waitForSelector('body[data-render="done"]', { timeout: 60_000 });
    const canvas = page.locator('[data-tracer]');
    const box = await canvas.boundingBox();
    await canvas.click({ position: { x: (10.5 * box.width) / 64, y: (12.5 * box.height) / 48 } });
    const results = [];
    for (let i = 0; i < SAVES + SAVE_WARMUP; i++) {
      let loaded = false;
      page.once('load', () => { loaded = true; });
      const swapsBefore = await page.evaluate(() => { window.firstPreview = 0; return window.__sketchbookSwaps ?? 0; });
      const written = Date.now();
      writeFileSync(resolve(ROOT, `${LIVE}.js`), `${js}\n// save ${i}\n`);
      await page.waitForFunction((n) => window.firstPreview && (window.__sketchbookSwaps ?? 0) !== n, swapsBefore, { timeout: 30_000, polling: 'raf' })
        .catch(() => page.waitForFunction(() => window.firstPreview, null, { timeout: 30_000, polling: 'raf' })); // a reload: a new page
      const r = await page.evaluate(() => ({
        arrived: Number(sessionStorage.getItem('bench:arrived')), start: performance.timeOrigin, preview: window.firstPreview,
      }));
      await page.waitForSelector('body[data-render="done"]', { timeout: 60_000 });
      const answer = await page.locator('[data-answer]').textContent();
      if (i >= SAVE_WARMUP) results.push({ ...r, written, kept: answer.startsWith('Pixel: 10,12;'), how: loaded ? 'reload' : 'swap' });
      await page.waitForTimeout(300); // a teacher does not save twice in 300 ms
    }
    if (results.some((r) => r.how !== how)) errors.push(`part 4: a save meant to ${how} did not (${results.map((r) => r.how).join(', ')})`);
    return results;
  } finally {
    await context.close();
    rmSync(resolve(ROOT, `${LIVE}.html`), { force: true });
    rmSync(resolve(ROOT, `${LIVE}.js`), { force: true });
  }
}

function reportSaves(swapped, reloaded) {
  console.log(`\n4. A save while the sketch is open (Vite dev server, sketch 10 at 64×48, ${swapped.length} saves each after ${SAVE_WARMUP} warm-up; load average ${loadavg()[0].toFixed(1)})`);
  const cells = (values) => [ms(median(values)), ms(Math.min(...values)), ms(Math.max(...values))];
  const row2 = (label, f) => [label, ...cells(swapped.map(f)), ...cells(reloaded.map(f))];
  table(['first coarse preview (ms)', 'swap: median', 'min', 'max', 'reload: median', 'min', 'max'], [
    row2('from the file written', (r) => r.preview - r.written),
    row2('from the save arriving at the page', (r) => r.preview - r.arrived),
  ], [36, 13, 7, 7, 15, 7, 7]);
  console.log(`   reloaded page's start to its first preview: median ${ms(median(reloaded.map((r) => r.preview - r.start)))}`);
  console.log(`   selected pixel kept: swap ${swapped.filter((r) => r.kept).length} of ${swapped.length}, reload ${reloaded.filter((r) => r.kept).length} of ${reloaded.length}`);
  console.log('   (swap: the script swapped in place, lib/p5/page/hot-swap.js; reload: the same sketch with a timer in it, which the dev server does not swap;');
  console.log('    arriving: the dev server\'s message reaches the page; file written to arriving: its file watcher)');
}

/* ---------------- report ---------------- */

function row(cells, widths) {
  return cells.map((c, i) => (i === 0 ? String(c).padEnd(widths[i]) : String(c).padStart(widths[i]))).join('  ');
}
function table(head, rows, widths) {
  console.log(row(head, widths));
  console.log('-'.repeat(widths.reduce((a, b) => a + b + 2, -2)));
  for (const r of rows) console.log(row(r, widths));
}

function reportProgressive({ result, trace, changes }, where) {
  const { frames, longTasks, firstStep, doneAt } = result;
  console.log(`\n1. Progressive render: class scene ${640}×${480}, coarse to fine, budget 8 ms, one tracer view, ${where}`);
  console.log(`   ${frames.length} frames; picture done ${ms(doneAt - firstStep)} ms after the first step; view created in ${ms(result.setupMs)} ms`);
  const intervals = frames.slice(1).map((f, i) => f.start - frames[i].start);
  const dist = (label, values) => [label, ms(median(values)), ms(quantile(values, 0.9)), ms(quantile(values, 0.99)), ms(Math.max(...values))];
  table(['per frame (ms)', 'median', 'p90', 'p99', 'max'], [
    dist('step() (tracing)', frames.map((f) => f.step)),
    dist('draw() (step + blit + bar)', frames.map((f) => f.draw)),
    dist('draw() − step() (blit, bar)', frames.map((f) => f.draw - f.step)),
    dist('frame to frame', intervals),
  ], [30, 8, 8, 8, 8]);
  const longest = frames.reduce((a, f) => (f.draw > a.draw ? f : a), frames[0]);
  console.log(`   longest draw(): frame ${frames.indexOf(longest) + 1}, ${ms(longest.draw)} ms (step ${ms(longest.step)} ms, block size ${longest.blockSize} px)`);

  const split = (tasks, first) => {
    const load = tasks.filter((t) => t.start + t.duration <= first), rendering = tasks.filter((t) => t.start + t.duration > first);
    const over = (list) => list.filter((t) => t.duration > TASK_LIMIT_MS);
    const longestOf = (list) => Math.max(0, ...list.map((t) => t.duration));
    return { load: over(load), loadLongest: longestOf(load), rendering: over(rendering), renderingLongest: longestOf(rendering) };
  };
  const rows = [];
  if (trace.firstStep !== null && trace.tasks.length) {
    const t = split(trace.tasks, trace.firstStep);
    rows.push(['all tasks (trace), wall clock', t.load.length, ms(t.loadLongest), t.rendering.length, ms(t.renderingLongest)]);
    // The same tasks by the thread's CPU time: a task long by the wall clock
    // but short in CPU time waited for a core (other processes, or Chromium's
    // own compositor and GPU threads, which run at a higher priority).
    const byCpu = trace.tasks.map((x) => ({ start: x.start, duration: x.cpu }));
    if (byCpu.every((x) => Number.isFinite(x.duration))) {
      const c = split(byCpu, trace.firstStep);
      rows.push(['all tasks (trace), CPU time', c.load.length, ms(c.loadLongest), c.rendering.length, ms(c.renderingLongest)]);
    }
    const over = t.rendering.map((x) => `${ms(x.duration)}${Number.isFinite(x.cpu) ? ` (CPU ${ms(x.cpu)})` : ''}`);
    console.log(`   trace: ${trace.tasks.length} main-thread tasks; over ${TASK_LIMIT_MS} ms by the wall clock while rendering: ${over.join(', ') || 'none'}`);
  } else {
    console.log('   trace: no main-thread tasks found (trace format changed?)');
  }
  if (result.longTasksObserved) {
    const l = split(longTasks, firstStep);
    rows.push(['Long Tasks API (> 50 ms)', l.load.length, ms(l.loadLongest), l.rendering.length, ms(l.renderingLongest)]);
  } else {
    rows.push(['Long Tasks API', 'n/a', '', 'n/a', '']);
  }
  table([`main-thread tasks > ${TASK_LIMIT_MS} ms`, 'load', 'longest', 'rendering', 'longest'], rows, [30, 6, 8, 10, 8]);
  console.log('   (load: tasks ending before the first step; rendering: from the first step to the picture, one frame after)');

  console.log(`\n2. Change to first coarse preview and to the whole picture (${CHANGES} changes each way, setScene and restart alternating)`);
  const changeRows = changes.map(({ results }) => {
    const where = results[0].from === 'task' ? 'from a timer/input event' : "from the sketch's draw()";
    return [where, ms(median(results.map((r) => r.changeMs))), ms(median(results.map((r) => r.blit))),
      ms(median(results.map((r) => r.painted))), ms(Math.max(...results.map((r) => r.painted))),
      ms(median(results.map((r) => r.done))), ms(Math.max(...results.map((r) => r.done)))];
  });
  table(['change made', 'call', 'blit', 'painted', 'max', 'done', 'max'], changeRows, [30, 8, 8, 8, 8, 8, 8]);
  console.log('   (medians in ms from the change call: the call itself, the first blit of traced pixels, the first task after that frame\'s paint, the whole picture)');
  const changeLong = changes.flatMap((c) => c.longTasks);
  console.log(`   long tasks (> 50 ms) during the changes: ${changeLong.length ? changeLong.map((t) => ms(t.duration)).join(', ') : 'none'}`);
}

function reportWorkers(result) {
  console.log(`\n3. Class scene ${result.width}×${result.height}, whole frame: ${result.runs} runs per case after ${result.warmup} warm-up rounds, cases in turn (navigator.hardwareConcurrency ${result.cores})`);
  const rows = result.cases.map((c) => [c.name, ms(median(c.times)), ms(Math.min(...c.times)), ms(Math.max(...c.times)), ms(c.first), c.differing === 0 ? 'identical' : `${c.differing} bytes differ`]);
  table(['case', 'median', 'min', 'max', 'first', 'vs render()'], rows, [30, 8, 8, 8, 8, 16]);
  const [main, ...rest] = result.cases.map((c) => median(c.times));
  console.log(`   page cross-origin isolated: ${result.isolated ? 'yes (workers share one frame)' : 'no (rows transferred)'}`);
  console.log(`   speed-up over render() on the main thread, ratio of medians: ${rest.map((t, k) => `${result.cases[k + 1].name} ${(main / t).toFixed(2)}×`).join('; ')}`);
  // Each round times every case once, back to back: the median of the rounds' own ratios
  // holds up better than a ratio of medians when the machine's load swings.
  const ratios = result.cases.slice(1).map((c) => median(c.times.map((t, i) => result.cases[0].times[i] / t)));
  console.log(`   median of per-round ratios: ${ratios.map((r, k) => `${result.cases[k + 1].name} ${r.toFixed(2)}×`).join('; ')}`);
  console.log("   ('first' = the first frame, workers just started)");
  const g = result.garbage;
  if (!g?.found) console.log('   garbage collections in the workers: not measured (the trace lacks the marks)');
  else console.log(`   garbage collections in the 2 workers, ${g.frames} frames after ${g.warmup} (traced, untimed): ${(g.minor / g.frames).toFixed(1)} minor and ${(g.major / g.frames).toFixed(1)} major a frame, ${ms(g.ms / g.frames)} ms a frame (0 to 1 minor a frame: nothing allocated per pixel)`);
}

/* ---------------- 5. the 3D scene view ---------------- */

const VIEW3D_TRACES = 5, VIEW3D_TURN_MS = 4000;

/**
 * The 3D view's own cost: frames per second while turning it (class scene,
 * selected pixel, software WebGL), and the progressive trace's time with and
 * without a 3D view following it, the two kinds of page in turn.
 */
async function view3d(browser, base, errors) {
  const open = async (withView) => {
    const page = await browser.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
    watch(page, errors);
    await page.goto(`${base}${VIEW3D_PAGE}?view3d=${withView ? 1 : 0}`);
    await page.waitForFunction(() => window.bench?.ready, null, { timeout: 60_000, polling: 100 });
    return page;
  };
  const traces = { without: [], with: [] };
  for (let round = 0; round < 2; round++) {
    for (const kind of ['without', 'with']) {
      const page = await open(kind === 'with');
      traces[kind].push(...(await page.evaluate((n) => window.bench.trace(n), VIEW3D_TRACES)).slice(round === 0 ? 1 : 0));
      await page.close();
    }
  }
  const page = await open(true);
  const turn = await page.evaluate((ms) => window.bench.turn(ms), VIEW3D_TURN_MS);
  await page.close();
  return { traces, turn };
}

function reportView3d({ traces, turn }) {
  console.log(`\n5. The 3D scene view (class scene; software WebGL in headless Chromium)`);
  console.log(`   turning, a new orbit every frame for ${VIEW3D_TURN_MS / 1000} s: ${turn.fps.toFixed(1)} frames/s (goal ≥ 30), median draw ${ms(turn.drawMs)} ms of script`);
  const a = median(traces.without), b = median(traces.with);
  console.log(`   progressive trace 640×480, restart to done (median of ${traces.without.length}): without a 3D view ${ms(a)} ms, with one ${ms(b)} ms: ` +
    `${(((b - a) / a) * 100).toFixed(0)} % slower (goal ≤ 20 %)`);
}

/* ---------------- 7. the GPU engine ---------------- */

/** The class scene with full shading on the GPU and on one worker per core (bench/browser/gpu.js). */
async function gpuEngine(browser, base, errors) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  watch(page, errors);
  await page.goto(`${base}${GPU_PAGE}`);
  await page.waitForFunction(() => window.bench?.ready, null, { timeout: 60_000, polling: 100 });
  const [width, height] = GPU_SIZE;
  const result = await page.evaluate((size) => window.bench.run(size), { width, height, seconds: 10, least: 2 });
  await page.close();
  if (result.beyond2 > 0.005 * width * height) errors.push(`the GPU's frame differs from render() by more than 2 on ${result.beyond2} pixels`);
  return { ...result, width, height };
}

function reportGpu({ gpu, cpu, beyond2, renderer, width, height }) {
  console.log(`\n7. The GPU engine: the class scene with full shading at ${width}×${height} (WebGL2 renderer: ${renderer})`);
  console.log(`   GPU: ${gpu.fps.toFixed(2)} frames/s (${gpu.frames} frames, ${ms(gpu.ms)} ms each; goal on a GPU ≥ 60 at 1280×720)`);
  console.log(`   CPU, ${cpu.cores} workers (one per core): ${cpu.fps.toFixed(2)} frames/s (${cpu.frames} frames, ${ms(cpu.ms)} ms each)`);
  console.log(`   ratio GPU / CPU: ${(gpu.fps / cpu.fps).toFixed(2)}×; pixels beyond 2 per channel from render(): ${beyond2}`);
}

/* ---------------- 8. the path tracer on the GPU and the CPU ---------------- */

/** Sketch 16's Cornell box path traced on the GPU, the page's thread and the workers (bench/browser/paths.js). */
async function pathEngines(browser, base, errors) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  watch(page, errors);
  await page.goto(`${base}${PATHS_PAGE}`);
  await page.waitForFunction(() => window.bench?.ready, null, { timeout: 60_000, polling: 100 });
  const [width, height] = PATHS_SIZE;
  const result = await page.evaluate((size) => window.bench.run(size), { width, height, seconds: 10, least: 2, samples: 4 });
  await page.close();
  const { gpu, cpu } = result.means;
  if (Math.abs(gpu - cpu) > 0.02 * cpu) errors.push(`the GPU's path-traced picture's mean byte ${gpu.toFixed(2)} is not the CPU's ${cpu.toFixed(2)} within 2 %`);
  return { ...result, width, height };
}

function reportPaths({ gpu, cpu, workers, means, renderer, pixels, width, height }) {
  const line = (what, { pathsPerSecond, pictures, msPerPicture }) => console.log(`   ${what}: ${(pathsPerSecond / 1e6).toFixed(3)} M samples/s, ` +
    `${(pathsPerSecond / pixels).toFixed(2)} samples/pixel/s (${pictures} pictures of 4 samples, ${ms(msPerPicture)} ms each)`);
  console.log(`\n8. The path tracer: sketch 16's Cornell box at ${width}×${height}, up to 16 bounces (WebGL2 renderer: ${renderer})`);
  line('GPU (pathTraceGPU)', gpu);
  line("CPU, the page's thread (pathTrace)", cpu);
  line(`CPU, ${workers.cores} workers (one per core)`, workers);
  console.log(`   ratio GPU / one core: ${(gpu.pathsPerSecond / cpu.pathsPerSecond).toFixed(2)}×, GPU / ${workers.cores} workers: ` +
    `${(gpu.pathsPerSecond / workers.pathsPerSecond).toFixed(2)}×; mean byte at 16 samples: GPU ${means.gpu.toFixed(2)}, CPU ${means.cpu.toFixed(2)}`);
}

/* ---------------- main ---------------- */

const executablePath = findBrowser();
if (executablePath === null) {
  console.error(HOW_TO_GET_ONE);
  process.exit(1);
}

const errors = [];
let server = null, outDir = null, browser = null;
try {
  if (!DEV) outDir = await buildPage();
  server = await startServer(outDir);
  browser = await chromium.launch({ executablePath, headless: !HEADED, ...(HEADED && { args: ['--ignore-gpu-blocklist'] }) });
  const base = `http://localhost:${PORT}/`;
  console.log(`Browser benchmark: Chromium ${browser.version()} headless, ${DEV ? 'Vite dev server (unbundled modules)' : 'production build (vite build + vite preview)'},` +
    ` ${availableParallelism()} cores, load average ${loadavg()[0].toFixed(1)}`);
  if (!ONLY_VIEW3D) {
    if (!ONLY || ONLY === 'progressive') {
      reportProgressive(await progressive(browser, base, errors), 'on Web Workers (the default for large frames)');
      reportProgressive(await progressive(browser, base, errors, '&workers=0'), "on the page's thread alone (workers: false)");
    }
    const w = !ONLY || ONLY === 'workers' ? await workers(browser, base, errors) : { cases: [] };
    if (w.width) reportWorkers(w);
    if (w.cases.some((c) => c.differing !== 0)) errors.push('a worker picture differs from render()');
    if (!ONLY || ONLY === 'animation') reportAnimation(await animation(browser, base, errors));
    if (!ONLY || ONLY === 'saves') {
      const devServer = DEV && SAVE_PORT === PORT ? null : await startServer(null, SAVE_PORT);
      try {
        const saveBase = `http://localhost:${SAVE_PORT}/`;
        reportSaves(await saves(browser, saveBase, errors, 'swap'), await saves(browser, saveBase, errors, 'reload'));
      } finally {
        devServer?.kill(); // the dev server this script started for part 4, by its PID
      }
    }
  }
  if (!ONLY || ONLY_VIEW3D) reportView3d(await view3d(browser, base, errors));
  if (!ONLY || ONLY === 'gpu') reportGpu(await gpuEngine(browser, base, errors));
  if (!ONLY || ONLY === 'paths') reportPaths(await pathEngines(browser, base, errors));
  console.log(`\nload average at the end: ${loadavg()[0].toFixed(1)}`);
} catch (error) {
  errors.push(error.stack ?? String(error));
} finally {
  await browser?.close();
  if (server) server.kill(); // the vite process this script started, by its PID
  if (outDir) rmSync(outDir, { recursive: true, force: true });
}
if (errors.length) {
  console.error(`\nBROKEN:\n${errors.join('\n')}`);
  process.exitCode = 1;
}
