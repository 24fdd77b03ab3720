/**
 * Argument checks shared by every constructor: each throws a TypeError or
 * RangeError whose message names the field, so a student sees what to fix.
 */

/** A finite number, else a TypeError naming `field`. */
export function finiteNumber(value, field) {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new TypeError(`${field} must be a finite number, got ${show(value)}`);
  }
  return value;
}

/** A finite number in [min, max], else a Type/RangeError naming `field`. */
export function numberInRange(value, field, min, max) {
  finiteNumber(value, field);
  if (value < min || value > max) {
    throw new RangeError(`${field} must be between ${min} and ${max}, got ${value}`);
  }
  return value;
}

/** A positive integer (width, height, …). */
export function positiveInteger(value, field) {
  finiteNumber(value, field);
  if (!Number.isInteger(value) || value <= 0) {
    throw new RangeError(`${field} must be a positive whole number, got ${value}`);
  }
  return value;
}

/** A boolean. */
export function bool(value, field) {
  if (typeof value !== 'boolean') throw new TypeError(`${field} must be true or false, got ${show(value)}`);
  return value;
}

/** Short printable form of a bad value for error messages. */
export function show(value) {
  if (typeof value === 'string') return JSON.stringify(value);
  if (Array.isArray(value)) return `[${value.map(show).join(', ')}]`;
  if (value && typeof value === 'object') {
    try { return JSON.stringify(value); } catch { return String(value); }
  }
  return String(value);
}

/** A whole number in [0, limit) — a pixel coordinate. */
export function pixelCoordinate(value, field, limit) {
  finiteNumber(value, field);
  if (!Number.isInteger(value) || value < 0 || value >= limit) {
    throw new RangeError(`${field} must be a whole number from 0 to ${limit - 1}, got ${value}`);
  }
  return value;
}
