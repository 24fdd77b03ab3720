/**
 * The class library's material model: a surface colour, how much it reflects
 * and lets through (0–1), and an emission — an emissive object is a light.
 * Specular highlights (Phong) and the index of refraction are extensions.
 */
import { toColor } from '../math/color.js';
import { numberInRange, show, checkOptions } from '../text/check.js';

/**
 * The material's fields, in one table that its options and checks, its JSON
 * (lib/shapes/json.js), its code (lib/scene/json.js), the restart checks
 * (lib/scene/check.js) and its packed numbers (packMaterial, for lib/tracing/kernel.js)
 * all read: a new field is one more row. `value` is its default, `check`
 * reads a given value (a colour: [r, g, b] from an array, a string or one
 * number), `numbers` how many numbers it packs as, in this order (0: none,
 * a field the kernel does not read), `omitAtDefault` leaves it out of the JSON
 * while it is its default.
 */
export const MATERIAL_FIELDS = Object.freeze([
  { name: 'color', value: [1, 1, 1], check: (v) => toColor(v, 'color'), numbers: 3 },
  { name: 'emission', value: [0, 0, 0], check: (v) => toColor(v, 'emission'), numbers: 3 },
  { name: 'reflection', value: 0, check: (v) => numberInRange(v, 'reflection', 0, 1), numbers: 1 },
  { name: 'transparency', value: 0, check: (v) => numberInRange(v, 'transparency', 0, 1), numbers: 1 },
  { name: 'ior', value: 1.1, check: (v) => numberInRange(v, 'ior', 1, 4), numbers: 1 },
  { name: 'specular', value: 0, check: (v) => numberInRange(v, 'specular', 0, 1), numbers: 1 },
  { name: 'shininess', value: 50, check: (v) => numberInRange(v, 'shininess', 1, 10000), numbers: 1 },
  // The path tracer's metal blur: Whitted's tracer ignores it; it packs as one number, last, for the GPU's path
  // tracer (lib/gpu/glsl-paths.js), which reads the packed scene. Left out of the JSON at 0, so scenes saved before
  // it read and write the same.
  { name: 'fuzz', value: 0, check: (v) => numberInRange(v, 'fuzz', 0, 1), numbers: 1, omitAtDefault: true },
].map((field) => Object.freeze(field)));

/** The options a material takes: its fields' names. */
const OPTIONS = MATERIAL_FIELDS.map((field) => field.name);

/** Field `name`'s value from what was given (undefined: its default), checked by its row of the table. */
function readField(name, given) {
  const { value, check } = MATERIAL_FIELDS.find((field) => field.name === name);
  return check(given === undefined ? (Array.isArray(value) ? [...value] : value) : given);
}

/** Numbers per material in the packed scene, and where each field's first one lies (`MATERIAL_AT.emission` is 3). */
export const MATERIAL_NUMBERS = MATERIAL_FIELDS.reduce((sum, field) => sum + field.numbers, 0);
export const MATERIAL_AT = Object.freeze(Object.fromEntries(MATERIAL_FIELDS.map((field, i) => [field.name, MATERIAL_FIELDS.slice(0, i).reduce((sum, f) => sum + f.numbers, 0)])));
/**
 * The same layout by the names the tracers' loops use: MATERIAL (numbers per material), COLOR,
 * EMISSION, … FUZZ. The kernel and the path tracer keep literal copies of the ones they read
 * (V8 folds a module's own literal, not an imported number) and check them against this at load.
 * @type {Readonly<Record<string, number>>}
 */
export const MATERIAL_LAYOUT = Object.freeze({ MATERIAL: MATERIAL_NUMBERS, ...Object.fromEntries(Object.entries(MATERIAL_AT).map(([name, at]) => [name.toUpperCase(), at])) });

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
    const given = checkOptions(options, OPTIONS, 'material');
    const read = (name) => readField(name, given[name]); // each field by its row of MATERIAL_FIELDS, in the table's order
    /** @type {number[]} */ this.color = read('color');
    /** @type {number[]} */ this.emission = read('emission');
    /** @type {number} */ this.reflection = read('reflection');
    /** @type {number} */ this.transparency = read('transparency');
    /** @type {number} */ this.ior = read('ior');
    /** @type {number} */ this.specular = read('specular');
    /** @type {number} */ this.shininess = read('shininess');
    /** @type {number} */ this.fuzz = read('fuzz');
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

/** A material's fields as options (`new Material(materialOptions(m))` builds it again, checked). */
export function materialOptions(m) {
  return Object.fromEntries(MATERIAL_FIELDS.map(({ name }) => [name, m[name]]));
}

/** A material's fields as JSON: colours as new [r, g, b] arrays; a field marked `omitAtDefault` only when it is not its default. */
export function materialJSON(m) {
  const written = MATERIAL_FIELDS.filter(({ name, value, omitAtDefault }) => !(omitAtDefault && m[name] === value));
  return Object.fromEntries(written.map(({ name, numbers }) => [name, numbers > 1 ? [...m[name]] : m[name]]));
}

/** A material's MATERIAL_NUMBERS numbers into `out` at `at`, in the table's order. */
export function packMaterial(m, out, at) {
  for (const { name, numbers } of MATERIAL_FIELDS) {
    if (numbers === 1) out[at++] = m[name];
    else for (let i = 0; i < numbers; i++) out[at++] = m[name][i];
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
