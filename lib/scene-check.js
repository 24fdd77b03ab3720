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
import { Camera } from './camera.js';
import { Material } from './material.js';
import { PointLight } from './lights.js';
import { SpotLight } from './spot-light.js';
import { AreaLight } from './area-light.js';
import { classOf } from './shapes/index.js';
import { toColor } from './color.js';
import { show, withPath } from './check.js';

/**
 * Checks every field of the scene, its shapes, their materials and its
 * lights (point, spot and area). A colour given as text or one number ('red', 0.5) is turned into
 * [r, g, b] in place, as the constructors do; anything else bad throws.
 * @param {Scene} scene
 */
export function checkScene(scene) {
  withPath(() => new Scene(sceneOptions(scene)), 'scene.');
  scene.background = asColor(scene.background, 'scene.background');
  scene.objects.forEach((o, i) => checkShape(o, `objects[${i}]`));
  scene.lights.forEach(({ source: s }, i) => withPath(() => rebuildLight(s), `lights[${i}].`));
}

/** A point, spot or area light built again from its fields as they are now (a light of the sketch's own is left as it is). */
function rebuildLight(s) {
  const { color, intensity, attenuation } = s;
  if (s instanceof PointLight) new PointLight(s.position, { color, intensity, attenuation });
  else if (s instanceof SpotLight) new SpotLight(s.position, s.target, { angle: s.angle, color, intensity, attenuation, name: s.name });
  else if (s instanceof AreaLight) new AreaLight(s.center, s.radius, { color, intensity, attenuation, samples: s.samples, normal: s.normal, name: s.name });
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
  const { color, emission, reflection, transparency, ior, specular, shininess, fuzz = 0 } = m;
  withPath(() => new Material({ color, emission, reflection, transparency, ior, specular, shininess, fuzz }), `${path}.`);
  m.color = asColor(m.color, `${path}.color`);
  m.emission = asColor(m.emission, `${path}.emission`);
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
