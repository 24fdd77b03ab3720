/**
 * A spot light: a point light that shines in a cone. Full strength inside
 * the inner part of the cone, none outside `angle` (degrees from its axis),
 * and a smooth edge between (smoothstep over the outer fifth of the angle),
 * so its circle of light on a floor has a soft rim, as a real spot does.
 */
import { toVec3, Vec3, normalize } from '../math/vec3.js';
import { finiteNumber, checkOptions } from '../text/check.js';
import { RAD_PER_DEG } from '../math/constants.js';
import { vector } from '../shapes/json.js';
import { lightColor, lightIntensity, checkAttenuation, lightName, fading, definedOnly } from './checks.js';

const OPTIONS = ['angle', 'color', 'intensity', 'attenuation', 'name'];

/** The share of the angle, from the rim inward, over which the light fades. */
export const SPOT_EDGE = 0.2;

export class SpotLight {
  /**
   * @param {number[]|{x,y,z}} position where the light is
   * @param {number[]|{x,y,z}} target a point it shines toward (the cone's axis)
   * @param {object} [options]
   * @param {number} [options.angle=30] the cone's half-angle, degrees, between 0 and 90 (not included)
   * @param {number[]|string} [options.color=[1,1,1]]
   * @param {number} [options.intensity=1]
   * @param {number} [options.attenuation=0] how it fades with distance d: by 1 / (1 + attenuation·d²); 0, not at all
   * @param {string} [options.name]
   * @example
   * const scene = new Scene().add(new Plane([0, -4, 0], [0, 1, 0])).add(new Sphere([0, 0, -20], 3));
   * scene.add(new SpotLight([0, 15, -20], [0, -4, -20], { angle: 25 })); // a circle of light on the floor, around the sphere
   */
  constructor(position, target, options = {}) {
    const { angle = 30, color = [1, 1, 1], intensity = 1, attenuation = 0, name = '' } = checkOptions(options, OPTIONS, 'spot light');
    this.position = toVec3(position, 'position');
    this.target = toVec3(target, 'target');
    const axis = new Vec3(this.target.x - this.position.x, this.target.y - this.position.y, this.target.z - this.position.z);
    if (axis.x === 0 && axis.y === 0 && axis.z === 0) throw new RangeError('target must not be the light\'s own position: it says which way the light shines');
    /** The unit direction it shines in, from position toward target. */
    this.axis = normalize(axis, axis);
    finiteNumber(angle, 'angle');
    if (!(angle > 0 && angle < 90)) throw new RangeError(`angle must be between 0 and 90 degrees (not included), got ${angle}`);
    this.angle = angle;
    /** cos of the rim (no light past it) and of where the fading starts (full light inside it). */
    this.cosOuter = Math.cos(angle * RAD_PER_DEG);
    this.cosInner = Math.cos(angle * (1 - SPOT_EDGE) * RAD_PER_DEG);
    this.intensity = lightIntensity(intensity);
    this.color = lightColor(color);
    /** What it gives off at full strength: colour × intensity. */
    this.emission = this.color.map((c) => c * intensity);
    this.attenuation = checkAttenuation(attenuation);
    this.name = lightName(name);
  }

  static get type() { return 'spotLight'; }
  static get codeName() { return 'SpotLight'; }
  static get label() { return 'spot light'; }
  static get fields() { return ['position', 'target', 'angle', 'color', 'intensity', 'attenuation']; }
  static build(o) {
    return new SpotLight(o.position, o.target, definedOnly({ angle: o.angle, color: o.color, intensity: o.intensity, attenuation: o.attenuation }));
  }
  static codeArguments(o) {
    return [o.position, o.target, { angle: o.angle, color: o.color, intensity: o.intensity, ...fading(o.attenuation) }];
  }

  toJSON() {
    return { type: 'spotLight', name: this.name, position: vector(this.position), target: vector(this.target), angle: this.angle, color: [...this.color], intensity: this.intensity, ...fading(this.attenuation) };
  }

  /** What its drawing in the 3D view depends on (a glow at its position). */
  viewKey() {
    return `${this.position.x},${this.position.y},${this.position.z}`;
  }

  /**
   * The scene's light source for it: a point light that knows its cone, `spot` (its axis, cosOuter and cosInner).
   * @returns {{ position: Vec3, emission: number[], object: null, source: SpotLight, spot: SpotLight, attenuation: number }[]}
   */
  sources() {
    return [{ position: this.position, emission: this.emission, object: null, source: this, spot: this, attenuation: this.attenuation }];
  }
}
