/**
 * Numbers that more than one module must agree on, in one place.
 */

/**
 * Hits closer than this are the surface the ray starts on, not a new hit.
 * @example
 * const { t } = intersectQuadratic(new Ray([0, 0, 0], [0, 0, -1]), new Sphere([0, 0, -20], 4));
 * const inFront = t !== null && t > EPSILON; // true: t = 16
 */
export const EPSILON = 1e-6;

/** Multiply degrees by this to get radians (π/180). */
export const RAD_PER_DEG = Math.PI / 180;

/** Multiply radians by this to get degrees (180/π). */
export const DEG_PER_RAD = 180 / Math.PI;
