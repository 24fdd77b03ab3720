/**
 * Lights. A point light is a position and a colour; an emissive object (a
 * sphere whose material has an emission) is a light too, at its centre.
 *
 * Every light class answers for itself (the light protocol, lib/lights/index.js,
 * docs/ARCHITECTURE.md "A new light"): its sources for the tracer, its JSON
 * and checks, its code, its 3D drawing and how the inspector shows it.
 */
import { toVec3 } from '../math/vec3.js';
import { middleOf } from '../shapes/index.js';
import { vector } from '../shapes/json.js';
import { checkOptions } from '../text/check.js';
import { lightColor, lightIntensity, checkAttenuation, lightName, fading, definedOnly } from './checks.js';

export { checkAttenuation } from './checks.js';

/** The options a point light takes as its second argument. */
const OPTIONS = ['color', 'intensity', 'attenuation', 'name'];

export class PointLight {
  /**
   * `new PointLight([0, 20, 0])`, `new PointLight(position, color, intensity)`
   * or `new PointLight(position, { color, intensity, attenuation, name })`.
   * @param {number[]|{x,y,z}} position where the light is
   * @param {number[]|string|{ color?: number[]|string, intensity?: number, attenuation?: number, name?: string }} [color=[1,1,1]] its colour, or the options
   * @param {number} [intensity=1] a multiplier, ≥ 0
   *   (options.attenuation, default 0: how it fades with distance d, by 1 / (1 + attenuation·d²); see checkAttenuation)
   * @example
   * const sun = new PointLight([40, 200, 60]);                       // white, intensity 1
   * const lamp = new PointLight([-10, 20, 0], [1, 0.8, 0.6], 0.7);   // a warm, dimmer light
   * const candle = new PointLight([0, 2, -18], { attenuation: 0.04 });  // half as bright 5 away (1 / (1 + 0.04·5²))
   * const scene = new Scene().add(new Sphere([0, 0, -20], 4)).add(sun).add(lamp);
   */
  constructor(position, color = [1, 1, 1], intensity = 1) {
    let name = '', attenuation = 0;
    if (isOptions(color)) {
      if (arguments.length > 2) throw new TypeError('a point light takes (position, { color, intensity }) or (position, color, intensity), not both');
      ({ color = [1, 1, 1], intensity = 1, attenuation = 0, name = '' } = checkOptions(color, OPTIONS, 'point light'));
      lightName(name);
    }
    this.position = toVec3(position, 'position');
    lightIntensity(intensity);
    this.color = lightColor(color);
    this.intensity = intensity;
    /** What it gives off: colour × intensity. */
    this.emission = this.color.map((c) => c * intensity);
    /** How it fades with distance d: by 1 / (1 + attenuation·d²); 0, no fading. */
    this.attenuation = checkAttenuation(attenuation);
    this.name = name;
  }

  /** Its name in scene JSON, and in the code that builds it. */
  static get type() { return 'pointLight'; }
  static get codeName() { return 'PointLight'; }
  /** What the inspector calls it. */
  static get label() { return 'point light'; }
  /** Its fields in scene JSON (besides type and name). */
  static get fields() { return ['position', 'color', 'intensity', 'attenuation']; }
  /** Built from its JSON fields (or its own, to check them again), with the constructor's checks. */
  static build(o) {
    return o.attenuation === undefined ? new PointLight(o.position, o.color, o.intensity)
      : new PointLight(o.position, definedOnly({ color: o.color, intensity: o.intensity, attenuation: o.attenuation }));
  }
  /** Built from its JSON to the last bit (the scene form need not build it again). */
  static get roundTrips() { return true; }

  /**
   * Its constructor's arguments for the code, from its JSON: positional,
   * defaults left out; the options form when it fades (only that form takes attenuation).
   * @param {object} o its JSON
   * @param {{ color: (rgb: number[]) => object }} code writes a colour argument as the code does
   */
  static codeArguments(o, code) {
    if (o.attenuation) return [o.position, { ...(isWhite(o.color) ? {} : { color: o.color }), ...(o.intensity === 1 ? {} : { intensity: o.intensity }), attenuation: o.attenuation }];
    return [o.position, isWhite(o.color) && o.intensity === 1 ? undefined : code.color(o.color), o.intensity === 1 ? undefined : o.intensity];
  }

  toJSON() {
    return { type: 'pointLight', name: this.name ?? '', position: vector(this.position), color: [...this.color], intensity: this.intensity, ...fading(this.attenuation) };
  }

  /**
   * The scene's light sources for it: one, itself.
   * @returns {{ position: import('../math/vec3.js').Vec3, emission: number[], object: null, source: PointLight, attenuation: number }[]}
   */
  sources() {
    return [{ position: this.position, emission: this.emission, object: null, source: this, attenuation: this.attenuation }];
  }

  /** What its drawing in the 3D view depends on (a glow at its position). */
  viewKey() {
    return `${this.position.x},${this.position.y},${this.position.z}`;
  }
}

const isWhite = (c) => c[0] === 1 && c[1] === 1 && c[2] === 1;

/** A plain object (not a colour array or string): the options form. */
function isOptions(value) {
  return value !== null && typeof value === 'object' && !Array.isArray(value) && !ArrayBuffer.isView(value);
}

/**
 * An emissive shape's light source, `{ position, emission, object, source, attenuation }`:
 * at its `middle()` (a sphere's centre, a box's middle); `object` is the shape
 * itself, which a shadow ray may not block; it does not fade with distance.
 * (A light's own sources are its `sources()`.)
 */
export function lightSource(shape) {
  return { position: middleOf(shape), emission: shape.material.emission, object: shape, source: shape, attenuation: 0 };
}
