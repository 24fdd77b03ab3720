/**
 * The sky: the light a path gathers when it leaves the scene. A constant
 * colour (the scene's background, by default), or a gradient from `bottom`
 * (straight down) to `top` (straight up), blended by the height of the
 * direction as in *Ray Tracing in One Weekend*: t = (dy + 1) / 2.
 */
import { toColor } from '../../math/color.js';
import { show, checkOptions } from '../../text/check.js';

/**
 * The sky of `pathTrace`'s `sky` option, checked: `[top r, g, b, bottom r, g, b]`.
 * @param {undefined|number[]|string|{ top: number[]|string, bottom: number[]|string }} value
 *   a colour (the same all round), `{ top, bottom }` (a gradient), or undefined: the scene's background
 * @param {number[]} background the scene's background colour
 * @returns {Float64Array}
 */
export function readSky(value, background) {
  if (value === undefined) return Float64Array.of(...background, ...background);
  if (value !== null && typeof value === 'object' && !Array.isArray(value)) {
    const { top, bottom } = checkOptions(value, ['top', 'bottom'], 'sky');
    if (top === undefined || bottom === undefined) throw new TypeError(`sky must have both top and bottom colours, got ${show(value)}`);
    return Float64Array.of(...toColor(top, 'sky.top'), ...toColor(bottom, 'sky.bottom'));
  }
  const color = toColor(value, 'sky');
  return Float64Array.of(...color, ...color);
}

/** Channel c of the sky's light along a unit direction whose y is `dy`. */
export function skyLight(sky, c, dy) {
  const t = 0.5 * (dy + 1);
  return t * sky[c] + (1 - t) * sky[c + 3];
}

/** True when the sky is the same colour all round (a uniform sky: the white furnace's). */
export function isUniform(sky) {
  return sky[0] === sky[3] && sky[1] === sky[4] && sky[2] === sky[5];
}
