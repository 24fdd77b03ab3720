/**
 * How much work one blocking call may do: render(), pathTrace() and
 * renderGPU() trace a whole frame before they return, and a page does
 * nothing else meanwhile (no drawing, no clicks). A call that would take
 * more than about a second on a slow laptop is refused with a RangeError
 * that says what to use instead: the tracer view, which traces a few
 * milliseconds each frame, or the Web Workers. `{ blocking: true }` lifts
 * the limit where nothing waits for the thread (Node, a worker, a test).
 *
 * Each budget is counted in the unit the tracer's time grows with, measured
 * on one core of the kit's 2-core build machine (docs/path-tracing.md,
 * "How long a call may take"), and set to about half a second there: a slow
 * laptop takes about twice as long.
 */
import { bool, checkOptions } from '../text/check.js';
import { isShape } from '../shapes/index.js';

/** render(): rays a frame may trace (pixels × camera samples × (1 + light sources) × bounces); 7 to 10 million a second were measured. */
export const RENDER_RAYS = 4_000_000;
/** pathTrace(): path segments a frame may trace (pixels × samples × (bounces + 1), see pathSegments); 3.4 to 5.7 million a second were measured. */
export const PATH_SEGMENTS = 2_000_000;
/** renderGPU(): tests of a ray against a shape a frame may make (pixels × shapes): its shader tests every ray against every shape. */
export const GPU_SHAPE_TESTS = 2 ** 28;

/** The ways that do not block, for the messages. */
const PROGRESSIVE = 'p.createTracerView({ scene, camera }) traces it a few milliseconds each frame, ParallelRenderer\'s render(scene, camera) on Web Workers';
const PROGRESSIVE_PATHS = 'p.createTracerView({ scene, camera, path: { samples } }) traces it a few milliseconds each frame, ParallelRenderer\'s render(scene, camera, { path }) on Web Workers';

/**
 * A call's `blocking` option: true lifts the limit.
 * @param {any} options the call's options (undefined: none)
 * @param {string} where the call, as its messages name it
 * @returns {boolean}
 */
export function readBlocking(options, where) {
  const { blocking = false } = checkOptions(options, ['blocking'], where);
  return bool(blocking, 'blocking');
}

/**
 * Rays render() traces for this frame, counted before it starts: each
 * pixel's camera rays, each with a shadow ray to every light source, and
 * as many bounces as the scene's maxDepth allows when a shape mirrors or lets light through.
 * @param {import('../scene/scene.js').Scene} scene
 * @param {import('../math/camera.js').Camera} camera
 * @param {number} rows the rows to trace
 */
export function renderRays(scene, camera, rows = camera.height) {
  return camera.width * rows * camera.samples * (1 + scene.lights.length) * bouncesOf(scene);
}

/** Rays each camera ray may lead to in a row: 1, or maxDepth + 1 when some shape mirrors or lets light through. */
function bouncesOf(scene) {
  for (const o of scene.objects) {
    const m = o.material;
    if (m.reflection > 0 || m.transparency > 0) return scene.maxDepth + 1;
  }
  return 1;
}

/** A RangeError when render()'s frame (or its rows) would trace more than RENDER_RAYS rays. */
export function checkRenderWork(scene, camera, rows = camera.height) {
  const rays = renderRays(scene, camera, rows);
  if (rays > RENDER_RAYS) {
    throw new RangeError(`render would trace about ${count(rays)} rays (${camera.width} × ${rows} pixels × ${camera.samples} samples × ${1 + scene.lights.length} for the light sources × ${bounces(scene)}), more than the ${count(RENDER_RAYS)} that take about a second on a slow laptop with the page frozen: ${PROGRESSIVE}; where nothing waits (Node, a worker) pass { blocking: true }`);
  }
}

/**
 * Path segments pathTrace traces for this frame, counted before it starts:
 * each pixel's samples, each a path of up to maxBounces + 1 segments; with
 * the roulette (from the 4th bounce on) most paths end within a bounce or
 * two, so no more than 5 are counted.
 * @param {import('../math/camera.js').Camera} camera
 * @param {{ samples: number, maxBounces: number, roulette: boolean }} options pathTrace's, read
 */
export function pathSegments(camera, { samples, maxBounces, roulette }) {
  return camera.width * camera.height * samples * segmentsOf(maxBounces, roulette);
}

const segmentsOf = (maxBounces, roulette) => (roulette ? Math.min(maxBounces, 4) : maxBounces) + 1;

/** A RangeError when pathTrace's frame would trace more than PATH_SEGMENTS path segments. */
export function checkPathWork(camera, options) {
  const segments = pathSegments(camera, options), { samples, maxBounces, roulette } = options;
  if (segments > PATH_SEGMENTS) {
    throw new RangeError(`pathTrace would trace about ${count(segments)} path segments (${camera.width} × ${camera.height} pixels × ${samples} samples × ${segmentsOf(maxBounces, roulette)} for maxBounces ${maxBounces}${roulette ? ' with the roulette' : ''}), more than the ${count(PATH_SEGMENTS)} that take about a second on a slow laptop with the page frozen: ${PROGRESSIVE_PATHS}; fewer samples or maxBounces do too; where nothing waits (Node, a worker) pass { blocking: true }`);
  }
}

/** A RangeError when renderGPU's frame would test more than GPU_SHAPE_TESTS ray–shape pairs. */
export function checkGpuWork(scene, camera) {
  let shapes = 0;
  for (const o of scene.objects) if (isShape(o)) shapes++;
  const tests = camera.width * camera.height * shapes;
  if (tests > GPU_SHAPE_TESTS) {
    throw new RangeError(`renderGPU would test every one of ${camera.width} × ${camera.height} pixels' rays against each of ${count(shapes)} shapes, ${count(tests)} tests, more than the ${count(GPU_SHAPE_TESTS)} a slow laptop's GPU makes in about a second with the page frozen: a smaller picture, fewer shapes (many triangles go faster as one Mesh), or render() on the CPU, whose tiles test only the shapes under them, through ${PROGRESSIVE}; pass { blocking: true } to wait anyway`);
  }
}

/** The bounces factor as a message says it. */
function bounces(scene) {
  const n = bouncesOf(scene);
  return n === 1 ? '1 bounce: no mirror or glass' : `${n} bounces: maxDepth ${scene.maxDepth} between mirrors or glass`;
}

/** A count as the messages write it: 6,000,000. */
function count(n) {
  return Math.round(n).toLocaleString('en');
}
