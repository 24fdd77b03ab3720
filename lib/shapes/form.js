/**
 * The scene form's boxes as each shape lists its own (its static `form`:
 * `{ title, what, columns }`, read by lib/scene/fields.js and
 * lib/p5/controls/scene-form.js). A column: `path` into the object's JSON, `label` for
 * messages, `head` for the column, `kind` 'number' or 'color', and `rule` for readNumber.
 */

/** Three boxes, x y z, of a point or direction field. */
export const xyz = (field, name) => ['x', 'y', 'z'].map((axis, i) => ({ path: [field, i], label: `${name} ${axis}`, head: axis, kind: 'number' }));

/** A material's share, 0–1 (reflection, transparency). */
export const share = (field) => ({ path: ['material', field], label: field, head: field, kind: 'number', rule: { min: 0, max: 1 } });

/** The material's surface colour. */
export const SURFACE = { path: ['material', 'color'], label: 'colour', head: 'colour', kind: 'color' };
