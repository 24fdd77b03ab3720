/** What the side and top views draw: the image plane, spheres, the ground, lights, the eye, keys. */
import { INK, MUTED, PAPER, RAY, NORMAL, LIT, SHADOW, FONT } from './style.js';
import { label } from './labels.js';
import { fmt } from './format.js';
import { line, darker } from './draw.js';

export function imagePlane(p, m, top, bottom, cells, selected, color, view) {
  const x0 = m.sx(top.u), y0 = m.sy(top.v), x1 = m.sx(bottom.u), y1 = m.sy(bottom.v);
  const len = Math.hypot(x1 - x0, y1 - y0) || 1;
  const nx = -(y1 - y0) / len * 6, ny = (x1 - x0) / len * 6; // half the plane's drawn thickness
  p.push();
  p.stroke(INK); p.strokeWeight(1.5); p.fill(PAPER);
  p.quad(x0 + nx, y0 + ny, x1 + nx, y1 + ny, x1 - nx, y1 - ny, x0 - nx, y0 - ny);
  // a tick per pixel when there is room, else every 4th or 8th
  const step = [1, 2, 4, 8, 16, 32, 64].find((k) => (len / cells) * k >= 4) ?? cells;
  p.stroke(MUTED); p.strokeWeight(1);
  for (let i = step; i < cells; i += step) {
    const s = i / cells, cx = x0 + (x1 - x0) * s, cy = y0 + (y1 - y0) * s;
    p.line(cx - nx, cy - ny, cx + nx, cy + ny);
  }
  if (selected !== null && selected >= 0 && selected < cells) {
    const s0 = selected / cells, s1 = (selected + 1) / cells;
    const ax = x0 + (x1 - x0) * s0, ay = y0 + (y1 - y0) * s0, bx = x0 + (x1 - x0) * s1, by = y0 + (y1 - y0) * s1;
    p.stroke(RAY); p.strokeWeight(2);
    p.fill(color ? p.color(color[0], color[1], color[2]) : PAPER);
    const grow = Math.max(0, 5 - Math.hypot(bx - ax, by - ay)) / 2 / len; // at least 5 px long, to be seen
    const gx = (x1 - x0) * grow, gy = (y1 - y0) * grow;
    p.quad(ax - gx + nx * 1.6, ay - gy + ny * 1.6, bx + gx + nx * 1.6, by + gy + ny * 1.6, bx + gx - nx * 1.6, by + gy - ny * 1.6, ax - gx - nx * 1.6, ay - gy - ny * 1.6);
  }
  p.pop();
  const side = view.planeLabel === 'below';
  const lx = side ? (x0 + x1) / 2 : Math.max(x0, x1) + 12, ly = side ? Math.max(y0, y1) + 18 : (y0 + y1) / 2 - 8;
  const align = side ? 'center' : 'left';
  label(p, `image plane, ${cells} px`, lx, ly, { color: INK, align, size: 13 });
  if (selected !== null) label(p, `${view.cellWord} ${selected}`, lx, ly + 16, { color: RAY, align, size: 13, bold: true });
}

export function sphereCircle(p, m, c, r, sphere, selected) {
  const mat = sphere.material, emits = mat.isEmissive;
  const rgb = (emits ? [1, 0.93, 0.55] : mat.color).map((v) => Math.min(1, v) * 255);
  const cx = m.sx(c.u), cy = m.sy(c.v), d = 2 * r * m.s;
  p.push();
  p.fill(rgb[0], rgb[1], rgb[2], emits ? 230 : 170);
  p.stroke(selected ? RAY : darker(rgb)); p.strokeWeight(selected ? 3 : 1.5);
  p.circle(cx, cy, Math.max(d, 4));
  p.pop();
  if (emits) sunRays(p, cx, cy, Math.max(d / 2, 2));
  if (sphere.name) label(p, sphere.name, cx, cy - Math.max(d / 2, 2) - 8, { color: INK, size: 12 });
}

/** A huge sphere (a ground) as the part of its circle inside the view. */
export function hugeArc(p, m, c, r, eye, sphere, selected) {
  const color = sphere.material.color;
  const vu = (m.box.umin + m.box.umax) / 2, vv = (m.box.vmin + m.box.vmax) / 2;
  const diag = Math.hypot(m.box.umax - m.box.umin, m.box.vmax - m.box.vmin) * 3;
  const theta = Math.atan2(vv - c.v, vu - c.u), alpha = Math.min(Math.PI, (1.5 * diag) / r);
  const outside = Math.hypot(eye.u - c.u, eye.v - c.v) > r;
  const rgb = color.map((v) => Math.min(1, v) * 255);
  p.push();
  if (outside) p.fill(rgb[0], rgb[1], rgb[2], 60); else p.noFill();
  p.stroke(selected ? RAY : darker(rgb)); p.strokeWeight(selected ? 3 : 2);
  p.beginShape();
  for (let i = 0; i <= 96; i++) {
    const a = theta - alpha + (2 * alpha * i) / 96;
    p.vertex(m.sx(c.u + r * Math.cos(a)), m.sy(c.v + r * Math.sin(a)));
  }
  if (outside) {
    const inner = Math.max(0, r - diag);
    p.vertex(m.sx(c.u + inner * Math.cos(theta + alpha)), m.sy(c.v + inner * Math.sin(theta + alpha)));
    p.vertex(m.sx(c.u + inner * Math.cos(theta - alpha)), m.sy(c.v + inner * Math.sin(theta - alpha)));
    p.endShape(p.CLOSE);
  } else p.endShape();
  p.pop();
  // where the arc crosses the view's middle: a label "ground, r = 10000"
  const lx = m.sx(c.u + r * Math.cos(theta)), ly = m.sy(c.v + r * Math.sin(theta));
  label(p, `${sphere.name || 'sphere'}, r = ${fmt(r, 0)}`, Math.min(Math.max(lx, m.area.x + 80), m.area.x + m.area.w - 80), ly + 14, { color: MUTED, size: 12 });
}

export function shadowRayLine(p, m, from, to, l) {
  if (!l.facing) {
    line(p, m, from, to, MUTED, 1.5, [2, 5]);
    return;
  }
  line(p, m, from, to, l.inShadow ? SHADOW : LIT, l.inShadow ? 2.5 : 3, l.inShadow ? [8, 6] : []);
}

export function angleArc(p, m, eye, view, along, angle) {
  const ex = m.sx(eye.u), ey = m.sy(eye.v);
  const a0 = Math.atan2(-view.ahead.v, view.ahead.u); // screen angle of "straight ahead"
  const a1 = Math.atan2(-(along.v - eye.v), along.u - eye.u);
  const r = 40;
  p.push();
  p.noFill(); p.stroke(RAY); p.strokeWeight(1.5);
  let d = a1 - a0;
  while (d > Math.PI) d -= 2 * Math.PI;
  while (d < -Math.PI) d += 2 * Math.PI;
  p.arc(ex, ey, 2 * r, 2 * r, Math.min(a0, a0 + d), Math.max(a0, a0 + d));
  p.pop();
  label(p, `${angle.name} = ${fmt(angle.value)}°`, ex, ey + 40, { color: RAY, bold: true });
}

export function eyeGlyph(p, x, y) {
  p.push();
  p.stroke(INK); p.strokeWeight(2); p.fill(PAPER);
  p.ellipse(x, y, 22, 13);
  p.noStroke(); p.fill(INK); p.circle(x, y, 7);
  p.pop();
  label(p, 'eye (Ro)', x, y + 22, { color: INK, bold: true });
}

/** A light as a small sun; on the view's edge (`area` given) its label goes beside it, inside. */
export function lightGlyph(p, x, y, name, area) {
  p.push();
  p.fill('#ffd23f'); p.stroke('#b08000'); p.strokeWeight(1.5);
  p.circle(x, y, 14);
  p.pop();
  sunRays(p, x, y, 7);
  if (!area) return label(p, name, x, y - 20, { color: INK, size: 12 });
  const nearTopOrBottom = y < area.y + 24 || y > area.y + area.h - 24;
  const nearRight = x > area.x + area.w / 2;
  if (nearTopOrBottom) label(p, name, x + (nearRight ? -20 : 20), y, { color: INK, size: 12, align: nearRight ? 'right' : 'left' });
  else label(p, name, x + (nearRight ? -4 : 4), y + 22, { color: INK, size: 12, align: nearRight ? 'right' : 'left' });
}

function sunRays(p, x, y, r) {
  p.push();
  p.stroke('#e0a000'); p.strokeWeight(2);
  for (let i = 0; i < 8; i++) {
    const a = (i * Math.PI) / 4;
    p.line(x + Math.cos(a) * (r + 3), y + Math.sin(a) * (r + 3), x + Math.cos(a) * (r + 9), y + Math.sin(a) * (r + 9));
  }
  p.pop();
}

/** The key to the line styles, along the bottom of a view. */
export function lineKey(p, { x, y, w }) {
  const items = [[RAY, [], 'ray'], [NORMAL, [], 'normal N'], [LIT, [], 'lit'], [SHADOW, [8, 6], 'in shadow'], [MUTED, [2, 5], 'faces away']];
  let cx = x + 6;
  const cy = y + 11;
  p.push();
  p.textFont(FONT); p.textSize(12);
  const widths = items.map(([, , text]) => 30 + p.textWidth(text) + 12);
  const total = widths.reduce((s, v) => s + v, 0);
  cx = x + Math.max(6, (w - total) / 2);
  items.forEach(([color, dash, text], i) => {
    p.stroke(color); p.strokeWeight(3);
    p.drawingContext.setLineDash(dash);
    p.line(cx, cy, cx + 22, cy);
    p.drawingContext.setLineDash([]);
    p.noStroke(); p.fill(INK); p.textAlign(p.LEFT, p.CENTER);
    p.text(text, cx + 28, cy);
    cx += widths[i];
  });
  p.pop();
}

export function axesKey(p, area, [across, upward]) {
  label(p, `${across}   ${upward}`, area.x + area.w - 8, area.y + area.h - 12, { color: MUTED, align: 'right', size: 12 });
}

export function edgeNote(p, area, text) {
  label(p, text, area.x + area.w - 8, area.y + area.h - 30, { color: RAY, align: 'right', bold: true });
}
