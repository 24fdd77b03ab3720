/**
 * The two halves of parallel rendering that need no Worker, so Node can test
 * them: how a frame's rows are dealt out, and what a worker does with its share.
 */
import { positiveInteger } from '../check.js';
import { sceneFromJSON, cameraFromJSON } from '../serialize.js';
import { render } from '../render.js';

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

/**
 * A worker's job: `{ id, scene, camera, bands }` with scene and camera as JSON.
 * Renders each band and posts `{ id, y0, y1, pixels }` (an ArrayBuffer of the
 * band's RGBA rows, transferred), then `{ id, done: true }`; or `{ id, error }`.
 * @param {object} job
 * @param {(message: object, transfer?: ArrayBuffer[]) => void} post
 */
export function runJob(job, post) {
  const { id, bands } = job;
  try {
    const scene = sceneFromJSON(job.scene);
    const camera = cameraFromJSON(job.camera);
    const width = camera.width;
    // render writes at the pixels' places in a whole frame; only our rows get filled.
    const frame = frameOf(width * camera.height * 4);
    for (const [y0, y1] of bands) {
      render(scene, camera, frame, { y0, y1 });
      const pixels = frame.slice(y0 * width * 4, y1 * width * 4);
      post({ id, y0, y1, pixels: pixels.buffer }, [pixels.buffer]);
    }
    post({ id, done: true });
  } catch (error) {
    post({ id, error: `${error.name}: ${error.message}` });
  }
}

let _frame = new Uint8ClampedArray(0);
/** One scratch frame per worker, kept between jobs of the same size. */
function frameOf(size) {
  if (_frame.length !== size) _frame = new Uint8ClampedArray(size);
  return _frame;
}
