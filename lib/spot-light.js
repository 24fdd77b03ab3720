/**
 * A spot light: a point light that shines in a cone. Full strength inside
 * the inner part of the cone, none outside `angle` (degrees from its axis),
 * and a smooth edge between (smoothstep over the outer fifth of the angle),
 * so its circle of light on a floor has a soft rim, as a real spot does.
 */
import { toVec3, Vec3, normalize } from './vec3.js';
import { toColor, MAX_COLOR } from './color.js';
import { finiteNumber, checkOptions, show } from './check.js';
import { RAD_PER_DEG } from './constants.js';
import { checkAttenuation } from './lights.js';

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
    finiteNumber(intensity, 'intensity');
    if (intensity < 0 || intensity > MAX_COLOR) throw new RangeError(`intensity must be between 0 and ${MAX_COLOR}, got ${intensity}`);
    this.color = toColor(color, 'color');
    this.intensity = intensity;
    /** What it gives off at full strength: colour × intensity. */
    this.emission = this.color.map((c) => c * intensity);
    this.attenuation = checkAttenuation(attenuation);
    if (typeof name !== 'string') throw new TypeError(`name must be text, got ${show(name)}`);
    this.name = name;
  }

  /**
   * The scene's light source for it: a point light that knows its cone (Scene.add keeps it in `scene.lights`).
   * @returns {{ position: Vec3, emission: number[], object: null, source: SpotLight, spot: SpotLight, attenuation: number }}
   */
  source() {
    return { position: this.position, emission: this.emission, object: null, source: this, spot: this, attenuation: this.attenuation };
  }
}

/** How much of a spot light's cone reaches a point: lib/optics.js, where trace.js and kernel.js both find it. */
export { spotShare } from './optics.js';
