/**
 * The inspector panel: the whole story of the selected pixel, in the
 * lesson's words and numbers. It follows a tracer view's selection and shows
 * what `inspectPixel` (lib/lesson/inspect.js) records — the very values the renderer
 * computed:
 *   - the answer line `Pixel: X,Y; H: a; V: b` (the class activity's format);
 *   - the final colour: swatch, hex and the nearest simple colour name;
 *   - the ray R(t) = Ro + Rd·t and what it hit (t, point, normal, incidence);
 *   - each light: facing it or not, in shadow or not, what it added;
 *   - per sphere, both routes: A, B, C, discriminant → roots t0, t1, and
 *     L, tca, d², thc → t0, t1, with a mark that the two routes agree;
 *   - every other shape by its own test (its `intersect` record's lines).
 * Every value sits in an element with data attributes (`data-field`, and `data-sphere`/`data-route`
 * or `data-light` where needed) and its full precision in `data-value`, so tests and worksheets can read it.
 */
import { recordOf } from './record.js';
import { toHex, colorName } from '../../math/color.js';
import { formatNumber, formatVector, formatAngle } from '../../text/format.js';
import { show, checkOptions } from '../../text/check.js';
import { useStyle, element, resolveParent, copyText, shownName, nameTitle } from '../dom.js';
import { showInBox, downloadText } from '../controls/text-box.js';
import { joinInSlices } from '../../text/slices.js';
import { pixelCSV, pixelCSVLines, rootsMeaning, routesAgree } from './csv.js';
import { gpuDifference } from '../tracer/engines.js';
import { createAnnouncer } from '../page/announce.js';
import { answerLine, pixelAnnouncement } from './words.js';
import { virtualRows, VIRTUAL_FROM } from './virtual-rows.js';

export { pixelCSV, pixelCSVLines, csvCell, rootsMeaning, routesAgree, AGREE_TOLERANCE } from './csv.js';
export { answerLine, pixelAnnouncement } from './words.js';

/**
 * A scene with more spheres than this shows only the rows that matter (the
 * hit, the other spheres the ray meets, the nearest misses) and the rest on
 * demand: a 1,000-sphere table took a click a quarter of a second.
 */
export const SPHERE_ROWS = 12;
/** Area lights listed at a hit, each with its shadow rays; past them "and N more" (9,998 lights × 64 rays made 2 million elements). */
export const AREA_LIGHTS_SHOWN = 8;

/**
 * Creates an inspector panel that follows `view`'s selected pixel:
 * `p.createInspector({ view })` in a sketch.
 * @param {import('p5').default} p the sketch (unused: the panel goes beside the view)
 * @param {object} options
 * @param {import('../tracer/view.js').TracerView} options.view
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] default: beside the view (its parent)
 * @param {string} [options.title] a heading above the panel's answer line (say whose angles it shows)
 * @returns {Inspector}
 * @example
 * const view = p.createTracerView({ scene: classScene(), camera: new Camera({ width: 64, height: 48 }) });
 * p.createInspector({ view }); // click a pixel: Pixel: X,Y; H: …; V: …, the discriminant, the roots, the hit
 */
export function createInspector(p, options) { // no options: checkOptions gives {}
  const { view, parent, title } = checkOptions(options, ['view', 'parent', 'title'], 'createInspector');
  return new Inspector({ view, parent, title });
}

/**
 * The inspector panel, what `p.createInspector({ view })` returns: the whole story of the selected pixel.
 * @example
 * const inspector = p.createInspector({ view });
 * view.select(10, 12);   // the panel follows: inspector.record is that pixel's inspectPixel record
 * inspector.csv();       // the same record as CSV, for a worksheet
 */
export class Inspector {
  /** The last `inspectPixel` record shown, or null. */
  record = null;
  #unsubscribe; #announcer;
  /** The last record's CSV text (a promise), `{ record, text }`. */
  #csv = null;

  constructor({ view, parent, title }) {
    if (!view || typeof view.onSelect !== 'function') throw new TypeError(`view must be a tracer view (createTracerView), got ${show(view)}`);
    this.view = view;
    useStyle();
    // Not a live region: its tables are read on demand; the pixel is said in one short status line.
    this.element = element('section', { class: 'rt-inspector', 'data-inspector': '', 'aria-label': 'Pixel inspector' });
    this.#announcer = createAnnouncer({ name: 'pixel' });
    this.answer = element('p', { class: 'rt-answer', 'data-answer': '' });
    this.body = element('div', { class: 'rt-inspector-body' });
    this.element.append(...[title && element('h2', { class: 'rt-inspector-title' }, title), this.answer, this.#announcer.element, this.body, this.#csvTools()].filter(Boolean));
    resolveParent(parent, view.figure?.parentElement ?? document.body).append(this.element);
    this.#unsubscribe = view.onSelect((selected) => this.show(selected));
    this.show(view.selected);
  }

  /** Shows pixel `{ x, y }` of the view's picture (null: the hint to click one), from its record (the view's own when it is the selected pixel). */
  show(selected) {
    if (!selected) {
      this.record = null;
      this.answer.textContent = '';
      this.body.replaceChildren(element('p', { class: 'rt-hint' }, 'Click a pixel of the picture, or click it once and move with the arrow keys (Shift: 10 at a time).'));
      this.element.dataset.state = 'empty';
      return;
    }
    const r = this.record = recordOf(this.view, selected);
    this.answer.textContent = answerLine(r);
    this.answer.style.setProperty('--rt-answer-chars', String(this.answer.textContent.length)); // style.css fits the line to the panel
    this.#announcer.say(pixelAnnouncement(r));
    this.element.dataset.x = String(r.x);
    this.element.dataset.y = String(r.y);
    this.#showBody(r, rowsThatMatter(r));
    if (this.csvDetails.open) this.#fillCSV(r); // written when opened or copied: 10,000 rows cost time
    else this.#showCSV('');
    this.status.textContent = '';
    this.element.dataset.state = 'shown';
  }

  /** The sections, with the spheres' tables limited to the tests `shown` (all when null). */
  #showBody(r, shown) {
    const tests = shown ?? r.tests;
    const more = shown ? this.#moreButton(r) : null;
    const spheres = r.tests.length > 0 || r.records.length === 0; // only other shapes (12, 13): no empty sphere tables
    this.body.replaceChildren(colorSection(r), ...gpuDifference(this.view, r), raySection(r), hitSection(r), lightsSection(r),
      ...(spheres ? [quadraticSection(r, tests, more), geometricSection(r, tests, more && this.#moreButton(r))] : []), shapesSection(r));
  }

  /** "Show all 1,000 spheres": the whole tables, for this pixel. */
  #moreButton(r) {
    const n = r.tests.length.toLocaleString('en');
    const button = element('button', { type: 'button', class: 'rt-button rt-more', 'data-show-all-spheres': '' }, `Show all ${n} spheres`);
    button.addEventListener('click', () => { if (this.record === r) this.#showBody(r, null); });
    return element('p', { class: 'rt-note', 'data-sphere-rows': `${SPHERE_ROWS} of ${r.tests.length}` },
      `Showing the ${SPHERE_ROWS} spheres that matter for this ray (the hit, the others it meets, the nearest misses) of ${n}. `, button);
  }

  /** The shown pixel's data as CSV (one row per sphere), or '' when none. */
  csv() {
    return this.record ? pixelCSV(this.record) : '';
  }

  /**
   * Copies the CSV to the clipboard when the browser allows it; the text is
   * always in the panel's text box too, selected, ready for Ctrl+C (up to
   * the box's limit, lib/p5/controls/text-box.js; "Download CSV" saves it all).
   * Built in slices (lib/text/slices.js): 10,000 rows are 1 MB of text.
   */
  async copyCSV() {
    const r = this.record;
    const text = r ? await this.#fillCSV(r) : '';
    this.csvDetails.open = true;
    this.csvBox.select();
    if (!text) { this.status.textContent = 'Select a pixel first.'; return false; }
    const copied = await copyText(text);
    this.status.textContent = copied ? 'Copied: paste it into a spreadsheet.' : 'Select the text below and press Ctrl+C (⌘C), or download it.';
    return copied;
  }

  /** Saves the shown pixel's CSV as a file, `pixel-X-Y.csv`. */
  async downloadCSV() {
    const r = this.record;
    if (!r) { this.status.textContent = 'Select a pixel first.'; return; }
    downloadText(await this.#csvText(r), `pixel-${r.x}-${r.y}.csv`, 'text/csv');
  }

  /** The CSV of record `r`, built in slices; kept for the record until another is shown. */
  async #csvText(r) {
    if (this.#csv?.record !== r) this.#csv = { record: r, text: joinInSlices(pixelCSVLines(r)) };
    return this.#csv.text;
  }

  /** Fills the text box with record `r`'s CSV, unless another pixel is shown by then; returns the text. */
  async #fillCSV(r) {
    const text = await this.#csvText(r);
    if (this.record === r) this.#showCSV(text);
    return text;
  }

  #showCSV(text) {
    this.csvNote.textContent = showInBox(this.csvBox, text);
  }

  /** Stops following the view and removes the panel. */
  destroy() {
    this.#unsubscribe();
    this.#announcer.destroy();
    this.element.remove();
  }

  #csvTools() {
    const button = element('button', { type: 'button', class: 'rt-button', 'data-copy-csv': '' }, 'Copy CSV');
    button.addEventListener('click', () => this.copyCSV());
    const save = element('button', { type: 'button', class: 'rt-button', 'data-download-csv': '' }, 'Download CSV');
    save.addEventListener('click', () => this.downloadCSV());
    this.status = element('span', { class: 'rt-status', 'data-copy-status': '', role: 'status' });
    this.csvBox = element('textarea', { class: 'rt-csv', 'data-csv': '', rows: '6', readonly: '', spellcheck: 'false', 'aria-label': 'This pixel as CSV' });
    this.csvNote = element('p', { class: 'rt-note', 'data-csv-note': '' });
    this.csvDetails = element('details', { class: 'rt-csv-details' }, element('summary', {}, 'CSV text'), this.csvBox, this.csvNote);
    this.csvDetails.addEventListener('toggle', () => { if (this.csvDetails.open && this.record) this.#fillCSV(this.record); });
    return element('footer', { class: 'rt-inspector-tools' }, element('div', { class: 'rt-row' }, button, save, this.status), this.csvDetails);
  }
}

/* ---------------- formatting ---------------- */

/** The name a light goes by in the panel (shapes have theirs in the record: shapeName). */
const nameOf = (object, fallback) => object?.name || fallback;

/* ---------------- sections ---------------- */

/** A value cell: formatted text, full precision in data-value, addressed by data attributes. */
function value(field, n, attributes = {}, text = formatNumber(n)) {
  return element('span', { class: 'rt-value', 'data-field': field, 'data-value': n === null ? '' : String(n), ...attributes }, text);
}

function vectorValue(field, v, attributes = {}, text = formatVector(v)) {
  return element('span', { class: 'rt-value', 'data-field': field, 'data-value': `${v.x},${v.y},${v.z}`, ...attributes }, text);
}

function textValue(field, text, attributes = {}) {
  return element('span', { class: 'rt-value', 'data-field': field, 'data-value': text, ...attributes }, text);
}

/** A name's value cell: cut on the page (shownName), whole in its title and data-value. */
function nameValue(field, name, attributes = {}) {
  return element('span', { class: 'rt-value', 'data-field': field, 'data-value': name, ...nameTitle(name), ...attributes }, shownName(name));
}

function section(title, ...children) {
  return element('section', { class: 'rt-section' }, element('h3', {}, title), ...children);
}

/** A two-column list of "term: value" rows. */
function facts(rows) {
  const dl = element('dl', { class: 'rt-facts' });
  for (const [term, ...values] of rows) dl.append(element('dt', {}, term), element('dd', {}, ...values));
  return dl;
}

function colorSection(r) {
  const hex = toHex(r.color), name = colorName(r.color);
  return element('div', { class: 'rt-color', 'data-section': 'color' },
    element('span', { class: 'rt-swatch', 'data-field': 'swatch', style: `background: ${hex}`, title: hex }),
    element('div', { class: 'rt-color-text' },
      element('div', { class: 'rt-color-name' }, textValue('color-name', name)),
      element('div', {}, textValue('hex', hex), ' ', textValue('rgb', `rgb(${r.color.join(', ')})`, { class: 'rt-value rt-muted' }))));
}

function raySection(r) {
  return section('Ray R(t) = Ro + Rd·t', facts([
    ['Ro (eye)', vectorValue('ray-origin', r.ray.origin)],
    ['Rd (direction)', vectorValue('ray-direction', r.ray.direction)],
    ['H, V', value('h', r.h, {}, `${formatAngle(r.h)}°`), ', ', value('v', r.v, {}, `${formatAngle(r.v)}°`)],
  ]));
}

function hitSection(r) {
  const hit = r.hit;
  if (!hit) {
    return section('Hit', element('p', { 'data-field': 'hit-object', 'data-value': '' },
      'No hit: the ray meets nothing, so the pixel takes the background colour.'));
  }
  const name = hit.name;
  return section('Hit', facts([
    ['object', nameValue('hit-object', name), hit.inside ? ' (from inside)' : ''],
    ['t', value('hit-t', hit.t)],
    ['point', vectorValue('hit-point', hit.point)],
    ['normal N', vectorValue('hit-normal', hit.normal)],
    ['incidence', value('incidence', hit.incidence, {}, `${formatNumber(hit.incidence)}°`), element('span', { class: 'rt-muted' }, ' between the ray and N')],
  ]));
}

function lightsSection({ hit }) {
  if (!hit || hit.lights.length === 0) return element('div', { hidden: '' });
  const grouped = new Set((hit.areaLights ?? []).flatMap((g) => g.indices));
  const own = hit.lights.map((l, i) => i).filter((i) => !grouped.has(i));
  const parts = [];
  if (own.length) parts.push(table(['light', 'cos θ', 'shadow ray', 'adds (r, g, b)'], own.length, (k) => lightRow(hit.lights[own[k]], own[k]), 'Lights'));
  const areas = hit.areaLights ?? [], more = areas.length - AREA_LIGHTS_SHOWN;
  areas.slice(0, AREA_LIGHTS_SHOWN).forEach((g, a) => parts.push(areaLightBlock(hit, g, a)));
  if (more > 0) parts.push(element('p', { class: 'rt-note', 'data-field': 'more-area-lights' }, `and ${more.toLocaleString('en')} more area lights, not shown`));
  return section(hit.areaLights?.length ? 'Lights (one shadow ray each; an area light, one per point of its disc)' : 'Lights (one shadow ray each)', ...parts);
}

/** One light's row: its name, cos θ, what its shadow ray met, what it added. */
function lightRow(l, i) {
  const at = { 'data-light': String(i) };
  const status = !l.facing ? 'faces away' : l.beam === 0 ? 'outside its cone' : l.inShadow ? (l.transmission > 0 ? 'partly shadowed' : 'in shadow') : 'lit';
  return element('tr', { class: `rt-light-${status.replace(' ', '-')}` },
    element('td', {}, nameValue('light', nameOf(l.light, `light ${i + 1}`), at)),
    element('td', {}, value('cos', l.cos, at)),
    element('td', {}, element('span', { class: 'rt-value', 'data-field': 'in-shadow', 'data-value': String(l.inShadow), ...at }, status), ...falloffText(l, at)),
    element('td', {}, ...addedCell(l.contribution, at)));
}

/** A fading light's factor where the point is, "falloff ×0.2 at distance 10"; nothing for a light that does not fade. */
function falloffText(l, at) {
  if (!(l.attenuation > 0)) return [];
  return [' ', element('span', { class: 'rt-value', 'data-field': 'falloff', 'data-value': String(l.falloff), ...at }, `falloff ×${formatNumber(l.falloff)} at distance ${formatNumber(l.distance)}`)];
}

function addedCell(added, at) {
  return [element('span', { class: 'rt-swatch rt-swatch-small', style: `background: ${toHex(added.map((c) => Math.min(1, c) * 255))}` }),
    element('span', { class: 'rt-value rt-wrap', 'data-field': 'contribution', 'data-value': added.join(','), ...at }, `(${added.map(formatNumber).join(', ')})`)];
}

/**
 * An area light as one line, "area light 'lamp': 11 of 16 shadow rays reached
 * it (69 %)", what all its points added, and its shadow rays one by one in a
 * closed <details> (a point per row, as the point lights' table).
 */
function areaLightBlock(hit, g, a) {
  const at = { 'data-area-light': String(a) };
  const name = g.light.name ? `${g.label} '${shownName(g.light.name)}'` : `${g.label} ${a + 1}`, rows = g.indices;
  const percent = Math.round((100 * g.reached) / g.samples);
  return element('div', { class: 'rt-area-light', ...at },
    element('p', {},
      element('span', { class: 'rt-value', 'data-field': 'area-reached', 'data-value': `${g.reached}/${g.samples}`, ...at },
        `${name}: ${g.reached} of ${g.samples} shadow rays reached it (${percent} %)`),
      '; adds ', ...addedCell(g.contribution, at)),
    element('details', { class: 'rt-area-rays' },
      element('summary', {}, `its ${g.samples} shadow rays, one per point of the disc`),
      table(['point', 'cos θ', 'shadow ray', 'adds (r, g, b)'], rows.length, (k) => lightRow({ ...hit.lights[rows[k]], light: { name: `point ${k + 1}` } }, rows[k]), `Shadow rays of ${name}`)));
}

function sphereCell(test) {
  return element('th', { scope: 'row', ...nameTitle(test.name) }, shownName(test.name));
}

/**
 * The tests worth a row when there are more than SPHERE_ROWS (else null: all):
 * the spheres the ray meets, nearest first, then the misses by how near the
 * ray passes (√d² − r), shown in the scene's order.
 */
export function rowsThatMatter(r, limit = SPHERE_ROWS) {
  if (r.tests.length <= limit) return null;
  const gap = (test) => {
    if (test.sphere === r.hit?.object) return -Infinity;
    if (test.quadratic.t !== null) return -1e300 + test.quadratic.t; // met further on: after the hit, before any miss
    return Math.sqrt(Math.max(0, test.geometric.d2)) - test.sphere.radius;
  };
  const ranked = r.tests.map((test, i) => [gap(test), i]).sort((a, b) => a[0] - b[0]).slice(0, limit);
  return ranked.map(([, i]) => i).sort((a, b) => a - b).map((i) => r.tests[i]);
}

function rowClass(r, test) {
  return [test.sphere === r.hit?.object ? 'rt-hit-row' : '', test.quadratic.roots === 0 ? 'rt-miss-row' : ''].join(' ').trim();
}

function quadraticSection(r, tests = r.tests, more = null) {
  const head = ['sphere', 'A', 'B', 'C', 'B² − 4AC', 'meaning', 't0', 't1'];
  const row = (k, test = tests[k]) => { // made when shown: a table of 10,000 rows keeps those in view only
    const i = tests === r.tests ? k : r.tests.indexOf(test);
    const q = test.quadratic, at = { 'data-sphere': String(i), 'data-route': 'quadratic' };
    return element('tr', { class: rowClass(r, test) }, sphereCell(test),
      ...['A', 'B', 'C', 'discriminant'].map((f) => element('td', {}, value(f, q[f], at))),
      element('td', {},
        element('span', { class: `rt-value rt-roots-${q.roots}`, 'data-field': 'meaning', 'data-value': String(q.roots), ...at }, rootsMeaning(q.roots)),
        // Real roots, all t ≤ 0: the sphere is behind the eye, so it is no hit after all.
        q.roots > 0 && q.t === null ? element('span', { class: 'rt-behind', 'data-field': 'behind', ...at }, 'behind the eye') : null),
      element('td', {}, value('t0', q.t0, at)),
      element('td', {}, value('t1', q.t1, at)));
  };
  return section('Quadratic route: At² + Bt + C = 0', tests.length ? table(head, tests.length, row, 'Quadratic route') : noSpheres(), more,
    element('p', { class: 'rt-note' }, 'Discriminant < 0: no hit; = 0: tangent; > 0: two hits, t = (−B ± √(B² − 4AC)) / 2A. The nearest hit is the smallest positive t (highlighted row).'));
}

function geometricSection(r, tests = r.tests, more = null) {
  const head = ['sphere', 'L = C − Ro', 'tca', 'd²', 'thc', 't0', 't1', 'agree'];
  const row = (k, test = tests[k]) => { // made when shown: a table of 10,000 rows keeps those in view only
    const i = tests === r.tests ? k : r.tests.indexOf(test);
    const g = test.geometric, at = { 'data-sphere': String(i), 'data-route': 'geometric' };
    const agree = routesAgree(test.quadratic, g);
    return element('tr', { class: rowClass(r, test) }, sphereCell(test),
      element('td', {}, wrapBeforeZ(vectorValue('L', g.L, at, formatVector(g.L).replaceAll(', ', ',')))), // narrow: the table is wide
      ...['tca', 'd2', 'thc', 't0', 't1'].map((f) => element('td', {}, value(f, g[f], at))),
      element('td', {}, element('span', {
        class: `rt-value ${agree ? 'rt-agree' : 'rt-disagree'}`, 'data-field': 'agree', 'data-value': String(agree), ...at,
        title: agree ? 'Both routes find the same roots' : 'The two routes disagree',
      }, agree ? '✓' : '✗')));
  };
  return section('Geometric route: tca = L·Rd, d² = L·L − tca², thc = √(r² − d²)', tests.length ? table(head, tests.length, row, 'Geometric route') : noSpheres(), more,
    element('p', { class: 'rt-note' }, 'd > r: the ray passes the sphere by. Otherwise t = tca ∓ thc — the same roots as the quadratic.'));
}

/** Lets a vector "(x,y,z)" wrap before its z (<wbr>) when its table is narrow; its text stays the same. */
function wrapBeforeZ(span) {
  const text = span.textContent, at = text.lastIndexOf(',') + 1;
  span.replaceChildren(text.slice(0, at), element('wbr'), text.slice(at));
  span.classList.add('rt-wrap');
  return span;
}

/**
 * Every shape that is not a sphere, by its own test (a plane's Rd·n and t, a
 * box's slabs): one row per shape, its record's lines; hidden when there is none.
 */
function shapesSection(r) {
  const spheres = new Set(r.tests.map((test) => test.sphere));
  const others = r.records.filter((entry) => !spheres.has(entry.object));
  if (others.length === 0) return element('div', { hidden: '' });
  // Many shapes: the ones the ray meets, nearest first (so the hit, if one of them), as many as the spheres' tables show.
  const shown = others.length <= SPHERE_ROWS ? others : others.filter((entry) => entry.record.t !== null).sort((a, b) => a.record.t - b.record.t).slice(0, SPHERE_ROWS);
  const rows = shown.map((entry) => {
    const at = { 'data-shape': String(entry.index) };
    const lines = entry.rows.map(([label, n], i) => element('span', { class: 'rt-record-line' }, i ? '; ' : '', `${label} = `,
      value('record', n, { ...at, 'data-label': label })));
    return element('tr', { class: entry.object === r.hit?.object ? 'rt-hit-row' : '' }, element('th', { scope: 'row', ...nameTitle(entry.name) }, shownName(entry.name)), element('td', { class: 'rt-wrap rt-record' }, ...lines));
  });
  const note = shown.length < others.length && element('p', { class: 'rt-note' }, `Showing ${shown.length} of the ${others.length.toLocaleString('en')} other shapes: ones the ray meets.`);
  return section('Other shapes: each one\'s own test', table(['shape', 'its record (t: the nearest hit past 0)'], rows.length, (k) => rows[k], 'Other shapes'), ...[note].filter(Boolean));
}

/** Instead of a table with no rows: the scene has no sphere to test yet. */
function noSpheres() {
  return element('p', { class: 'rt-muted rt-empty', 'data-field': 'no-spheres' }, 'No spheres in the scene yet: nothing to test this ray against.');
}

/**
 * A table in a box that scrolls sideways when narrow: the box takes focus (the arrow keys scroll it) and is named.
 * Its `count` rows are made by `rowAt(k)`; past VIRTUAL_FROM only those in view (lib/p5/pixel/virtual-rows.js).
 */
function table(head, count, rowAt, name) {
  const body = element('tbody', {});
  const box = element('div', { class: 'rt-table-wrap', tabindex: '0', role: 'region', 'aria-label': `${name} table` }, element('table', { class: 'rt-table' },
    element('thead', {}, element('tr', {}, ...head.map((h) => element('th', { scope: 'col' }, h)))),
    body));
  if (count > VIRTUAL_FROM) virtualRows(box, body, count, rowAt, head.length);
  else for (let k = 0; k < count; k++) body.append(rowAt(k));
  return box;
}
