/**
 * pathTraceGPU(scene, camera, options): pathTrace's picture, its paths traced
 * on the GPU, for a page with WebGL2 (no p5 needed). One engine (one WebGL2
 * context) serves every call, made at the first; a lost context is made
 * again at the next call.
 */
import { checkSceneAndCamera } from '../tracing/render.js';
import { readPathOptions } from '../tracing/pathtrace/path-trace.js';
import { GpuPathTracer } from './path-engine.js';

/**
 * Paths a pass traces at most (samples × pixels): a pass is one draw, and a
 * browser ends a draw that holds the GPU for seconds. The samples of a
 * pass depend on the picture's size alone, so the bytes do not change.
 */
export const PASS_PATHS = 2 ** 18;

let engine = null;

/**
 * Renders the scene by path tracing on the GPU: pathTrace's options, checked
 * by the same function, its materials, sky and Russian roulette, in a WebGL2
 * fragment shader reading the packed scene renderGPU reads; each pixel the
 * mean of `samples` paths, summed pass after pass in float32. The same seed
 * gives the same bytes; the paths are drawn as the CPU draws them, not the
 * same numbers, so the picture agrees with pathTrace's within its noise
 * (tests/e2e/gpu-paths.spec.js).
 * @param {import('../scene/scene.js').Scene} scene its emissive shapes are the lights
 * @param {import('../math/camera.js').Camera} camera
 * @param {object} options pathTrace's: `{ samples, seed, maxBounces, sky, roulette }`
 * @param {number} options.samples paths per pixel, 1 to 65536
 * @param {number} [options.seed=0] which random paths: the same seed, the same bytes
 * @param {number} [options.maxBounces=16] bounces a path may take at most, 0 to 64
 * @param {number[]|string|{top, bottom}} [options.sky] the light from outside the scene (the scene's background when left out)
 * @param {boolean} [options.roulette=true] Russian roulette after 3 bounces
 * @param {boolean} [options.lightSampling] taken and not used: the GPU traces bounces alone (the same expected picture, more noise)
 * @returns {Uint8ClampedArray} RGBA, width·height·4, as pathTrace returns it
 * @throws {Error} without WebGL2 (or its float colour buffers), or for a shape the GPU cannot trace (the error names it)
 * @example
 * const picture = () => pathTraceGPU(classScene(), new Camera({ width: 320, height: 240 }), { samples: 64 });
 * // in a browser with WebGL2, picture() is pathTrace's picture traced on the GPU;
 * // in Node it throws "the GPU engine needs WebGL2: there is no canvas here (a browser is needed)"
 */
export function pathTraceGPU(scene, camera, options) {
  checkSceneAndCamera(scene, camera);
  const paths = readPathOptions(options, scene, camera, 'pathTraceGPU');
  if (!engine || engine.lost) engine = new GpuPathTracer();
  engine.setScene(scene, paths);
  engine.start(camera);
  const perPass = samplesPerPass(camera);
  while (engine.samples < paths.samples) engine.pass(camera, Math.min(perPass, paths.samples - engine.samples));
  return engine.read(new Uint8ClampedArray(camera.width * camera.height * 4));
}

/** How many samples of each pixel one pass traces: PASS_PATHS shared over the picture's pixels, at least 1. */
export function samplesPerPass(camera) {
  return Math.max(1, Math.floor(PASS_PATHS / (camera.width * camera.height)));
}
