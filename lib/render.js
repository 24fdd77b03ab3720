/**
 * A whole frame into an RGBA buffer: one primary ray per pixel, traced by
 * `trace`, written as bytes the way the inspector writes them too.
 */
import { Ray } from './ray.js';
import { copy } from './vec3.js';
import { trace } from './trace.js';

const _ray = new Ray();
const _color = [0.5, 0.5, 0.5]; // doubles from the start (one array shape)

/**
 * Renders the scene as seen by the camera.
 * @returns {Uint8ClampedArray} RGBA, width·height·4 bytes, row by row from the top
 */
export function render(scene, camera, target = new Uint8ClampedArray(camera.width * camera.height * 4)) {
  const { width, height } = camera;
  copy(_ray.origin, camera.position); // every primary ray starts at the eye
  for (let y = 0, i = 0; y < height; y++) {
    for (let x = 0; x < width; x++, i += 4) {
      camera.directionAt(x, y, _ray.direction);
      trace(scene, _ray, _color);
      writePixel(target, i, _color);
    }
  }
  return target;
}

/** Traces pixel (x, y) and writes its RGBA bytes into `target` at the pixel's place. */
export function renderPixel(scene, camera, x, y, target) {
  copy(_ray.origin, camera.position);
  camera.directionAt(x, y, _ray.direction);
  trace(scene, _ray, _color);
  writePixel(target, (y * camera.width + x) * 4, _color);
}

/** Colour (0–1, clamped) to bytes; the one place a float colour becomes a pixel. */
export function writePixel(target, i, color) {
  target[i] = color[0] * 255;
  target[i + 1] = color[1] * 255;
  target[i + 2] = color[2] * 255;
  target[i + 3] = 255;
}
