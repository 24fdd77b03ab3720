/** A visual mode's legend (modeLegend's data), on a canvas or as a DOM element. */
import { INK, MUTED, FONT } from './style.js';
import { label } from './labels.js';
import { panel, closePanel, placeholder } from './draw.js';
import { element } from '../dom.js';

/**
 * A visual mode's legend (modeLegend's data) drawn into a p5 sketch: the title,
 * a colour bar with its labels (or swatches), and the note.
 */
export function drawLegend(p, legend, { x, y, w, h }) {
  const content = panel(p, x, y, w, h, legend?.title ?? 'Legend');
  if (!legend?.stops?.length) {
    placeholder(p, content, 'No legend for this mode.');
    return closePanel(p);
  }
  let cy = content.y + 8;
  if (legend.kind === 'gradient') {
    const bx = content.x + 14, bw = content.w - 28, bh = 22;
    const ctx = p.drawingContext;
    const grad = ctx.createLinearGradient(bx, 0, bx + bw, 0);
    legend.stops.forEach((s, i) => grad.addColorStop(i / (legend.stops.length - 1), s.color));
    ctx.save(); ctx.fillStyle = grad; ctx.fillRect(bx, cy, bw, bh); ctx.strokeStyle = INK; ctx.lineWidth = 1; ctx.strokeRect(bx, cy, bw, bh); ctx.restore();
    legend.stops.forEach((s, i) => {
      const sx = bx + (bw * i) / (legend.stops.length - 1);
      p.push(); p.stroke(INK); p.line(sx, cy + bh, sx, cy + bh + 5); p.pop();
      const align = i === 0 ? 'left' : i === legend.stops.length - 1 ? 'right' : 'center';
      label(p, s.label, sx, cy + bh + 15, { color: INK, size: 12, align, halo: false });
    });
    cy += bh + 34;
  } else {
    const cols = Math.max(1, Math.floor(content.w / 170)), colW = content.w / cols;
    legend.stops.forEach((s, i) => {
      const cx = content.x + 10 + (i % cols) * colW, ry = cy + Math.floor(i / cols) * 22;
      p.push(); p.fill(s.color); p.stroke(INK); p.strokeWeight(1); p.rect(cx, ry, 16, 16); p.pop();
      label(p, s.label, cx + 22, ry + 8, { color: INK, size: 12, align: 'left', halo: false });
    });
    cy += Math.ceil(legend.stops.length / cols) * 22 + 6;
  }
  if (legend.note) {
    p.push();
    p.noStroke(); p.fill(MUTED); p.textFont(FONT); p.textSize(12); p.textAlign(p.LEFT, p.TOP);
    p.text(legend.note, content.x + 10, cy, content.w - 20, content.y + content.h - cy);
    p.pop();
  }
  closePanel(p);
}

/**
 * The same legend as a DOM element (for under a tracer view, which is its own
 * canvas): `<div class="rt-legend" data-legend>` with the sketchbook's classes.
 */
export function createLegendElement(legend) {
  const box = element('div', { class: 'rt-legend', 'data-legend': '' });
  box.append(element('div', { class: 'rt-legend-title' }, legend?.title ?? 'Legend'));
  const stops = element('div', { class: `rt-legend-stops rt-legend-${legend?.kind ?? 'swatches'}` });
  const list = legend?.stops ?? [];
  if (legend?.kind === 'gradient' && list.length > 1) {
    const colors = list.map((s, i) => `${s.color} ${(100 * i) / (list.length - 1)}%`);
    stops.append(element('div', { class: 'rt-legend-ramp', style: `background: linear-gradient(to right, ${colors.join(', ')})` }));
    stops.append(element('div', { class: 'rt-legend-labels' }, ...list.map((s) => element('span', {}, s.label))));
  } else {
    for (const s of list) {
      stops.append(element('span', { class: 'rt-legend-item' },
        element('span', { class: 'rt-legend-swatch', style: `background: ${s.color}` }), s.label));
    }
  }
  box.append(stops);
  if (legend?.note) box.append(element('p', { class: 'rt-legend-note' }, legend.note));
  return box;
}
