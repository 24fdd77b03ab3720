/**
 * A path-traced picture that gets better sample after sample: each pass adds
 * one more path to every pixel's sum (an accumulation buffer of floats), and
 * after each pass the picture shows the mean so far. A step() traces for a
 * time budget, a row at a time, so the page stays responsive.
 *
 * After n passes the bytes are pathTrace(scene, camera, { samples: n, … })'s:
 * each pixel's samples are summed in the same order, 0, 1, …, n − 1.
 * From the outside it is a ProgressiveRenderer (step, restart, buffer,
 * progress, done…), so a tracer view shows it (`createTracerView({ path })`).
 */
import { checkOptions, show } from '../../text/check.js';
import { checkSceneAndCamera } from '../render.js';
import { readPathOptions, preparePaths } from './path-trace.js';
import { tracePath, radiance } from './integrator.js';
import { formatRate } from '../../text/format.js';

/** What restart() may change. */
const CHANGES = ['scene', 'camera', 'path'];

export class PathProgressiveRenderer {
  #frame = null;
  #sums = null;
  /** Each pixel's sum of its samples' brightness (the mean of r, g, b) squared: the noise's other half. */
  #squares = null;
  /** The pass (sample index) being traced, and its next row. */
  #sample = 0;
  #row = 0;
  #paths = 0;
  #tracingMs = 0;

  /**
   * @param {object} options
   * @param {import('../../scene/scene.js').Scene} options.scene
   * @param {import('../../math/camera.js').Camera} options.camera
   * @param {object} options.path pathTrace's options: `{ samples, seed, maxBounces, sky, roulette, lightSampling }`
   * @param {number} [options.budgetMs=8] tracing time per step(), milliseconds
   * @param {() => number} [options.now=performance.now] the clock, in milliseconds
   * @example
   * const tracer = new PathProgressiveRenderer({ scene, camera, path: { samples: 64 } });
   * while (!tracer.done) tracer.step();
   * tracer.buffer; // the bytes of pathTrace(scene, camera, { samples: 64 })
   */
  constructor(options) {
    const { scene, camera, path, budgetMs = 8, now = () => performance.now() } = checkOptions(options, ['scene', 'camera', 'path', 'budgetMs', 'now'], 'PathProgressiveRenderer');
    if (typeof now !== 'function') throw new TypeError(`now must be a function returning milliseconds, got ${show(now)}`);
    if (!(typeof budgetMs === 'number' && budgetMs > 0 && budgetMs <= 1000)) throw new RangeError(`budgetMs must be a number of milliseconds in (0, 1000], got ${show(budgetMs)}`);
    this.now = now;
    this.budgetMs = budgetMs;
    this.buffer = null;
    /** As a ProgressiveRenderer's: the render order (a path-traced picture fills in whole passes), no pixel being traced alone, no worker problem. */
    this.order = 'coarse';
    this.current = null;
    this.problem = null;
    /** For the tracer view's engines (lib/p5/tracer/engines.js): this picture is path traced, on the CPU. */
    this.pathTraced = true;
    /** As a ProgressiveRenderer's slow motion (which a path-traced picture has not): unused. */
    this.slowRaysPerStep = 1;
    this.slowRaysPerSecond = 0;
    this.restart({ scene, camera, path });
  }

  /**
   * Starts again from the first sample with whatever changed, each change
   * checked before any is applied. `path` options are merged into the old ones.
   * @param {{ scene?, camera?, path? }} [changes]
   */
  restart(changes = {}) {
    if (changes === null || typeof changes !== 'object') throw new TypeError(`changes must be an object like { path: { maxBounces: 1 } }, got ${show(changes)}`);
    const { scene = this.scene, camera = this.camera, path = {} } = checkOptions(changes, CHANGES, 'restart (a path-traced view)');
    checkSceneAndCamera(scene, camera);
    const options = { ...this.options, ...path };
    const read = readPathOptions(options, scene, camera, 'path');
    this.scene = scene;
    this.camera = camera;
    /** The path options as given (merged over the earlier ones). */
    this.options = options;
    this.width = camera.width;
    this.height = camera.height;
    this.#frame = preparePaths(scene, camera, read);
    const pixels = this.width * this.height;
    if (this.buffer?.length === pixels * 4) this.buffer.fill(0);
    else this.buffer = new Uint8ClampedArray(pixels * 4);
    if (this.#sums?.length === pixels * 3) this.#sums.fill(0);
    else this.#sums = new Float64Array(pixels * 3);
    if (this.#squares?.length === pixels) this.#squares.fill(0);
    else this.#squares = new Float64Array(pixels);
    this.#sample = 0;
    this.#row = 0;
    this.#paths = 0;
    this.#tracingMs = 0;
    return this;
  }

  /** Paths per pixel the picture will have. */
  get samples() { return this.#frame.samples; }
  /** Samples every pixel has now (the picture shows their mean). */
  get sample() { return this.#sample; }
  get done() { return this.#sample >= this.#frame.samples; }
  get progress() { return (this.#sample * this.height + this.#row) / (this.#frame.samples * this.height); }
  /** Paths traced per second of tracing. */
  get raysPerSecond() { return this.#tracingMs > 0 ? (this.#paths * 1000) / this.#tracingMs : 0; }
  /**
   * The picture's noise so far: each pixel's standard error (the spread of its
   * samples' brightness, the mean of r, g, b, over √samples), averaged over
   * the pixels; null before two samples. Light sampling lowers it at the same
   * number of samples.
   */
  get noise() {
    const n = this.#sample, sums = this.#sums, squares = this.#squares;
    if (n < 2) return null;
    let total = 0;
    for (let p = 0, i = 0; p < squares.length; p++, i += 3) {
      const sum = (sums[i] + sums[i + 1] + sums[i + 2]) / 3, variance = Math.max(0, (squares[p] - (sum * sum) / n) / (n - 1));
      total += Math.sqrt(variance / n);
    }
    return total / squares.length;
  }

  /** The view's progress line: "Sample 37 of 256 · 1.2M paths/s". */
  get progressText() {
    return `Sample ${this.#sample} of ${this.#frame.samples} · ${formatRate(this.raysPerSecond)} paths/s`;
  }

  /**
   * Traces rows of the current pass for `budgetMs`; when a pass is complete
   * the picture shows the new mean.
   * @returns {{ changed: boolean, done: boolean }}
   */
  step(budgetMs = this.budgetMs) {
    if (this.done) return { changed: false, done: true };
    const start = this.now();
    let changed = false;
    do {
      this.#traceRow(this.#row);
      if (++this.#row === this.height) {
        this.#row = 0;
        this.#sample++;
        this.#show();
        changed = true;
        if (this.done) break;
      }
    } while (this.now() - start < budgetMs);
    this.#tracingMs += this.now() - start;
    return { changed, done: this.done };
  }

  /** Nothing runs apart from the page's thread. */
  terminate() {}

  /** One more path for every pixel of row y. */
  #traceRow(y) {
    const frame = this.#frame, sums = this.#sums, squares = this.#squares, s = this.#sample, width = this.width;
    for (let x = 0, i = y * width * 3, p = y * width; x < width; x++, i += 3, p++) {
      tracePath(frame, x, y, s);
      sums[i] += radiance[0]; sums[i + 1] += radiance[1]; sums[i + 2] += radiance[2];
      const brightness = (radiance[0] + radiance[1] + radiance[2]) / 3;
      squares[p] += brightness * brightness;
    }
    this.#paths += width;
  }

  /** The mean of the samples so far as bytes: pathTrace's arithmetic. */
  #show() {
    const sums = this.#sums, bytes = this.buffer, n = this.#sample;
    for (let p = 0, i = 0; i < sums.length; p += 4, i += 3) {
      bytes[p] = (sums[i] / n) * 255; bytes[p + 1] = (sums[i + 1] / n) * 255; bytes[p + 2] = (sums[i + 2] / n) * 255; bytes[p + 3] = 255;
    }
  }
}
