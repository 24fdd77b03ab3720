/**
 * A scene and a camera checked again, as they are now: a sketch may change a
 * sphere's centre or a material's colour after making them, and the next
 * render must say what is wrong, as the constructors do, not fail deep inside
 * with "Cannot read properties of null" or give a black picture. Each part is
 * checked by its own class with the constructor's own checks (the same
 * messages) and the path goes in front: "objects[0].center must be [x, y, z]
 * or {x, y, z}, got null". Every tracer runs it once per call (render,
 * renderGPU, pathTrace, inspectPixel, inspectPath, and each renderer as it
 * starts again), never per pixel.
 */
import { Scene } from './scene.js';
import { Camera, MAX_CAMERA_SIDE, MAX_CAMERA_PIXELS } from '../math/camera.js';
import { Vec3 } from '../math/vec3.js';
import { Material, MATERIAL_FIELDS } from '../shapes/material.js';
import { lightClassOf } from '../lights/index.js';
import { lightName } from '../lights/checks.js';
import { classOf, isShape, middleOf } from '../shapes/index.js';
import { toColor, MAX_COLOR } from '../math/color.js';
import { finiteNumber, show, withPath } from '../text/check.js';

/**
 * Checks every field of the scene, its shapes, their materials and its
 * lights. A colour given as text or one number ('red', 0.5) is turned into
 * [r, g, b] in place, as the constructors do; anything else bad throws a
 * TypeError or RangeError naming the field: `objects[2].radius`,
 * `objects[0].material.emission`, `lights[1]`, `scene.background`.
 * @param {Scene} scene
 */
export function checkScene(scene) {
  if (!sceneFieldsFine(scene)) { // the constructor's checks say which and why (or read a colour given as text)
    withPath(() => new Scene(sceneOptions(scene)), 'scene.');
    scene.background = asColor(scene.background, 'scene.background');
  }
  if (!Array.isArray(scene.objects)) throw new TypeError(`scene.objects must be a list of shapes, got ${show(scene.objects)}`);
  if (!Array.isArray(scene.lights)) throw new TypeError(`scene.lights must be a list of light sources, got ${show(scene.lights)}`);
  for (let i = 0; i < scene.objects.length; i++) {
    try {
      checkShape(scene.objects[i], i);
    } catch (error) {
      throw alsoAsShapes(error, i);
    }
  }
  checkLights(scene.lights);
}
/**
 * Checks the camera's fields with the Camera constructor's checks, the size
 * limit too (MAX_CAMERA_SIDE, MAX_CAMERA_PIXELS): "camera.width must be at most 16384 pixels, got 50000".
 * @param {Camera} camera
 */
export function checkCamera(camera) {
  if (cameraFieldsFine(camera)) return;
  const { width, height, fov, position, yaw, pitch, samples } = camera;
  withPath(() => new Camera({ width, height, fov, position, yaw, pitch, samples }), 'camera.');
}

/**
 * The quick look before the constructors' checks (once per trace, so
 * nothing built while all is well): true when every field is what the
 * constructor makes of good options; anything else goes to the constructor,
 * which names the field in its own words.
 */
function sceneFieldsFine({ background, ambient, shadows, bias, epsilon, maxDepth, specular }) {
  return isColor(background) && inUnit(ambient) && inUnit(bias) && inUnit(epsilon) && typeof shadows === 'boolean' && typeof specular === 'boolean'
    && Number.isInteger(maxDepth) && maxDepth >= 0 && maxDepth <= 16;
}

/** cameraFieldsFine: sceneFieldsFine's quick look, for a camera. */
function cameraFieldsFine({ width: w, height: h, fov, position: p, yaw, pitch, samples }) {
  return Number.isInteger(w) && w > 0 && w <= MAX_CAMERA_SIDE && Number.isInteger(h) && h > 0 && h <= MAX_CAMERA_SIDE && w * h <= MAX_CAMERA_PIXELS
    && typeof fov === 'number' && fov > 0 && fov < 180 && p instanceof Vec3 && Number.isFinite(p.x) && Number.isFinite(p.y) && Number.isFinite(p.z)
    && Number.isFinite(yaw) && typeof pitch === 'number' && pitch >= -90 && pitch <= 90 && (samples === 1 || samples === 4 || samples === 9 || samples === 16);
}

const inUnit = (v) => typeof v === 'number' && v >= 0 && v <= 1;

/** The scene's own options as they are now. */
function sceneOptions({ background, ambient, shadows, bias, epsilon, maxDepth, specular }) {
  return { background, ambient, shadows, bias, epsilon, maxDepth, specular };
}

/**
 * One shape: a listed shape (a Sphere, Plane, Box, …) checked by its class's
 * `check` when it has one (a fast look at its fields; a Mesh builds its BVH
 * again only when its data changed), else rebuilt by its class's own `build`
 * from its fields as they are now; a shape of the sketch's own (the
 * protocol's methods of its own) by its material alone.
 */
function checkShape(o, i) {
  if (o === null || typeof o !== 'object' || typeof o.hit !== 'function') {
    throw new TypeError(`objects[${i}] must be a shape (a Sphere, Plane, Box, … with hit, normalAt, intersect and bounds), got ${show(o)}`);
  }
  const material = o.material;
  checkMaterial(material, i);
  const Shape = classOf(o);
  if (Shape) {
    try {
      if (typeof Shape.check === 'function') Shape.check(o, material);
      else Shape.build(o, material);
    } catch (error) {
      named(error, `objects[${i}].`);
    }
  }
  if (o.name !== undefined && typeof o.name !== 'string') throw new TypeError(`objects[${i}].name must be text, got ${show(o.name)}`);
}

/**
 * A shape's material, field by field with the Material constructor's own
 * checks (MATERIAL_FIELDS); a colour that is already three numbers in range is
 * taken as it is (nothing built), text or one number becomes [r, g, b] in place.
 */
function checkMaterial(m, i) {
  if (!(m instanceof Material)) throw new TypeError(`objects[${i}].material must be a Material, got ${show(m)}`);
  for (const { name, numbers, check } of MATERIAL_FIELDS) {
    const value = m[name];
    if (numbers > 1 && isColor(value)) continue;
    try {
      const read = check(value);
      if (numbers > 1) m[name] = read;
    } catch (error) {
      named(error, `objects[${i}].material.`);
    }
  }
}

/** Three finite numbers from 0 to MAX_COLOR: a colour toColor would take as it is. */
function isColor(value) {
  if (!(Array.isArray(value) || ArrayBuffer.isView(value))) return false;
  const list = /** @type {ArrayLike<unknown>} */ (value);
  if (list.length !== 3) return false;
  for (let c = 0; c < 3; c++) {
    const v = list[c];
    if (typeof v !== 'number' || !(v >= 0 && v <= MAX_COLOR)) return false;
  }
  return true;
}

/**
 * The scene's light sources (scene.lights, as Scene.add makes them): each an
 * object with a finite position and emission; a light behind them (a
 * PointLight, SpotLight, AreaLight) rebuilt once by its class from its fields
 * as they are now, named by its first place in scene.lights.
 */
function checkLights(lights) {
  let checked = null; // the lights rebuilt so far (an area light has many sources)
  for (let i = 0; i < lights.length; i++) {
    const l = lights[i];
    if (l === null || typeof l !== 'object' || typeof l.position !== 'object' || l.position === null || !('source' in l)) {
      throw new TypeError(`lights[${i}] must be a light source as scene.add(light) makes them (add lights with scene.add(new PointLight(…)), not lights.push), got ${show(l)}`);
    }
    const emissive = l.object !== null && typeof l.object === 'object' && l.object.material instanceof Material; // a lamp: a shape's source
    const Light = emissive ? undefined : lightClassOf(l.source);
    if (Light && !checked?.has(l.source)) {
      try {
        Light.build(l.source);
        if (l.source.name !== undefined) lightName(l.source.name);
      } catch (error) {
        named(error, `lights[${i}].`);
      }
      (checked ??= new Set()).add(l.source);
    }
    if (emissive && isShape(l.object)) { // an emissive shape's source: where it is and what it gives off, as they are now
      l.position = middleOf(l.object);
      l.emission = l.object.material.emission;
    }
    try {
      checkSource(l);
    } catch (error) {
      named(error, `lights[${i}].`);
    }
  }
}

/**
 * The numbers the tracers read from a light source: where it is and what it
 * gives off (a light's colour × intensity, so past MAX_COLOR, but finite and not negative).
 */
function checkSource(l) {
  const { position: p, emission: e } = l;
  finiteNumber(p.x, 'position.x'); finiteNumber(p.y, 'position.y'); finiteNumber(p.z, 'position.z');
  if (!(Array.isArray(e) || ArrayBuffer.isView(e)) || /** @type {ArrayLike<number>} */ (e).length !== 3) throw new TypeError(`emission must be [r, g, b], got ${show(e)}`);
  for (let c = 0; c < 3; c++) {
    if (!(finiteNumber(e[c], `emission[${c}]`) >= 0)) throw new RangeError(`emission[${c}] must not be negative, got ${e[c]}`);
  }
}

/** Throws `error` again with `prefix` in front of its message (as withPath does), keeping its kind. */
/**
 * A shape's mistake also by the path through `scene.shapes` (the same list as
 * `scene.objects`, whose name the scene's JSON and the earlier messages use):
 * "objects[2].radius must be … (scene.shapes[2].radius)".
 */
function alsoAsShapes(error, i) {
  const path = new RegExp(`^objects\\[${i}\\]((?:\\.\\w+)*)`).exec(error?.message ?? '');
  if (!path || !(error instanceof TypeError || error instanceof RangeError)) return error;
  const Kind = error instanceof TypeError ? TypeError : RangeError;
  return new Kind(`${error.message} (scene.shapes[${i}]${path[1]})`, { cause: error });
}

function named(error, prefix) {
  withPath(() => { throw error; }, prefix);
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
