/**
 * The renderer's benchmark: `npm run bench`.
 *
 * The class's example scene (classScene(): 640×480, fov 30, eye at the origin)
 * rendered on one thread, two ways, frame for frame side by side:
 *   (a) the original library's work per pixel: nearest hit, one shadow ray per
 *       light, Lambert (diffuse only, no ambient, no mirrors or glass);
 *   (b) full shading: mirrors, glass with Fresnel, specular, maxDepth 5.
 * Then the same at 160×120, a teaching resolution; the 640×480 frame of (a)
 * traced by a ProgressiveRenderer in 8 ms steps until done, beside render();
 * the heap before and after ten frames (per-pixel work should allocate
 * nothing); and bench/reference.c, the work of (a) in C, compiled with
 * `cc -O3 -march=native` when a compiler is present (else it says skipped),
 * timed alternately with render() and compared byte for byte: it prints both
 * and the ratio (today's figures: docs/performance.md).
 *
 * Performance (Node 20, 2 cores, medians; five runs over one afternoon with
 * load averages of 2–4 from the machine's neighbours). The machine itself
 * runs in two speeds, about 1.7× apart, from run to run and sometimes within
 * one run: a flat, hand-inlined Float64Array version of (a) timed beside
 * render() in one process took 35 or 62 ms and render() 51 or 87 ms, always
 * flipping together, with no V8 deoptimisation in the trace. So compare code
 * side by side in one process (ratios), never one run against another:
 *   (a) 640×480  59–102 ms/frame  5.2–3.0 Mpx/s  (fastest frame 55 ms, 5.6)
 *       160×120  3.8–6.3 ms       5.1–3.0 Mpx/s
 *   (b) 640×480  444–731 ms/frame 0.69–0.42 Mpx/s; 160×120 26–45 ms
 *   ratio (a)/(b) 0.13–0.16 (full shading costs 6–7.5×: mirrors and glass
 *   recurse up to maxDepth 5)
 *   heap across 10 frames of (a): +2.5 MB, 1 collection (boxed numbers gone);
 *   (b): 7 collections (mirrorAndGlass still passes bare numbers around).
 *   render() traces by 16×16 tiles, each primary ray against the shapes its
 *   tile can show (lib/bounds.js): 7.8 sphere tests a pixel, down from 12.8;
 *   1.15–1.3× faster side by side. The 8 Mpx/s goal for (a) is not reached:
 *   the time is spread over shading (lights, shadow rays, normals) rather
 *   than one hot spot; a flat Float64Array sphere test measured only 1.3×
 *   faster than Sphere.hit, and a last-blocker cache for shadow rays saved
 *   no tests on this scene. Culling shadow rays per tile (a first look at
 *   the tile's hit points, then per light only the shapes within a capsule
 *   from those points to the light) cut sphere tests from 7.8 to 4.4 a
 *   pixel with the same bytes, yet measured 0.84–1.02× side by side: the
 *   tests are cheap next to the rest of a pixel's work, so it was left out.
 *   Even the flat version above reaches only 8.1 Mpx/s in the fast mode.
 *   lightPoint skipping lights behind the surface and returning from a
 *   shadow ray at its first opaque blocker: 1.03–1.16× (median 1.07×).
 *   Progressive, the frame of (a) in 8 ms steps (seven runs, load 4–12, CPU
 *   time, which stays steadier than the wall clock on a busy machine):
 *   coarse 1.04–1.20× render()'s time, scanline 1.05–1.14× (one 0.83×),
 *   slow 0.97–1.14×; in a quiet moment 1.08 / 1.00 / 1.01× by the wall
 *   clock. It took 1.29–1.54×, 1.23–1.63× and 1.18–1.37× before it tested
 *   each primary ray against its tile's shapes only, as render() does, traced
 *   a row's run of pixels per loop and read the clock a few dozen times a
 *   step rather than every 16 pixels. Coarse stays the dearest: each pass
 *   also paints its blocks, about 3.25 pixel writes per pixel.
 *
 * Timing figures are printed, never asserted: they depend on the machine.
 * Before timing, the script checks that inspectPixel's colour equals render's
 * pixel for every pixel of a 64×48 class scene, both ways (exit code 1 if not).
 */
import { performance, PerformanceObserver } from 'node:perf_hooks';
import { loadavg, availableParallelism, tmpdir } from 'node:os';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { Camera, classScene, render, inspectPixel } from '../lib/index.js';
import { ProgressiveRenderer } from '../lib/progressive.js';

const FRAMES = 15;
const WARMUP = 5;

/** Median of a list of numbers. */
function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/**
 * Times `frames` frames of each case, alternating between them so that both
 * see the same machine state; returns the milliseconds of every frame per case,
 * by the wall clock and in CPU time (the steadier one on a busy machine).
 */
function timeSideBySide(cases, frames) {
  for (const c of cases) for (let i = 0; i < WARMUP; i++) c.run();
  const times = cases.map(() => ({ wall: [], cpu: [] }));
  for (let i = 0; i < frames; i++) {
    cases.forEach((c, k) => {
      const cpu = process.cpuUsage(), start = performance.now();
      c.run();
      times[k].wall.push(performance.now() - start);
      const used = process.cpuUsage(cpu);
      times[k].cpu.push((used.user + used.system) / 1000);
    });
  }
  return times;
}

function makeCase(label, full, width, height) {
  const camera = new Camera({ width, height, fov: 30, position: [0, 0, 0] });
  const c = { label, scene: classScene({ full }), camera, target: new Uint8ClampedArray(width * height * 4) };
  c.run = () => render(c.scene, c.camera, c.target);
  return c;
}

/** A whole frame of `c`'s, traced by a ProgressiveRenderer in `mode`, 8 ms steps until done (as a tracer view would, minus the waits). */
function progressiveCase(c, mode) {
  const renderer = new ProgressiveRenderer({ scene: c.scene, camera: c.camera, mode, slowRaysPerStep: 4096 });
  const run = () => {
    renderer.restart();
    while (!renderer.step(8).done);
  };
  return { ...c, label: `    progressive, ${mode}`, run };
}

/** Every pixel of a 64×48 frame: the inspector's colour must be render's pixel. */
function inspectorMatchesRender() {
  let mismatches = 0;
  for (const full of [false, true]) {
    const scene = classScene({ full });
    const camera = new Camera({ width: 64, height: 48, fov: 30 });
    const pixels = render(scene, camera);
    for (let y = 0; y < camera.height; y++) {
      for (let x = 0; x < camera.width; x++) {
        const { color } = inspectPixel(scene, camera, x, y);
        const i = (y * camera.width + x) * 4;
        if (color[0] !== pixels[i] || color[1] !== pixels[i + 1] || color[2] !== pixels[i + 2]) mismatches++;
      }
    }
  }
  return mismatches;
}

/**
 * Heap before and after `frames` frames, and how many garbage collections ran
 * meanwhile (each young-generation collection means about 1 MB was allocated).
 */
async function heapAcross(c, frames) {
  let collections = 0;
  const observer = new PerformanceObserver((list) => { collections += list.getEntries().length; });
  observer.observe({ entryTypes: ['gc'] });
  globalThis.gc?.();
  const before = process.memoryUsage().heapUsed;
  let after = before;
  for (let i = 0; i < frames; i++) {
    c.run();
    after = process.memoryUsage().heapUsed;
    await new Promise((resolve) => setImmediate(resolve)); // GC entries arrive on a later tick
  }
  observer.disconnect();
  return { before, after, collections };
}

function row(cells, widths) {
  return cells.map((cell, i) => (i === 0 ? String(cell).padEnd(widths[i]) : String(cell).padStart(widths[i]))).join('  ');
}

const WIDTHS = [32, 11, 8, 10, 8, 9, 9];

function header() {
  console.log(row(['case', 'median ms', 'Mpx/s', 'CPU ms', 'Mpx/s', 'min ms', 'max ms'], WIDTHS));
  console.log(row(['', '(wall)', '(wall)', '(median)', '(CPU)', '(wall)', '(wall)'], WIDTHS));
  console.log('-'.repeat(WIDTHS.reduce((a, b) => a + b + 2, -2)));
}

/** Prints one line per case; returns the median wall-clock ms of each. */
function report(cases, times) {
  return cases.map((c, k) => {
    const { wall, cpu } = times[k];
    const ms = median(wall), cpuMs = median(cpu);
    const pixels = c.camera.width * c.camera.height;
    console.log(row([c.label, ms.toFixed(2), (pixels / (ms * 1000)).toFixed(2), cpuMs.toFixed(2),
      (pixels / (cpuMs * 1000)).toFixed(2), Math.min(...wall).toFixed(2), Math.max(...wall).toFixed(2)], WIDTHS));
    return ms;
  });
}

const mismatches = inspectorMatchesRender();
console.log(`inspectPixel vs render, 64×48, both scenes: ${mismatches === 0 ? 'identical' : `${mismatches} pixels differ`}`);
if (mismatches) process.exitCode = 1;
console.log(`Node ${process.version}, one thread, ${FRAMES} frames per case (${FRAMES * 4} at 160×120) after ${WARMUP} warm-up frames,` +
  ` load average ${loadavg()[0].toFixed(1)} on ${availableParallelism()} cores\n`);

const large = [makeCase('(a) Lambert + shadows, 640×480', false, 640, 480), makeCase('(b) full shading, 640×480', true, 640, 480)];
const small = [makeCase('(a) Lambert + shadows, 160×120', false, 160, 120), makeCase('(b) full shading, 160×120', true, 160, 120)];
header();
const [a, b] = report(large, timeSideBySide(large, FRAMES));
const [as, bs] = report(small, timeSideBySide(small, FRAMES * 4));
console.log(`\nratio (a)/(b) of median times: ${(a / b).toFixed(2)} at 640×480, ${(as / bs).toFixed(2)} at 160×120` +
  ` (full shading costs ${(b / a).toFixed(1)}× and ${(bs / as).toFixed(1)}×)`);

const progressive = [large[0], ...['coarse', 'scanline', 'slow'].map((mode) => progressiveCase(large[0], mode))];
console.log(`\nThe same frame of (a) traced progressively (ProgressiveRenderer, 8 ms steps until done) beside render():`);
header();
const progressiveTimes = timeSideBySide(progressive, FRAMES);
const [byRender, ...byMode] = report(progressive, progressiveTimes);
const cpu = progressiveTimes.map((t) => median(t.cpu));
console.log(`progressive over render(), median wall / CPU time: ${byMode.map((ms, k) => `${['coarse', 'scanline', 'slow'][k]} ${(ms / byRender).toFixed(2)}× / ${(cpu[k + 1] / cpu[0]).toFixed(2)}×`).join(', ')}`);

const mb = (bytes) => `${(bytes / 1048576).toFixed(2)} MB`;
for (const c of large) {
  const { before, after, collections } = await heapAcross(c, 10);
  console.log(`heap, 10 frames of ${c.label}: ${mb(before)} before, ${mb(after)} after, ${collections} collections` +
    `${globalThis.gc ? '' : ' (run with node --expose-gc for a clean "before")'}`);
}

/* ---------------- the C reference ---------------- */

/**
 * Compiles bench/reference.c (the same work as (a): the class scene, 640×480,
 * nearest hit, one shadow ray per light, Lambert) with `cc -O3 -march=native`
 * (plain -O3 where the compiler refuses -march=native); null when there is no
 * C compiler.
 */
function compileReference(dir) {
  const source = join(import.meta.dirname, 'reference.c'), binary = join(dir, 'reference');
  for (const flags of [['-O3', '-march=native'], ['-O3']]) {
    const cc = spawnSync(process.env.CC ?? 'cc', [...flags, '-o', binary, source, '-lm'], { encoding: 'utf8' });
    if (cc.error) return null; // no compiler at all
    if (cc.status === 0) return { binary, flags: flags.join(' ') };
  }
  return null;
}

/** Runs the reference for `frames` frames; returns each frame's milliseconds (its own clock). */
function runReference(binary, frames, out) {
  const run = spawnSync(binary, [String(frames), ...(out ? [out] : [])], { encoding: 'utf8' });
  if (run.status !== 0) throw new Error(`${binary} failed: ${run.stderr || run.status}`);
  return run.stdout.trim().split('\n').map(Number);
}

const ROUNDS = 9, PER_ROUND = 3;
const dir = mkdtempSync(join(tmpdir(), 'rt-bench-c-'));
try {
  const reference = compileReference(dir);
  if (!reference) {
    console.log('\nC reference: skipped (no C compiler: install one, e.g. `sudo apt-get install -y gcc`, or set CC)');
  } else {
    const c = large[0], out = join(dir, 'frame.rgba');
    runReference(reference.binary, 1, out);
    const cFrame = readFileSync(out), jsFrame = render(c.scene, c.camera);
    let differ = 0;
    for (let i = 0; i < jsFrame.length; i++) if (jsFrame[i] !== cFrame[i]) differ++;
    // Alternately: a few frames of C, then as many of render(), round after round, so
    // that both see the machine's same moments; the ratio is taken within each round.
    const cTimes = [], jsTimes = [], ratios = [];
    for (let i = 0; i < WARMUP; i++) c.run();
    for (let round = 0; round < ROUNDS; round++) {
      const cRound = runReference(reference.binary, PER_ROUND);
      const jsRound = [];
      for (let i = 0; i < PER_ROUND; i++) {
        const start = performance.now();
        c.run();
        jsRound.push(performance.now() - start);
      }
      cTimes.push(...cRound);
      jsTimes.push(...jsRound);
      ratios.push(median(jsRound) / median(cRound));
    }
    console.log(`\nC reference (bench/reference.c, cc ${reference.flags}, one thread), the frame of (a), ${ROUNDS} rounds of ${PER_ROUND} frames each way, alternating:`);
    console.log(`  bytes: ${differ === 0 ? 'identical to render()' : `${differ} bytes differ from render()`}`);
    console.log(`  C ${median(cTimes).toFixed(2)} ms/frame (min ${Math.min(...cTimes).toFixed(2)}), render() ${median(jsTimes).toFixed(2)} ms/frame (min ${Math.min(...jsTimes).toFixed(2)})`);
    console.log(`  render() / C: ${median(ratios).toFixed(2)}× (median of the rounds' ratios; ${(median(jsTimes) / median(cTimes)).toFixed(2)}× of the medians; goal 2.0×)`);
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
