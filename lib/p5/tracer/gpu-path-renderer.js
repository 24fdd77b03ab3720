/**
 * A path-traced tracer view on the GPU engine: the renderer the view drives
 * (as it drives lib/tracing/pathtrace/progressive.js's), whose passes are
 * traced by the GPU's path tracer (lib/gpu/path-engine.js) and shown on the
 * view's canvas GPU to GPU. A step starts a pass when the last one is done
 * (a fence tells, without waiting), so the page never waits for the GPU; a
 * pass that came back within a frame or two doubles the samples of the next,
 * one that took longer halves them. The sums add sample after sample in
 * order whatever the passes, so a finished picture is pathTraceGPU's bytes.
 * Its `buffer` is read back only when asked (a saved PNG, a test).
 */
import { GpuPathTracer } from '../../gpu/path-engine.js';
import { samplesPerPass } from '../../gpu/path-trace-gpu.js';
import { checkSceneAndCamera } from '../../tracing/render.js';
import { readPathOptions } from '../../tracing/pathtrace/path-trace.js';
import { checkOptions, show } from '../../text/check.js';
import { formatRate } from '../../text/format.js';

/** A pass that came back within this long was short: the next one takes twice the samples. */
const SHORT_PASS_MS = 33;

export class GpuPathRenderer {
  #fence = null; #started = 0; #perPass = 1; #tracingMs = 0; #paths = 0; #buffer = null; #stale = true; #shown = 0;

  /**
   * @param {{ scene: any, camera: any, path: object, budgetMs?: number }} options as PathProgressiveRenderer's
   * @throws {Error} without WebGL2 (or its float colour buffers), or for a shape the GPU cannot trace
   */
  constructor({ scene, camera, path, budgetMs = 8 }) {
    this.tracer = new GpuPathTracer(undefined, { preserveDrawingBuffer: true });
    this.budgetMs = budgetMs;
    this.engine = 'gpu';
    /** As PathProgressiveRenderer's: path traced, in passes of whole samples, no pixel alone, no worker problem. */
    this.pathTraced = true;
    this.order = 'coarse';
    this.current = null;
    this.problem = null;
    this.slowRaysPerStep = 1;
    this.slowRaysPerSecond = 0;
    this.options = {};
    /** @type {any} */ this.scene = null;
    /** @type {any} */ this.camera = null;
    this.width = 0; this.height = 0;
    /** Paths per pixel the picture will have. */
    this.total = 0;
    this.restart({ scene, camera, path });
  }

  /**
   * Starts again from the first sample with whatever changed (`path` merged over the earlier options), each checked first.
   * @param {{ scene?: any, camera?: any, path?: object, shader?: any }} [changes]
   */
  restart(changes = {}) {
    if (changes === null || typeof changes !== 'object') throw new TypeError(`changes must be an object like { path: { maxBounces: 1 } }, got ${show(changes)}`);
    const { scene = this.scene, camera = this.camera, path = {} } = checkOptions(changes, ['scene', 'camera', 'path'], 'restart (a path-traced view)');
    checkSceneAndCamera(scene, camera);
    const options = { ...this.options, ...path };
    const read = readPathOptions(options, scene, camera, 'path');
    this.tracer.setScene(scene, read);
    this.tracer.start(camera);
    Object.assign(this, { scene, camera, options, width: camera.width, height: camera.height, total: read.samples });
    this.#fence = null; // a pass still running belongs to the old picture: the next one starts from nothing
    this.#perPass = 1;
    this.#tracingMs = 0;
    this.#paths = 0;
    this.#shown = 0;
    this.#stale = true;
    this.tracer.present(); // no samples yet: black, not the old picture
    return this;
  }

  /** Paths per pixel the picture will have, and those it shows now. */
  get samples() { return this.total; }
  get sample() { return this.#shown; }
  get done() { return this.#shown >= this.total; }
  get progress() { return this.#shown / this.total; }
  /** Paths per second, from the passes' times on the clock (the GPU works apart from the page). */
  get raysPerSecond() { return this.#tracingMs > 0 ? (this.#paths * 1000) / this.#tracingMs : 0; }
  /** The view's progress line, as the CPU's: "Sample 37 of 256 · 1.2M paths/s". */
  get progressText() { return `Sample ${this.#shown} of ${this.total} · ${formatRate(this.raysPerSecond)} paths/s`; }
  /** Why the GPU cannot go on (the view then goes back to the CPU), or null. */
  get lost() { return this.tracer.lost ? 'the GPU context was lost' : null; }

  /**
   * Shows the pass that finished (if one did) and starts the next; never waits for the GPU.
   * Allocates nothing but the pass's fence (a WebGLSync, one a pass, not one a frame).
   * @returns {{ changed: boolean, done: boolean }}
   */
  step() {
    const gl = this.tracer.gl;
    let changed = false;
    if (this.#fence) {
      if (gl.getSyncParameter(this.#fence, gl.SYNC_STATUS) !== gl.SIGNALED) return WAITING;
      gl.deleteSync(this.#fence);
      this.#fence = null;
      const ms = performance.now() - this.#started, traced = this.tracer.samples - this.#shown;
      this.#tracingMs += ms;
      this.#paths += traced * this.width * this.height;
      this.#perPass = ms < SHORT_PASS_MS ? Math.min(this.#perPass * 2, samplesPerPass(this.camera)) : Math.max(1, this.#perPass >> (ms > 4 * SHORT_PASS_MS ? 1 : 0));
      this.#shown = this.tracer.samples;
      this.#stale = true;
      this.tracer.present(); // the new mean onto the engine's canvas, before the next pass changes the sums
      changed = true;
    }
    if (!this.done) {
      this.tracer.pass(this.camera, Math.min(this.#perPass, this.total - this.tracer.samples));
      this.#fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
      this.#started = performance.now();
    }
    if (!changed) return this.done ? DONE : WAITING;
    return this.done ? SHOWN_DONE : SHOWN;
  }

  /** Draws the mean shown last onto a 2D context (the view's canvas), GPU to GPU. */
  blitTo(ctx) {
    ctx.drawImage(this.tracer.canvas, 0, 0);
  }

  /** The picture's RGBA bytes (the mean of the samples shown), read back when they changed since the last read. */
  get buffer() {
    const n = this.width * this.height * 4;
    if (this.#buffer?.length !== n) { this.#buffer = new Uint8ClampedArray(n); this.#stale = true; }
    if (this.#stale) {
      if (this.#shown > 0) this.tracer.read(this.#buffer, this.#fence !== null); // while a pass runs, the sums before it
      else this.#buffer.fill(0);
      this.#stale = false;
    }
    return this.#buffer;
  }

  terminate() {
    if (this.#fence) this.tracer.gl.deleteSync(this.#fence);
    this.tracer.dispose();
  }
}

/** What a step did, without a new object each frame: waiting for the GPU, or a pass shown (the last, or not). */
const WAITING = Object.freeze({ changed: false, done: false });
const SHOWN = Object.freeze({ changed: true, done: false });
const SHOWN_DONE = Object.freeze({ changed: true, done: true });
const DONE = Object.freeze({ changed: false, done: true });
