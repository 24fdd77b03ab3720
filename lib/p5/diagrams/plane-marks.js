/**
 * What the side and top views draw: the image plane, spheres, the ground,
 * lights, the eye, lines, keys. Each mark is drawn at once and told to the
 * view's label placer (`labels`), so no label lands on it; a mark with a
 * name returns its label as { text, places, style, optional }, for the view
 * to place once every mark is down.
 */
import { INK, MUTED, PAPER, RAY, NORMAL, LIT, SHADOW, FONT } from './style.js';
import { ON_LABEL, ON_THICK, ON_FILL, ON_THIN, around, sidesToward } from './labels.js';
import { formatLabel } from '../../text/format.js';
import { line, screenArrow, darker } from './draw.js';

/** A line in world (u, v), kept clear of labels at `cost` (ON_THICK for a line a label should not cross). */
export function markLine(p, m, labels, a, b, color, weight, dash, cost) {
  line(p, m, a, b, color, weight, dash);
  labels.keepClearLine(m.sx(a.u), m.sy(a.v), m.sx(b.u), m.sy(b.v), cost, weight / 2);
}

/** The image plane between its ends `top` and `bottom`, a tick per pixel, the selected one in its colour. */
export function imagePlane(p, m, labels, top, bottom, cells, selected, color, view) {
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
  // the plane and the selected cell's outline, 1.6 × its half thickness out
  const pad = 1.6 * Math.max(Math.abs(nx), Math.abs(ny)) + 2;
  const bounds = { left: Math.min(x0, x1) - pad, right: Math.max(x0, x1) + pad, upper: Math.min(y0, y1) - pad, lower: Math.max(y0, y1) + pad };
  labels.keepClear(bounds.left, bounds.upper, bounds.right - bounds.left, bounds.lower - bounds.upper);
  return planeLabel(view, cells, selected, bounds);
}

/**
 * "image plane, 48 px" over "row 15": off an end of the plane (below it in
 * the side view, beside it in the top view), beside it, at a corner; then
 * the same further out.
 */
function planeLabel(view, cells, selected, { left, right, upper, lower }) {
  const cx = (left + right) / 2, cy = (upper + lower) / 2;
  const at = (g) => ({
    below: [cx, lower + g, 'center', 'top'], above: [cx, upper - g, 'center', 'bottom'],
    right: [right + g + 2, cy, 'left'], left: [left - g - 2, cy, 'right'],
    'below right': [left, lower + g, 'left', 'top'], 'below left': [right, lower + g, 'right', 'top'],
    'above right': [left, upper - g, 'left', 'bottom'], 'above left': [right, upper - g, 'right', 'bottom'],
    'right below': [right + g + 2, lower, 'left', 'bottom'], 'right above': [right + g + 2, upper, 'left', 'top'],
    'left below': [left - g - 2, lower, 'right', 'bottom'], 'left above': [left - g - 2, upper, 'right', 'top'],
    'corner above left': [left - g - 2, upper - g + 2, 'right', 'bottom'], 'corner above right': [right + g + 2, upper - g + 2, 'left', 'bottom'],
    'corner below left': [left - g - 2, lower + g - 2, 'right', 'top'], 'corner below right': [right + g + 2, lower + g - 2, 'left', 'top'],
  });
  const sides = [...(view.planeLabel === 'below'
    ? ['below', 'below right', 'below left', 'above', 'above right', 'above left', 'left above', 'left below', 'right above', 'right below', 'right', 'left']
    : ['right', 'left', 'right below', 'right above', 'left below', 'left above', 'below', 'above', 'below right', 'below left', 'above right', 'above left']),
  'corner above left', 'corner above right', 'corner below left', 'corner below right'];
  const rows = [[`image plane, ${cells} px`, { color: INK }]];
  if (selected !== null) rows.push([`${view.cellWord} ${selected}`, { color: RAY, bold: true }]);
  const places = [4, 28].flatMap((g) => { const where = at(g); return sides.map((side) => where[side]); });
  return { text: rows, places, style: { size: 13 } };
}

/** A sphere's circle (a light's, with sun rays, when it glows), its name beside it. */
export function sphereCircle(p, m, labels, c, r, sphere, selected) {
  const mat = sphere.material, emits = mat.isEmissive;
  const rgb = (emits ? [1, 0.93, 0.55] : mat.color).map((v) => Math.min(1, v) * 255);
  const cx = m.sx(c.u), cy = m.sy(c.v), d = 2 * r * m.s, rr = Math.max(d / 2, 2);
  p.push();
  p.fill(rgb[0], rgb[1], rgb[2], emits ? 230 : 170);
  p.stroke(selected ? RAY : darker(rgb)); p.strokeWeight(selected ? 3 : 1.5);
  p.circle(cx, cy, Math.max(d, 4));
  p.pop();
  labels.keepClearCircle(cx, cy, rr, ON_THIN, { pad: selected ? 2.5 : 1.5 });
  if (!emits) labels.keepClearCircle(cx, cy, rr, ON_FILL, { disc: true });
  else {
    sunRays(p, cx, cy, rr);
    labels.keepClearCircle(cx, cy, rr + 9, ON_LABEL, { disc: true });
  }
  if (!sphere.name) return null;
  // beside its circle; inside it, near the top, when the circle fills the view
  const gap = emits ? 10 : 3;
  const places = around(cx, cy, rr, gap, ['above', 'below', 'above right', 'above left', 'right', 'left', 'below right', 'below left']);
  if (!emits) places.push([cx, cy - rr + 6, 'center', 'top'], [cx, cy, 'center', 'middle']);
  return { text: sphere.name, places, style: { color: INK, size: 12 } };
}

/** A huge sphere (a ground) as the part of its circle inside the view. */
export function hugeArc(p, m, labels, c, r, eye, sphere, selected) {
  const color = sphere.material.color;
  const vu = (m.box.umin + m.box.umax) / 2, vv = (m.box.vmin + m.box.vmax) / 2;
  const diag = Math.hypot(m.box.umax - m.box.umin, m.box.vmax - m.box.vmin) * 3;
  const theta = Math.atan2(vv - c.v, vu - c.u), alpha = Math.min(Math.PI, (1.5 * diag) / r);
  const outside = Math.hypot(eye.u - c.u, eye.v - c.v) > r;
  const rgb = color.map((v) => Math.min(1, v) * 255);
  const onArc = (a, k = r) => [m.sx(c.u + k * Math.cos(a)), m.sy(c.v + k * Math.sin(a))];
  const arc = [];
  for (let i = 0; i <= 96; i++) arc.push(onArc(theta - alpha + (2 * alpha * i) / 96));
  p.push();
  if (outside) p.fill(rgb[0], rgb[1], rgb[2], 60); else p.noFill();
  p.stroke(selected ? RAY : darker(rgb)); p.strokeWeight(selected ? 3 : 2);
  p.beginShape();
  for (const [x, y] of arc) p.vertex(x, y);
  if (outside) {
    const inner = Math.max(0, r - diag);
    p.vertex(...onArc(theta + alpha, inner));
    p.vertex(...onArc(theta - alpha, inner));
    p.endShape(p.CLOSE);
  } else p.endShape();
  p.pop();
  labels.keepClearPath(arc, selected ? ON_THICK : ON_THIN, selected ? 1.5 : 1);
  // "ground, r = 10000" along the arc, from the view's middle out, on the
  // sphere's side of it, then further in, then on the other side
  const step = (m.area.w * 0.22) / (r * m.s), cx = m.sx(c.u), cy = m.sy(c.v);
  const places = [];
  for (const off of [15, 34, -15]) {
    for (const k of [0, -0.5, 0.5, -1, 1, -1.5, 1.5, -2, 2]) {
      const [x, y] = onArc(theta + k * step), len = Math.hypot(cx - x, cy - y) || 1;
      places.push([x + ((cx - x) / len) * off, y + ((cy - y) / len) * off, 'center', 'middle']);
    }
  }
  return { text: `${sphere.name || 'sphere'}, r = ${formatLabel(r, 0)}`, places, style: { color: MUTED, size: 12 }, optional: true, later: 0.2 };
}

/** A shadow ray from the hit point to a light: lit, in shadow, or (faint) facing away. */
export function shadowRayLine(p, m, labels, from, to, l) {
  if (!l.facing) return markLine(p, m, labels, from, to, MUTED, 1.5, [2, 5], ON_THIN);
  markLine(p, m, labels, from, to, l.inShadow ? SHADOW : LIT, l.inShadow ? 2.5 : 3, l.inShadow ? [8, 6] : [], ON_THICK);
}

/** The normal at the hit point, its "N" beyond the tip or beside it. */
export function normalArrow(p, labels, x0, y0, x1, y1) {
  screenArrow(p, x0, y0, x1, y1, NORMAL, 3);
  labels.keepClearLine(x0, y0, x1, y1, ON_THICK, 3);
  const sides = sidesToward(x1 - x0, y1 - y0);
  // optional: with the hit off the view there is no room for it, and the key says "normal N"
  return { text: 'N', places: [...around(x1, y1, 3, 4, sides), ...around(x1, y1, 3, 16, sides)], style: { color: NORMAL, bold: true }, optional: true };
}

/** The angle between straight ahead and the ray, as an arc at the eye; its label under the eye's, or near. */
export function angleArc(p, labels, ex, ey, view, along, angle) {
  const a0 = Math.atan2(-view.ahead.v, view.ahead.u); // screen angle of "straight ahead"
  const a1 = Math.atan2(-along.v, along.u);
  const r = 40;
  let d = a1 - a0;
  while (d > Math.PI) d -= 2 * Math.PI;
  while (d < -Math.PI) d += 2 * Math.PI;
  const from = Math.min(a0, a0 + d), to = Math.max(a0, a0 + d);
  p.push();
  p.noFill(); p.stroke(RAY); p.strokeWeight(1.5);
  p.arc(ex, ey, 2 * r, 2 * r, from, to);
  p.pop();
  const arc = [];
  for (let i = 0; i <= 12; i++) { const a = from + ((to - from) * i) / 12; arc.push([ex + r * Math.cos(a), ey + r * Math.sin(a)]); }
  labels.keepClearPath(arc, ON_THIN, 2);
  const places = [
    [ex, ey + 28.5, 'center', 'top'], [ex, ey - 26.5, 'center', 'bottom'],
    [ex - 16, ey, 'right'], [ex + 16, ey, 'left'],
    [ex - 14, ey + 12, 'right', 'top'], [ex + 14, ey + 12, 'left', 'top'],
    [ex - 14, ey - 10, 'right', 'bottom'], [ex + 14, ey - 10, 'left', 'bottom'],
    [ex - 18, ey + 22, 'right', 'top'], [ex + 18, ey + 22, 'left', 'top'],
    ...around(ex, ey, r, 6, sidesToward(-Math.cos(a0 + d / 2), -Math.sin(a0 + d / 2))),
  ];
  return { text: `${angle.name} = ${formatLabel(angle.value)}°`, places, style: { color: RAY, bold: true } };
}

/** The eye, "eye (Ro)" under it or beside it. */
export function eyeGlyph(p, labels, x, y) {
  p.push();
  p.stroke(INK); p.strokeWeight(2); p.fill(PAPER);
  p.ellipse(x, y, 22, 13);
  p.noStroke(); p.fill(INK); p.circle(x, y, 7);
  p.pop();
  labels.keepClear(x - 12, y - 8, 24, 16);
  const places = [[x, y + 11, 'center', 'top'], [x, y - 9, 'center', 'bottom'], [x - 15, y, 'right'], [x + 15, y, 'left'],
    [x - 12, y + 9, 'right', 'top'], [x + 12, y + 9, 'left', 'top'], [x - 12, y - 8, 'right', 'bottom'], [x + 12, y - 8, 'left', 'bottom']];
  return { text: 'eye (Ro)', places, style: { color: INK, bold: true } };
}

/** A light as a small sun; with `area`, a marker on the view's edge for a light beyond it (its label inward). */
export function lightGlyph(p, labels, x, y, name, area = null) {
  p.push();
  p.fill('#ffd23f'); p.stroke('#b08000'); p.strokeWeight(1.5);
  p.circle(x, y, 14);
  p.pop();
  sunRays(p, x, y, 7);
  labels.keepClearCircle(x, y, 16, ON_LABEL, { disc: true });
  if (!area) {
    const places = around(x, y, 16, 2, ['above', 'below', 'right', 'left', 'above right', 'above left', 'below right', 'below left']);
    return { text: name, places, style: { color: INK, size: 12 } };
  }
  // on the edge: inward first, then under or over it from the edge in, then
  // further out; left out in a crowd, where the sun and its shadow ray still say it
  const sides = sidesToward(area.x + area.w / 2 - x, (area.y + area.h / 2 - y) / 2);
  const inward = x < area.x + area.w / 2 ? 1 : -1, align = inward > 0 ? 'left' : 'right';
  const places = [2, 16, 32, 48].flatMap((gap) => [
    ...around(x, y, 16, gap, sides),
    [x - inward * 12, y + 16 + gap, align, 'top'], [x - inward * 12, y - 16 - gap, align, 'bottom'],
  ]);
  return { text: `${name} (off view)`, places, style: { color: INK, size: 12 }, optional: true };
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

/** The view's axes ("−z forward →   y up ↑"): what the title line holds when it has room. */
export function axesText([across, upward]) {
  return `${across}   ${upward}`;
}

/** A label along the view's right or left edge, corners first: the axes when the title had no room. */
export function edgeLabel(area, text, style) {
  const left = area.x + 8, right = area.x + area.w - 8, top = area.y + 12, bottom = area.y + area.h - 12;
  const places = [];
  for (const f of [1, 0, 0.75, 0.25, 0.5]) {
    const y = top + (bottom - top) * f;
    places.push([right, y, 'right'], [left, y, 'left']);
  }
  return { text, places, style };
}

/**
 * A note on the ray ("no hit", "hit off the view"): beside the ray where it
 * leaves the view, else along an edge.
 */
export function rayEndNote(area, x0, y0, x1, y1, text) {
  const len = Math.hypot(x1 - x0, y1 - y0) || 1, ux = (x1 - x0) / len, uy = (y1 - y0) / len;
  const exit = toEdge(x0, y0, x1, y1, area, 0);
  const places = [];
  for (const back of [24, 70, 130]) {
    for (const side of [1, -1]) {
      const nx = -uy * side, ny = ux * side; // the normal on this side of the ray
      const x = exit.x - ux * back + nx * 14, y = exit.y - uy * back + ny * 14;
      places.push([x, y, nx > 0.3 ? 'left' : nx < -0.3 ? 'right' : 'center', ny > 0.3 ? 'top' : ny < -0.3 ? 'bottom' : 'middle']);
    }
  }
  return { text, places: [...places, ...edgeLabel(area, text).places], style: { color: RAY, bold: true }, later: 0.2 };
}

/** The point where the segment from (x0, y0) toward (x1, y1) leaves `area` shrunk by `inset`. */
export function toEdge(x0, y0, x1, y1, area, inset) {
  const left = area.x + inset, right = area.x + area.w - inset, top = area.y + inset, bottom = area.y + area.h - inset;
  x0 = Math.min(right, Math.max(left, x0)); y0 = Math.min(bottom, Math.max(top, y0));
  const dx = x1 - x0, dy = y1 - y0;
  let s = 1;
  if (dx > 0) s = Math.min(s, (right - x0) / dx);
  if (dx < 0) s = Math.min(s, (left - x0) / dx);
  if (dy > 0) s = Math.min(s, (bottom - y0) / dy);
  if (dy < 0) s = Math.min(s, (top - y0) / dy);
  return { x: x0 + dx * s, y: y0 + dy * s };
}
