/**
 * The full record of one pixel, built by the same functions the renderer
 * uses: its ray and angles, both intersection routes for every sphere, the
 * hit and how each light coloured it, and the pixel's final colour.
 */
import { intersectQuadratic, intersectGeometric } from './shapes/sphere.js';
import { trace } from './trace.js';
import { writePixel, checkSceneAndCamera } from './render.js';
import { pixelCoordinate } from './check.js';
import { shapeName } from './scene.js';

const _bytes = new Uint8ClampedArray(4);

/**
 * Everything about pixel (x, y):
 * `{ x, y, h, v, ray, tests, hit, color }` — `tests` one entry per sphere
 * `{ sphere, index, name, quadratic, geometric }`; `hit` the nearest hit record
 * (its `name` too) or null; `color` `[r, g, b]` bytes, identical to `render`'s
 * pixel. `name`: the shape's own, else "sphere 1", "plane 1", … (shapeName).
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
  const tests = scene.spheres.map((sphere) => ({
    sphere,
    index: scene.objects.indexOf(sphere),
    name: shapeName(sphere, scene.objects),
    quadratic: intersectQuadratic(ray, sphere),
    geometric: intersectGeometric(ray, sphere),
  }));
  const steps = {};
  const color = trace(scene, ray, [0, 0, 0], steps);
  writePixel(_bytes, 0, color);
  if (steps.hit) steps.hit.name = shapeName(steps.hit.object, scene.objects);
  return { x, y, h, v, ray, tests, hit: steps.hit, light: color, color: [_bytes[0], _bytes[1], _bytes[2]] };
}
