/**
 * A frame traced a little at a time, so a sketch's draw() stays smooth while
 * the picture builds up. Three orders of work:
 *   'coarse'   blocks of 16, 8, 4, 2, then 1 px: a rough picture at once, then
 *              sharper; each pass traces only pixels no earlier pass traced;
 *   'scanline' row by row, left to right, the way Appel described it;
 *   'slow'     scanline order, a fixed number of rays per step, so a diagram
 *              can follow the current ray.
 * Every pixel is traced exactly once, by the same shader as `render`, so the
 * finished buffer is byte for byte `render(scene, camera)`'s; with that
 * default shader, each primary ray is tested only against its tile's
 * candidate shapes, as `render` does (lib/tracing/bounds.js).
 */
import { renderPixel, renderPackedPixel, prepareFrame } from './render.js';
import { TILE } from './bounds.js';
import { checkScene, checkCamera } from '../scene/check.js';
import { positiveInteger, finiteNumber, show, checkOptions } from '../text/check.js';

/** The render orders a ProgressiveRenderer knows. */
export const ORDERS = ['coarse', 'scanline', 'slow'];

/** Block sizes of the coarse passes, largest first. */
export const COARSE_PASSES = [16, 8, 4, 2, 1];
const FULL_RESOLUTION = [1];

/** The options a ProgressiveRenderer takes, and the changes restart() takes. */
const OPTIONS = ['scene', 'camera', 'order', 'mode', 'budgetMs', 'shader', 'slowRaysPerStep', 'now'];
const CHANGES = ['scene', 'camera', 'order', 'mode', 'shader', 'slowRaysPerStep'];

/**
 * Pixels traced before the first look at the clock in a step, and at least
 * between two looks: reading it costs more than a cheap pixel (about 1 µs in
 * Chromium, whose clock moves only every 100 µs or so anyway).
 */
export const CHECK_EVERY = 16;

/**
 * A run of at least this many milliseconds tells the render's dearest pace
 * (ms a pixel); a shorter one is too near the clock's own steps to tell it.
 */
const PACE_RUN_MS = 0.5;

export class ProgressiveRenderer {
  #passes = COARSE_PASSES;
  #passIndex = 0;
  /** The pass's block size, and the step from one traced pixel of the row to the next. */
  #size = 1;
  #stride = 1;
  /** The next pixel to trace, and the one traced last. */
  #x = 0;
  #y = 0;
  #lastX = 0;
  #lastY = 0;
  /** The buffer as one 32-bit word per pixel: a coarse block is painted a word, not four bytes, at a time (the bytes move together, whatever the byte order). */
  #words = null;
  #traced = 0;
  #tracingMs = 0;
  #done = false;
  /** The default shader's per-tile candidate shapes, `{ columns, lists }`; null for another shader. */
  #tiles = null;
  /** 'slow' mode at `slowRaysPerSecond`: rays owed (fractional) and when the last step ran. */
  #credit = 0;
  #lastStepAt = null;
  #raysPerSecond = 0;
  /** The dearest pace a run of this render has had, ms a pixel (0: none measured yet). */
  #dearest = 0;

  /**
   * @param {object} options
   * @param {import('../scene/scene.js').Scene} options.scene
   * @param {import('../math/camera.js').Camera} options.camera
   * @param {'coarse'|'scanline'|'slow'} [options.order='coarse'] the order the pixels are traced in
   * @param {'coarse'|'scanline'|'slow'} [options.mode] the order's older name
   * @param {number} [options.budgetMs=8] tracing time per step(), milliseconds
   * @param {Function} [options.shader=renderPixel] `(scene, camera, x, y, targetRGBA)`, writes pixel (x, y) at `(y·width + x)·4`
   * @param {number} [options.slowRaysPerStep=1] pixels per step() in 'slow' mode
   * @param {() => number} [options.now=performance.now] the clock, in milliseconds
   * @example
   * const tracer = new ProgressiveRenderer({ scene: classScene(), camera: new Camera({ width: 64, height: 48 }) });
   * tracer.step();             // about 8 ms of tracing: coarse blocks first
   * while (!tracer.done) tracer.step();
   * tracer.buffer;             // RGBA, the same bytes as render()
   */
  constructor(options) { // no options: checkOptions gives {}, and the first required field says it is missing
    const { scene, camera, order, mode, budgetMs = 8, shader = renderPixel, slowRaysPerStep = 1, now = () => performance.now() } = checkOptions(options, OPTIONS, 'ProgressiveRenderer');
    if (typeof now !== 'function') throw new TypeError(`now must be a function returning milliseconds, got ${show(now)}`);
    this.now = now;
    this.budgetMs = budget(budgetMs, 'budgetMs');
    /** Primary rays traced by each step() in 'slow' mode. */
    this.slowRaysPerStep = positiveInteger(slowRaysPerStep, 'slowRaysPerStep');
    /** The traced image, RGBA, width·height·4 bytes; a new array when the camera's size changes. */
    this.buffer = null;
    this.slowRaysPerSecond = 0;
    /** In 'slow' and 'scanline' modes the pixel `{ x, y }` traced last, else null. */
    this.current = null;
    this.restart({ scene, camera, order: orderOf({ order, mode }) ?? 'coarse', shader });
  }

  /** The render order's older name (`order`). */
  get mode() { return this.order; }

  /**
   * Starts again from the first pass, with whatever changed. Every change is
   * checked before any is applied, so a bad value leaves the render as it was.
   * @param {object} [changes] `{ scene?, camera?, order? (or mode, its older name), shader?, slowRaysPerStep? }`
   */
  restart(changes = {}) {
    if (changes === null || typeof changes !== 'object') throw new TypeError(`changes must be an object like { camera }, got ${show(changes)}`);
    changes = checkOptions(changes, CHANGES, 'restart');
    const scene = changes.scene ?? this.scene;
    const camera = changes.camera ?? this.camera;
    const order = orderOf(changes) ?? this.order;
    const shader = changes.shader ?? this.shader;
    if (!scene || !Array.isArray(scene.objects)) throw new TypeError(`scene must be a Scene, got ${show(scene)}`);
    if (!camera || typeof camera.directionAt !== 'function') throw new TypeError(`camera must be a Camera, got ${show(camera)}`);
    if (typeof shader !== 'function') throw new TypeError(`shader must be a function (scene, camera, x, y, target), got ${show(shader)}`);
    checkCamera(camera); // as they are now: either may have been changed in place since
    checkScene(scene);
    if (changes.slowRaysPerStep !== undefined) this.slowRaysPerStep = positiveInteger(changes.slowRaysPerStep, 'slowRaysPerStep');

    this.scene = scene;
    this.camera = camera;
    /** The order the pixels are traced in: 'coarse', 'scanline' or 'slow'. */
    this.order = order;
    this.shader = shader;
    this.width = camera.width;
    this.height = camera.height;
    const size = this.width * this.height * 4;
    if (this.buffer?.length === size) this.buffer.fill(0); // alpha 0: not traced yet
    else {
      this.buffer = new Uint8ClampedArray(size);
      this.#words = new Uint32Array(this.buffer.buffer);
    }
    this.#tiles = shader === renderPixel ? prepareFrame(scene, camera) : null; // also packs the scene for the fast path

    this.#passes = order === 'coarse' ? COARSE_PASSES : FULL_RESOLUTION;
    this.#passIndex = 0;
    this.#size = this.#passes[0];
    this.#y = 0;
    this.#startRow();
    this.#traced = 0;
    this.#tracingMs = 0;
    this.#done = false;
    this.#credit = 0;
    this.#lastStepAt = null;
    this.#dearest = 0;
    this.current = null;
    this.#nextRow(); // a row with nothing to trace (1 px wide, later passes): on to one with something
    return this;
  }

  /**
   * Traces until `budgetMs` is spent (see #traceFor: a step may run over by
   * a few pixels and always makes progress); in 'slow' mode traces exactly
   * `slowRaysPerStep` pixels whatever the budget.
   * @param {number} [budgetMs=this.budgetMs]
   * @returns {{ changed: boolean, done: boolean }} changed: some pixel was traced
   */
  step(budgetMs = this.budgetMs) {
    budget(budgetMs, 'budgetMs');
    if (this.#done) return { changed: false, done: true };
    const start = this.now();
    const count = this.order === 'slow' ? this.#traceRun(this.#slowCount(start)) : this.#traceFor(budgetMs, start);
    if (count === 0) return { changed: false, done: false };
    this.#tracingMs += this.now() - start;
    this.#traced += count;
    if (this.order !== 'coarse') this.current = { x: this.#lastX, y: this.#lastY };
    return { changed: true, done: this.#done };
  }

  /** Pixels due in a 'slow' step: `slowRaysPerStep`, or the rays per second owed since the last step. */
  #slowCount(now) {
    if (!(this.slowRaysPerSecond > 0)) return this.slowRaysPerStep;
    const elapsed = this.#lastStepAt === null ? 1000 / this.slowRaysPerSecond : now - this.#lastStepAt;
    this.#lastStepAt = now;
    this.#credit = Math.min(this.#credit + (elapsed * this.slowRaysPerSecond) / 1000, Math.max(1, this.slowRaysPerSecond / 10));
    const count = Math.floor(this.#credit);
    this.#credit -= count;
    return count;
  }

  /**
   * In 'slow' mode, when above 0: rays per second instead of
   * `slowRaysPerStep` per step (slower than one a frame, for rays a class
   * can follow with its eyes). A finite number ≥ 0, else a Type/RangeError:
   * Infinity would owe Infinity × 0 = NaN rays and trace nothing.
   */
  get slowRaysPerSecond() { return this.#raysPerSecond; }
  set slowRaysPerSecond(n) {
    finiteNumber(n, 'slowRaysPerSecond');
    if (n < 0) throw new RangeError(`slowRaysPerSecond must not be negative, got ${n}`);
    this.#raysPerSecond = n;
  }

  /** True once every pixel is traced. */
  get done() {
    return this.#done;
  }

  /** Pixels traced so far: each pixel is traced once, whatever the pass. */
  get traced() {
    return this.#traced;
  }

  /**
   * Share of the work done, 0–1: pixels traced / (width·height). A coarse
   * pass of blocks of s px traces about 1/s² of the pixels, so the 16 px
   * preview is honest about being under 1 % of the picture.
   */
  get progress() {
    return this.#traced / (this.width * this.height);
  }

  /** Primary rays per second of time spent inside step() since the last restart (0 before any). */
  get raysPerSecond() {
    return this.#tracingMs > 0 ? (this.#traced * 1000) / this.#tracingMs : 0;
  }

  /** The block size of the coarse pass under way: 16, 8, 4, 2, 1 (1 when done; always 1 in the 'scanline' and 'slow' orders). */
  get blockSize() {
    return this.order === 'coarse' ? this.#passes[this.#passIndex] : 1;
  }

  /** The row being traced (height when done): in 'scanline' and 'slow' the rows above it are finished. */
  get row() {
    return this.#done ? this.height : this.#y;
  }

  /** @deprecated `blockSize` in the 'coarse' order, `row` in the others: one name for two ideas, kept for old sketches. */
  get pass() {
    return this.order === 'coarse' ? this.blockSize : this.row;
  }

  /**
   * Traces until `budgetMs` have passed since `start`; returns how many pixels
   * it traced. The clock is read after CHECK_EVERY pixels, then after runs of
   * a quarter of the pixels that the pace so far says still fit (CHECK_EVERY
   * at least): a few dozen reads a step instead of one every CHECK_EVERY
   * pixels, and a quarter leaves room for pixels up to four times dearer than
   * the average so far. A run is also at most twice the last one, and half of
   * what fits at the dearest pace this render has had: with 10,000 spheres a
   * lit pixel costs a hundred background ones, and runs sized by the
   * background made one step take half a second.
   */
  #traceFor(budgetMs, start) {
    let count = 0, run = this.#firstRun(budgetMs), before = 0;
    while (!this.#done) {
      const traced = this.#traceRun(run);
      count += traced;
      const elapsed = this.now() - start;
      if (traced > 0 && elapsed - before >= PACE_RUN_MS) this.#dearest = Math.max(this.#dearest, (elapsed - before) / traced);
      before = elapsed;
      if (elapsed >= budgetMs) break;
      const left = budgetMs - elapsed;
      const byAverage = elapsed > 0 ? Math.floor((count * left) / elapsed / 4) : Infinity;
      const byDearest = this.#dearest > 0 ? Math.floor(left / this.#dearest / 2) : Infinity;
      run = Math.max(this.#fewest(budgetMs), Math.min(2 * run, byAverage, byDearest));
    }
    return count;
  }

  /**
   * A step's first run: one pixel at a render's start (its pace unknown: a
   * pixel under 10,000 shadow rays costs a quarter of a second, and 16 of
   * them made a 4 s step), then what half the budget holds at the dearest
   * pace, from 1 to CHECK_EVERY.
   */
  #firstRun(budgetMs) {
    if (this.#dearest > 0) return Math.max(1, Math.min(CHECK_EVERY, Math.floor(budgetMs / this.#dearest / 2)));
    return this.#traced === 0 ? 1 : CHECK_EVERY;
  }

  /** The fewest pixels between two looks at the clock: CHECK_EVERY, or 1 when so many would overrun the whole budget. */
  #fewest(budgetMs) {
    return this.#dearest * CHECK_EVERY > budgetMs ? 1 : CHECK_EVERY;
  }

  /**
   * Traces the next n pixels in this render's order (fewer when the picture
   * is done first), a row's run at a time; returns how many it traced.
   */
  #traceRun(n) {
    let traced = 0;
    while (traced < n && !this.#done) {
      const y = this.#y, size = this.#size, stride = this.#stride;
      const end = Math.min(this.width, this.#x + (n - traced) * stride);
      let x = this.#x;
      for (; x < end; x += stride, traced++) this.#tracePixel(x, y, size);
      this.#lastX = x - stride;
      this.#lastY = y;
      this.#x = x;
      if (x >= this.width) this.#nextRow();
    }
    return traced;
  }

  /** Traces one pixel with the shader and, in a coarse pass, paints its whole block. */
  #tracePixel(x, y, size) {
    const tiles = this.#tiles;
    if (tiles) {
      const tile = Math.floor(y / TILE) * tiles.columns + Math.floor(x / TILE);
      if (tiles.packed) renderPackedPixel(tiles, tile, this.camera, x, y, this.buffer);
      else renderPixel(this.scene, this.camera, x, y, this.buffer, tiles.lists[tile]);
    } else {
      this.shader(this.scene, this.camera, x, y, this.buffer);
    }
    if (size > 1) this.#paintBlock(x, y, size);
  }

  /** Gives the size × size block at (x, y) (cut at the edges) the colour of pixel (x, y). */
  #paintBlock(x, y, size) {
    const words = this.#words, width = this.width;
    const color = words[y * width + x];
    const right = Math.min(x + size, width), bottom = Math.min(y + size, this.height);
    for (let by = y; by < bottom; by++) {
      for (let i = by * width + x, end = by * width + right; i < end; i++) words[i] = color;
    }
  }

  /**
   * Where row #y starts and how it steps. A later pass skips the pixels an
   * earlier one traced: on rows that are multiples of 2·size, every other one.
   */
  #startRow() {
    const size = this.#size;
    const skipping = this.#passIndex > 0 && this.#y % (2 * size) === 0;
    this.#x = skipping ? size : 0;
    this.#stride = skipping ? 2 * size : size;
  }

  /** Moves on from a finished row, or pass, to the next pixel there is (or to done). */
  #nextRow() {
    while (this.#x >= this.width) {
      this.#y += this.#size;
      if (this.#y >= this.height) {
        if (this.#passIndex === this.#passes.length - 1) {
          this.#done = true;
          this.#x = 0;
          this.#y = this.height;
          return;
        }
        this.#passIndex++;
        this.#size = this.#passes[this.#passIndex];
        this.#y = 0;
      }
      this.#startRow();
    }
  }
}

/**
 * The render order given as `order` or as `mode` (its older name), checked;
 * undefined when neither is given.
 */
function orderOf({ order, mode }) {
  if (order !== undefined && mode !== undefined) throw new TypeError('give the render order as order or as mode (its older name), not both');
  const [field, value] = order !== undefined ? ['order', order] : ['mode', mode];
  if (value !== undefined && !ORDERS.includes(value)) throw new RangeError(`${field} must be one of ${ORDERS.map((m) => `'${m}'`).join(', ')}, got ${show(value)}`);
  return value;
}

function budget(value, field) {
  finiteNumber(value, field);
  if (value < 0) throw new RangeError(`${field} must not be negative, got ${value}`);
  return value;
}
