/**
 * The two halves of parallel rendering that need no Worker, so Node can test
 * them: how a frame's rows are dealt out, and what a worker does with its share.
 */
import { positiveInteger } from '../../text/check.js';
import { sceneFromJSON, cameraFromJSON } from '../../scene/json.js';
import { renderRows, prepareFrame } from '../render.js';
import { TILE } from '../bounds.js';
import { readPathOptions, preparePaths, pathTraceRows } from '../pathtrace/path-trace.js';

/**
 * Deals a frame's rows to `parts` workers: bands of `rowsPerBand` rows, handed
 * out in turn (band k to worker k mod parts), so every worker gets some sky and
 * some spheres. Every row 0…height−1 is in exactly one band, the last band
 * being shorter when the height does not divide evenly.
 * @returns {Array<Array<[number, number]>>} per worker, its bands as [firstRow, endRow)
 */
export function splitRows(height, parts, rowsPerBand = 1) {
  positiveInteger(height, 'height');
  positiveInteger(parts, 'parts');
  positiveInteger(rowsPerBand, 'rowsPerBand');
  const shares = Array.from({ length: parts }, () => []);
  for (let y0 = 0, k = 0; y0 < height; y0 += rowsPerBand, k++) {
    shares[k % parts].push([y0, Math.min(y0 + rowsPerBand, height)]);
  }
  return shares;
}

/** Bands per worker at least: many, so the shares balance (the bands travel in a few messages, however many). */
const BANDS_PER_WORKER = 16;

/**
 * Rows per band for a frame of `height` rows over `parts` workers: half a
 * tile's height (8) when the frame is tall enough to give every worker
 * BANDS_PER_WORKER of them, fewer rows otherwise. Dealt in turn, such thin
 * bands give every worker about the same mix of sky and spheres.
 */
export function bandHeight(height, parts) {
  return Math.max(1, Math.min(TILE / 2, Math.floor(height / (parts * BANDS_PER_WORKER))));
}

/**
 * Rows per band when the workers take bands from one counter as they go (a
 * shared frame): a worker that finishes early takes more, so the bands can be
 * few rows each: the shares then end within a band's time of each other.
 */
export function claimHeight(height, parts) {
  return Math.max(1, Math.min(TILE / 4, Math.floor(height / (parts * 2 * BANDS_PER_WORKER))));
}

/**
 * A worker reports its finished bands at most once per this many milliseconds
 * of work, and when it is done. Often enough that the page copies most rows
 * while the workers still trace (its copying then delays them little: they take
 * bands as they go), seldom enough that a message costs nothing that counts.
 */
export const REPORT_MS = 4;

/**
 * What a worker does, as a function of its messages (the worker's whole
 * state lives in the closure). A job is
 *   { id, version, scene?, camera?, bands }                      its share, rows transferred back;
 *   { id, version, scene?, camera?, shared, next, rowsPerBand }  bands taken as it goes.
 * `scene` and `camera` (JSON) come only when `version` is new to this worker:
 * they are parsed, and the tiles' candidate shapes found, once per change.
 * With `path` (pathTrace's options) the rows are path traced instead: the
 * same bytes as pathTrace, since each sample depends on (seed, x, y, s) alone.
 * `shared` is a SharedArrayBuffer of the whole frame, written in place;
 * `next` a SharedArrayBuffer holding one Int32, the next band of `rowsPerBand`
 * rows to take: every worker on the frame takes from it (Atomics.add) until
 * the frame runs out, so one that runs faster does more of it.
 * The worker posts `{ id, bands, done }` (with `pixels` on the transfer path:
 * an ArrayBuffer, transferred, of those bands' rows one after the other) when
 * REPORT_MS have passed since its last message, and once done. A frame that
 * takes less time is answered in one message. On a problem it posts `{ id, error }`.
 * @param {object} [options]
 * @param {() => number} [options.now=performance.now] the clock, in milliseconds (tests pass their own)
 * @returns {(job: object, post: (message: object, transfer?: ArrayBuffer[]) => void) => void}
 */
export function workerHandler({ now = () => performance.now() } = {}) {
  let version = null, scene = null, camera = null, tiles = null;
  let frame = new Uint8ClampedArray(0); // scratch frame for the transfer path, kept between jobs

  return function handle(job, post) {
    const { id } = job;
    try {
      if (job.scene !== undefined) {
        version = null; // until the new scene is whole
        scene = sceneFromJSON(job.scene);
        camera = cameraFromJSON(job.camera);
        tiles = prepareFrame(scene, camera);
        version = job.version;
      }
      if (job.version !== version) throw new Error(`scene version ${job.version} never arrived (have ${version})`);
      const rowBytes = camera.width * 4, size = rowBytes * camera.height;
      const target = job.shared ? new Uint8ClampedArray(job.shared) : frame.length === size ? frame : (frame = new Uint8ClampedArray(size));
      if (target.length !== size) throw new RangeError(`shared frame holds ${target.length} bytes, the camera needs ${size}`);
      const report = (bands, done) => {
        if (job.shared) {
          post({ id, bands, done });
          return;
        }
        const pixels = new Uint8ClampedArray(bands.reduce((n, [y0, y1]) => n + (y1 - y0) * rowBytes, 0));
        let at = 0;
        for (const [y0, y1] of bands) {
          pixels.set(target.subarray(y0 * rowBytes, y1 * rowBytes), at);
          at += (y1 - y0) * rowBytes;
        }
        post({ id, bands, pixels: pixels.buffer, done }, [pixels.buffer]);
      };
      const paths = job.path ? preparePaths(scene, camera, readPathOptions(job.path, scene, camera)) : null;
      const bands = job.next ? claimed(job.next, positiveInteger(job.rowsPerBand, 'rowsPerBand'), camera.height) : job.bands.values();
      let finished = [], reportedAt = now();
      for (const [y0, y1] of bands) {
        if (finished.length > 0 && now() - reportedAt >= REPORT_MS) { // (before the band: the last one goes with `done`)
          report(finished, false);
          finished = [];
          reportedAt = now();
        }
        if (paths) pathTraceRows(paths, target, y0, y1);
        else renderRows(scene, camera, target, y0, y1, tiles);
        finished.push([y0, y1]);
      }
      report(finished, true);
    } catch (error) {
      post({ id, error: `${error.name}: ${error.message}` });
    }
  };
}

/** The bands [y0, y1) a worker takes from the shared counter `next`, one at a time, until the frame runs out. */
function* claimed(next, rowsPerBand, height) {
  const counter = new Int32Array(next);
  for (let k = Atomics.add(counter, 0, 1); k * rowsPerBand < height; k = Atomics.add(counter, 0, 1)) {
    yield [k * rowsPerBand, Math.min((k + 1) * rowsPerBand, height)];
  }
}
