/**
 * Progressive rendering that hands the bulk of a large frame to Web Workers.
 * The page's own thread traces the coarse passes (blocks of 16, then 8 px: a
 * preview at once, 1/64 of the pixels), while the workers render the whole
 * frame at full resolution; their rows replace the blocks as they arrive.
 * The finished buffer is render()'s, byte for byte, as a ProgressiveRenderer's.
 *
 * It is a ProgressiveRenderer from the outside (same options, step, restart,
 * buffer, progress…), and it is one on the inside when workers would not help:
 * a small frame, a visual mode other than the shaded picture, the scanline and
 * slow orders, a scene that cannot travel as JSON, no Web Workers, or workers
 * that failed (then the main thread finishes the frame itself, time-sliced).
 */
import { ProgressiveRenderer } from '../frames.js';
import { renderPixel } from '../render.js';
import { ParallelRenderer } from './parallel.js';
import { show, positiveInteger } from '../../text/check.js';

/** Frames from this many pixels up go to the workers (640×480 does; 320×240 traces in a few frames here). */
export const MIN_PIXELS = 100_000;
/** The main thread traces the coarse passes down to blocks of this size, then leaves the rest to the workers. */
export const MAIN_PASSES_DOWN_TO = 8;
/** Milliseconds a step spends on those passes at most: 640×480's 16 and 8 px passes take about 1. */
export const MAIN_BUDGET_MS = 2;

export class WorkerProgressiveRenderer {
  #inner;
  #workers;
  #createWorker;
  #minPixels;
  #parallel = null;
  /** Bumped by every restart: answers for an older frame are dropped. */
  #generation = 0;
  /** This frame goes to the workers; a job is posted; a newer frame waits for it to end. */
  #useWorkers = false;
  #inFlight = false;
  #waiting = false;
  /** This frame went out to the workers: at its first step, not before, so a renderer thrown away unused (a view that starts on the GPU) starts no worker. */
  #posted = false;
  /** Bands [y0, y1) that arrived since the last step, in #frame, the workers' frame so far; rows shown. */
  #arrived = [];
  #frame = null;
  #rowsShown = 0;
  /** The workers have finished the frame; step() has shown it whole. */
  #finished = false;
  #complete = false;
  #startedAt = 0;
  #endedAt = 0;

  /**
   * @param {object} options a ProgressiveRenderer's:
   * @param {import('../../scene/scene.js').Scene} options.scene
   * @param {import('../../math/camera.js').Camera} options.camera
   * @param {'coarse'|'scanline'|'slow'} [options.order='coarse'] (or `mode`, its older name)
   * @param {number} [options.budgetMs=8] tracing time per step(), milliseconds
   * @param {Function} [options.shader=renderPixel] writes one pixel (see ProgressiveRenderer)
   * @param {number} [options.slowRaysPerStep=1] pixels per step() in 'slow' mode
   * @param {() => number} [options.now=performance.now] the clock, in milliseconds
   *   and its own:
   * @param {'auto'|number|false} [options.workers='auto'] how many workers large frames use ('auto': one per core; false: none)
   * @param {number} [options.minPixels=MIN_PIXELS] frames from this many pixels up go to the workers
   * @param {() => Worker} [options.createWorker] starts one worker (tests pass a stand-in)
   */
  constructor({ workers = 'auto', minPixels = MIN_PIXELS, createWorker, ...options } = /** @type {any} */ ({})) {
    if (workers !== 'auto' && workers !== false && !(Number.isInteger(workers) && workers > 0)) {
      throw new RangeError(`workers must be 'auto', false or a positive whole number, got ${show(workers)}`);
    }
    this.#workers = workers === 'auto' ? globalThis.navigator?.hardwareConcurrency || 2 : workers;
    this.#createWorker = createWorker;
    this.#minPixels = positiveInteger(minPixels, 'minPixels');
    this.#inner = new ProgressiveRenderer(options);
    /** Why the workers were given up on (the frames are then traced here), or null. */
    this.problem = null;
    this.#begin();
  }

  /** Starts again from the first pass with whatever changed (see ProgressiveRenderer.restart). */
  restart(changes) {
    this.#inner.restart(changes); // checks everything before changing anything
    this.#begin();
    return this;
  }

  /**
   * One slice of work. On the workers' path: the coarse passes here (at most
   * MAIN_BUDGET_MS of them a step, the workers need the cores more) until the
   * workers' first rows are in, then nothing but showing the rows that
   * arrived since the last step, and at last the whole frame.
   * @returns {{ changed: boolean, done: boolean }}
   */
  step(budgetMs) {
    if (!this.#useWorkers) return this.#inner.step(budgetMs);
    if (!this.#posted) {
      this.#posted = true;
      this.#post();
    }
    const inner = this.#inner;
    if (this.#complete) return { changed: false, done: true };
    if (this.#finished) {
      inner.buffer.set(this.#frame); // the workers' frame, whole: render()'s bytes
      this.#complete = true;
      this.#endedAt = inner.now();
      return { changed: true, done: true };
    }
    let changed = false;
    if (this.#rowsShown === 0 && inner.blockSize >= MAIN_PASSES_DOWN_TO && !inner.done) {
      inner.step(Math.min(budgetMs ?? inner.budgetMs, MAIN_BUDGET_MS));
      changed = true;
    }
    // Rows that arrived go over the coarse blocks; the blocks are never painted over them again.
    const rowBytes = inner.width * 4;
    for (const [y0, y1] of this.#arrived) {
      inner.buffer.set(this.#frame.subarray(y0 * rowBytes, y1 * rowBytes), y0 * rowBytes);
      this.#rowsShown += y1 - y0;
      changed = true;
    }
    this.#arrived = [];
    return { changed, done: false };
  }

  /** Stops the workers (the view is gone). */
  terminate() {
    this.#parallel?.terminate();
    this.#parallel = null;
  }

  /** True when this frame is (or was) rendered by workers. */
  get usingWorkers() { return this.#useWorkers; }
  get done() { return this.#useWorkers ? this.#complete : this.#inner.done; }
  get traced() {
    if (!this.#useWorkers) return this.#inner.traced;
    return this.#complete ? this.width * this.height : Math.min(this.width * this.height - 1, this.#inner.traced + this.#rowsShown * this.width);
  }
  get progress() { return this.traced / (this.width * this.height); }
  get raysPerSecond() {
    if (!this.#useWorkers) return this.#inner.raysPerSecond;
    const ms = (this.#complete ? this.#endedAt : this.#inner.now()) - this.#startedAt;
    return ms > 0 ? (this.traced * 1000) / ms : 0;
  }
  /** As ProgressiveRenderer's: the coarse block size, 1 once the workers' rows show. */
  get blockSize() {
    if (!this.#useWorkers) return this.#inner.blockSize;
    return this.#complete || this.#rowsShown > 0 ? 1 : this.#inner.blockSize;
  }
  /** As ProgressiveRenderer's: the row being traced on this thread (height when done). */
  get row() { return this.done ? this.height : this.#inner.row; }
  /** @deprecated `blockSize` in the 'coarse' order, `row` in the others. */
  get pass() { return this.order === 'coarse' ? this.blockSize : this.row; }
  get current() { return this.#inner.current; }
  get buffer() { return this.#inner.buffer; }
  get scene() { return this.#inner.scene; }
  get camera() { return this.#inner.camera; }
  get order() { return this.#inner.order; }
  /** The render order's older name. */
  get mode() { return this.order; }
  get shader() { return this.#inner.shader; }
  get width() { return this.#inner.width; }
  get height() { return this.#inner.height; }
  get budgetMs() { return this.#inner.budgetMs; }
  set budgetMs(ms) { this.#inner.budgetMs = ms; }
  get slowRaysPerStep() { return this.#inner.slowRaysPerStep; }
  set slowRaysPerStep(n) { this.#inner.slowRaysPerStep = n; }
  get slowRaysPerSecond() { return this.#inner.slowRaysPerSecond; }
  set slowRaysPerSecond(n) { this.#inner.slowRaysPerSecond = n; }

  /* ---------------- the workers' side ---------------- */

  /** A new frame: to the workers if they help, else the inner renderer alone. */
  #begin() {
    this.#generation++;
    this.#arrived = [];
    this.#frame = null;
    this.#rowsShown = 0;
    this.#finished = false;
    this.#complete = false;
    this.#startedAt = this.#inner.now();
    this.#useWorkers = this.#helps();
    this.#posted = false; // posted at the next step
  }

  /** Would workers help with this frame? */
  #helps() {
    const inner = this.#inner;
    return this.#workers !== false && this.problem === null
      && (this.#createWorker !== undefined || ParallelRenderer.available)
      && inner.order === 'coarse' && inner.shader === renderPixel
      && inner.width * inner.height >= this.#minPixels;
  }

  /** Posts the current frame to the workers, or, while they are busy with an older one, once they are done. */
  #post() {
    if (this.#inFlight) {
      this.#waiting = true;
      return;
    }
    this.#parallel ??= new ParallelRenderer({ workers: /** @type {number} */ (this.#workers), fallback: false, createWorker: this.#createWorker }).warm();
    const generation = this.#generation;
    const current = () => generation === this.#generation;
    this.#inFlight = true;
    this.#parallel.render(this.#inner.scene, this.#inner.camera, {
      onRows: (y0, y1, frame) => {
        if (!current()) return;
        this.#frame = frame;
        this.#arrived.push([y0, y1]);
      },
    }).then((frame) => {
      if (!current()) return;
      this.#frame = frame;
      this.#finished = true;
    }, () => {
      // No workers for this frame after all (a failed worker, or a scene that cannot travel as
      // JSON): the inner renderer, paused at its coarse passes, traces the rest here.
      if (this.#parallel?.problem) this.problem = this.#parallel.problem;
      if (current()) this.#useWorkers = false;
    }).finally(() => {
      this.#inFlight = false;
      if (this.#waiting) {
        this.#waiting = false;
        if (this.#useWorkers) this.#post();
      }
    });
  }
}
