/**
 * The scene form: value boxes (value-box.js) for a whole scene (every
 * sphere's centre, radius, colour, reflection, transparency and emission,
 * every point light) that hand back a new Scene only when the values are good.
 * A change is checked and applied on its own object (lib/scene/edits.js), not
 * on the whole scene again: at 1,000 spheres that is what keeps a typed value
 * or "Add sphere" quick.
 *
 *   const form = p.createSceneForm({ json: sceneToJSON(scene), parent, onChange: (scene, json) => view.setScene(scene) });
 *
 * Which boxes each kind of object gets, and the new JSON a box's value makes:
 * lib/scene/fields.js.
 */
import { colorToHex } from '../../math/color.js';
import { readColor, colorText } from '../../scene/values.js';
import { tableColumns, fieldText, formTypes } from '../../scene/fields.js';
import { shapeClass } from '../../shapes/index.js';
import { SceneEdits } from '../../scene/edits.js';
import { show, checkOptions } from '../../text/check.js';
import { useStyle, element, shownName, nameTitle } from '../dom.js';
import { valueBox } from './value-box.js';

/** The point light's table (each shape's is its class's `form`). */
const POINT_LIGHTS = { title: 'Point lights', what: 'Point light' };

/** Each table, in order: its type, what it is called and what a row is called. */
function tables() {
  return formTypes().map((type) => ({ type, ...(type === 'pointLight' ? POINT_LIGHTS : shapeClass(type).form) }));
}

/* ---------------- the scene form ---------------- */

/**
 * A table of the form shows this many rows at first, and this many more at
 * each "Show more": 1,000 spheres of boxes took 0.9 s to build, and each
 * "Add sphere" built them all again.
 */
export const FORM_ROWS = 40;

/**
 * A form of value boxes for a scene: one table per kind of object (a row per
 * sphere, point light, plane, box), a background colour, add and remove
 * buttons. Each change is checked box by box and then on its object with
 * sceneFromJSON's checks; a bad value gets a message beside its box and
 * changes nothing, a good one calls `onChange(scene, json)`.
 * @param {import('p5').default} p the sketch (unused: the form goes into `parent`)
 * @param {object} options
 * @param {object} options.json scene JSON (sceneToJSON)
 * @param {HTMLElement} options.parent
 * @param {(scene: import('../../scene/scene.js').Scene, json: object) => void} options.onChange
 * @example
 * p.createSceneForm({
 *   json: sceneToJSON(classScene()), parent: document.getElementById('values'),
 *   onChange: (scene) => view.setScene(scene), // only a scene whose every box is right
 * });
 */
export function createSceneForm(p, options) {
  const { json, parent, onChange } = checkOptions(options, ['json', 'parent', 'onChange'], 'createSceneForm');
  return new SceneForm({ json, parent, onChange });
}

export class SceneForm {
  /** How many rows each table (by type) shows. */
  #shown = new Map();
  /** Each table on show, by type: `{ rows, body, showUpTo }`. */
  #tables = new Map();
  /** The scene and its JSON, one change at a time. */
  #edits;
  /** A call of onChange waiting for its task (see remove), else 0. */
  #pending = 0;

  constructor({ json, parent, onChange }) {
    if (typeof onChange !== 'function') throw new TypeError(`onChange must be a function, got ${show(onChange)}`);
    useStyle();
    this.#edits = new SceneEdits(json); // checked, every field present
    this.onChange = onChange;
    this.element = element('div', { class: 'sf-form', 'data-scene-form': '' });
    parent.append(this.element);
    this.build();
  }

  /** The current scene (the last good one). */
  get scene() { return this.#edits.scene; }
  /** Its JSON; the objects in the order of the rows (see lib/scene/edits.js). */
  get json() { return this.#edits.json; }

  /** Replaces every box from `json` (after add/remove, or a new scene). */
  build() {
    const background = this.#colorBox(colorText(this.json.background), 'background', 'background colour',
      (value) => this.#try(['background'], value, ''));
    background.element.querySelector('.sf-label').classList.remove('sf-hidden-label'); // no column head above this one
    const top = element('div', { class: 'sf-top' }, background.element, ...this.#addButtons());
    this.#tables.clear();
    this.element.replaceChildren(top, ...tables().map((t) => this.#table(t)).filter(Boolean));
  }

  /** Adds an object's JSON at the end: one new row (or one more in "not shown"); the other rows stay. */
  add(object) {
    const index = this.#edits.add(object), o = this.json.objects[index];
    this.#changed();
    const table = this.#tables.get(o.type);
    if (!table) return this.build(); // the first of its type: a new table
    const showsAll = table.body.children.length === table.rows.length;
    table.rows.push({ o, index });
    table.showUpTo(showsAll ? table.rows.length : table.body.children.length);
  }

  /**
   * Removes the object at `index` of `json.objects`. The boxes are built again
   * now (the later rows' indices moved); the new scene goes to `onChange` in a
   * task of its own: at 10,000 spheres the two took one task of 200–270 ms.
   */
  remove(index) {
    this.#edits.remove(index);
    this.build();
    this.#changeSoon();
  }

  /** Calls onChange in a task of its own, once for any changes until then, with the scene as it is then. */
  #changeSoon() {
    if (this.#pending) return;
    this.#pending = setTimeout(() => this.#changed(), 0);
  }

  #addButtons() {
    const n = () => this.json.objects.length + 1;
    const add = (label, make) => {
      const b = element('button', { type: 'button', class: 'rt-button', 'data-add': label }, label);
      b.addEventListener('click', () => this.add(make()));
      return b;
    };
    return [
      add('Add sphere', () => ({ type: 'sphere', name: `sphere ${n()}`, center: [0, 3, -12], radius: 1, material: { color: [0.3, 0.8, 0.4] } })),
      add('Add light sphere', () => ({ type: 'sphere', name: `light ${n()}`, center: [-10, 10, -10], radius: 1, material: { color: [0, 0, 0], emission: 1 } })),
      add('Add point light', () => ({ type: 'pointLight', name: `point light ${n()}`, position: [10, 10, 0], color: [1, 1, 1], intensity: 1 })),
    ];
  }

  #table(kind) {
    const { type, title } = kind;
    const rows = this.json.objects.map((o, index) => ({ o, index })).filter(({ o }) => o.type === type);
    if (!rows.length) return null;
    const columns = tableColumns(type);
    const head = element('tr', {}, element('th', {}, 'name'), ...columns.map((c) => element('th', {}, c.head)), element('th', {}, ''));
    const body = element('tbody', {});
    const more = element('button', { type: 'button', class: 'rt-button', 'data-show-more': type });
    const note = element('p', { class: 'rt-note sf-more' }, more);
    const showUpTo = (n) => { // appends rows up to n: only the new ones are built
      for (let k = body.children.length; k < Math.min(n, rows.length); k++) body.append(this.#row(rows[k].o, rows[k].index, columns, this.#who(kind, k, rows[k].o)));
      this.#shown.set(type, body.children.length);
      const hidden = rows.length - body.children.length;
      note.hidden = hidden === 0;
      more.textContent = `Show ${Math.min(FORM_ROWS, hidden)} more (${hidden.toLocaleString('en')} not shown)`;
    };
    more.addEventListener('click', () => showUpTo(body.children.length + FORM_ROWS));
    showUpTo(Math.max(FORM_ROWS, this.#shown.get(type) ?? 0));
    this.#tables.set(type, { rows, body, showUpTo });
    // The table scrolls in its box on a narrow screen: focusable and named, so a keyboard scrolls it too.
    return element('section', { class: 'sf-section', 'data-table': type },
      element('h3', {}, title),
      element('div', { class: 'sf-table-wrap', tabindex: '0', role: 'region', 'aria-label': `${title} table` }, element('table', { class: 'sf-table' }, element('thead', {}, head), body)), note);
  }

  /** What a row is called in messages: "Sphere 3 (pink)". */
  #who({ what }, k, o) {
    return `${what} ${k + 1}${o.name ? ` (${shownName(o.name)})` : ''}`; // a 100,000-character name is no label
  }

  #row(o, index, columns, who) {
    const isLight = o.type === 'pointLight' || o.material?.emission.some((c) => c > 0);
    const name = element('th', { scope: 'row', ...nameTitle(o.name) }, isLight ? '☀ ' : '', o.name ? shownName(o.name) : who);
    const cells = columns.map((c) => {
      const id = `objects[${index}].${c.path.join('.')}`;
      const label = `${who} ${c.label}`;
      const commit = (value) => this.#try(['objects', index, ...c.path], value, who);
      const box = c.kind === 'color'
        ? this.#colorBox(fieldText(o, c), id, label, commit, !c.grey)
        : this.#numberBox(fieldText(o, c), id, label, c.rule, commit);
      return element('td', {}, box.element);
    });
    const remove = element('button', { type: 'button', class: 'rt-button sf-remove', 'data-remove': String(index), title: `Remove ${who}` }, 'Remove');
    remove.addEventListener('click', () => this.remove(index));
    return element('tr', { 'data-object': String(index) }, name, ...cells, element('td', {}, remove));
  }

  #numberBox(text, id, label, rule, commit) {
    const box = valueBox({ label, value: text, rule, name: id, size: '5' });
    box.element.querySelector('.sf-label').classList.add('sf-hidden-label'); // the column head says it; messages and screen readers use it
    this.#commitOnChange(box, commit);
    return box;
  }

  /** A colour picker and a text box for the same colour (the text box also takes lights' values above 1). */
  #colorBox(text, id, label, commit, picker = true) {
    const box = valueBox({ label, value: text, parse: readColor, name: id, size: picker ? '7' : '5' });
    box.element.querySelector('.sf-label').classList.add('sf-hidden-label'); // the column head says it; messages and screen readers use it
    box.input.removeAttribute('inputmode');
    if (!picker) {
      this.#commitOnChange(box, commit);
      return box;
    }
    const pick = element('input', { type: 'color', 'aria-label': `${label} (picker)`, 'data-picker-for': id });
    const showPicker = (rgb) => { pick.value = colorToHex(rgb); };
    box.input.addEventListener('change', () => {
      const v = box.read();
      if (v === undefined) return;
      if (this.#report(box, commit(v))) showPicker(v);
    });
    pick.addEventListener('input', () => {
      box.input.value = pick.value;
      const v = box.read();
      if (v !== undefined) this.#report(box, commit(v));
    });
    try { showPicker(readColor(text, label)); } catch { /* the text box shows what is wrong */ }
    box.input.before(pick);
    return box;
  }

  /** A value typed in `box` (Enter, or leaving the box) is committed when good; any problem shows beside the box. */
  #commitOnChange(box, commit) {
    box.input.addEventListener('change', () => {
      const v = box.read();
      if (v !== undefined) this.#report(box, commit(v));
    });
  }

  /** Puts `value` at `path` of the scene's JSON when good; else returns the message, with the row's name for the path. */
  #try(path, value, who) {
    try {
      this.#edits.set(path, value);
    } catch (error) {
      // sceneFromJSON's checks name the path: "objects[1].material.color[0] must …" → "Sphere 2: color[0] must …"
      const field = error.message.replace(/^objects\[\d+\]\.(material\.)?/, '');
      return who ? `${who}: ${field}` : field;
    }
    this.#changed();
    return '';
  }

  /** Shows a whole-scene problem beside the box; true when there was none. */
  #report(box, problem) {
    if (problem) box.fail(problem);
    return !problem;
  }

  #changed() {
    clearTimeout(this.#pending); // a change made now hands on the scene a pending one would have
    this.#pending = 0;
    this.onChange(this.scene, this.json);
  }
}
