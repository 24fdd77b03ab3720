/**
 * The class library's material model: a surface colour, how much it reflects
 * and lets through (0–1), and an emission — an emissive object is a light.
 * Specular highlights (Phong) and the index of refraction are extensions.
 */
import { toColor } from './color.js';
import { numberInRange, show, checkOptions } from './check.js';

/** The options a material takes. */
const OPTIONS = ['color', 'emission', 'reflection', 'transparency', 'ior', 'specular', 'shininess', 'fuzz'];

export class Material {
  /**
   * @param {object} [options]
   * @param {number[]|string} [options.color=[1,1,1]] surface colour (0–1)
   * @param {number|number[]|string} [options.emission=0] light given off; a number n is [n, n, n]
   * @param {number} [options.reflection=0] share of light mirrored, 0–1
   * @param {number} [options.transparency=0] share of light let through, 0–1
   * @param {number} [options.ior=1.1] index of refraction inside (the class library's 1.1)
   * @param {number} [options.specular=0] strength of the highlight, 0–1
   * @param {number} [options.shininess=50] highlight sharpness (Phong exponent), ≥ 1
   * @param {number} [options.fuzz=0] how much a mirror blurs what it reflects, 0–1: the path tracer's metal (docs/path-tracing.md); Whitted's tracer ignores it
   * @example
   * const mirror = new Material({ color: [0.9, 0.9, 0.9], reflection: 0.8 });
   * const glass = new Material({ color: 'white', transparency: 0.9, ior: 1.5 });
   * const ball = new Sphere([0, 0, -20], 4, glass); // or the same options as a plain object
   */
  constructor(options = {}) {
    if (options === null || typeof options !== 'object') {
      throw new TypeError(`material must be an object like { color: [1, 0, 0] }, got ${show(options)}`);
    }
    const {
      color = [1, 1, 1], emission = 0, reflection = 0, transparency = 0,
      ior = 1.1, specular = 0, shininess = 50, fuzz = 0,
    } = checkOptions(options, OPTIONS, 'material');
    this.color = toColor(color, 'color');
    this.emission = toColor(emission, 'emission');
    this.reflection = numberInRange(reflection, 'reflection', 0, 1);
    this.transparency = numberInRange(transparency, 'transparency', 0, 1);
    this.ior = numberInRange(ior, 'ior', 1, 4);
    this.specular = numberInRange(specular, 'specular', 0, 1);
    this.shininess = numberInRange(shininess, 'shininess', 1, 10000);
    this.fuzz = numberInRange(fuzz, 'fuzz', 0, 1);
  }

  /** True when the material gives off light (it is then a light of the scene). */
  get isEmissive() {
    return this.emission[0] > 0 || this.emission[1] > 0 || this.emission[2] > 0;
  }

  /** A Material from a Material, a plain options object, or undefined (white). */
  static from(value) {
    if (value instanceof Material) return value;
    return new Material(value ?? {});
  }
}

/**
 * A shape's last argument: a Material, or material options that may also name
 * the shape, `{ color: 'pink', name: 'ball' }` (the inspector and the
 * diagrams call it by that name).
 * @param {Material|object} [value]
 * @returns {{ name: string, material: Material }}
 */
export function shapeOptions(value) {
  if (value === undefined || value instanceof Material) return { name: '', material: Material.from(value) };
  const { name = '', ...material } = checkOptions(value, [...OPTIONS, 'name'], 'material');
  if (typeof name !== 'string') throw new TypeError(`name must be text, got ${show(name)}`);
  return { name, material: Material.from(material) };
}
