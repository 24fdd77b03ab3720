/** Shared drawing helpers of the diagrams: the card, the world-to-screen mapping, lines, arrows, marks. */
import { INK, MUTED, FAINT, PAPER, FONT } from './style.js';
import { label } from './labels.js';

/**
 * A white card with a title, and `note` (in small grey type) at the right
 * end of the title line when both fit; returns the content box under the
 * title, with `noteShown`.
 */
export function panel(p, x, y, w, h, title, note = null) {
  p.push();
  p.drawingContext.save();
  p.fill(PAPER); p.stroke(FAINT); p.strokeWeight(1);
  p.rect(x + 0.5, y + 0.5, w - 1, h - 1, 6);
  p.noStroke(); p.fill(INK); p.textFont(FONT); p.textStyle(p.BOLD); p.textSize(15);
  p.textAlign(p.LEFT, p.TOP);
  p.text(title, x + 10, y + 8);
  const titleWidth = p.textWidth(title);
  p.textStyle(p.NORMAL);
  let noteShown = false;
  if (note) {
    p.textSize(12);
    noteShown = 10 + titleWidth + 24 + p.textWidth(note) + 10 <= w;
    if (noteShown) { p.fill(MUTED); p.textAlign(p.RIGHT, p.TOP); p.text(note, x + w - 10, y + 11); }
  }
  return { x: x + 4, y: y + 30, w: w - 8, h: h - 34, noteShown };
}

export function closePanel(p) {
  p.drawingContext.restore();
  p.pop();
}

export function placeholder(p, content, text) {
  message(p, content, text);
}

/** `text` on a white card in the middle of `area`. */
export function message(p, area, text) {
  const { w, h } = messageBox(), x = area.x + area.w / 2, y = area.y + area.h / 2;
  p.push();
  p.noStroke(); p.fill(255, 255, 255, 200);
  p.rect(x - w / 2, y - h / 2, w, h, 8);
  p.pop();
  label(p, text, x, y, { color: INK, size: 16, bold: true });
}

/** The size of `message`'s card. */
export function messageBox() {
  return { w: 300, h: 44 };
}

/** World (u, v) → screen with one scale for both axes (v up), fitted to `area`. */
export function mapping(box, area, margin) {
  const bw = box.umax - box.umin || 1, bh = box.vmax - box.vmin || 1;
  const mx = area.w * margin, my = area.h * margin;
  const s = Math.min((area.w - 2 * mx) / bw, (area.h - 2 * my) / bh);
  const ox = area.x + area.w / 2 - ((box.umin + box.umax) / 2) * s;
  const oy = area.y + area.h / 2 + ((box.vmin + box.vmax) / 2) * s;
  return { s, box, area, sx: (u) => ox + u * s, sy: (v) => oy - v * s };
}

export function clip(p, a) {
  const ctx = p.drawingContext;
  ctx.save();
  ctx.beginPath(); ctx.rect(a.x, a.y, a.w, a.h); ctx.clip();
}

export function unclip(p) {
  p.drawingContext.restore();
}

export function line(p, m, a, b, color, weight, dash) {
  p.push();
  p.stroke(color); p.strokeWeight(weight);
  p.drawingContext.setLineDash(dash);
  p.line(m.sx(a.u), m.sy(a.v), m.sx(b.u), m.sy(b.v));
  p.drawingContext.setLineDash([]);
  p.pop();
}

export function arrow(p, m, a, b, color, weight, text) {
  screenArrow(p, m.sx(a.u), m.sy(a.v), m.sx(b.u), m.sy(b.v), color, weight);
  if (text) label(p, text, m.sx(b.u) + (m.sx(b.u) >= m.sx(a.u) ? 10 : -10), m.sy(b.v) - 8, { color, bold: true });
}

export function screenArrow(p, x0, y0, x1, y1, color, weight) {
  const a = Math.atan2(y1 - y0, x1 - x0), head = 6 + 2 * weight;
  p.push();
  p.stroke(color); p.strokeWeight(weight); p.fill(color);
  p.line(x0, y0, x1 - Math.cos(a) * head * 0.6, y1 - Math.sin(a) * head * 0.6);
  p.noStroke();
  p.triangle(x1, y1, x1 - Math.cos(a - 0.4) * head, y1 - Math.sin(a - 0.4) * head, x1 - Math.cos(a + 0.4) * head, y1 - Math.sin(a + 0.4) * head);
  p.pop();
}

export function dot(p, x, y, r, color) {
  p.push(); p.noStroke(); p.fill(color); p.circle(x, y, 2 * r); p.pop();
}

export function ring(p, x, y, r, color) {
  p.push(); p.noFill(); p.stroke(color); p.strokeWeight(2); p.circle(x, y, 2 * r); p.pop();
}

export function rightAngle(p, x, y, dir) {
  p.push(); p.noFill(); p.stroke(INK); p.strokeWeight(1);
  p.line(x + dir * 9, y, x + dir * 9, y - 9); p.line(x + dir * 9, y - 9, x, y - 9);
  p.pop();
}

/** A measurement line between two x positions at height y, with end bars and its label on it (or below; none when null). */
export function dimension(p, xa, xb, y, text, color, below = false) {
  p.push();
  p.stroke(color); p.strokeWeight(1.5);
  p.line(xa, y, xb, y);
  p.line(xa, y - 5, xa, y + 5); p.line(xb, y - 5, xb, y + 5);
  p.pop();
  if (text === null) return;
  if (below) label(p, text, (xa + xb) / 2, y + 14, { color, bold: true });
  else label(p, text, (xa + xb) / 2, y, { color, bold: true, box: true });
}
export function darker(rgb) {
  return `rgb(${rgb.map((c) => Math.round(c * 0.6)).join(',')})`;
}

export function offset(point, dir, s) {
  return { x: point.x + dir.x * s, y: point.y + dir.y * s, z: point.z + dir.z * s };
}

export function norm2(u, v) {
  const len = Math.hypot(u, v) || 1;
  return { u: u / len, v: v / len };
}
