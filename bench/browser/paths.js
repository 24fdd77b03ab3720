/**
 * Section 8 of `npm run bench:browser`: sketch 16's Cornell box path traced
 * at a given size (320×240), up to 16 bounces, as samples per second (a
 * sample is one path; samples per pixel per second are those ÷ the pixels),
 * in one run:
 *   - on the GPU engine (pathTraceGPU: passes of float sums, bytes read back);
 *   - on the CPU, pathTrace on the page's thread (one core);
 *   - on the CPU, on one Web Worker per core (ParallelRenderer with `path`).
 * Each is timed over whole pictures of `samples` paths a pixel, for about
 * `seconds`, after one to warm up (the shader compiled, the workers started).
 * The GPU's picture must agree with the CPU's in its mean (within 2 %).
 * window.bench.run({ width, height, seconds, samples }) → { gpu, cpu, workers: { pathsPerSecond, … }, means, renderer }
 */
import { pathTrace, pathTraceGPU } from '../../lib/index.js';
import { ParallelRenderer } from '../../lib/tracing/workers/parallel.js';
import { cornellBox, cornellCamera } from '../../tests/shared/cornell-box.js';

/** Pictures by `picture()` for about `seconds` (at least `least`), after one to warm up: paths per second. */
async function timed(picture, paths, seconds, least) {
  await picture();
  const start = performance.now();
  let pictures = 0;
  while (pictures < least || performance.now() - start < seconds * 1000) { await picture(); pictures++; }
  const ms = performance.now() - start;
  return { pathsPerSecond: (pictures * paths * 1000) / ms, pictures, msPerPicture: ms / pictures };
}

/** A picture's mean byte (r, g and b together). */
function meanOf(frame) {
  let sum = 0;
  for (let i = 0; i < frame.length; i += 4) sum += frame[i] + frame[i + 1] + frame[i + 2];
  return sum / ((frame.length / 4) * 3);
}

async function run({ width = 320, height = 240, seconds = 10, least = 2, samples = 4 } = {}) {
  const scene = cornellBox(), camera = cornellCamera(width, height), options = { samples, maxBounces: 16 };
  const paths = width * height * samples;
  const gpu = await timed(() => pathTraceGPU(scene, camera, options), paths, seconds, least);
  const cpu = await timed(() => pathTrace(scene, camera, options), paths, seconds, least);
  const cores = navigator.hardwareConcurrency || 2, crew = new ParallelRenderer({ workers: cores }).warm();
  const workers = await timed(() => crew.render(scene, camera, { path: options }), paths, seconds, least);
  crew.terminate();
  const check = { samples: 16, maxBounces: 16 };
  const means = { gpu: meanOf(pathTraceGPU(scene, camera, check)), cpu: meanOf(pathTrace(scene, camera, check)) };
  const gl = document.createElement('canvas').getContext('webgl2'), info = gl?.getExtension('WEBGL_debug_renderer_info');
  const renderer = gl ? gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER) : 'none';
  return { gpu, cpu, workers: { ...workers, cores }, means, renderer, pixels: width * height };
}

window.bench = { run, ready: true };
