/**
 * The selected pixel's rays when the camera traces several per pixel
 * (camera.samples 4, 9 or 16): the pixel drawn large, split into its n × n
 * cells, each painted with the colour its own ray brought back and marked
 * where that ray crosses; beside it their average, the pixel's colour; and a
 * table of the rays (offset, H, V, what each hit, its colour). With one ray
 * per pixel it says so: the one ray decides the whole pixel.
 *
 *   const view = p.createTracerView({ scene, camera: new Camera({ width: 64, height: 48, samples: 4 }) });
 *   p.createSampleRays({ view });
 */
import { recordOf } from './record.js';
import { toHex, colorName } from '../../math/color.js';
import { formatAngle, formatNumber } from '../../text/format.js';
import { show, checkOptions } from '../../text/check.js';
import { element, useStyle, resolveParent } from '../dom.js';

/** Screen pixels of the drawn pixel's side. */
const ZOOM = 144;

/**
 * `p.createSampleRays({ view, parent? })`: follows the view's selected pixel.
 * @param {import('p5').default} _p the sketch (unused: the panel is plain DOM)
 * @param {{ view: import('../tracer/view.js').TracerView, parent?: HTMLElement|string }} options
 */
export function createSampleRays(_p, options) {
  const { view, parent } = checkOptions(options, ['view', 'parent'], 'createSampleRays');
  if (!view || typeof view.onSelect !== 'function') throw new TypeError(`view must be a tracer view (createTracerView), got ${show(view)}`);
  return new SampleRays(view, resolveParent(parent, view.figure?.parentElement ?? document.body));
}

class SampleRays {
  constructor(view, parent) {
    useStyle();
    this.view = view;
    this.canvas = element('canvas', { width: ZOOM, height: ZOOM, class: 'rt-sample-zoom', role: 'img', 'aria-label': 'The selected pixel, split into its cells' });
    this.average = element('span', { class: 'rt-swatch', 'data-field': 'average' });
    this.words = element('p', { class: 'rt-note', 'data-field': 'average-words' });
    // a region that scrolls sideways on a phone: focusable and named, so the keyboard can scroll it
    this.table = element('div', { class: 'rt-table-wrap', tabindex: '0', role: 'region', 'aria-label': 'The pixel\'s rays table' });
    this.element = element('section', { class: 'rt-sample-rays', 'data-sample-rays': '', 'aria-label': "The pixel's rays" },
      element('h2', {}, "The pixel's rays"),
      element('div', { class: 'rt-sample-picture' }, this.canvas, this.average, this.words),
      this.table);
    parent.append(this.element);
    this.unsubscribe = view.onSelect((selected) => this.show(selected));
    this.show(view.selected);
  }

  /** Shows pixel `{ x, y }` (null: a hint), from its record (the view's own when it is the selected pixel). */
  show(selected) {
    const context = this.canvas.getContext('2d');
    context.clearRect(0, 0, ZOOM, ZOOM);
    this.table.replaceChildren();
    this.average.style.background = 'transparent';
    if (!selected) {
      this.words.textContent = 'Click a pixel to see the rays through it.';
      return;
    }
    const record = recordOf(this.view, selected);
    const rays = record.samples ?? [{ dx: 0, dy: 0, h: record.h, v: record.v, hit: record.hit?.name ?? null, color: record.color }];
    drawCells(context, rays);
    const hex = toHex(record.color);
    this.average.style.background = hex;
    this.average.title = hex;
    this.element.dataset.rays = String(rays.length);
    this.words.textContent = rays.length === 1
      ? `One ray through the pixel's centre: it alone decides the pixel's colour, ${colorName(record.color)} (${hex}).`
      : `${rays.length} rays; their average is the pixel's colour: ${colorName(record.color)} (${hex}).${mixed(rays)}`;
    this.table.append(raysTable(rays));
  }

  /** Stops following the view and removes the panel. */
  destroy() {
    this.unsubscribe();
    this.element.remove();
  }
}

/** " They hit: the pink sphere ×3, nothing ×1." when the rays do not all agree. */
function mixed(rays) {
  const counts = new Map();
  for (const ray of rays) counts.set(ray.hit ?? 'nothing', (counts.get(ray.hit ?? 'nothing') ?? 0) + 1);
  if (counts.size === 1) return '';
  return ` They do not all hit the same thing: ${[...counts].map(([name, n]) => `${name} ×${n}`).join(', ')}: an edge, smoothed.`;
}

/** The pixel as its grid of cells, each in its ray's colour, a dot where the ray crosses. */
function drawCells(context, rays) {
  const n = Math.sqrt(rays.length), cell = ZOOM / n;
  rays.forEach((ray, s) => {
    context.fillStyle = toHex(ray.color);
    context.fillRect((s % n) * cell, Math.floor(s / n) * cell, cell, cell);
  });
  context.strokeStyle = '#ffffff';
  for (let i = 1; i < n; i++) {
    context.beginPath();
    context.moveTo(i * cell, 0); context.lineTo(i * cell, ZOOM);
    context.moveTo(0, i * cell); context.lineTo(ZOOM, i * cell);
    context.stroke();
  }
  for (const ray of rays) {
    const x = (ray.dx + 0.5) * ZOOM, y = (ray.dy + 0.5) * ZOOM;
    context.beginPath();
    context.arc(x, y, 3, 0, 2 * Math.PI);
    context.fillStyle = '#111111';
    context.fill();
    context.strokeStyle = '#ffffff';
    context.stroke();
  }
}

function raysTable(rays) {
  const head = element('tr', {}, ...['ray', 'offset (x, y)', 'H', 'V', 'hit', 'colour'].map((h) => element('th', { scope: 'col' }, h)));
  const rows = rays.map((ray, s) => element('tr', { 'data-ray': String(s) },
    element('th', { scope: 'row' }, String(s + 1)),
    element('td', {}, `${formatNumber(ray.dx)}, ${formatNumber(ray.dy)}`),
    element('td', {}, `${formatAngle(ray.h)}°`),
    element('td', {}, `${formatAngle(ray.v)}°`),
    element('td', { 'data-field': 'hit' }, ray.hit ?? 'nothing'),
    element('td', { 'data-field': 'color' },
      element('span', { class: 'rt-swatch rt-swatch-small', style: `background: ${toHex(ray.color)}` }), ` ${colorName(ray.color)} ${toHex(ray.color)}`)));
  return element('table', { class: 'rt-table', 'aria-label': "The pixel's rays" }, element('thead', {}, head), element('tbody', {}, ...rows));
}
