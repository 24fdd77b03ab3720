/**
 * An area light: a disc of light. A point light casts hard shadows (a point
 * is either seen or not); a disc can be partly hidden, and the shadow's edge
 * becomes a penumbra. The disc is sampled at `samples` fixed points, one in
 * each cell of an n × n grid mapped onto the disc (stratified: no two points
 * crowd together, and no Math.random: the same picture, byte for byte, every
 * run). Each point is a light of its own with 1/samples of the light, so a
 * hit point lights up by the share of the disc its shadow rays reach.
 */
import { toVec3, Vec3, normalize, cross } from '../math/vec3.js';
import { finiteNumber, checkOptions, show } from '../text/check.js';
import { vector } from '../shapes/json.js';
import { lightColor, lightIntensity, checkAttenuation, lightName, fading, definedOnly } from './checks.js';

/** Shadow rays per hit an area light may ask for: an n × n grid, n from 1 to 8. */
export const AREA_SAMPLES = [1, 4, 9, 16, 25, 36, 49, 64];
/** Shadow rays of an area light that does not say. */
const DEFAULT_SAMPLES = 16;

const OPTIONS = ['color', 'intensity', 'samples', 'normal', 'attenuation', 'name'];

export class AreaLight {
  /**
   * @param {number[]|{x,y,z}} center the disc's centre
   * @param {number} radius the disc's radius, > 0
   * @param {object} [options]
   * @param {number[]|string} [options.color=[1,1,1]]
   * @param {number} [options.intensity=1] the whole disc's, shared among its points
   * @param {number} [options.samples=16] points on the disc, one shadow ray each: 1, 4, 9, …, 64 (an n × n grid)
   * @param {number[]|{x,y,z}} [options.normal=[0,-1,0]] the way the disc faces (down, for a ceiling light)
   * @param {number} [options.attenuation=0] how it fades with distance d: by 1 / (1 + attenuation·d²), d from each sample point; 0, not at all
   * @param {string} [options.name]
   * @example
   * const scene = new Scene().add(new Plane([0, -4, 0], [0, 1, 0])).add(new Sphere([0, 0, -20], 3));
   * scene.add(new AreaLight([0, 20, -20], 4, { samples: 16 })); // soft shadows under a disc of radius 4, 16 shadow rays per hit
   */
  constructor(center, radius, options = {}) {
    const { color = [1, 1, 1], intensity = 1, samples = DEFAULT_SAMPLES, normal = [0, -1, 0], attenuation = 0, name = '' } = checkOptions(options, OPTIONS, 'area light');
    this.center = toVec3(center, 'center');
    finiteNumber(radius, 'radius');
    if (!(radius > 0)) throw new RangeError(`radius must be greater than 0, got ${radius}`);
    this.radius = radius;
    this.color = lightColor(color);
    this.intensity = lightIntensity(intensity);
    if (!AREA_SAMPLES.includes(samples)) throw new RangeError(`samples must be a square number of shadow rays, 1, 4, 9, … 64 (an n × n grid), got ${show(samples)}`);
    this.samples = samples;
    this.normal = toVec3(normal, 'normal');
    if (this.normal.x === 0 && this.normal.y === 0 && this.normal.z === 0) throw new RangeError('normal must not be (0, 0, 0): it says which way the disc faces');
    normalize(this.normal, this.normal);
    this.attenuation = checkAttenuation(attenuation);
    this.name = lightName(name);
  }

  static get type() { return 'areaLight'; }
  static get codeName() { return 'AreaLight'; }
  static get label() { return 'area light'; }
  /** The inspector shows its shadow rays as one group (one per point of its disc). */
  static get grouped() { return true; }
  static get fields() { return ['center', 'radius', 'color', 'intensity', 'samples', 'normal', 'attenuation']; }
  /**
   * The shadow rays its JSON makes from each hit point, counted before any check (lib/scene/work.js),
   * and the field that says so.
   */
  static workOf(o) {
    return { shadowRays: Number.isInteger(o.samples) && o.samples > 0 ? o.samples : DEFAULT_SAMPLES, field: 'samples' };
  }
  static build(o) {
    return new AreaLight(o.center, o.radius, definedOnly({ color: o.color, intensity: o.intensity, samples: o.samples, normal: o.normal, attenuation: o.attenuation }));
  }
  static codeArguments(o) {
    return [o.center, o.radius, { color: o.color, intensity: o.intensity, samples: o.samples, normal: o.normal, ...fading(o.attenuation) }];
  }

  toJSON() {
    return { type: 'areaLight', name: this.name, center: vector(this.center), radius: this.radius, color: [...this.color], intensity: this.intensity, samples: this.samples, normal: vector(this.normal), ...fading(this.attenuation) };
  }

  /** What the whole disc gives off: colour × intensity. */
  get emission() {
    return this.color.map((c) => c * this.intensity);
  }

  /**
   * The disc's sample points, `samples` of them: the centre of each cell of an
   * n × n grid over the square [−1, 1]², mapped onto the unit disc by the
   * concentric map (Shirley and Chiu, 1997: it keeps cells of equal area
   * equal), then scaled and turned onto this disc.
   * @returns {Vec3[]}
   */
  points() {
    const n = Math.sqrt(this.samples), { u, v } = this.axes(), c = this.center, r = this.radius;
    const points = [];
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const [a, b] = concentric((2 * (i + 0.5)) / n - 1, (2 * (j + 0.5)) / n - 1);
        points.push(new Vec3(c.x + r * (a * u.x + b * v.x), c.y + r * (a * u.y + b * v.y), c.z + r * (a * u.z + b * v.z)));
      }
    }
    return points;
  }

  /** Two unit vectors across the disc, `{ u, v }`, at right angles to each other and to its normal: the sample points and the rim are laid out along them. */
  axes() {
    return discAxes(this.normal);
  }

  /** The disc's rim, `n` points round it in its plane: what the 3D view draws of it (beside a glow per point). */
  outlines(n = 48) {
    const c = this.center, r = this.radius, { u, v } = this.axes();
    const rim = [];
    for (let i = 0; i < n; i++) {
      const a = (2 * Math.PI * i) / n, cu = r * Math.cos(a), sv = r * Math.sin(a);
      rim.push(new Vec3(c.x + cu * u.x + sv * v.x, c.y + cu * u.y + sv * v.y, c.z + cu * u.z + sv * v.z));
    }
    return [rim];
  }

  /** What its drawing in the 3D view depends on: the disc (its glows sit at its points). */
  viewKey() {
    const { center: c, normal: n } = this;
    return `${c.x},${c.y},${c.z},${this.radius},${n.x},${n.y},${n.z},${this.samples}`;
  }

  /**
   * The scene's light sources for this light: one per sample point, each a
   * point light with 1/samples of the emission (Scene.add keeps them in
   * `scene.lights`, each with `source` this light and its `sample` number).
   * @returns {{ position: Vec3, emission: number[], object: null, source: AreaLight, sample: number, attenuation: number }[]}
   */
  sources() {
    const emission = this.emission.map((e) => e / this.samples), attenuation = this.attenuation;
    return this.points().map((position, sample) => ({ position, emission, object: null, source: this, sample, attenuation }));
  }
}

/** The concentric map of (a, b) in [−1, 1]² onto the unit disc. */
export function concentric(a, b) {
  if (a === 0 && b === 0) return [0, 0];
  const quarter = Math.PI / 4;
  const [r, phi] = Math.abs(a) > Math.abs(b) ? [a, quarter * (b / a)] : [b, 2 * quarter - quarter * (a / b)];
  return [r * Math.cos(phi), r * Math.sin(phi)];
}

/** Two unit vectors across the disc, at right angles to each other and to its normal. */
function discAxes(normal) {
  const helper = Math.abs(normal.y) < 0.9 ? new Vec3(0, 1, 0) : new Vec3(1, 0, 0);
  const u = normalize(new Vec3(), cross(new Vec3(), helper, normal));
  const v = cross(new Vec3(), normal, u);
  return { u, v };
}
