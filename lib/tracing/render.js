/**
 * A whole frame into an RGBA buffer, tile by tile: each primary ray is tested
 * only against the shapes that can be under its tile (bounds.js), and traced
 * by the fast kernel over the packed scene (kernel.js) or, when the scene does
 * not pack, by trace.js: the same bytes either way. One ray per pixel, or the
 * camera's `samples` averaged. Colours become bytes in one place, writePixel,
 * which the inspector uses too.
 */
import { Ray } from '../math/ray.js';
import { copy } from '../math/vec3.js';
import { trace } from './trace.js';
import { tileCandidates, TILE } from './bounds.js';
import { Scene } from '../scene/scene.js';
import { Camera, sampleOffsets } from '../math/camera.js';
import { clamp } from '../math/numbers.js';
import { show, pixelCoordinate } from '../text/check.js';
import { packScene, tracePrimary } from './kernel.js';
import { checkScene, checkCamera } from '../scene/check.js';
import { readBlocking, checkRenderWork } from './budget.js';

const _ray = new Ray();
const _color = [0.5, 0.5, 0.5]; // doubles from the start (one array shape)

/**
 * Renders the scene as seen by the camera, tile by tile: each primary ray is
 * tested only against the shapes that can be under its tile (lib/tracing/bounds.js),
 * which gives the same nearest hit as testing them all.
 * @param {Scene} scene
 * @param {Camera} camera
 * @param {Uint8ClampedArray} [target] RGBA, at least width·height·4 bytes (a new one when left out)
 * @param {{y0: number, y1: number}} [rows] render only rows y0 ≤ y < y1 (a worker's band), 0 ≤ y0 ≤ y1 ≤ height
 * @param {{ blocking?: boolean }} [options] `blocking: true` traces however long it takes; without it, a frame
 *   of more than RENDER_RAYS rays (lib/tracing/budget.js: about a second on a slow laptop, the page frozen) throws a
 *   RangeError pointing to the tracer view and the Web Workers
 * @returns {Uint8ClampedArray} RGBA, row by row from the top
 * @example
 * const rgba = render(classScene(), new Camera({ width: 64, height: 48 }));
 * rgba.length; // 64 · 48 · 4 bytes: r, g, b, a of each pixel, row by row from the top left
 */
export function render(scene, camera, target, rows, options) {
  checkSceneAndCamera(scene, camera);
  const blocking = readBlocking(options, 'render');
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
  if (!blocking) checkRenderWork(scene, camera, y1 - y0);
  return renderRows(scene, camera, target, y0, y1, prepareFrame(scene, camera, y0, y1));
}

/**
 * What rendering a frame of this scene works out once, before any pixel: the
 * shapes that can be under each tile (lib/tracing/bounds.js) and the scene packed for
 * the fast path (lib/tracing/kernel.js; null when a shape is not a plain listed shape
 * with a packed form: every light packs), with tile t's shapes as indices into it, `candidates[starts[t] …
 * starts[t + 1])`. Good until the scene or camera changes: a worker prepares
 * once per change, then renders band after band.
 * @returns {{ columns: number, lists: object[][], packed: import('./kernel.js').PackedScene|null, candidates: Int32Array|null, starts: Int32Array|null }}
 */
export function prepareFrame(scene, camera, y0 = 0, y1 = camera.height) {
  const { columns, lists } = tileCandidates(scene, camera, y0, y1);
  const packed = packScene(scene);
  if (!packed) return { columns, lists, packed, candidates: null, starts: null };
  const starts = new Int32Array(lists.length + 1);
  for (let t = 0; t < lists.length; t++) starts[t + 1] = starts[t] + (lists[t]?.length ?? 0); // (rows left out: no list)
  const candidates = new Int32Array(starts[lists.length]);
  for (let t = 0; t < lists.length; t++) {
    for (let n = 0; n < (lists[t]?.length ?? 0); n++) candidates[starts[t] + n] = packed.index.get(lists[t][n]);
  }
  return { columns, lists, packed, candidates, starts };
}

/**
 * Rows y0 ≤ y < y1 of the frame into `target`, with what `prepareFrame`
 * worked out for those rows.
 */
export function renderRows(scene, camera, target, y0, y1, prepared) {
  const { width } = camera, { columns } = prepared;
  copy(_ray.origin, camera.position); // every primary ray starts at the eye
  for (let ty = Math.floor(y0 / TILE) * TILE; ty < y1; ty += TILE) {
    for (let tx = 0; tx < width; tx += TILE) {
      const tile = (ty / TILE) * columns + tx / TILE;
      const x0 = tx, x1 = Math.min(tx + TILE, width), y = Math.max(ty, y0), yEnd = Math.min(ty + TILE, y1);
      if (prepared.packed) renderPackedTile(prepared, tile, camera, target, x0, y, x1, yEnd);
      else renderTile(scene, camera, target, prepared.lists[tile], x0, y, x1, yEnd);
    }
  }
  return target;
}

/** The pixels x0 ≤ x < x1, y0 ≤ y < y1, each primary ray tested against `objects` only. */
function renderTile(scene, camera, target, objects, x0, y0, x1, y1) {
  for (let y = y0; y < y1; y++) {
    for (let x = x0, i = (y * camera.width + x0) * 4; x < x1; x++, i += 4) {
      if (camera.samples > 1) {
        writePixel(target, i, traceSamples(scene, camera, x, y, objects));
        continue;
      }
      camera.directionAt(x, y, _ray.direction);
      trace(scene, _ray, _color, undefined, 0, objects);
      writePixel(target, i, _color);
    }
  }
}

/** renderTile by the fast path: the same pixels, by lib/tracing/kernel.js. */
function renderPackedTile(prepared, tile, camera, target, x0, y0, x1, y1) {
  for (let y = y0; y < y1; y++) {
    for (let x = x0, i = (y * camera.width + x0) * 4; x < x1; x++, i += 4) renderPackedPixel(prepared, tile, camera, x, y, target, i);
  }
}

/**
 * Pixel (x, y) of tile `tile` by the fast path, with what `prepareFrame`
 * worked out (`prepared.packed` not null): renderPixel's bytes, sooner. They
 * go to `target` at `i`, the pixel's own place when left out.
 */
export function renderPackedPixel(prepared, tile, camera, x, y, target, i = (y * camera.width + x) * 4) {
  if (camera.samples > 1) {
    writePixel(target, i, tracePackedSamples(prepared, tile, camera, x, y));
    return;
  }
  const d = camera.directionAt(x, y, _ray.direction);
  const color = tracePrimary(prepared.packed, camera.position, d, prepared.candidates, prepared.starts[tile], prepared.starts[tile + 1]);
  writePixel(target, i, color);
}

/**
 * Traces pixel (x, y) and writes its RGBA bytes into `target` at the pixel's place.
 * @param {object[]} [objects=scene.objects] the shapes its ray may hit: all, or its tile's candidates (the same colour)
 */
export function renderPixel(scene, camera, x, y, target, objects = scene.objects) {
  copy(_ray.origin, camera.position);
  if (camera.samples > 1) {
    writePixel(target, (y * camera.width + x) * 4, traceSamples(scene, camera, x, y, objects));
    return;
  }
  camera.directionAt(x, y, _ray.direction);
  trace(scene, _ray, _color, undefined, 0, objects);
  writePixel(target, (y * camera.width + x) * 4, _color);
}

/**
 * Several rays per pixel (camera.samples > 1): the average of the colours of
 * the rays through the centres of the pixel's n × n cells, each clamped to
 * 0–1 first (what that ray alone would show), so an edge pixel is the share
 * of its cells that see each side. Reused array: read it before the next call.
 */
function traceSamples(scene, camera, x, y, objects) {
  const offsets = sampleOffsets(camera.samples);
  _average[0] = _average[1] = _average[2] = 0;
  for (let s = 0; s < offsets.length; s += 2) {
    camera.directionAt(x + offsets[s], y + offsets[s + 1], _ray.direction);
    addClamped(_average, trace(scene, _ray, _color, undefined, 0, objects));
  }
  return divide(_average, offsets.length / 2);
}

/** traceSamples by the fast path (lib/tracing/kernel.js). */
function tracePackedSamples(prepared, tile, camera, x, y) {
  const offsets = sampleOffsets(camera.samples);
  _average[0] = _average[1] = _average[2] = 0;
  for (let s = 0; s < offsets.length; s += 2) {
    const d = camera.directionAt(x + offsets[s], y + offsets[s + 1], _ray.direction);
    addClamped(_average, tracePrimary(prepared.packed, camera.position, d, prepared.candidates, prepared.starts[tile], prepared.starts[tile + 1]));
  }
  return divide(_average, offsets.length / 2);
}

const _average = [0.5, 0.5, 0.5];

function addClamped(sum, color) {
  sum[0] += clamp(color[0], 0, 1); sum[1] += clamp(color[1], 0, 1); sum[2] += clamp(color[2], 0, 1);
}

function divide(sum, n) {
  sum[0] /= n; sum[1] /= n; sum[2] /= n;
  return sum;
}

/** Colour (0–1, clamped) to bytes; the one place a float colour becomes a pixel. */
export function writePixel(target, i, color) {
  target[i] = color[0] * 255;
  target[i + 1] = color[1] * 255;
  target[i + 2] = color[2] * 255;
  target[i + 3] = 255;
}

/**
 * Every tracer's first check (render, renderGPU, pathTrace, inspectPixel,
 * inspectPath, and the renderers as they start again): a TypeError unless
 * `scene` is a Scene and `camera` a Camera, then both checked as they are now
 * (lib/scene/check.js: a sketch may have changed them since they were made),
 * a TypeError or RangeError naming the field (`objects[2].radius`, `lights[1]`).
 * Once per call, never per pixel.
 */
export function checkSceneAndCamera(scene, camera) {
  if (!(scene instanceof Scene)) throw new TypeError(`scene must be a Scene (new Scene(…)), got ${show(scene)}`);
  if (!(camera instanceof Camera)) throw new TypeError(`camera must be a Camera (new Camera({ width, height })), got ${show(camera)}`);
  checkCamera(camera);
  checkScene(scene);
}
