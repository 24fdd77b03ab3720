/**
 * Which fields of the scene a number literal of the code writes, so that a
 * new value reaches the picture without running the code again.
 *
 * The page learns it by comparison, not by trusting the frame: the code ran
 * with the literal at one value and then at another (its first step), and
 * the scene and camera the frame reported each time differ in exactly the
 * fields that held the old value and now hold the new one. Any other
 * difference (a loop count adds shapes, a size changes the canvas, a value
 * computed from the literal) means the literal is not simply a field of the
 * scene: the code runs again, as after typing.
 */
import { isDecimal } from './number-literal.js';

/** Camera fields that change the canvas, not the picture in it: a literal that sets one runs the code again. */
const CANVAS_FIELDS = new Set(['camera.width', 'camera.height', 'camera.samples']);

/** Every number in `value` (plain JSON data) by its path, `scene.objects.0.radius`. */
function numbers(value, path, into) {
  if (typeof value === 'number') into.set(path, value);
  else if (value !== null && typeof value === 'object') {
    for (const key of Object.keys(value)) numbers(value[key], `${path}.${key}`, into);
  } else into.set(path, value); // strings and booleans: they must not differ either
  return into;
}

/**
 * The paths of the fields the literal writes, or null when the two runs
 * differ otherwise (or not at all).
 * @param {{ scene: object, camera: object }} before the frame's report with the literal at `oldValue`
 * @param {{ scene: object, camera: object }} after its report with the literal at `newValue`
 * @param {number} oldValue
 * @param {number} newValue
 * @returns {string[][]|null} paths such as ['scene', 'objects', '0', 'radius']
 */
export function fieldsOfLiteral(before, after, oldValue, newValue) {
  if (oldValue === newValue) return null;
  const was = numbers(before, '', new Map()), now = numbers(after, '', new Map());
  if (was.size !== now.size) return null;
  const fields = [];
  for (const [path, value] of now) {
    if (!was.has(path)) return null;
    const old = was.get(path);
    if (Object.is(old, value)) continue;
    if (old !== oldValue || value !== newValue || CANVAS_FIELDS.has(path.slice(1))) return null;
    fields.push(path.slice(1).split('.'));
  }
  return fields.length ? fields : null;
}

/**
 * The literal's new value when `code` differs from the code the binding was
 * made for only inside that literal, and it is still a literal we can read;
 * else null (then the code runs again).
 * @param {{ prefix: string, suffix: string }} binding the code around the literal
 * @param {string} code the editor's code now
 */
export function valueInPlace(binding, code) {
  const { prefix, suffix } = binding;
  if (code.length < prefix.length + suffix.length || !code.startsWith(prefix) || !code.endsWith(suffix)) return null;
  const text = code.slice(prefix.length, code.length - suffix.length).trim();
  return isDecimal(text) ? Number(text) : null;
}

/** How a field's path is said: `radius`, `center z`, `color g`, `fov`. */
export function fieldWords(path) {
  const [last, ...rest] = [...path].reverse();
  const index = Number(last);
  if (!Number.isInteger(index)) return last;
  const axes = rest[0] === 'color' || rest[0] === 'emission' || rest[0] === 'background' ? 'rgb' : 'xyz';
  return `${rest[0]} ${axes[index] ?? index}`;
}
