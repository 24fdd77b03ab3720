/**
 * Lights. A point light is a position and a colour; an emissive object (a
 * sphere whose material has an emission) is a light too, at its centre.
 */
import { toVec3 } from './vec3.js';
import { middleOf } from './shapes/index.js';
import { toColor, MAX_COLOR } from './color.js';
import { finiteNumber, checkOptions, show } from './check.js';

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
      if (typeof name !== 'string') throw new TypeError(`name must be text, got ${show(name)}`);
    }
    this.position = toVec3(position, 'position');
    finiteNumber(intensity, 'intensity');
    if (intensity < 0) throw new RangeError(`intensity must not be negative, got ${intensity}`);
    if (intensity > MAX_COLOR) throw new RangeError(`intensity must be at most ${MAX_COLOR}, got ${intensity}`);
    this.color = toColor(color, 'color');
    this.intensity = intensity;
    /** What it gives off: colour × intensity. */
    this.emission = this.color.map((c) => c * intensity);
    /** How it fades with distance d: by 1 / (1 + attenuation·d²); 0, no fading. */
    this.attenuation = checkAttenuation(attenuation);
    this.name = name;
  }
}

/**
 * A light's `attenuation`, k in 1 / (1 + k·d²) (lib/optics.js's falloff): a
 * finite number ≥ 0; 0 (the default) keeps the light as strong at any distance.
 */
export function checkAttenuation(value) {
  finiteNumber(value, 'attenuation');
  if (value < 0) throw new RangeError(`attenuation must not be negative (0: no falloff), got ${value}`);
  return value;
}

/** A plain object (not a colour array or string): the options form. */
function isOptions(value) {
  return value !== null && typeof value === 'object' && !Array.isArray(value) && !ArrayBuffer.isView(value);
}

/**
 * The scene's light sources as `{ position, emission, object, attenuation }`: point lights
 * (object null) and emissive objects (their `middle()`: a sphere's centre, a
 * box's middle; object is the shape itself, which a shadow ray may not block;
 * they do not fade with distance).
 */
export function lightSource(item) {
  if (item instanceof PointLight) return { position: item.position, emission: item.emission, object: null, source: item, attenuation: item.attenuation };
  return { position: middleOf(item), emission: item.material.emission, object: item, source: item, attenuation: 0 };
}
