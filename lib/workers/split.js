/**
 * The two halves of parallel rendering that need no Worker, so Node can test
 * them: how a frame's rows are dealt out, and what a worker does with its share.
 */
import { positiveInteger } from '../check.js';
import { sceneFromJSON, cameraFromJSON } from '../serialize.js';
import { renderRows } from '../render.js';
import { tileCandidates, TILE } from '../bounds.js';

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

/** Bands per worker at least: enough for the shares to balance, few enough to cost little. */
const BANDS_PER_WORKER = 8;

/**
 * Rows per band for a frame of `height` rows over `parts` workers: a tile's
 * height (16, the rows render() finds candidate shapes for at once) when the
 * frame is tall enough to give every worker BANDS_PER_WORKER of them, fewer
 * rows otherwise, so the shares stay within a band of each other.
 */
export function bandHeight(height, parts) {
  return Math.max(1, Math.min(TILE, Math.floor(height / (parts * BANDS_PER_WORKER))));
}

/** Messages a worker sends per share at most: its bands, finished, in about this many groups. */
export const GROUPS = 4;

/**
 * What a worker does, as a function of its messages (the worker's whole
 * state lives in the closure). A job is
 *   { id, version, scene?, camera?, bands, shared? }
 * `scene` and `camera` (JSON) come only when `version` is new to this worker:
 * they are parsed, and the tiles' candidate shapes found, once per change.
 * With `shared` (a SharedArrayBuffer of the whole frame) the worker writes its
 * rows straight into it and posts `{ id, bands, done }` for each group of
 * bands; without, it posts `{ id, bands, pixels, done }`, `pixels` an
 * ArrayBuffer (transferred) of those bands' rows one after the other. On a
 * problem it posts `{ id, error }`.
 * @returns {(job: object, post: (message: object, transfer?: ArrayBuffer[]) => void) => void}
 */
export function workerHandler() {
  let version = null, scene = null, camera = null, tiles = null;
  let frame = new Uint8ClampedArray(0); // scratch frame for the transfer path, kept between jobs

  return function handle(job, post) {
    const { id, bands } = job;
    try {
      if (job.scene !== undefined) {
        version = null; // until the new scene is whole
        scene = sceneFromJSON(job.scene);
        camera = cameraFromJSON(job.camera);
        tiles = tileCandidates(scene, camera);
        version = job.version;
      }
      if (job.version !== version) throw new Error(`scene version ${job.version} never arrived (have ${version})`);
      const rowBytes = camera.width * 4, size = rowBytes * camera.height;
      const target = job.shared ? new Uint8ClampedArray(job.shared) : frame.length === size ? frame : (frame = new Uint8ClampedArray(size));
      if (target.length !== size) throw new RangeError(`shared frame holds ${target.length} bytes, the camera needs ${size}`);
      const perGroup = Math.ceil(bands.length / GROUPS);
      for (let g = 0; g < bands.length; g += perGroup) {
        const group = bands.slice(g, g + perGroup);
        for (const [y0, y1] of group) renderRows(scene, camera, target, y0, y1, tiles);
        const done = g + perGroup >= bands.length;
        if (job.shared) {
          post({ id, bands: group, done });
        } else {
          const pixels = new Uint8ClampedArray(group.reduce((n, [y0, y1]) => n + (y1 - y0) * rowBytes, 0));
          let at = 0;
          for (const [y0, y1] of group) {
            pixels.set(target.subarray(y0 * rowBytes, y1 * rowBytes), at);
            at += (y1 - y0) * rowBytes;
          }
          post({ id, bands: group, pixels: pixels.buffer, done }, [pixels.buffer]);
        }
      }
      if (bands.length === 0) post({ id, bands: [], done: true });
    } catch (error) {
      post({ id, error: `${error.name}: ${error.message}` });
    }
  };
}
