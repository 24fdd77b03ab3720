/**
 * The eye and the image plane. The camera sits at `position` looking toward −z,
 * turned right by `yaw` (H) and up by `pitch` (V), all angles in degrees;
 * `fov` is the vertical field of view. Pixel (0, 0) is the top-left one, and
 * its ray passes through its pixel's centre; with `samples` of 4, 9 or 16 a
 * pixel gets an n × n grid of rays, one through the centre of each cell, and
 * their average colour (`sampleOffsets`).
 */
import { toVec3, Vec3, normalize } from './vec3.js';
import { finiteNumber, numberInRange, positiveInteger, checkOptions, show } from '../text/check.js';
import { Ray } from './ray.js';
import { RAD_PER_DEG } from './constants.js';
import { clamp } from './numbers.js';

/** The camera size limit: at most 16384 pixels a side (a canvas's limit) and 4096 × 4096 pixels in all (a 64 MB frame). */
export const MAX_CAMERA_SIDE = 16384;
export const MAX_CAMERA_PIXELS = 4096 * 4096;

/** The options a camera takes. */
const OPTIONS = ['width', 'height', 'fov', 'position', 'yaw', 'pitch', 'samples'];

/** Rays per pixel a camera may trace: a 1×1, 2×2, 3×3 or 4×4 grid over the pixel. */
export const SAMPLE_COUNTS = [1, 4, 9, 16];

export class Camera {
  /**
   * @param {object} options
   * @param {number} options.width image width in pixels, at most MAX_CAMERA_SIDE (16384)
   * @param {number} options.height image height in pixels, at most 16384; width × height at most MAX_CAMERA_PIXELS (4096 × 4096)
   * @param {number} [options.fov=30] vertical field of view, degrees, in (0, 180)
   * @param {number[]|{x,y,z}} [options.position=[0,0,0]] the eye
   * @param {number} [options.yaw=0] turn right, degrees
   * @param {number} [options.pitch=0] look up, degrees, −90 to 90
   * @param {number} [options.samples=1] rays per pixel, 1, 4, 9 or 16: one through the centre of each cell of an
   *   n × n grid over the pixel (stratified, the same rays every run), their colours averaged: smooth edges
   * @example
   * const camera = new Camera({ width: 64, height: 48, fov: 30, position: [0, 2, 0], pitch: -5 });
   * const { ray, h, v } = camera.primaryRay(10, 12); // the ray through pixel (10, 12) and its angles
   */
  constructor(options) { // no options: checkOptions gives {}, and the first required field says it is missing
    const { width, height, fov = 30, position = [0, 0, 0], yaw = 0, pitch = 0, samples = 1 } = checkOptions(options, OPTIONS, 'camera');
    this.width = positiveInteger(width, 'width');
    this.height = positiveInteger(height, 'height');
    if (width > MAX_CAMERA_SIDE) throw new RangeError(`width must be at most ${MAX_CAMERA_SIDE} pixels, got ${width}`);
    if (height > MAX_CAMERA_SIDE) throw new RangeError(`height must be at most ${MAX_CAMERA_SIDE} pixels, got ${height}`);
    if (width * height > MAX_CAMERA_PIXELS) {
      throw new RangeError(`width × height must be at most ${MAX_CAMERA_PIXELS.toLocaleString('en')} pixels (4096 × 4096), got ${width} × ${height}`);
    }
    finiteNumber(fov, 'fov');
    if (!(fov > 0 && fov < 180)) throw new RangeError(`fov must be between 0 and 180 degrees (not included), got ${fov}`);
    this.fov = fov;
    this.position = toVec3(position, 'position');
    this.yaw = finiteNumber(yaw, 'yaw');
    this.pitch = numberInRange(pitch, 'pitch', -90, 90);
    this.samples = sampleCount(samples);
    this.#setBasis();
  }

  /** right, up and forward unit vectors, and the image plane's half-size at distance 1. */
  #setBasis() {
    const cy = Math.cos(this.yaw * RAD_PER_DEG), sy = Math.sin(this.yaw * RAD_PER_DEG);
    const cp = Math.cos(this.pitch * RAD_PER_DEG), sp = Math.sin(this.pitch * RAD_PER_DEG);
    this.right = new Vec3(cy, 0, sy);
    this.up = new Vec3(-sy * sp, cp, cy * sp);
    this.forward = new Vec3(sy * cp, sp, -cy * cp);
    this.halfHeight = Math.tan((this.fov * RAD_PER_DEG) / 2);
    this.halfWidth = (this.halfHeight * this.width) / this.height;
  }

  /** Writes the unit direction of the ray through pixel (x, y) into `out`. */
  directionAt(x, y, out = new Vec3()) {
    const sx = (2 * (x + 0.5) / this.width - 1) * this.halfWidth;
    const sy = (1 - 2 * (y + 0.5) / this.height) * this.halfHeight;
    const r = this.right, u = this.up, f = this.forward;
    out.x = sx * r.x + sy * u.x + f.x;
    out.y = sx * r.y + sy * u.y + f.y;
    out.z = sx * r.z + sy * u.z + f.z;
    return normalize(out, out);
  }

  /**
   * The primary ray through pixel (x, y) and its angles: `h` = atan2(dx, −dz)
   * (positive to the right), `v` = asin(dy) (positive up), in degrees.
   */
  primaryRay(x, y) {
    finiteNumber(x, 'x');
    finiteNumber(y, 'y');
    const ray = new Ray(this.position);
    this.directionAt(x, y, ray.direction); // exactly the renderer's direction, bit for bit
    return { ray, ...angles(ray.direction) };
  }

  /**
   * Where a point lands on the picture, the inverse of directionAt: `x`, `y`
   * in pixels (fractional; a pixel's centre is whole, and outside 0…width−1
   * or 0…height−1 is off the picture) and `depth`, its distance along the
   * view. A `depth` ≤ 0 is beside or behind the eye: no pixel sees it.
   * @param {number[]|{x,y,z}} point
   * @returns {{ x: number, y: number, depth: number }}
   * @example
   * new Camera({ width: 64, height: 48 }).project([0, 0, -10]); // { x: 31.5, y: 23.5, depth: 10 }: the picture's middle
   */
  project(point) {
    const p = toVec3(point, 'point'), e = this.position;
    const dx = p.x - e.x, dy = p.y - e.y, dz = p.z - e.z;
    const along = (v) => dx * v.x + dy * v.y + dz * v.z;
    const depth = along(this.forward);
    return { x: this.pixelX(along(this.right) / depth), y: this.pixelY(along(this.up) / depth), depth };
  }

  /** The pixel x (fractional) of image-plane coordinate `sx` (sideways ÷ forward): the inverse of directionAt's sx = (2(x + ½)/W − 1)·halfWidth. */
  pixelX(sx) {
    return ((sx / this.halfWidth + 1) * this.width) / 2 - 0.5;
  }

  /** The pixel y (fractional) of image-plane coordinate `sy` (up ÷ forward): the inverse of directionAt's sy = (1 − 2(y + ½)/H)·halfHeight. */
  pixelY(sy) {
    return ((1 - sy / this.halfHeight) * this.height) / 2 - 0.5;
  }
}

/**
 * Where the sub-pixel rays of a camera with `samples` rays per pixel cross
 * their pixel, as offsets from its centre in pixels (−½ … ½): `[dx0, dy0,
 * dx1, dy1, …]`, the centres of the cells of the √samples × √samples grid,
 * row by row from the top left. Made once per count (no allocation per pixel).
 * @param {number} samples 1, 4, 9 or 16
 * @returns {Float64Array}
 * @example
 * sampleOffsets(4); // [-0.25, -0.25, 0.25, -0.25, -0.25, 0.25, 0.25, 0.25]
 */
export function sampleOffsets(samples) {
  let offsets = OFFSETS.get(samples);
  if (offsets) return offsets;
  const n = Math.sqrt(sampleCount(samples));
  offsets = new Float64Array(2 * samples);
  for (let s = 0; s < samples; s++) {
    offsets[2 * s] = ((s % n) + 0.5) / n - 0.5;
    offsets[2 * s + 1] = (Math.floor(s / n) + 0.5) / n - 0.5;
  }
  OFFSETS.set(samples, offsets);
  return offsets;
}

const OFFSETS = new Map();

/** `samples` checked: 1, 4, 9 or 16 (a square number, so the pixel splits into an even grid). */
function sampleCount(samples) {
  if (!SAMPLE_COUNTS.includes(samples)) {
    throw new RangeError(`samples must be 1, 4, 9 or 16 rays per pixel (an n × n grid), got ${show(samples)}`);
  }
  return samples;
}

/** The horizontal and vertical angles (degrees) of a unit direction. */
export function angles(d) {
  return { h: horizontalAngle(d), v: verticalAngle(d) };
}

/** H, degrees: how far left (−) or right (+) of straight ahead (−z) a direction points, atan2(dx, −dz). */
export function horizontalAngle(d) {
  return Math.atan2(d.x, -d.z) / RAD_PER_DEG;
}

/** V, degrees: how far below (−) or above (+) the horizon a unit direction points, asin(dy). */
export function verticalAngle(d) {
  return Math.asin(clamp(d.y, -1, 1)) / RAD_PER_DEG; // dy a hair over 1 after normalising: no NaN
}
