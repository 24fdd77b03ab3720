/**
 * A whole frame into an RGBA buffer: one primary ray per pixel, traced by
 * `trace`, written as bytes the way the inspector writes them too.
 */
import { Ray } from './ray.js';
import { copy } from './vec3.js';
import { trace } from './trace.js';
import { tileCandidates, TILE } from './bounds.js';
import { Scene } from './scene.js';
import { Camera } from './camera.js';
import { show, pixelCoordinate } from './check.js';

const _ray = new Ray();
const _color = [0.5, 0.5, 0.5]; // doubles from the start (one array shape)

/**
 * Renders the scene as seen by the camera, tile by tile: each primary ray is
 * tested only against the shapes that can be under its tile (lib/bounds.js),
 * which gives the same nearest hit as testing them all.
 * @param {Scene} scene
 * @param {Camera} camera
 * @param {Uint8ClampedArray} [target] RGBA, at least width·height·4 bytes (a new one when left out)
 * @param {{y0: number, y1: number}} [rows] render only rows y0 ≤ y < y1 (a worker's band), 0 ≤ y0 ≤ y1 ≤ height
 * @returns {Uint8ClampedArray} RGBA, row by row from the top
 * @example
 * const rgba = render(classScene(), new Camera({ width: 64, height: 48 }));
 * rgba.length; // 64 · 48 · 4 bytes: r, g, b, a of each pixel, row by row from the top left
 */
export function render(scene, camera, target, rows) {
  checkSceneAndCamera(scene, camera);
  const bytes = camera.width * camera.height * 4;
  if (target === undefined) target = new Uint8ClampedArray(bytes);
  else if (!(target instanceof Uint8ClampedArray)) throw new TypeError(`target must be a Uint8ClampedArray, got ${show(target)}`);
  else if (target.length < bytes) throw new RangeError(`target must hold width × height × 4 = ${bytes} bytes, got ${target.length}`);
  const y0 = rows?.y0 ?? 0, y1 = rows?.y1 ?? camera.height;
  if (rows !== undefined) {
    if (rows === null || typeof rows !== 'object') throw new TypeError(`rows must be { y0, y1 }, got ${show(rows)}`);
    pixelCoordinate(y0, 'rows.y0', camera.height + 1);
    pixelCoordinate(y1, 'rows.y1', camera.height + 1);
    if (y1 < y0) throw new RangeError(`rows.y1 must not be less than rows.y0, got y0 = ${y0}, y1 = ${y1}`);
  }
  return renderRows(scene, camera, target, y0, y1, tileCandidates(scene, camera, y0, y1));
}

/**
 * Rows y0 ≤ y < y1 of the frame into `target`, with the tiles' candidate
 * shapes already worked out (`tileCandidates(scene, camera)` covering those
 * rows): a worker finds them once per scene, then renders band after band.
 */
export function renderRows(scene, camera, target, y0, y1, { columns, lists }) {
  const { width } = camera;
  copy(_ray.origin, camera.position); // every primary ray starts at the eye
  for (let ty = Math.floor(y0 / TILE) * TILE; ty < y1; ty += TILE) {
    for (let tx = 0; tx < width; tx += TILE) {
      const objects = lists[(ty / TILE) * columns + tx / TILE];
      renderTile(scene, camera, target, objects, tx, Math.max(ty, y0), Math.min(tx + TILE, width), Math.min(ty + TILE, y1));
    }
  }
  return target;
}

/** The pixels x0 ≤ x < x1, y0 ≤ y < y1, each primary ray tested against `objects` only. */
function renderTile(scene, camera, target, objects, x0, y0, x1, y1) {
  for (let y = y0; y < y1; y++) {
    for (let x = x0, i = (y * camera.width + x0) * 4; x < x1; x++, i += 4) {
      camera.directionAt(x, y, _ray.direction);
      trace(scene, _ray, _color, undefined, 0, objects);
      writePixel(target, i, _color);
    }
  }
}

/**
 * Traces pixel (x, y) and writes its RGBA bytes into `target` at the pixel's place.
 * @param {object[]} [objects=scene.objects] the shapes its ray may hit: all, or its tile's candidates (the same colour)
 */
export function renderPixel(scene, camera, x, y, target, objects = scene.objects) {
  copy(_ray.origin, camera.position);
  camera.directionAt(x, y, _ray.direction);
  trace(scene, _ray, _color, undefined, 0, objects);
  writePixel(target, (y * camera.width + x) * 4, _color);
}

/** Colour (0–1, clamped) to bytes; the one place a float colour becomes a pixel. */
export function writePixel(target, i, color) {
  target[i] = color[0] * 255;
  target[i + 1] = color[1] * 255;
  target[i + 2] = color[2] * 255;
  target[i + 3] = 255;
}

/** A TypeError unless `scene` is a Scene and `camera` a Camera (render's and inspectPixel's first check). */
export function checkSceneAndCamera(scene, camera) {
  if (!(scene instanceof Scene)) throw new TypeError(`scene must be a Scene (new Scene(…)), got ${show(scene)}`);
  if (!(camera instanceof Camera)) throw new TypeError(`camera must be a Camera (new Camera({ width, height })), got ${show(camera)}`);
}
