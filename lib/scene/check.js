/**
 * A scene and a camera checked again, as they are now: a sketch may change a
 * sphere's centre or a material's colour after making them, and the next
 * render must say what is wrong, as the constructors do, not fail deep inside
 * with "Cannot read properties of null". Each check rebuilds the part with
 * its own constructor (the same checks, the same messages) and throws the
 * path in front: "objects[0].center must be [x, y, z] or {x, y, z}, got null".
 * Run once per restart, never per pixel.
 */
import { Scene } from './scene.js';
import { Camera } from '../math/camera.js';
import { Material, MATERIAL_FIELDS, materialOptions } from '../shapes/material.js';
import { lightsOf, lightClassOf } from '../lights/index.js';
import { lightName } from '../lights/checks.js';
import { classOf } from '../shapes/index.js';
import { toColor } from '../math/color.js';
import { show, withPath } from '../text/check.js';

/**
 * Checks every field of the scene, its shapes, their materials and its
 * lights. A colour given as text or one number ('red', 0.5) is turned into
 * [r, g, b] in place, as the constructors do; anything else bad throws.
 * @param {Scene} scene
 */
export function checkScene(scene) {
  withPath(() => new Scene(sceneOptions(scene)), 'scene.');
  scene.background = asColor(scene.background, 'scene.background');
  scene.objects.forEach((o, i) => checkShape(o, `objects[${i}]`));
  for (const light of lightsOf(scene)) { // rebuilt by its class from its fields as they are now; named by its first place in scene.lights
    withPath(() => {
      lightClassOf(light).build(light);
      if (light.name !== undefined) lightName(light.name);
    }, `lights[${scene.lights.findIndex((l) => l.source === light)}].`);
  }
}

/**
 * Checks the camera's fields with the Camera constructor's checks, the size
 * limit too (MAX_CAMERA_SIDE, MAX_CAMERA_PIXELS): "camera.width must be at most 16384 pixels, got 50000".
 * @param {Camera} camera
 */
export function checkCamera(camera) {
  const { width, height, fov, position, yaw, pitch, samples } = camera;
  withPath(() => new Camera({ width, height, fov, position, yaw, pitch, samples }), 'camera.');
}

/** The scene's own options as they are now. */
function sceneOptions({ background, ambient, shadows, bias, epsilon, maxDepth, specular }) {
  return { background, ambient, shadows, bias, epsilon, maxDepth, specular };
}

/**
 * One shape: a listed shape (a Sphere, Plane, Box, …) rebuilt by its class's
 * own `build` from its fields as they are now, or checked by its class's
 * `check` (a Mesh: its BVH built again only when its data changed); a shape
 * of the sketch's own (the protocol's methods of its own) by its material alone.
 */
function checkShape(o, path) {
  if (o === null || typeof o !== 'object' || typeof o.hit !== 'function') {
    throw new TypeError(`${path} must be a shape (a Sphere, Plane, Box, … with hit, normalAt, intersect and bounds), got ${show(o)}`);
  }
  const material = checkMaterial(o.material, `${path}.material`);
  const Shape = classOf(o);
  if (Shape) withPath(() => (typeof Shape.check === 'function' ? Shape.check(o, material) : Shape.build(o, material)), `${path}.`);
  if (o.name !== undefined && typeof o.name !== 'string') throw new TypeError(`${path}.name must be text, got ${show(o.name)}`);
}

/** A shape's material, checked by the Material constructor; its colours made [r, g, b]. */
function checkMaterial(m, path) {
  if (!(m instanceof Material)) throw new TypeError(`${path} must be a Material, got ${show(m)}`);
  withPath(() => new Material(materialOptions(m)), `${path}.`);
  for (const { name, numbers } of MATERIAL_FIELDS) if (numbers > 1) m[name] = asColor(m[name], `${path}.${name}`); // the colours
  return m;
}

/**
 * A colour already checked: an array stays (the same array), text or a number becomes [r, g, b].
 * @param {any} value
 * @param {string} field
 * @returns {number[]}
 */
function asColor(value, field) {
  return Array.isArray(value) || ArrayBuffer.isView(value) ? /** @type {number[]} */ (value) : toColor(value, field);
}
