/**
 * A frame rendered by several Web Workers at once. Each worker gets the scene
 * and camera as JSON and a share of the rows; the main thread only copies the
 * finished rows into place. The picture is render()'s, byte for byte: the
 * workers run the same code on the same numbers.
 */
import { render } from '../render.js';
import { positiveInteger, show, checkOptions } from '../check.js';
import { sceneToJSON, cameraToJSON } from '../serialize.js';
import { splitRows } from './split.js';

export { splitRows } from './split.js';

/** A module worker running render-worker.js (Vite sees this pattern and bundles the worker). */
function startWorker() {
  return new Worker(new URL('./render-worker.js', import.meta.url), { type: 'module' });
}

/** The options a ParallelRenderer takes. */
const OPTIONS = ['workers', 'rowsPerBand', 'createWorker'];

export class ParallelRenderer {
  #workers = [];
  #jobs = new Map();
  #nextId = 1;

  /**
   * @param {object} [options]
   * @param {number} [options.workers=navigator.hardwareConcurrency || 2] how many workers
   * @param {number} [options.rowsPerBand=4] rows per message; bands are dealt to the workers in turn
   * @param {() => Worker} [options.createWorker] starts one worker (tests pass a stand-in)
   */
  constructor(options = {}) {
    const { workers = globalThis.navigator?.hardwareConcurrency || 2, rowsPerBand = 4, createWorker } = checkOptions(options, OPTIONS, 'ParallelRenderer');
    this.workers = positiveInteger(workers, 'workers');
    this.rowsPerBand = positiveInteger(rowsPerBand, 'rowsPerBand');
    if (createWorker !== undefined && typeof createWorker !== 'function') {
      throw new TypeError(`createWorker must be a function, got ${show(createWorker)}`);
    }
    this.createWorker = createWorker ?? (ParallelRenderer.available ? startWorker : null);
  }

  /** True where Web Workers exist (browsers); elsewhere render() runs on the main thread. */
  static get available() {
    return typeof Worker === 'function';
  }

  /**
   * Renders the scene as the camera sees it.
   * @param {import('../scene.js').Scene} scene spheres, planes, boxes and point lights (it travels as JSON)
   * @param {import('../camera.js').Camera} camera
   * @param {object} [options]
   * @param {(y0: number, y1: number, buffer: Uint8ClampedArray) => void} [options.onRows] called as rows y0…y1−1 arrive
   * @returns {Promise<Uint8ClampedArray>} RGBA, width·height·4, identical to render(scene, camera)
   */
  async render(scene, camera, options = {}) {
    const { onRows } = checkOptions(options, ['onRows'], 'ParallelRenderer.render');
    if (onRows !== undefined && typeof onRows !== 'function') throw new TypeError(`onRows must be a function, got ${show(onRows)}`);
    const sceneJSON = sceneToJSON(scene), cameraJSON = cameraToJSON(camera);
    const { width, height } = camera;
    if (!this.createWorker) {
      const buffer = render(scene, camera);
      onRows?.(0, height, buffer);
      return buffer;
    }
    const buffer = new Uint8ClampedArray(width * height * 4);
    const shares = splitRows(height, this.workers, this.rowsPerBand).filter((bands) => bands.length > 0);
    const id = this.#nextId++;
    return new Promise((resolve, reject) => {
      this.#jobs.set(id, { buffer, width, onRows, resolve, reject, waiting: shares.length });
      shares.forEach((bands, i) => this.#worker(i).postMessage({ id, scene: sceneJSON, camera: cameraJSON, bands }));
    });
  }

  /** Stops every worker; renders still under way are rejected. */
  terminate() {
    for (const worker of this.#workers) worker?.terminate();
    this.#workers = [];
    this.#failAll(new Error('ParallelRenderer was terminated'));
  }

  /** Worker i, started the first time it is needed. */
  #worker(i) {
    if (!this.#workers[i]) {
      const worker = this.createWorker();
      worker.onmessage = (event) => this.#receive(event.data);
      worker.onerror = (event) => {
        event.preventDefault?.();
        this.#workers[i] = null; // started again by the next render
        worker.terminate();
        this.#failAll(new Error(`render worker failed: ${event.message ?? 'could not start'}`));
      };
      this.#workers[i] = worker;
    }
    return this.#workers[i];
  }

  /** Copies a band of finished rows into its frame: the main thread's only work. */
  #receive(message) {
    const job = this.#jobs.get(message.id);
    if (!job) return; // a render already failed or terminated
    if (message.error) {
      this.#jobs.delete(message.id);
      job.reject(new Error(`render worker: ${message.error}`));
    } else if (message.done) {
      if (--job.waiting === 0) {
        this.#jobs.delete(message.id);
        job.resolve(job.buffer);
      }
    } else {
      job.buffer.set(new Uint8ClampedArray(message.pixels), message.y0 * job.width * 4);
      try {
        job.onRows?.(message.y0, message.y1, job.buffer);
      } catch (error) {
        this.#jobs.delete(message.id);
        job.reject(error);
      }
    }
  }

  #failAll(error) {
    for (const job of this.#jobs.values()) job.reject(error);
    this.#jobs.clear();
  }
}
