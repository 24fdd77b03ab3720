/**
 * A frame rendered by several Web Workers at once. The workers stay up
 * between frames and get the scene and camera (as JSON) once per change.
 * Where the page is cross-origin isolated they write straight into one
 * SharedArrayBuffer and take bands of a few rows from a shared counter as
 * they go, so they end within a band of each other whatever the picture;
 * elsewhere each gets a share of thin bands dealt out in turn, and its rows
 * come back transferred. A worker answers a short frame in one message. The
 * picture is render()'s, byte for byte: the workers run the same code on the
 * same numbers.
 *
 * A worker that fails to start, reports an error or stays silent for
 * `timeoutMs` is stopped: its rows, and every later frame, are rendered on
 * the main thread instead (the same bytes), and `onProblem` hears why. A
 * worker still loading its code (it says `{ ready: true }` once loaded, or
 * answers) has `startTimeoutMs` instead: the first frame on a Chromebook
 * fetching the worker from the teacher's laptop, or on a busy machine, may
 * wait longer for it than for a worker that went quiet in the middle of a frame.
 */
import { render, checkSceneAndCamera } from '../render.js';
import { pathTrace, pathTraceRows, readPathOptions, preparePaths } from '../pathtrace/path-trace.js';
import { positiveInteger, show, checkOptions } from '../../text/check.js';
import { sceneToJSON, cameraToJSON } from '../../scene/json.js';
import { splitRows, bandHeight, claimHeight } from './split.js';

export { splitRows, bandHeight, claimHeight } from './split.js';

/** A module worker running render-worker.js (Vite sees this pattern and bundles the worker). */
function startWorker() {
  return new Worker(new URL('./render-worker.js', import.meta.url), { type: 'module' });
}

/** The options a ParallelRenderer takes. */
const OPTIONS = ['workers', 'rowsPerBand', 'timeoutMs', 'startTimeoutMs', 'shared', 'fallback', 'onProblem', 'createWorker'];

/** True where a SharedArrayBuffer can be handed to a worker: a cross-origin isolated page. */
function canShare() {
  return typeof SharedArrayBuffer === 'function' && globalThis.crossOriginIsolated === true;
}

export class ParallelRenderer {
  /** Per worker index: `{ worker, version }` (the scene version it holds), or null before it starts. */
  #workers = [];
  #jobs = new Map();
  #nextId = 1;
  /** The scene and camera as last sent: their JSON text (to spot a change), version and data. */
  #key = null;
  #version = 0;
  #json = null;
  /** Shared frames of finished renders, `{ frame, next }` (next: its band counter), kept for the next one of the same size. */
  #spare = [];
  /** Bumped when the workers are stopped: a frame they may still touch is never handed out again. */
  #crew = 0;

  /**
   * @param {object} [options]
   * @param {number} [options.workers=navigator.hardwareConcurrency || 2] how many workers
   * @param {'auto'|number} [options.rowsPerBand='auto'] rows per band ('auto': thin bands, see split.js's claimHeight and bandHeight)
   * @param {number} [options.timeoutMs=6000] a worker silent this long during a render is given up on
   * @param {number} [options.startTimeoutMs=30000] a worker that has not loaded its code (not said it is ready) this long into a render is given up on
   * @param {'auto'|boolean} [options.shared='auto'] share one frame with the workers ('auto': where the page is cross-origin isolated)
   * @param {boolean} [options.fallback=true] when the workers fail, render on the main thread (false: reject)
   * @param {(error: Error) => void} [options.onProblem] told once when the workers fail and the main thread takes over
   * @param {() => Worker} [options.createWorker] starts one worker (tests pass a stand-in)
   * @example
   * const workers = new ParallelRenderer({ workers: 4 });
   * workers.render(classScene(), new Camera({ width: 64, height: 48 }))
   *   .then((rgba) => rgba.length) // the same bytes as render(); in Node (no Workers) traced on this thread
   *   .finally(() => workers.terminate());
   */
  constructor(options = {}) {
    const { workers = globalThis.navigator?.hardwareConcurrency || 2, rowsPerBand = 'auto', timeoutMs = 6000, startTimeoutMs = 30_000, shared = 'auto', fallback = true, onProblem, createWorker } = checkOptions(options, OPTIONS, 'ParallelRenderer');
    this.workers = positiveInteger(workers, 'workers');
    this.rowsPerBand = rowsPerBand === 'auto' ? rowsPerBand : positiveInteger(rowsPerBand, 'rowsPerBand');
    this.timeoutMs = positiveInteger(timeoutMs, 'timeoutMs');
    this.startTimeoutMs = positiveInteger(startTimeoutMs, 'startTimeoutMs');
    if (shared !== 'auto' && typeof shared !== 'boolean') throw new TypeError(`shared must be 'auto', true or false, got ${show(shared)}`);
    if (shared === true && typeof SharedArrayBuffer !== 'function') throw new TypeError('shared: this page has no SharedArrayBuffer');
    /** True when the workers write into one SharedArrayBuffer, false when their rows are transferred. */
    this.shared = shared === 'auto' ? canShare() : shared;
    if (typeof fallback !== 'boolean') throw new TypeError(`fallback must be true or false, got ${show(fallback)}`);
    /** When the workers fail: true, render on the main thread instead; false, reject (the caller has its own way). */
    this.fallback = fallback;
    if (onProblem !== undefined && typeof onProblem !== 'function') throw new TypeError(`onProblem must be a function, got ${show(onProblem)}`);
    this.onProblem = onProblem;
    if (createWorker !== undefined && typeof createWorker !== 'function') {
      throw new TypeError(`createWorker must be a function, got ${show(createWorker)}`);
    }
    this.createWorker = createWorker ?? (ParallelRenderer.available ? startWorker : null);
    /** Why the workers were given up on (every render then runs on the main thread), or null. */
    this.problem = null;
  }

  /** True where Web Workers exist (browsers); elsewhere render() runs on the main thread. */
  static get available() {
    return typeof Worker === 'function';
  }

  /** True while renders go to the workers: they exist, and none has failed. */
  get usingWorkers() {
    return this.createWorker !== null && this.problem === null;
  }

  /** Starts every worker now, so the first frame does not wait for them to load. */
  warm() {
    if (!this.usingWorkers) return this;
    try {
      for (let i = 0; i < this.workers; i++) this.#worker(i);
    } catch (error) {
      this.#giveUp(`render workers could not start (${error.message})`);
    }
    return this;
  }

  /**
   * Renders the scene as the camera sees it.
   * @param {import('../../scene/scene.js').Scene} scene spheres, planes, boxes and point lights (it travels as JSON)
   * @param {import('../../math/camera.js').Camera} camera
   * @param {object} [options]
   * @param {(y0: number, y1: number, buffer: Uint8ClampedArray) => void} [options.onRows] called as rows y0…y1−1 arrive
   * @param {object} [options.path] path trace the frame with these options of pathTrace's (`samples`, `seed`, `maxBounces`, `sky`, `roulette`)
   * @returns {Promise<Uint8ClampedArray>} RGBA, width·height·4, identical to render(scene, camera) (with `path`: to pathTrace(scene, camera, path))
   */
  async render(scene, camera, options = {}) {
    const { onRows, path } = checkOptions(options, ['onRows', 'path'], 'ParallelRenderer.render');
    if (onRows !== undefined && typeof onRows !== 'function') throw new TypeError(`onRows must be a function, got ${show(onRows)}`);
    checkSceneAndCamera(scene, camera); // as they are now, each field by its path
    const sceneJSON = sceneToJSON(scene), cameraJSON = cameraToJSON(camera);
    if (path !== undefined) readPathOptions(path, scene, camera, 'path'); // checked here, before any worker hears of it
    const { width, height } = camera;
    if (!this.usingWorkers) {
      if (!this.fallback) throw new Error(this.problem ?? 'no Web Workers here');
      const buffer = path ? pathTrace(scene, camera, { ...path, blocking: true }) : render(scene, camera, undefined, undefined, { blocking: true }); // no Workers: the frame in one go, as asked
      onRows?.(0, height, buffer);
      return buffer;
    }
    const key = JSON.stringify([sceneJSON, cameraJSON]);
    if (key !== this.#key) {
      this.#key = key;
      this.#version++;
      this.#json = { scene: sceneJSON, camera: cameraJSON };
    }
    const size = width * height * 4;
    const job = {
      id: this.#nextId++, crew: this.#crew, scene, camera, onRows, path, buffer: new Uint8ClampedArray(size), shared: null,
      /** Bands [y0, y1) not yet in `buffer`, by y0; workers that have not said they are done, with when they were last heard. */
      owed: new Map(), working: new Map(), timer: 0,
    };
    const messages = [];
    if (this.shared) {
      // One job for every worker: each takes bands from the shared counter until the frame runs out.
      const rowsPerBand = this.rowsPerBand === 'auto' ? claimHeight(height, this.workers) : this.rowsPerBand;
      job.shared = this.#sharedFrame(size);
      Atomics.store(job.shared.next, 0, 0);
      for (let y0 = 0; y0 < height; y0 += rowsPerBand) job.owed.set(y0, [y0, Math.min(y0 + rowsPerBand, height)]);
      const message = { id: job.id, version: this.#version, shared: job.shared.frame.buffer, next: job.shared.next.buffer, rowsPerBand, ...(path ? { path } : {}) };
      for (let i = 0; i < Math.min(this.workers, job.owed.size); i++) messages.push([i, message]);
    } else {
      const rowsPerBand = this.rowsPerBand === 'auto' ? bandHeight(height, this.workers) : this.rowsPerBand;
      splitRows(height, this.workers, rowsPerBand).forEach((bands, i) => {
        for (const band of bands) job.owed.set(band[0], band);
        if (bands.length) messages.push([i, { id: job.id, version: this.#version, bands, ...(path ? { path } : {}) }]);
      });
    }
    return new Promise((resolve, reject) => {
      Object.assign(job, { resolve, reject });
      this.#jobs.set(job.id, job);
      for (const [i, message] of messages) this.#send(i, job, message);
      this.#watch(job);
    });
  }

  /** Stops every worker; renders still under way are rejected. */
  terminate() {
    this.#stopWorkers();
    for (const job of this.#jobs.values()) this.#finish(job, new Error('ParallelRenderer was terminated'));
  }

  /* ---------------- the workers ---------------- */

  /** Worker i, started the first time it is needed. */
  #worker(i) {
    if (!this.#workers[i]) {
      const worker = this.createWorker();
      worker.onmessage = (event) => this.#receive(i, event.data);
      worker.onerror = (event) => {
        event.preventDefault?.(); // handled here: no uncaught error in the console
        this.#giveUp(`render worker ${i + 1} failed (${event.message || 'it could not start'})`);
      };
      this.#workers[i] = { worker, version: null, ready: false };
    }
    return this.#workers[i];
  }

  /** Posts `message` (a job) to worker i, with the scene and camera if it does not hold them yet. */
  #send(i, job, message) {
    if (!this.#jobs.has(job.id)) return; // already taken over by the main thread
    let entry;
    try {
      entry = this.#worker(i);
    } catch (error) {
      this.#giveUp(`render workers could not start (${error.message})`);
      return;
    }
    if (entry.version !== this.#version) message = { ...message, ...this.#json };
    entry.version = this.#version;
    job.working.set(i, performance.now());
    entry.worker.postMessage(message);
  }

  /** Copies bands a worker finished into the frame: the main thread's only work. */
  #receive(i, message) {
    const entry = this.#workers[i];
    if (entry && !entry.ready) this.#started(i, entry);
    if (message?.ready) return;
    const job = this.#jobs.get(message.id);
    if (!job || !job.working.has(i)) return; // a render already finished, failed or taken over
    if (message.error) {
      this.#giveUp(`render worker ${i + 1} reported ${message.error}`);
      return;
    }
    job.working.set(i, performance.now());
    const rowBytes = job.camera.width * 4, source = job.shared?.frame ?? new Uint8ClampedArray(message.pixels);
    let at = 0;
    for (const [y0, y1] of message.bands) {
      const start = y0 * rowBytes, length = (y1 - y0) * rowBytes, from = job.shared ? start : at;
      job.buffer.set(source.subarray(from, from + length), start);
      job.owed.delete(y0);
      at += length;
    }
    if (message.done) job.working.delete(i);
    try {
      for (const [y0, y1] of message.bands) job.onRows?.(y0, y1, job.buffer);
    } catch (error) {
      this.#finish(job, error);
      return;
    }
    if (job.working.size > 0) return;
    if (job.owed.size > 0) this.#giveUp(`render workers left rows ${[...job.owed.keys()].join(', ')} undone`);
    else this.#finish(job);
  }

  /** Worker i has loaded its code: from now on it has timeoutMs to answer, counted from now. */
  #started(i, entry) {
    entry.ready = true;
    const now = performance.now();
    for (const job of this.#jobs.values()) if (job.working.has(i)) job.working.set(i, now);
  }

  /** Gives up on a worker silent for timeoutMs while it owes rows (startTimeoutMs while it is still loading). */
  #watch(job) {
    clearTimeout(job.timer);
    if (!this.#jobs.has(job.id)) return;
    const now = performance.now();
    let wait = this.timeoutMs;
    for (const [i, heard] of job.working) {
      const started = this.#workers[i]?.ready !== false;
      const allowed = started ? this.timeoutMs : this.startTimeoutMs;
      const silent = now - heard;
      if (silent >= allowed) {
        this.#giveUp(`render worker ${i + 1} did not ${started ? 'answer' : 'start'} within ${allowed / 1000} s`);
        return;
      }
      wait = Math.min(wait, allowed - silent);
    }
    job.timer = setTimeout(() => this.#watch(job), Math.max(1, wait));
  }

  /**
   * The workers failed: stop them all, render the rows still owed on the
   * main thread (the same bytes), and from now on render every frame there.
   */
  #giveUp(why) {
    const first = this.problem === null;
    if (first) this.problem = this.fallback ? `${why}; rendering on the main thread instead` : why;
    this.#stopWorkers();
    if (first) this.onProblem?.(new Error(this.problem));
    for (const job of [...this.#jobs.values()]) {
      if (!this.fallback) {
        this.#finish(job, new Error(this.problem));
        continue;
      }
      try {
        const owed = [...job.owed.values()].sort((a, b) => a[0] - b[0]);
        const paths = job.path ? preparePaths(job.scene, job.camera, readPathOptions(job.path, job.scene, job.camera)) : null;
        for (const [y0, y1] of owed) {
          if (paths) pathTraceRows(paths, job.buffer, y0, y1);
          else render(job.scene, job.camera, job.buffer, { y0, y1 }, { blocking: true });
        }
        job.owed.clear();
        for (const [y0, y1] of owed) job.onRows?.(y0, y1, job.buffer);
        this.#finish(job);
      } catch (error) {
        this.#finish(job, error);
      }
    }
  }

  #stopWorkers() {
    for (const entry of this.#workers) entry?.worker.terminate();
    this.#workers = [];
    // A stopped worker may run on for a moment: no frame it could still write into is used again.
    this.#crew++;
    this.#spare = [];
  }

  /** Settles a render: its picture, or `error`. */
  #finish(job, error) {
    if (!this.#jobs.delete(job.id)) return;
    clearTimeout(job.timer);
    if (job.shared && job.crew === this.#crew) this.#spare.push(job.shared);
    if (error) job.reject(error);
    else job.resolve(job.buffer);
  }

  /** A shared frame of `size` bytes and its band counter: a spare one, or a new one. */
  #sharedFrame(size) {
    const k = this.#spare.findIndex(({ frame }) => frame.length === size);
    if (k >= 0) return this.#spare.splice(k, 1)[0];
    this.#spare = [];
    return { frame: new Uint8ClampedArray(new SharedArrayBuffer(size)), next: new Int32Array(new SharedArrayBuffer(4)) };
  }
}
