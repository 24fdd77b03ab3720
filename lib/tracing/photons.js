/**
 * Light-based ray tracing, the way light works in nature (the lesson's first
 * slide): photons leave the lights in random directions, bounce diffusely off
 * whatever they meet, taking its colour, and the few that happen to enter the
 * eye land on the picture. Eye-based tracing (lib/tracing/trace.js) turns this around
 * and only follows the rays that matter: one per pixel.
 *
 * Deterministic: the same seed gives the same photons, however the work is
 * split into steps.
 */
import { Vec3, dot, normalize, set } from '../math/vec3.js';
import { Ray } from '../math/ray.js';
import { Sphere } from '../shapes/sphere.js';
import { ballOf } from '../shapes/index.js';
import { nearestHit } from './trace.js';
import { checkOptions, positiveInteger, show } from '../text/check.js';

/** A small fast seeded random generator (mulberry32): numbers in [0, 1). */
export function seededRandom(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const OPTIONS = ['scene', 'camera', 'seed', 'eyeRadius', 'maxBounces', 'samplePaths'];

export class PhotonTracer {
  /**
   * @param {object} options
   * @param {import('../scene/scene.js').Scene} options.scene its lights (emissive shapes, point lights) send the photons
   * @param {import('../math/camera.js').Camera} options.camera the eye: a small ball at its position, and its picture
   * @param {number} [options.seed=1] the random sequence (a whole number)
   * @param {number} [options.eyeRadius=1] the eye's (pupil's) radius in scene units: a photon must pass this close to the eye
   * @param {number} [options.maxBounces=4] bounces before a photon is given up on
   * @param {number} [options.samplePaths=40] how many photon paths to keep for drawing (the first ones, and as many that reached the eye)
   */
  constructor(options) {
    const { scene, camera, seed = 1, eyeRadius = 1, maxBounces = 4, samplePaths = 40 } = checkOptions(options, OPTIONS, 'photon tracer');
    if (!scene || !Array.isArray(scene.objects)) throw new TypeError(`scene must be a Scene, got ${show(scene)}`);
    if (!camera || typeof camera.directionAt !== 'function') throw new TypeError(`camera must be a Camera, got ${show(camera)}`);
    if (!Number.isInteger(seed)) throw new TypeError(`seed must be a whole number, got ${show(seed)}`);
    if (!(typeof eyeRadius === 'number' && eyeRadius > 0 && Number.isFinite(eyeRadius))) throw new RangeError(`eyeRadius must be a number greater than 0, got ${show(eyeRadius)}`);
    this.scene = scene;
    this.camera = camera;
    this.maxBounces = positiveInteger(maxBounces, 'maxBounces');
    this.samplePaths = Number.isInteger(samplePaths) && samplePaths >= 0 ? samplePaths : positiveInteger(samplePaths, 'samplePaths');
    this.eye = new Sphere(camera.position, eyeRadius);
    this.random = seededRandom(seed);
    this.lights = scene.lights.filter((l) => l.emission.some((e) => e > 0));
    if (this.lights.length === 0) throw new RangeError('the scene has no light to send photons from (an emissive shape or a PointLight)');
    const power = this.lights.map((l) => l.emission[0] + l.emission[1] + l.emission[2]);
    let sum = 0;
    this.#lightShare = power.map((p) => (sum += p) / power.reduce((a, b) => a + b, 0));
    /** Light gathered by each pixel, r, g, b per pixel. */
    this.light = new Float64Array(camera.width * camera.height * 3);
    /** Photons sent so far, and how many of them landed on the picture. */
    this.emitted = 0;
    this.reached = 0;
    /** Sample paths `{ points: Vec3[], reached: boolean }`: the first photons sent, and the first that reached the eye. */
    this.paths = [];
    this.#pathsReached = 0;
  }

  #lightShare; #pathsReached;
  #ray = new Ray();
  #hit = { object: null, t: Infinity };
  #power = [0, 0, 0];

  /** Sends `count` more photons; returns how many of them reached the eye. */
  emit(count) {
    positiveInteger(count, 'count');
    const before = this.reached;
    for (let i = 0; i < count; i++) this.#photon();
    return this.reached - before;
  }

  /** Share of the photons sent that reached the eye, 0–1. */
  get share() {
    return this.emitted ? this.reached / this.emitted : 0;
  }

  /**
   * The picture so far into `out` (RGBA bytes). Exposure is set by the light
   * the landed photons carry on average, so one photon alone shows its colour
   * clearly and a pixel that gathered several is brighter.
   */
  writePicture(out, exposure = 1.5) {
    const n = this.camera.width * this.camera.height, L = this.light;
    let total = 0;
    for (let i = 0; i < L.length; i++) total += L[i];
    const k = this.reached ? (exposure * 3 * this.reached) / total : 0;
    for (let i = 0; i < n; i++) {
      for (let c = 0; c < 3; c++) out[i * 4 + c] = 255 * (1 - Math.exp(-k * L[i * 3 + c]));
      out[i * 4 + 3] = 255;
    }
    return out;
  }

  /** One photon: from a light, bounce after bounce, until it enters the eye, is lost or gives up. */
  #photon() {
    const rnd = this.random, ray = this.#ray, power = this.#power;
    this.emitted++;
    const u = rnd();
    let li = 0;
    while (this.#lightShare[li] < u) li++;
    const light = this.lights[li];
    power[0] = light.emission[0]; power[1] = light.emission[1]; power[2] = light.emission[2];
    const ball = light.object && ballOf(light.object);
    const from = ball ? this.#leaveSphere(ball, ray) : this.#leavePoint(light.position, ray);
    const keep = this.paths.length < this.samplePaths;
    const points = keep || this.#pathsReached < this.samplePaths ? [from] : null;
    for (let bounce = 0; bounce <= this.maxBounces; bounce++) {
      const found = nearestHit(this.scene.objects, ray, this.#hit, this.scene.epsilon);
      const tEye = this.eye.hit(ray, this.scene.epsilon);
      if (tEye < this.#hit.t) {
        if (this.#land(ray.direction)) {
          points?.push(at(ray, tEye));
          this.#keep(points, true);
          return;
        }
      }
      if (!found) { points?.push(at(ray, 30)); break; } // off into the sky: lost
      const object = this.#hit.object, P = at(ray, this.#hit.t, _P);
      points?.push(new Vec3(P.x, P.y, P.z));
      if (object.material.isEmissive) break; // back into a light
      const c = object.material.color;
      power[0] *= c[0]; power[1] *= c[1]; power[2] *= c[2];
      const N = object.normalAt(P, _N);
      if (dot(N, ray.direction) > 0) { N.x = -N.x; N.y = -N.y; N.z = -N.z; }
      ray.origin.x = P.x + N.x * this.scene.bias; ray.origin.y = P.y + N.y * this.scene.bias; ray.origin.z = P.z + N.z * this.scene.bias;
      cosineDirection(ray.direction, N, rnd);
    }
    if (keep) this.#keep(points, false);
  }

  #keep(points, reached) {
    if (!points) return;
    if (reached && this.#pathsReached < this.samplePaths) { this.#pathsReached++; this.paths.push({ points, reached }); } else if (!reached && this.paths.length < this.samplePaths) this.paths.push({ points, reached });
  }

  /** A photon entering the eye along `d` lands on the pixel that looks back along −d; false when outside the picture. */
  #land(d) {
    const cam = this.camera;
    const z = -dot(d, cam.forward);
    if (z <= 0) return false;
    const sx = -dot(d, cam.right) / z, sy = -dot(d, cam.up) / z;
    const x = Math.floor(((sx / cam.halfWidth + 1) / 2) * cam.width);
    const y = Math.floor(((1 - sy / cam.halfHeight) / 2) * cam.height);
    if (x < 0 || y < 0 || x >= cam.width || y >= cam.height) return false;
    const i = (y * cam.width + x) * 3, p = this.#power;
    this.light[i] += p[0]; this.light[i + 1] += p[1]; this.light[i + 2] += p[2];
    this.reached++;
    return true;
  }

  /** A photon leaves a glowing sphere from a random point of its surface, in a cosine-weighted random direction. */
  #leaveSphere(sphere, ray) {
    const n = uniformDirection(_N, this.random);
    const c = sphere.center, r = sphere.radius + this.scene.bias;
    ray.origin.x = c.x + n.x * r; ray.origin.y = c.y + n.y * r; ray.origin.z = c.z + n.z * r;
    cosineDirection(ray.direction, n, this.random);
    return new Vec3(ray.origin.x, ray.origin.y, ray.origin.z);
  }

  /** A photon leaves a point light in any direction. */
  #leavePoint(p, ray) {
    ray.origin.x = p.x; ray.origin.y = p.y; ray.origin.z = p.z;
    uniformDirection(ray.direction, this.random);
    return new Vec3(p.x, p.y, p.z);
  }
}

const _P = new Vec3(), _N = new Vec3(), _t = new Vec3(), _b = new Vec3(), _tt = new Vec3();

function at(ray, t, out = new Vec3()) {
  const o = ray.origin, d = ray.direction;
  out.x = o.x + d.x * t; out.y = o.y + d.y * t; out.z = o.z + d.z * t;
  return out;
}

/** A uniformly random unit direction into `out`. */
function uniformDirection(out, rnd) {
  const z = 2 * rnd() - 1, a = 2 * Math.PI * rnd(), s = Math.sqrt(1 - z * z);
  out.x = s * Math.cos(a); out.y = s * Math.sin(a); out.z = z;
  return out;
}

/** A random unit direction around the normal n, more often near it (Lambert's cosine law), into `out`. */
function cosineDirection(out, n, rnd) {
  const a = 2 * Math.PI * rnd(), r2 = rnd(), r = Math.sqrt(r2);
  // a basis (t, b, n)
  const t = Math.abs(n.x) > 0.9 ? set(_t, 0, 1, 0) : set(_t, 1, 0, 0);
  const b = normalize(_b, set(_b, n.y * t.z - n.z * t.y, n.z * t.x - n.x * t.z, n.x * t.y - n.y * t.x));
  const tt = set(_tt, b.y * n.z - b.z * n.y, b.z * n.x - b.x * n.z, b.x * n.y - b.y * n.x);
  const x = r * Math.cos(a), y = r * Math.sin(a), z = Math.sqrt(1 - r2);
  out.x = tt.x * x + b.x * y + n.x * z;
  out.y = tt.y * x + b.y * y + n.y * z;
  out.z = tt.z * x + b.z * y + n.z * z;
  return normalize(out, out);
}
