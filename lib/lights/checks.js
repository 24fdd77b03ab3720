/**
 * The checks every light shares, with one wording: its colour, its intensity,
 * how it fades with distance, its name. Each light class checks its own
 * fields (a spot's angle, a disc's radius) and these through the same calls.
 */
import { toColor, MAX_COLOR } from '../math/color.js';
import { finiteNumber, show } from '../text/check.js';

/** A light's colour as [r, g, b] (an array, '#ff5160', 'pink'). */
export function lightColor(value) {
  return toColor(value, 'color');
}

/** A light's `intensity`, the multiplier of its colour: a finite number from 0 to MAX_COLOR. */
export function lightIntensity(value) {
  finiteNumber(value, 'intensity');
  if (value < 0) throw new RangeError(`intensity must not be negative, got ${value}`);
  if (value > MAX_COLOR) throw new RangeError(`intensity must be at most ${MAX_COLOR}, got ${value}`);
  return value;
}

/**
 * A light's `attenuation`, k in 1 / (1 + k·d²) (lib/tracing/optics.js's falloff): a
 * finite number ≥ 0; 0 (the default) keeps the light as strong at any distance.
 */
export function checkAttenuation(value) {
  finiteNumber(value, 'attenuation');
  if (value < 0) throw new RangeError(`attenuation must not be negative (0: no falloff), got ${value}`);
  return value;
}

/** A light's `name`: text ('' for none). */
export function lightName(value) {
  if (typeof value !== 'string') throw new TypeError(`name must be text, got ${show(value)}`);
  return value;
}

/** `{ attenuation }` when a light fades with distance, else nothing: the JSON and code of a light that does not stay as they were. */
export function fading(attenuation) {
  return attenuation ? { attenuation } : {};
}

/** `options` without its undefined entries (a constructor's defaults then apply). */
export function definedOnly(options) {
  return Object.fromEntries(Object.entries(options).filter(([, v]) => v !== undefined));
}
