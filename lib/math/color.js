/**
 * Colours: `[r, g, b]` in 0–1 (values above 1 are allowed for lights), or a
 * CSS-style string: '#ff5160', '#f56', 'rgb(255, 81, 96)' or a colour name.
 */
import { show, closestName } from '../text/check.js';
import { clamp } from './numbers.js';

/**
 * The largest colour channel (a light's, say): products of a few such numbers
 * stay finite, so no Infinity × 0 = NaN turns a bright pixel black.
 */
export const MAX_COLOR = 1e6;

const NAMES = {
  black: '#000000', white: '#ffffff', gray: '#808080', grey: '#808080',
  silver: '#c0c0c0', red: '#ff0000', maroon: '#800000', orange: '#ffa500',
  yellow: '#ffff00', gold: '#ffd700', green: '#008000', lime: '#00ff00',
  olive: '#808000', teal: '#008080', cyan: '#00ffff', aqua: '#00ffff',
  blue: '#0000ff', navy: '#000080', skyblue: '#87ceeb', purple: '#800080',
  violet: '#ee82ee', magenta: '#ff00ff', fuchsia: '#ff00ff', pink: '#ffc0cb',
  hotpink: '#ff69b4', brown: '#a52a2a', salmon: '#fa8072', coral: '#ff7f50',
};

/**
 * `[r, g, b]` (0–1 floats) from an array or a CSS-style string, else a
 * TypeError/RangeError naming `field`. A single number n means grey `[n, n, n]`.
 * @example
 * toColor('pink');       // [1, 0.753, 0.796]
 * toColor('#ff5160');    // [1, 0.318, 0.376]
 * toColor([1, 0.5, 0]);  // [1, 0.5, 0]
 */
export function toColor(value, field = 'color') {
  if (typeof value === 'number') value = [value, value, value];
  if (Array.isArray(value) || ArrayBuffer.isView(value)) return checkArray(value, field);
  if (typeof value === 'string') return parseString(value.trim().toLowerCase(), field);
  throw new TypeError(`${field} must be [r, g, b] or a colour like '#ff5160', got ${show(value)}`);
}

function checkArray(value, field) {
  if (value.length !== 3) throw new TypeError(`${field} must have 3 numbers [r, g, b], got ${show(value)}`);
  const rgb = [0.5, 0.5, 0.5]; // a double array from the start: one shape for every colour
  Array.from(value).forEach((c, i) => {
    if (typeof c !== 'number' || !Number.isFinite(c)) {
      throw new TypeError(`${field}[${i}] must be a finite number, got ${show(c)}`);
    }
    if (c < 0) throw new RangeError(`${field}[${i}] must not be negative, got ${c}`);
    if (c > MAX_COLOR) throw new RangeError(`${field}[${i}] must be at most ${MAX_COLOR} (brighter is white anyway), got ${c}`);
    rgb[i] = c;
  });
  return rgb;
}

function parseString(text, field) {
  if (Object.hasOwn(NAMES, text)) text = NAMES[text]; // not 'constructor' or '__proto__' from Object.prototype
  let m = /^#([0-9a-f]{3})$/.exec(text);
  if (m) return checkArray([...m[1]].map((h) => parseInt(h + h, 16) / 255), field);
  m = /^#([0-9a-f]{6})$/.exec(text);
  if (m) return checkArray([0, 2, 4].map((i) => parseInt(m[1].slice(i, i + 2), 16) / 255), field);
  m = /^rgb\(\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*\)$/.exec(text);
  if (m && m.slice(1).every((c) => Number(c) <= 255)) return checkArray(m.slice(1).map((c) => Number(c) / 255), field);
  const meant = /^[a-z]+$/.test(text) ? closestName(text, Object.keys(NAMES)) : null; // 'pinkk' → 'pink'
  throw new TypeError(`${field} must be a colour like '#ff5160', 'rgb(255, 81, 96)' or 'pink', got ${show(text)}${meant ? ` (did you mean '${meant}'?)` : ''}`);
}

/**
 * '#rrggbb' for 0–255 channel values (clamped, so the answer is always six digits).
 * @param {ArrayLike<number>} rgb `[r, g, b]`, each 0–255
 * @returns {string}
 * @example
 * toHex([255, 81, 96]); // '#ff5160'
 */
export function toHex(rgb) {
  checkChannels(rgb, 'toHex');
  const r = rgb[0], g = rgb[1], b = rgb[2];
  return '#' + [r, g, b].map((c) => Math.round(clamp(c, 0, 255)).toString(16).padStart(2, '0')).join('');
}

/**
 * A TypeError naming `where` unless `rgb` holds three finite numbers: a NaN
 * would print as '#NaN0000' or be named a colour it is not. Allocates nothing
 * (colorName may run for every pixel of a picture).
 */
function checkChannels(rgb, where) {
  if (rgb === null || typeof rgb !== 'object' || !(rgb.length >= 3)) {
    throw new TypeError(`${where} takes [r, g, b], got ${show(rgb)}`);
  }
  const r = rgb[0], g = rgb[1], b = rgb[2];
  if (!(Number.isFinite(r) && Number.isFinite(g) && Number.isFinite(b))) { // also not '12', not undefined
    throw new TypeError(`${where} takes [r, g, b], three finite numbers, got ${show(rgb)}`);
  }
}

/** '#rrggbb' for 0–1 channel values (clamped). */
export function colorToHex(rgb) {
  return toHex(rgb.map((c) => c * 255));
}

/**
 * The name of the nearest simple colour for 0–255 channel values, by hue,
 * saturation and lightness: black, white, gray, red, pink, orange, brown,
 * yellow, green, cyan, blue or purple. A red that is not fully saturated and
 * not dark is "pink", and so is a light magenta: the lesson's pink sphere,
 * [1, 0.32, 0.36], stays pink as its shading darkens, until it is dim red.
 * @param {ArrayLike<number>} rgb `[r, g, b]`, each 0–255
 * @returns {string}
 * @example
 * colorName([255, 81, 96]); // 'pink'
 * colorName([20, 200, 40]); // 'green'
 */
export function colorName(rgb) {
  checkChannels(rgb, 'colorName');
  const r = rgb[0], g = rgb[1], b = rgb[2];
  const { h, s, l } = rgbToHsl(r / 255, g / 255, b / 255);
  if (l < 0.1) return 'black';
  if (l > 0.93) return 'white';
  if (s < 0.18 || (l < 0.2 && s < 0.35)) return l > 0.8 ? 'white' : 'gray';
  if (h < 15 || h >= 345) return isPinkRed(r, g, b) ? 'pink' : 'red';
  if (h < 45) return l < 0.4 ? 'brown' : 'orange';
  if (h < 70) return l < 0.3 ? 'brown' : 'yellow';
  if (h < 165) return 'green';
  if (h < 200) return 'cyan';
  if (h < 260) return 'blue';
  if (h < 290) return 'purple';
  return l >= 0.45 ? 'pink' : 'purple';
}

/**
 * A red hue reads as pink when white is mixed in (HSV saturation below 0.85:
 * the pink sphere's own 0.68 survives shading) and it is not dark (value ≥ 0.7).
 */
function isPinkRed(r, g, b) {
  const max = Math.max(r, g, b), min = Math.min(r, g, b);
  return max >= 0.7 * 255 && 1 - min / max < 0.85;
}

/** Hue in degrees [0, 360), saturation and lightness in 0–1. */
export function rgbToHsl(r, g, b) {
  const max = Math.max(r, g, b), min = Math.min(r, g, b);
  const l = (max + min) / 2;
  const d = max - min;
  if (d === 0) return { h: 0, s: 0, l };
  const s = d / (1 - Math.abs(2 * l - 1));
  let h;
  if (max === r) h = ((g - b) / d) % 6;
  else if (max === g) h = (b - r) / d + 2;
  else h = (r - g) / d + 4;
  h *= 60;
  if (h < 0) h += 360;
  return { h, s, l };
}
