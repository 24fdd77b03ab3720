/**
 * What a student types in a box, read and checked: numbers and colours, each
 * bad value a TypeError/RangeError whose message starts with the box's label;
 * and how a box shows a colour so that it reads back the same. No page needed:
 * the value boxes, the answer forms and the slider fields all read with these.
 */
import { toColor, colorToHex } from '../math/color.js';
import { show } from '../text/check.js';
import { PLAIN_NUMBER } from '../text/format.js';

export { PLAIN_NUMBER }; // a plain number as typed, the same test as CSV cells use (lib/text/format.js)

/** 2,5: a decimal comma (or, in a whole-number box, two numbers in one box). */
const DECIMAL_COMMA = /^[+-]?\d+,\d+$/;

/** The longest text a number or colour box reads: past it, a message, not a long wait. */
export const TYPED_MAX = 100;

/** A RangeError starting with `label` when `text` is longer than TYPED_MAX. */
function notTooLong(text, label) {
  if (text.length > TYPED_MAX) {
    throw new RangeError(`${label} is too long: ${text.length.toLocaleString('en')} characters, at most ${TYPED_MAX}`);
  }
}

/**
 * The number typed in a box, else a TypeError/RangeError whose message
 * starts with the box's `label`: empty, not a number, not whole, out of range.
 * @param {string} text what the box holds
 * @param {string} label the box's name as the page shows it ("Pixel x", "radius")
 * @param {object} [rule] `min`/`max` (included), `above` (excluded), `integer`
 */
export function readNumber(text, label, { min = -Infinity, max = Infinity, above, integer = false } = {}) {
  const t = String(text ?? '').trim().replace(/^−/, '-'); // a typographic minus counts too
  const wanted = integer ? 'a whole number' : 'a number';
  const range = Number.isFinite(min) && Number.isFinite(max) ? ` from ${min} to ${max}` : '';
  if (t === '') throw new TypeError(`${label} is empty: type ${wanted}${range}`);
  notTooLong(t, label);
  if (DECIMAL_COMMA.test(t)) throw new TypeError(`${label} must be ${wanted}, got ${show(t)}: ${integer ? 'one number to a box' : `write decimals with a point, ${t.replace(',', '.')}`}`);
  if (!PLAIN_NUMBER.test(t)) throw new TypeError(`${label} must be ${wanted}, got ${show(t)}`);
  const n = Number(t);
  if (!Number.isFinite(n)) throw new RangeError(`${label} is too big, got ${show(t)}`);
  if (integer && !Number.isInteger(n)) throw new RangeError(`${label} must be a whole number, got ${n}`);
  if (above !== undefined && !(n > above)) throw new RangeError(`${label} must be greater than ${above}, got ${n}`);
  if (n < min || n > max) {
    throw new RangeError(range ? `${label} must be${range}, got ${n}` : `${label} must be ${n < min ? `at least ${min}` : `at most ${max}`}, got ${n}`);
  }
  return n;
}

/**
 * The colour typed in a box as `[r, g, b]` (0–1, more for lights): '#ff5160',
 * 'pink', 'rgb(255, 81, 96)', three numbers '1, 0.3, 0.4', or one number for
 * a grey ('1.2'). Else a TypeError/RangeError starting with `label`.
 */
export function readColor(text, label) {
  const t = String(text ?? '').trim();
  if (t === '') throw new TypeError(`${label} is empty: type a colour like #ff5160, pink, or 1, 0.3, 0.4`);
  notTooLong(t, label);
  const parts = t.replace(/^\[|\]$/g, '').split(/\s*,\s*|\s+/);
  if (parts.every((p) => PLAIN_NUMBER.test(p)) && (parts.length === 1 || parts.length === 3)) {
    const rgb = parts.map(Number);
    return withLabel(() => toColor(rgb.length === 1 ? rgb[0] : rgb, label), label);
  }
  return withLabel(() => toColor(t, label), label);
}

/** Runs `make`; the library's message gets the box's label, once, in front. */
function withLabel(make, label) {
  try {
    return make();
  } catch (error) {
    if (String(error.message).startsWith(label)) throw error;
    const Kind = error instanceof RangeError ? RangeError : TypeError;
    throw new Kind(`${label}: ${error.message}`);
  }
}

/**
 * How a box shows a colour: '#rrggbb' when every channel is 0–1 (unless it
 * is a grey and `grey` asks for a number), one number for other greys,
 * else 'r, g, b'.
 */
export function colorText(rgb, { grey = false } = {}) {
  const isGrey = rgb[0] === rgb[1] && rgb[1] === rgb[2];
  if (isGrey && (grey || rgb[0] > 1)) return String(rgb[0]);
  if (rgb.every((c) => c >= 0 && c <= 1)) return colorToHex(rgb);
  return rgb.join(', ');
}
