/**
 * The eye and the image plane. The camera sits at `position` looking toward −z,
 * turned right by `yaw` (H) and up by `pitch` (V), all angles in degrees;
 * `fov` is the vertical field of view. Pixel (0, 0) is the top-left one, and
 * each ray passes through its pixel's centre.
 */
import { toVec3, Vec3, normalize } from './vec3.js';
import { finiteNumber, numberInRange, positiveInteger, checkOptions } from './check.js';
import { Ray } from './ray.js';
import { RAD_PER_DEG } from './constants.js';

/** The camera size limit: at most 16384 pixels a side (a canvas's limit) and 4096 × 4096 pixels in all (a 64 MB frame). */
export const MAX_CAMERA_SIDE = 16384;
export const MAX_CAMERA_PIXELS = 4096 * 4096;

/** The options a camera takes. */
const OPTIONS = ['width', 'height', 'fov', 'position', 'yaw', 'pitch'];

export class Camera {
  /**
   * @param {object} options
   * @param {number} options.width image width in pixels, at most MAX_CAMERA_SIDE (16384)
   * @param {number} options.height image height in pixels, at most 16384; width × height at most MAX_CAMERA_PIXELS (4096 × 4096)
   * @param {number} [options.fov=30] vertical field of view, degrees, in (0, 180)
   * @param {number[]|{x,y,z}} [options.position=[0,0,0]] the eye
   * @param {number} [options.yaw=0] turn right, degrees
   * @param {number} [options.pitch=0] look up, degrees, −90 to 90
   * @example
   * const camera = new Camera({ width: 64, height: 48, fov: 30, position: [0, 2, 0], pitch: -5 });
   * const { ray, h, v } = camera.primaryRay(10, 12); // the ray through pixel (10, 12) and its angles
   */
  constructor(options) { // no options: checkOptions gives {}, and the first required field says it is missing
    const { width, height, fov = 30, position = [0, 0, 0], yaw = 0, pitch = 0 } = checkOptions(options, OPTIONS, 'camera');
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
}

/** The horizontal and vertical angles (degrees) of a unit direction. */
export function angles(d) {
  return { h: Math.atan2(d.x, -d.z) / RAD_PER_DEG, v: Math.asin(Math.max(-1, Math.min(1, d.y))) / RAD_PER_DEG };
}
