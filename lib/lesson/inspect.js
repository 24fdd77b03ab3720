/**
 * The full record of one pixel, built by the same functions the renderer
 * uses: its ray and angles, both intersection routes for every sphere, the
 * hit and how each light coloured it, and the pixel's final colour.
 */
import { intersectQuadratic, intersectGeometric } from '../shapes/sphere.js';
import { trace } from '../tracing/trace.js';
import { writePixel, checkSceneAndCamera } from '../tracing/render.js';
import { pixelCoordinate } from '../text/check.js';
import { shapeName, shapeNames } from '../scene/scene.js';
import { sampleOffsets } from '../math/camera.js';
import { clamp } from '../math/numbers.js';
import { lightClassOf } from '../lights/index.js';

const _bytes = new Uint8ClampedArray(4);

/**
 * Everything about pixel (x, y):
 * `{ x, y, h, v, ray, tests, records, hit, color }` — `tests` one entry per sphere
 * `{ sphere, index, name, quadratic, geometric }`; `records` one per shape
 * `{ object, index, name, record, rows }`, its own `intersect` record (a
 * plane's Rd·n and t, a box's slabs) and that record's `[label, value]`
 * lines (its `recordRows`, else its numbers); `hit` the nearest hit record
 * (its `name` too) or null; `color` `[r, g, b]` bytes, identical to `render`'s
 * pixel; `tracedColor` the colour as traced, before it became bytes (0–1, a
 * bright highlight over 1; `light` is its old name). `name`: the shape's own,
 * else "sphere 1", "plane 1", … (shapeName).
 * @example
 * const record = inspectPixel(classScene(), new Camera({ width: 64, height: 48 }), 32, 24);
 * record.tests[0].quadratic.discriminant; // the first sphere's discriminant for this pixel's ray
 * record.color;                           // [r, g, b], the very bytes render() gives this pixel
 */
export function inspectPixel(scene, camera, x, y) {
  checkSceneAndCamera(scene, camera);
  pixelCoordinate(x, 'x', camera.width);
  pixelCoordinate(y, 'y', camera.height);
  const { ray, h, v } = camera.primaryRay(x, y);
  const names = shapeNames(scene.objects), first = new Map();
  scene.objects.forEach((object, index) => { if (!first.has(object)) first.set(object, index); });
  const tests = scene.spheres.map((sphere) => ({
    sphere,
    index: first.get(sphere),
    name: names[first.get(sphere)],
    quadratic: intersectQuadratic(ray, sphere),
    geometric: intersectGeometric(ray, sphere),
  }));
  const records = scene.objects.map((object, index) => {
    const record = typeof object.intersect === 'function' ? object.intersect(ray) : { t: null };
    return { object, index, name: names[index], record, rows: recordRows(object, record) };
  });
  const steps = {};
  const color = trace(scene, ray, [0, 0, 0], steps);
  writePixel(_bytes, 0, color);
  if (steps.hit) steps.hit.name = shapeName(steps.hit.object, scene.objects);
  groupAreaLights(steps.hit);
  const record = { x, y, h, v, ray, tests, records, hit: steps.hit, tracedColor: color, light: color, color: [_bytes[0], _bytes[1], _bytes[2]] };
  if (camera.samples > 1) addSamples(record, scene, camera);
  return record;
}

/**
 * Several rays per pixel: `record.samples`, one entry per sub-pixel ray
 * `{ dx, dy, ray, h, v, hit, t, color }` (its offset from the pixel's centre, what
 * it hit and how far along (null for a miss), its colour as bytes), and `record.color` becomes their average, the
 * very bytes render() gives the pixel. The rest of the record (the tests, the
 * hit) stays the ray through the pixel's centre.
 */
function addSamples(record, scene, camera) {
  const offsets = sampleOffsets(camera.samples), sum = [0, 0, 0];
  record.samples = [];
  for (let s = 0; s < offsets.length; s += 2) {
    const dx = offsets[s], dy = offsets[s + 1], { ray, h, v } = camera.primaryRay(record.x + dx, record.y + dy);
    const steps = {}, light = trace(scene, ray, [0, 0, 0], steps);
    for (let c = 0; c < 3; c++) sum[c] += clamp(light[c], 0, 1);
    writePixel(_bytes, 0, light);
    record.samples.push({ dx, dy, ray, h, v, hit: steps.hit ? shapeName(steps.hit.object, scene.objects) : null, t: steps.hit ? steps.hit.t : null, color: [_bytes[0], _bytes[1], _bytes[2]] });
  }
  writePixel(_bytes, 0, sum.map((c) => c / camera.samples));
  record.color = [_bytes[0], _bytes[1], _bytes[2]];
}

/**
 * An area light casts one shadow ray per sample point, so the hit record has
 * one `lights` entry per point. `hit.areaLights` gathers them, one entry per
 * light whose class is `grouped` (an AreaLight), in the order it first appears: `{ light, label, samples, reached,
 * transmission, contribution, rays }` — `reached` the shadow rays that got to
 * the light (some light through), `transmission` their sum (the share of the
 * disc seen, × samples), `contribution` the sum of what they added, `rays` the
 * per-point entries themselves (still in `hit.lights` too), and `indices`
 * where they sit in `hit.lights`; each of those entries gets its point's
 * `sample` number. The same for every bounce's hit.
 */
export function groupAreaLights(hit) {
  if (!hit) return;
  const groups = new Map();
  hit.lights.forEach((l, index) => {
    const Light = /** @type {any} */ (lightClassOf(l.light));
    if (!Light?.grouped) return; // a point or spot light: its own row
    let g = groups.get(l.light);
    if (!g) groups.set(l.light, g = { light: l.light, label: Light.label, samples: 0, reached: 0, transmission: 0, contribution: [0, 0, 0], rays: [], indices: [] });
    l.sample = g.samples++; // its point's number: scene.lights holds them in the disc's order
    if (l.transmission > 0) g.reached++;
    g.transmission += l.transmission;
    for (let c = 0; c < 3; c++) g.contribution[c] += l.contribution[c];
    g.rays.push(l);
    g.indices.push(index);
  });
  hit.areaLights = [...groups.values()];
  groupAreaLights(hit.reflection?.hit);
  groupAreaLights(hit.refraction?.hit);
}

/** A shape's record as `[label, value]` lines: the shape's own `recordRows`, else the record's numbers by name. */
function recordRows(object, record) {
  if (typeof object.recordRows === 'function') return object.recordRows(record);
  return Object.entries(record).filter(([, v]) => v === null || typeof v === 'number');
}
