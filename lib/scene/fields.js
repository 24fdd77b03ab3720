/**
 * The values of a scene a student edits in boxes: for each type of object
 * (sphere, point light, plane, box; a shape lists its own, its static `form`)
 * the fields of its JSON (see json.js) in table order, each with its label and the rule its number must meet; the
 * text a box shows for one; and a copy of scene JSON with one value changed.
 * lib/p5/controls/scene-form.js builds its tables from these.
 */
import { colorText } from './values.js';
import { show } from '../text/check.js';
import { shapeClasses, shapeClass } from '../shapes/index.js';
import { xyz } from '../shapes/form.js';

/** The point light's boxes (each shape class lists its own: its static `form`, lib/shapes/form.js). */
const POINT_LIGHT = [...xyz('position', 'position'), { path: ['color'], label: 'colour', head: 'colour', kind: 'color' },
  { path: ['intensity'], label: 'intensity', head: 'intensity', kind: 'number', rule: { min: 0 } }];

/**
 * The boxes of each object type of the kit, in table order: `path` into the
 * object's JSON, `label` for messages, `head` for the column, `kind` 'number'
 * or 'color', and `rule` for readNumber. (A shape listed later: tableColumns.)
 */
export const COLUMNS = Object.fromEntries(formTypes().map((type) => [type, tableColumns(type)]));

/** The types with a table in the scene form, in the form's order: the first shape (the lesson's spheres), the point light, the other shapes. */
export function formTypes() {
  const shapes = shapeClasses().filter((Shape) => Shape.form).map((Shape) => Shape.type);
  return [...shapes.slice(0, 1), 'pointLight', ...shapes.slice(1)];
}

/** The columns for objects of `type` (a TypeError for an unknown one). */
export function tableColumns(type) {
  if (type === 'pointLight') return POINT_LIGHT;
  const columns = typeof type === 'string' ? shapeClass(type)?.form?.columns : undefined;
  if (!columns) throw new TypeError(`type must be one of ${formTypes().join(', ')}, got ${show(type)}`);
  return columns;
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
