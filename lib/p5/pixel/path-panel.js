/**
 * The path panel: the story of one path of a path-traced view's selected
 * pixel, bounce by bounce, from `inspectPath` (the renderer's own
 * integrator): where each bounce hit, facing which way, what the surface did,
 * the direction drawn and its probability density, the throughput after it
 * and the light it gathered (with its MIS weight), the light sample aimed
 * from it (which light, the point, blocked or seen, its weight, or why none);
 * how the path ended; and the pixel's estimate,
 * its mean and standard error, with a small chart of the running mean
 * converging inside its error band (mean ± 2 standard errors, narrowing as 1/√N).
 * Buttons step through the pixel's samples: each is another random path.
 *
 *   const paths = p.createTracerView({ scene, camera, path: { samples: 256 } });
 *   p.createPathPanel({ view: paths });
 *
 * Every value sits in an element with `data-field` (and `data-bounce` for a
 * bounce's row), its full precision in `data-value`.
 */
import { inspectPath } from '../../tracing/pathtrace/inspect-path.js';
import { formatNumber, formatVector } from '../../text/format.js';
import { show, checkOptions } from '../../text/check.js';
import { useStyle, element, resolveParent, sketchNode, shownName } from '../dom.js';

const OPTIONS = ['view', 'parent', 'onPath', 'sceneView'];
const ENDS = {
  sky: 'left the scene: it gathered the sky (the background)',
  absorbed: 'was absorbed (nothing of it went on)',
  roulette: 'was ended by Russian roulette',
  maxBounces: 'stopped: it took the most bounces allowed',
};
/** The chart's size in CSS pixels. */
const CHART_W = 280, CHART_H = 110;

/**
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {import('../tracer/view.js').TracerView} options.view a path-traced tracer view (`createTracerView({ path })`)
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where it goes; default the sketch's node
 * @param {(record: object|null) => void} [options.onPath] told each path shown (inspectPath's record), null when none
 * @param {import('../scene-view/view.js').SceneView} [options.sceneView] a 3D view to draw the path in: a segment per bounce, coloured by its throughput
 * @returns {PathPanel}
 * @example
 * const view = p.createTracerView({ scene, camera, path: { samples: 64 } });
 * p.createPathPanel({ view }); // click a pixel: its first path, bounce by bounce
 */
export function createPathPanel(p, options) {
  return new PathPanel(p, checkOptions(options, OPTIONS, 'createPathPanel'));
}

/** What `p.createPathPanel({ … })` returns. */
export class PathPanel {
  #view; #onPath; #sample = 0; #stops = [];
  /** The path shown (inspectPath's record), or null. */
  path = null;

  constructor(p, { view, parent, onPath, sceneView }) {
    if (!view?.pathState) throw new TypeError(`createPathPanel needs { view }: a path-traced tracer view (createTracerView({ path })), got ${show(view)}`);
    if (onPath !== undefined && typeof onPath !== 'function') throw new TypeError(`onPath must be a function, got ${show(onPath)}`);
    if (sceneView !== undefined && typeof sceneView?.setExtraRays !== 'function') throw new TypeError(`sceneView must be a 3D view (p.createSceneView), got ${show(sceneView)}`);
    this.#view = view;
    this.#onPath = (path) => {
      sceneView?.setExtraRays(path ? pathRays(path) : []);
      onPath?.(path);
    };
    useStyle();
    this.#build(resolveParent(parent, sketchNode(p)));
    this.#stops.push(view.onSelect(() => { this.#sample = 0; this.update(); }));
    this.#stops.push(view.on('progress', ({ done }) => { if (done) this.update(); }));
    this.#stops.push(view.on('restart', () => this.update()));
    this.update();
  }

  /** Shows sample `n` of the selected pixel (0 and up). */
  showSample(n) {
    this.#sample = Math.max(0, n);
    this.update();
    return this;
  }

  /** Traces the selected pixel's path and estimate again (the view calls it when its picture changes). */
  update() {
    const s = this.#view.selected, state = this.#view.pathState;
    if (!s) {
      this.path = null;
      this.body.replaceChildren(element('p', { class: 'rt-hint' }, 'Click a pixel of the path-traced picture to see one of its paths, bounce by bounce.'));
      this.#onPath?.(null);
      return this;
    }
    const samples = Math.max(1, state.sample, this.#sample + 1); // the samples the picture has now (and the one shown)
    this.path = inspectPath(this.#view.scene, this.#view.camera, s.x, s.y, { ...state.options, sample: this.#sample, samples });
    this.#show(this.path);
    this.#onPath?.(this.path);
    return this;
  }

  destroy() {
    for (const stop of this.#stops) stop();
    this.element.remove();
  }

  #build(parent) {
    this.body = element('div', { class: 'rt-path-body' });
    const previous = element('button', { type: 'button', class: 'rt-button', 'data-sample-step': '-1' }, '← Previous sample');
    const next = element('button', { type: 'button', class: 'rt-button', 'data-sample-step': '1' }, 'Next sample →');
    previous.addEventListener('click', () => this.showSample(this.#sample - 1));
    next.addEventListener('click', () => this.showSample(this.#sample + 1));
    this.element = element('section', { class: 'rt-inspector rt-path-panel', 'data-path-inspector': '', 'aria-label': 'The selected pixel\'s path' },
      element('h2', { class: 'rt-inspector-title' }, 'One path of the selected pixel'),
      element('div', { class: 'controls' }, previous, next), this.body);
    parent.append(this.element);
  }

  #show(path) {
    const rows = path.bounces.map((b, i) => bounceRow(b, i));
    const table = element('table', { class: 'rt-table rt-path-table' },
      element('caption', {}, `Sample ${path.sample} of pixel ${path.x},${path.y}: ${path.bounces.length} ${path.bounces.length === 1 ? 'hit' : 'hits'}`),
      element('thead', {}, element('tr', {}, ...['#', 'surface', 'what it did', 'point', 'normal', 'new direction', 'pdf', 'throughput after', 'light gathered', 'light sample (shadow ray)'].map((h) => element('th', { scope: 'col' }, h)))),
      element('tbody', {}, ...rows));
    const ended = element('p', { 'data-field': 'end', 'data-value': path.end },
      `Then the path ${ENDS[path.end]}${path.end === 'sky' ? `: ${rgb(path.sky)}` : ''}. This sample's light: ${rgb(path.radiance)}.`);
    const estimate = element('p', { 'data-field': 'estimate', 'data-value': path.mean.join(' ') },
      `The pixel after ${path.samples} ${path.samples === 1 ? 'sample' : 'samples'}: mean ${rgb(path.mean)} ± ${rgb(path.stderr)} (standard error).`);
    this.body.replaceChildren(element('div', { class: 'rt-table-wrap', tabindex: '0', role: 'region', 'aria-label': 'The path, bounce by bounce' }, table), ended, estimate, convergenceChart(path));
  }
}

/** How far a path that left the scene is drawn past its last hit. */
const SKY_LENGTH = 12;

/**
 * A path as segments for a 3D view (`sceneView.setExtraRays`): from the eye to
 * the first hit, hit to hit, and on toward the sky when it left; each coloured
 * by the throughput it carries (the colour the light found past it is
 * multiplied by), thicker while the throughput is high.
 * @param {ReturnType<typeof inspectPath>} path
 * @returns {{ from: object, to: object, color: string, weight: number }[]}
 */
export function pathRays(path) {
  const points = [path.ray.origin, ...path.bounces.map((b) => b.point)];
  const carried = [[1, 1, 1], ...path.bounces.map((b) => b.throughput ?? [0, 0, 0])];
  const last = path.bounces.at(-1);
  if (path.end === 'sky') {
    const from = last?.point ?? path.ray.origin, d = last?.direction ?? path.ray.direction;
    points.push({ x: from.x + d.x * SKY_LENGTH, y: from.y + d.y * SKY_LENGTH, z: from.z + d.z * SKY_LENGTH });
  }
  return points.slice(1).map((to, i) => ({ from: points[i], to, color: throughputColor(carried[i]), weight: 1 + 2 * Math.min(1, Math.max(...carried[i])) }));
}

/** A throughput as a CSS colour: its hue, brightened so that a dim path still shows. */
function throughputColor(t) {
  const top = Math.max(...t, 1e-9), level = (v) => Math.round(255 * (0.25 + 0.75 * Math.min(1, v / top)));
  return `rgb(${level(t[0])}, ${level(t[1])}, ${level(t[2])})`;
}

const rgb = (c) => `(${c.map(formatNumber).join(', ')})`;

/** One bounce as a table row. */
function bounceRow(b, i) {
  const cell = (field, text, value) => element('td', { 'data-field': field, 'data-value': value ?? text }, text);
  const what = b.lobe === null ? '—' : `${b.lobe}${b.survival !== undefined ? ` (roulette: went on with q = ${formatNumber(b.survival)})` : ''}`;
  const pdf = b.pdf === null ? '—' : `${formatNumber(b.pdf)}${b.delta ? ' (chance of this lobe)' : ''}`;
  return element('tr', { 'data-bounce': String(i) },
    element('th', { scope: 'row' }, String(i + 1)),
    cell('surface', shownName(b.name), b.name),
    cell('lobe', what, b.lobe ?? ''),
    cell('point', formatVector(b.point)),
    cell('normal', formatVector(b.normal)),
    cell('direction', formatVector(b.direction)),
    cell('pdf', pdf, String(b.pdf)),
    cell('throughput', b.throughput ? rgb(b.throughput) : '—', b.throughput?.join(' ') ?? ''),
    cell('emitted', `${rgb(b.emitted)}${b.emissionWeight !== undefined && b.emissionWeight < 1 ? ` (MIS weight ${formatNumber(b.emissionWeight)})` : ''}`, b.emitted.join(' ')),
    cell('light', ...lightSampleText(b)));
}

/**
 * A bounce's light sample in words, and its verdict for `data-value`: the light
 * aimed at and the point, then blocked (by what), behind the surface, or seen
 * (its MIS weight and the light it added); or why none was drawn.
 */
function lightSampleText(b) {
  const s = b.lightSample;
  if (!s) return b.lightSkipped ? [`none: ${b.lightSkipped}`, 'skipped'] : ['—', ''];
  const aim = `${shownName(s.light)}${s.point ? ` at ${formatVector(s.point)}` : ` toward ${formatVector(s.direction)}`}`;
  if (s.below) return [`${aim}: behind the surface, no light`, 'below'];
  if (s.outsideBlur) return [`${aim}: outside the metal's blur, no light`, 'outside'];
  if (s.blocked !== null) return [`${aim}: blocked by ${shownName(s.blocked)}`, 'blocked'];
  return [`${aim}: seen, pdf ${formatNumber(s.pdf)}, MIS weight ${formatNumber(s.weight)}, added ${rgb(s.contribution)}`, 'seen'];
}

/** Brightness of a colour (Rec. 709 weights): the chart's one line. */
const brightness = (c) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];

/**
 * The running mean's brightness after each sample, inside the band mean ± 2σ/√n
 * (σ the samples' spread, from the final standard error): the noise falls as 1/√N.
 */
function convergenceChart(path) {
  const canvas = element('canvas', {
    class: 'rt-path-chart', width: CHART_W, height: CHART_H, 'data-field': 'chart', role: 'img',
    'aria-label': `The pixel's brightness after each of ${path.history.length} samples, settling at ${formatNumber(brightness(path.mean))}, inside a band of two standard errors that narrows as 1/√N.`,
  });
  const ctx = canvas.getContext('2d');
  if (!ctx) return canvas;
  const n = path.history.length, final = brightness(path.mean), sigma = brightness(path.stderr) * Math.sqrt(n);
  const values = path.history.map(brightness);
  const top = Math.max(1e-6, ...values, final + 2 * sigma) * 1.05;
  const x = (k) => 4 + ((CHART_W - 8) * k) / Math.max(1, n - 1), y = (v) => CHART_H - 4 - ((CHART_H - 8) * Math.min(v, top)) / top;
  ctx.fillStyle = '#dfe8f7';
  ctx.beginPath();
  for (let k = 0; k < n; k++) ctx.lineTo(x(k), y(final + (2 * sigma) / Math.sqrt(k + 1)));
  for (let k = n - 1; k >= 0; k--) ctx.lineTo(x(k), y(Math.max(0, final - (2 * sigma) / Math.sqrt(k + 1))));
  ctx.fill();
  ctx.strokeStyle = '#8a94a3';
  ctx.setLineDash([4, 3]);
  ctx.beginPath(); ctx.moveTo(x(0), y(final)); ctx.lineTo(x(n - 1), y(final)); ctx.stroke();
  ctx.setLineDash([]);
  ctx.strokeStyle = '#1b4f9c';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  values.forEach((v, k) => ctx.lineTo(x(k), y(v)));
  ctx.stroke();
  return canvas;
}
