/**
 * Numbers that more than one module must agree on, in one place.
 */

/** Hits closer than this are the surface the ray starts on, not a new hit. */
export const EPSILON = 1e-6;
