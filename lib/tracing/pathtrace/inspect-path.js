/**
 * The story of one path, and of a pixel's estimate: `inspectPath` traces
 * sample `sample` of pixel (x, y) by the renderer's own integrator, with its
 * record, and the pixel's mean, standard error and running mean over
 * `samples` samples, summed in pathTrace's order (so mean × 255 is its byte).
 */
import { checkSceneAndCamera } from '../render.js';
import { checkOptions, show } from '../../text/check.js';
import { angles } from '../../math/camera.js';
import { shapeName } from '../../scene/scene.js';
import { readPathOptions, preparePaths, checkPixel, PATH_OPTIONS, MAX_SAMPLES } from './path-trace.js';
import { tracePath, radiance } from './integrator.js';

const clamp01 = (v) => Math.min(1, Math.max(0, v));

/**
 * Sample `sample` of pixel (x, y), bounce by bounce, and the pixel's estimate.
 * @param {import('../../scene/scene.js').Scene} scene
 * @param {import('../../math/camera.js').Camera} camera
 * @param {number} x
 * @param {number} y
 * @param {object} [options] pathTrace's options (`samples`, `seed`, `maxBounces`, `sky`, `roulette`, `lightSampling`) and:
 * @param {number} [options.sample=0] which sample's path to tell (0 to samples − 1 or beyond)
 * @param {number} [options.samples=sample + 1] samples the mean, standard error and history are over
 * @returns {{ x, y, h, v, sample, seed, samples, ray, bounces: object[], end: string, sky: number[], radiance: number[],
 *   mean: number[], stderr: number[], history: number[][], unclamped: number[] }}
 *   `bounces[i]`: `{ object, name, point, normal, inside, emitted, emissionWeight, lobe, direction, pdf, delta, weight, throughput, survival?,
 *   lightSample?, lightSkipped? }`;
 *   `emitted` the light the surface gives off as it reaches the eye (throughput × emission × emissionWeight, the MIS weight:
 *   below 1 when a diffuse bounce found a light that light sampling could also have drawn), `throughput` after the bounce,
 *   `lightSample` at a diffuse or fuzzy metal bounce with light sampling on: `{ light, point, direction, blocked, pdf, weight, contribution, below?, outsideBlur? }`
 *   (the light's name or 'sky', the point aimed at (null for the sky), the blocker's name or null, pick × solid-angle density,
 *   the MIS weight, the light it added), `lightSkipped` why a bounce drew none (no light, a mirror, glass),
 *   `pdf` the density the direction was drawn with (for a mirror or glass, `delta`: the probability of that lobe),
 *   `survival` the roulette's q where it played; `end` 'sky', 'absorbed', 'roulette' or 'maxBounces';
 *   `mean` and `history` linear 0–1 (×255 is pathTrace's byte), `unclamped` the mean before clamping
 * @example
 * const scene = new Scene({ background: [0.5, 0.5, 0.5] }).add(new Sphere([0, 0, -10], 2, { color: [0.8, 0.8, 0.8] }));
 * const camera = new Camera({ width: 32, height: 24 });
 * const path = inspectPath(scene, camera, 16, 12, { sample: 3, samples: 64 });
 * path.bounces.map((b) => b.lobe); // ['diffuse']: the ball, then the sky
 * path.mean; // [0.4, 0.4, 0.4]: the pixel's estimate after 64 samples, ×255 = pathTrace(…, { samples: 64 })'s bytes
 */
export function inspectPath(scene, camera, x, y, options = {}) {
  checkSceneAndCamera(scene, camera);
  checkPixel(camera, x, y);
  if (options === null || typeof options !== 'object') throw new TypeError(`options must be an object, got ${show(options)}`);
  const { sample = 0, ...rest } = checkOptions(options, ['sample', ...PATH_OPTIONS], 'inspectPath');
  if (!Number.isInteger(sample) || sample < 0 || sample > 0xffffffff) throw new RangeError(`sample must be a whole number from 0, got ${show(sample)}`);
  if (rest.samples === undefined && sample >= MAX_SAMPLES) { // samples left out is sample + 1: say so in sample's own words
    throw new RangeError(`sample must be a whole number from 0 to ${MAX_SAMPLES - 1} when samples is left out (the mean is over samples 0 to sample), got ${sample}`);
  }
  const samples = rest.samples ?? sample + 1;
  const frame = preparePaths(scene, camera, readPathOptions({ ...rest, samples }, scene, camera, 'inspectPath'));

  /** @type {any} */
  const bounces = [];
  tracePath(frame, x, y, sample, bounces);
  const story = { radiance: [...radiance], ray: bounces.ray, end: bounces.end, sky: bounces.sky };
  for (const b of bounces) b.name = shapeName(b.object, scene.objects);

  const sum = [0, 0, 0], squares = [0, 0, 0], history = [];
  for (let s = 0; s < samples; s++) { // pathTrace's sums, in its order
    tracePath(frame, x, y, s);
    for (let c = 0; c < 3; c++) { sum[c] += radiance[c]; squares[c] += radiance[c] * radiance[c]; }
    history.push(sum.map((v) => clamp01(v / (s + 1))));
  }
  const unclamped = sum.map((v) => v / samples);
  const stderr = unclamped.map((m, c) => (samples > 1 ? Math.sqrt(Math.max(0, squares[c] / samples - m * m) / (samples - 1)) : 0));
  return {
    x, y, ...angles(story.ray.direction), sample, seed: frame.seed, samples,
    ray: story.ray, bounces, end: story.end, sky: story.sky, radiance: story.radiance,
    mean: unclamped.map(clamp01), stderr, history, unclamped,
  };
}
