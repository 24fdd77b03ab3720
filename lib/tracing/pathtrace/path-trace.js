/**
 * A picture as the average of random paths: `pathTrace` gives render()'s
 * RGBA bytes (linear, ×255, clamped) of the mean of `samples` paths per
 * pixel. Sample s of pixel (x, y) draws from a sequence of (seed, x, y, s)
 * alone (random.js), and every pixel's samples are summed in the order
 * s = 0, 1, …, so the bytes are the same whatever splits the frame: rows,
 * workers, or sample after sample (progressive.js).
 */
import { checkSceneAndCamera } from '../render.js';
import { checkOptions, show, positiveInteger, bool, pixelCoordinate } from '../../text/check.js';
import { packScene } from '../kernel.js';
import { checkPathWork } from '../budget.js';
import { PathRandom } from './random.js';
import { readSky } from './sky.js';
import { packMaterials } from './materials.js';
import { tracePath, radiance, shapeGroups, shapeKinds } from './integrator.js';
import { lightTable } from './lights.js';

/** The options pathTrace takes. */
export const PATH_OPTIONS = ['samples', 'seed', 'maxBounces', 'sky', 'roulette', 'lightSampling'];
/** The most samples per pixel, and bounces per path, anyone may ask for: limits on the work, not only on the size. */
export const MAX_SAMPLES = 65536, MAX_BOUNCES = 64;
/** Paths per frame at most (samples × pixels): about a minute of one core. */
export const MAX_PATHS = 2 ** 26;
/** Bounces when none are asked for: the roulette ends most paths long before. */
export const DEFAULT_BOUNCES = 16;

/**
 * pathTrace's options, checked, with the scene's sky.
 * @returns {{ samples: number, seed: number, maxBounces: number, sky: Float64Array, roulette: boolean, lightSampling: boolean }}
 */
export function readPathOptions(options, scene, camera, where = 'pathTrace') {
  if (options === undefined) throw new TypeError(`${where} needs options { samples } (how many paths per pixel)`);
  const { samples, seed = 0, maxBounces = DEFAULT_BOUNCES, sky, roulette = true } = checkOptions(options, PATH_OPTIONS, where);
  if (samples === undefined) throw new TypeError(`samples must be given: how many paths per pixel, 1 to ${MAX_SAMPLES}`);
  positiveInteger(samples, 'samples');
  if (samples > MAX_SAMPLES) throw new RangeError(`samples must be at most ${MAX_SAMPLES}, got ${samples}`);
  if (samples * camera.width * camera.height > MAX_PATHS) {
    throw new RangeError(`samples × width × height must be at most ${MAX_PATHS.toLocaleString('en')} paths, got ${samples} × ${camera.width} × ${camera.height}`);
  }
  if (!Number.isInteger(seed) || seed < 0 || seed > 0xffffffff) throw new RangeError(`seed must be a whole number from 0 to 4294967295, got ${show(seed)}`);
  if (!Number.isInteger(maxBounces) || maxBounces < 0 || maxBounces > MAX_BOUNCES) {
    throw new RangeError(`maxBounces must be a whole number from 0 to ${MAX_BOUNCES}, got ${show(maxBounces)}`);
  }
  return { samples, seed, maxBounces, sky: readSky(sky, scene.background), roulette: bool(roulette, 'roulette'), lightSampling: bool(options.lightSampling ?? true, 'lightSampling') };
}

/**
 * What tracing paths through this scene needs, worked out once per frame.
 * @param {import('../../scene/scene.js').Scene} scene
 * @param {import('../../math/camera.js').Camera} camera
 * @param {ReturnType<typeof readPathOptions>} options
 */
export function preparePaths(scene, camera, options) {
  const packed = packScene(scene), materials = packed?.materials ?? packMaterials(scene.objects); // the kernel's packing, or for a scene that does not pack the same layout (lib/shapes/material.js)
  return {
    scene, camera, objects: scene.objects, materials, packed, groups: shapeGroups(scene.objects, packed), kinds: shapeKinds(scene.objects), random: new PathRandom(),
    lights: lightTable(scene.objects, materials, options.sky, camera.position), ...options,
  };
}

/**
 * Renders the scene by path tracing: each pixel the mean of `samples` random
 * paths (*Ray Tracing in One Weekend*'s materials, read from the kit's; see
 * docs/path-tracing.md), as RGBA bytes like render()'s.
 * @param {import('../../scene/scene.js').Scene} scene its emissive shapes are the lights (point, spot and area lights are not seen by paths)
 * @param {import('../../math/camera.js').Camera} camera
 * @param {object} options
 * @param {number} options.samples paths per pixel, 1 to 65536
 * @param {number} [options.seed=0] which random paths (0 to 2³² − 1): the same seed, the same bytes
 * @param {number} [options.maxBounces=16] bounces a path may take at most, 0 to 64 (1: direct light only)
 * @param {number[]|string|{top, bottom}} [options.sky] the light from outside the scene: a colour, or a gradient
 *   from `bottom` (straight down) to `top` (straight up); the scene's background when left out
 * @param {boolean} [options.roulette=true] end long paths by Russian roulette after 3 bounces (unbiased)
 * @param {boolean} [options.blocking=false] trace however long it takes; without it, a frame of more than
 *   PATH_SEGMENTS path segments (pixels × samples × (maxBounces + 1), lib/tracing/budget.js: about a second on a
 *   slow laptop, the page frozen) throws a RangeError pointing to the tracer view with `path` and the Web Workers
 * @param {boolean} [options.lightSampling=true] at each diffuse bounce also aim one shadow ray at a light (next-event
 *   estimation, weighed by multiple importance sampling): the same expected picture as bounces alone, less noise
 * @returns {Uint8ClampedArray} RGBA, width·height·4
 * @example
 * const scene = new Scene({ background: [0.5, 0.5, 0.5] }).add(new Sphere([0, 0, -10], 2, { color: [0.8, 0.8, 0.8] }));
 * const rgba = pathTrace(scene, new Camera({ width: 32, height: 24 }), { samples: 64 });
 * rgba[(12 * 32 + 16) * 4]; // 102: the ball's red, 0.8 × 0.5 × 255 (a convex ball sends every bounce to the sky)
 */
export function pathTrace(scene, camera, options) {
  checkSceneAndCamera(scene, camera);
  const { blocking = false, ...rest } = checkOptions(options, [...PATH_OPTIONS, 'blocking'], 'pathTrace');
  const read = readPathOptions(options === undefined ? undefined : rest, scene, camera);
  if (!bool(blocking, 'blocking')) checkPathWork(camera, read);
  const frame = preparePaths(scene, camera, read);
  return pathTraceRows(frame, new Uint8ClampedArray(camera.width * camera.height * 4), 0, camera.height);
}

/** Rows y0 ≤ y < y1 of a path-traced frame into `target` (a worker's band). */
export function pathTraceRows(frame, target, y0, y1) {
  const { camera, samples } = frame, width = camera.width;
  for (let y = y0; y < y1; y++) {
    for (let x = 0; x < width; x++) {
      let r = 0, g = 0, b = 0;
      for (let s = 0; s < samples; s++) {
        tracePath(frame, x, y, s);
        r += radiance[0]; g += radiance[1]; b += radiance[2];
      }
      const i = (y * width + x) * 4;
      target[i] = (r / samples) * 255; target[i + 1] = (g / samples) * 255; target[i + 2] = (b / samples) * 255; target[i + 3] = 255;
    }
  }
  return target;
}

/**
 * Pixel (x, y) checked against the camera (the inspector's and the workers' first check).
 */
export function checkPixel(camera, x, y) {
  pixelCoordinate(x, 'x', camera.width);
  pixelCoordinate(y, 'y', camera.height);
}
