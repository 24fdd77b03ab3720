/**
 * A scene: shapes, lights, a background colour and the switches of the
 * lesson's lighting (ambient term, shadows, shadow-ray offset, mirror depth).
 */
import { toColor } from '../math/color.js';
import { numberInRange, bool, show, checkOptions } from '../text/check.js';
import { EPSILON } from '../math/constants.js';
import { isShape, ballOf, kindOf } from '../shapes/index.js';
import { lightSource } from '../lights/point-light.js';
import { isLight } from '../lights/index.js';

/** The options a scene takes. */
const OPTIONS = ['background', 'ambient', 'shadows', 'bias', 'epsilon', 'maxDepth', 'specular'];

export class Scene {
  /**
   * @param {object} [options]
   * @param {number[]|string} [options.background=[0,0,0]] colour of a ray that hits nothing
   * @param {number} [options.ambient=0] light that reaches everything, 0–1
   * @param {boolean} [options.shadows=true] cast shadow rays toward each light
   * @param {number} [options.bias=1e-4] how far a shadow or mirror ray starts off the surface
   * @param {number} [options.epsilon=1e-6] the smallest t that counts as a hit; with bias 0 and epsilon 0 a
   *   surface shadows itself at random ("shadow acne"), which is what the two guard against
   * @param {number} [options.maxDepth=5] how many mirror/glass bounces a ray may take, 0–16
   * @param {boolean} [options.specular=true] draw highlights of materials with `specular` > 0
   * @example
   * const scene = new Scene({ background: [0.85, 0.92, 1], ambient: 0.1 })
   *   .add(new Sphere([0, 0, -20], 4, { color: 'pink' }))
   *   .add(new PointLight([-10, 20, 0]));
   * scene.objects.length; // 1 shape; scene.lights.length: 1 light
   */
  constructor(options = {}) {
    const { background = [0, 0, 0], ambient = 0, shadows = true, bias = 1e-4, epsilon = EPSILON, maxDepth = 5, specular = true } = checkOptions(options, OPTIONS, 'scene');
    this.background = toColor(background, 'background');
    this.ambient = numberInRange(ambient, 'ambient', 0, 1);
    this.shadows = bool(shadows, 'shadows');
    this.bias = numberInRange(bias, 'bias', 0, 1);
    this.epsilon = numberInRange(epsilon, 'epsilon', 0, 1);
    this.maxDepth = numberInRange(maxDepth, 'maxDepth', 0, 16);
    if (!Number.isInteger(maxDepth)) throw new RangeError(`maxDepth must be a whole number, got ${maxDepth}`);
    this.specular = bool(specular, 'specular');
    /** Shapes a ray can hit, in the order added. */
    this.objects = [];
    /** Light sources `{ position, emission, object, source }`, kept in step with `objects`. */
    this.lights = [];
  }

  /**
   * Adds a shape (a Sphere, Plane, Box or any object with the shape protocol, lib/shapes/index.js)
   * or a light (a PointLight, SpotLight, AreaLight or any listed light, lib/lights/index.js); returns the scene (chainable).
   */
  add(item) {
    if (isLight(item)) {
      this.lights.push(...item.sources()); // a point light's one source, an area light's one per point of its disc
    } else if (isShape(item)) {
      this.objects.push(item);
      if (item.material.isEmissive) this.lights.push(lightSource(item));
    } else {
      throw new TypeError(`scene.add takes a shape (a Sphere, Plane, Box, … with hit, normalAt, intersect, bounds and a material), a PointLight, SpotLight or AreaLight, got ${show(item)}`);
    }
    return this;
  }

  /** Removes a shape or light added before; returns the scene. */
  remove(item) {
    this.objects = this.objects.filter((o) => o !== item);
    this.lights = this.lights.filter((l) => l.source !== item);
    return this;
  }

  /** The scene's shapes, in order: `objects` by the name the tracers' messages use (`shapes[2].radius`). */
  get shapes() {
    return this.objects;
  }

  /** Every sphere (every ball), in order: the inspector tests each of them by both routes. */
  get spheres() {
    return this.objects.filter((o) => ballOf(o) !== null);
  }
}

/**
 * The name a shape goes by on the page: its own `name`, else its kind and its
 * number among the scene's shapes of that kind, counted from 1 as a class
 * does ("sphere 1", "plane 1", "box 2").
 * @param {{ name?: string }} object a shape of `objects`
 * @param {readonly object[]} objects the scene's shapes, in order
 * @returns {string}
 * @example
 * const scene = new Scene().add(new Plane([0, -1, 0], [0, 1, 0])).add(new Sphere([0, 0, -20], 4));
 * shapeName(scene.objects[1], scene.objects); // 'sphere 1'
 */
export function shapeName(object, objects) {
  if (object?.name) return object.name;
  const word = kindOf(object);
  const same = word === 'object' ? objects : objects.filter((o) => kindOf(o) === word);
  const number = same.indexOf(object) + 1;
  return number > 0 ? `${word} ${number}` : word;
}

/**
 * shapeName of every shape of `objects`, in one pass (a 10,000-shape scene
 * would take 10,000 passes one shape at a time).
 * @param {readonly object[]} objects the scene's shapes, in order
 * @returns {string[]}
 */
export function shapeNames(objects) {
  const counts = new Map(), numbers = new Map(); // per kind word: how many so far; per shape: its number (the first place it stands)
  objects.forEach((o, i) => {
    const word = kindOf(o), n = word === 'object' ? i + 1 : (counts.get(word) ?? 0) + 1;
    counts.set(word, n);
    if (!numbers.has(o)) numbers.set(o, n);
  });
  return objects.map((o) => (o?.name ? o.name : `${kindOf(o)} ${numbers.get(o)}`));
}
