/**
 * The values of a scene a student edits in boxes: for each type of object
 * (sphere, point light, plane, box) the fields of its JSON (see serialize.js)
 * in table order, each with its label and the rule its number must meet; the
 * text a box shows for one; and a copy of scene JSON with one value changed.
 * lib/p5/scene-form.js builds its tables from these.
 */
import { colorText } from './values.js';
import { show } from './check.js';

const xyz = (field, name) => ['x', 'y', 'z'].map((axis, i) => ({ path: [field, i], label: `${name} ${axis}`, head: axis, kind: 'number' }));
const share = (field) => ({ path: ['material', field], label: field, head: field, kind: 'number', rule: { min: 0, max: 1 } });
const surface = { path: ['material', 'color'], label: 'colour', head: 'colour', kind: 'color' };

/**
 * The boxes of each object type, in table order: `path` into the object's
 * JSON, `label` for messages, `head` for the column, `kind` 'number' or
 * 'color', and `rule` for readNumber.
 */
export const COLUMNS = {
  sphere: [...xyz('center', 'centre'), { path: ['radius'], label: 'radius', head: 'radius', kind: 'number', rule: { above: 0 } },
    surface, share('reflection'), share('transparency'),
    { path: ['material', 'emission'], label: 'emission', head: 'emission', kind: 'color', grey: true }],
  pointLight: [...xyz('position', 'position'), { path: ['color'], label: 'colour', head: 'colour', kind: 'color' },
    { path: ['intensity'], label: 'intensity', head: 'intensity', kind: 'number', rule: { min: 0 } }],
  plane: [...xyz('point', 'point'), ...xyz('normal', 'normal'), surface, share('reflection')],
  box: [...xyz('min', 'min'), ...xyz('max', 'max'), surface, share('reflection')],
};

/** The columns for objects of `type` (a TypeError for an unknown one). */
export function tableColumns(type) {
  if (!Object.hasOwn(COLUMNS, type)) throw new TypeError(`type must be one of ${Object.keys(COLUMNS).join(', ')}, got ${show(type)}`);
  return COLUMNS[type];
}

/** A copy of `json` with `value` at `path` (an array of keys); `json` itself is untouched. */
export function withValue(json, path, value) {
  const copy = structuredClone(json);
  let at = copy;
  for (const key of path.slice(0, -1)) at = at[key];
  at[path.at(-1)] = value;
  return copy;
}

function valueAt(json, path) {
  return path.reduce((at, key) => at?.[key], json);
}

/** The text a box shows for the value of `column` in an object's JSON. */
export function fieldText(o, column) {
  const v = valueAt(o, column.path);
  return column.kind === 'color' ? colorText(v, { grey: column.grey }) : String(v);
}
