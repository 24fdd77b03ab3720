/**
 * renderGPU(scene, camera): render()'s frame traced on the GPU, for a page
 * with WebGL2 (no p5 needed). One engine (one WebGL2 context) serves every
 * call, made at the first; a lost context is made again at the next call.
 */
import { checkSceneAndCamera } from '../tracing/render.js';
import { GpuTracer } from './engine.js';
import { readBlocking, checkGpuWork } from '../tracing/budget.js';

let engine = null;

/**
 * The frame `render(scene, camera)` gives, traced by a WebGL2 fragment shader
 * that follows lib/tracing/kernel.js step for step in float32: per channel within 2
 * of render()'s bytes on all but grazing pixels (tests/e2e/gpu.spec.js).
 * @param {import('../scene/scene.js').Scene} scene
 * @param {import('../math/camera.js').Camera} camera
 * @param {{ blocking?: boolean }} [options] `blocking: true` waits however long the GPU takes; without it, a frame
 *   of more than GPU_SHAPE_TESTS ray–shape tests (pixels × shapes, lib/tracing/budget.js) throws a RangeError
 * @returns {Uint8ClampedArray} RGBA, width × height × 4, row 0 at the top
 * @throws {Error} without WebGL2, or for a shape the GPU cannot draw (the error names it)
 * @example
 * const frame = () => renderGPU(classScene({ full: true }), new Camera({ width: 640, height: 480 }));
 * // in a browser with WebGL2, frame() is render()'s picture traced on the GPU;
 * // in Node it throws "the GPU engine needs WebGL2: there is no canvas here (a browser is needed)"
 */
export function renderGPU(scene, camera, options) {
  checkSceneAndCamera(scene, camera);
  if (!readBlocking(options, 'renderGPU')) checkGpuWork(scene, camera);
  if (!engine || engine.lost) engine = new GpuTracer();
  engine.setScene(scene);
  engine.draw(camera);
  return engine.read(new Uint8ClampedArray(camera.width * camera.height * 4), camera.width, camera.height);
}
