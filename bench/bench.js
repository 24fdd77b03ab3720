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
 * and the ratio (today's figures: docs/performance.md). Then bench/bvh.js:
 * the mesh BVH's per-ray cost at 1k and 100k triangles, and a frame of the bunny; then
 * bench/scrub.js: a scrubbed number's first coarse picture of the class scene; then
 * bench/paths.js: path tracing's samples per second per core at 320×240, and bytes per sample;
 * and last bench/paired.js: render() of an older commit against the work tree's.
 *
 * Today's figures, the conditions they were taken in (load average), and
 * what was tried and measured on the way (tiles, culling shadow rays, Math.pow)
 * are in docs/performance.md. The machine's speed moves from moment to
 * moment, so this script times what it compares in turns, in one run, and
 * reports medians and ratios: compare ratios across runs, never one run's
 * milliseconds with another's.
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
import { ProgressiveRenderer } from '../lib/tracing/frames.js';

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
  c.run = () => render(c.scene, c.camera, c.target, undefined, { blocking: true }); // whole frames on purpose: a benchmark, not a page
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
const startLoad = loadavg()[0];
console.log(`Node ${process.version}, one thread, ${FRAMES} frames per case (${FRAMES * 4} at 160×120) after ${WARMUP} warm-up frames,` +
  ` load average ${startLoad.toFixed(1)} on ${availableParallelism()} cores\n`);

const large = [makeCase('(a) Lambert + shadows, 640×480', false, 640, 480), makeCase('(b) full shading, 640×480', true, 640, 480)];
const small = [makeCase('(a) Lambert + shadows, 160×120', false, 160, 120), makeCase('(b) full shading, 160×120', true, 160, 120)];
header();
const [a, b] = report(large, timeSideBySide(large, FRAMES));
const [as, bs] = report(small, timeSideBySide(small, FRAMES * 4));
console.log(`\nratio (a)/(b) of median times: ${(a / b).toFixed(2)} at 640×480, ${(as / bs).toFixed(2)} at 160×120` +
  ` (full shading costs ${(b / a).toFixed(1)}× and ${(bs / as).toFixed(1)}×)`);
console.log(`full shading at 640×480: ${(640 * 480 / (b * 1000)).toFixed(2)} Mpx/s by the wall clock (goal 2)`);

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
    const cFrame = readFileSync(out), jsFrame = render(c.scene, c.camera, undefined, undefined, { blocking: true });
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
// The machine's neighbours come and go: the load at both ends says how quiet the run was.
console.log(`\nload average ${startLoad.toFixed(1)} at the start, ${loadavg()[0].toFixed(1)} at the end (1 minute, ${availableParallelism()} cores)`);

// Meshes: the BVH's scaling (1k vs 100k triangles) and a frame of the bunny (bench/bvh.js).
const { runBvhBench } = await import('./bvh.js');
runBvhBench();

// A scrubbed number's first coarse picture (bench/scrub.js).
const { runScrubBench } = await import('./scrub.js');
runScrubBench();

// Path tracing: samples per second per core at 320×240 and the heap per sample (bench/paths.js).
const { runPathBench } = await import('./paths.js');
runPathBench();

// render() of an older commit (9e9a563, or BENCH_OLD) against the work tree's, in one process, in turns (bench/paired.js).
const { runPairedBench } = await import('./paired.js');
await runPairedBench();
