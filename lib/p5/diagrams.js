/**
 * Diagrams a sketch places next to its tracer view, each drawn into a p5
 * sketch `p` inside a box { x, y, w, h }, big and labelled for a projector:
 *
 *   drawSideView / drawTopView     the eye, the image plane, the spheres, the
 *                                  selected ray, its normal and shadow rays
 *   drawGeometricConstruction     L, tca, d, thc, r and t0, t1 for one sphere
 *   drawParabola                  f(t) = At² + Bt + C and its roots
 *   drawLegend, createLegendElement   the key of a visual mode
 *
 * `record` is `inspectPixel(scene, camera, x, y)`'s result; without one the
 * diagrams draw the scene and ask for a click. Nothing here throws on a miss,
 * a tangent ray, a ray starting inside a sphere or a huge ground sphere.
 */
import { intersectGeometric } from '../shapes/sphere.js';
import { isHuge } from '../modes.js';
import { element } from './dom.js';

/* ---- the diagrams' palette and type, chosen to read from the back of a room ---- */
const INK = '#1d2433';
const MUTED = '#6b7280';
const FAINT = '#d7dbe3';
const PAPER = '#ffffff';
const RAY = '#c2185b';
const NORMAL = '#0b8a3e';
const LIT = '#e0a000';
const SHADOW = '#d62828';
const CONSTRUCT = '#1f5fbf';
const FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const SIZE = 14;

/* ========================= side and top views ========================= */

/**
 * The side view: the scene cut along the y–z plane, seen from the right of
 * the camera (−z, "forward", to the right; y up).
 * @param {object} p a p5 instance
 * @param {object} o
 * @param {import('../scene.js').Scene} o.scene
 * @param {import('../camera.js').Camera} o.camera
 * @param {object|null} [o.record] inspectPixel's result, or null before a click
 * @param {number} o.x
 * @param {number} o.y
 * @param {number} o.w
 * @param {number} o.h
 * @param {{umin:number, umax:number, vmin:number, vmax:number}} [o.bounds] world units along the view's axes (u = −z, v = y); default: fitted
 */
export function drawSideView(p, o) {
  drawPlaneView(p, o, SIDE);
}

/**
 * The top view: the scene seen from above, in the x–z plane (x to the right,
 * −z, "forward", up the page). Same options as drawSideView, with u = x, v = −z.
 */
export function drawTopView(p, o) {
  drawPlaneView(p, o, TOP);
}

const SIDE = {
  title: 'Side view (y–z)',
  axes: ['−z forward →', 'y up ↑'],
  u: (q) => -q.z, v: (q) => q.y,
  across: 'up', half: 'halfHeight', cells: 'height', cellOf: (r) => r.y, cellWord: 'row',
  angle: (r) => ({ name: 'V', value: r.v }),
  ahead: { u: 1, v: 0 },
};
const TOP = {
  title: 'Top view (x–z)',
  axes: ['x right →', '−z forward ↑'],
  u: (q) => q.x, v: (q) => -q.z,
  across: 'right', half: 'halfWidth', cells: 'width', cellOf: (r) => r.x, cellWord: 'column',
  angle: (r) => ({ name: 'H', value: r.h }),
  ahead: { u: 0, v: 1 },
};

function drawPlaneView(p, o, view) {
  const { scene, camera, record = null, x, y, w, h } = o;
  const content = panel(p, x, y, w, h, view.title + (record ? `  ·  pixel ${record.x},${record.y}` : ''));
  if (!scene || !camera) {
    placeholder(p, content, 'Pass a scene and a camera to draw this view.');
    return closePanel(p);
  }
  const pr = (q) => ({ u: view.u(q), v: view.v(q) });
  const eye = pr(camera.position);

  const box = o.bounds ? { ...o.bounds } : fitBounds(scene, record, pr, eye, view.ahead);
  const keyHeight = 26;
  const area = { x: content.x, y: content.y, w: content.w, h: content.h - keyHeight };
  const m = mapping(box, area, 0.05);
  const span = Math.max(box.umax - box.umin, box.vmax - box.vmin);
  const inArea = (q) => m.sx(q.u) > area.x + 4 && m.sx(q.u) < area.x + area.w - 4 && m.sy(q.v) > area.y + 4 && m.sy(q.v) < area.y + area.h - 4;
  clip(p, area);

  // Huge spheres first (the ground), then the frustum and image plane, then spheres.
  for (const s of scene.spheres) if (isHuge(s)) hugeArc(p, m, pr(s.center), s.radius, eye, s, s === record?.hit?.object);

  // The image plane at a display distance: any distance gives the same rays
  // (similar triangles), so put it between the eye and the nearest sphere.
  const D = imagePlaneDistance(scene, pr, eye, span);
  const f = camera.forward, a = camera[view.across], half = camera[view.half] * D;
  const centre = offset(camera.position, f, D);
  const top = pr(offset(centre, a, half)), bottom = pr(offset(centre, a, -half));
  const far = 4 * span;
  for (const end of [top, bottom]) {
    const dir = norm2(end.u - eye.u, end.v - eye.v);
    line(p, m, eye, { u: eye.u + dir.u * far, v: eye.v + dir.v * far }, MUTED, 1.5, [6, 5]);
  }
  // straight ahead: the axis the angle is measured from
  line(p, m, eye, { u: eye.u + view.ahead.u * span * 0.35, v: eye.v + view.ahead.v * span * 0.35 }, MUTED, 1, [2, 4]);

  for (const s of scene.spheres) {
    if (!isHuge(s) && !s.material.isEmissive) sphereCircle(p, m, pr(s.center), s.radius, s, s === record?.hit?.object);
  }
  // Lights: drawn where they are, or, when far off the view, as a marker on
  // its edge in their direction (the shadow rays still point at them).
  const hitAt = record?.hit ? pr(record.hit.point) : null;
  for (const light of scene.lights) {
    const at = pr(light.position), name = light.source?.name || 'light';
    if (inArea(at)) {
      if (light.object && !isHuge(light.object)) sphereCircle(p, m, at, light.object.radius, light.object, false);
      else lightGlyph(p, m.sx(at.u), m.sy(at.v), name);
    } else {
      const from = hitAt ?? { u: (box.umin + box.umax) / 2, v: (box.vmin + box.vmax) / 2 };
      const edge = toEdge(m.sx(from.u), m.sy(from.v), m.sx(at.u), m.sy(at.v), area, 16);
      lightGlyph(p, edge.x, edge.y, `${name} (off view)`, area);
    }
  }

  imagePlane(p, m, top, bottom, camera[view.cells], record ? view.cellOf(record) : null, record?.color, view);
  eyeGlyph(p, m.sx(eye.u), m.sy(eye.v));

  if (record) {
    const ray = record.ray, hit = record.hit;
    const end = hit ? hitAt : pr(offset(ray.origin, ray.direction, far));
    if (hit) {
      for (const l of hit.lights) shadowRayLine(p, m, hitAt, pr(l.position), l);
      arrow(p, m, hitAt, pr(offset(hit.point, hit.normal, 0.1 * span)), NORMAL, 3, 'N');
    }
    line(p, m, eye, end, RAY, 3.5, hit ? [] : [10, 6]);
    if (hit) {
      dot(p, m.sx(end.u), m.sy(end.v), 5, RAY);
      if (!inArea(end)) edgeNote(p, area, `hit at t = ${fmt(hit.t)}, off the view →`);
    } else {
      edgeNote(p, area, 'no hit: the background colour');
    }
    angleArc(p, m, eye, view, pr(offset(ray.origin, ray.direction, 1)), view.angle(record));
  } else {
    message(p, area, 'Click a pixel to see its ray');
  }
  unclip(p);
  axesKey(p, area, view.axes);
  lineKey(p, { x: content.x, y: content.y + content.h - keyHeight + 4, w: content.w });
  closePanel(p);
}

/**
 * Bounds (u, v) around what matters: the eye (with room behind it for its
 * labels), the ordinary spheres, boxes and a hit point. Lights count only
 * when near; far ones become markers on the edge. A huge sphere adds just
 * its surface nearest the eye, so the ground line shows.
 */
function fitBounds(scene, record, pr, eye, ahead) {
  const b = { umin: eye.u, umax: eye.u, vmin: eye.v, vmax: eye.v };
  const grow = (q, r = 0) => {
    b.umin = Math.min(b.umin, q.u - r); b.umax = Math.max(b.umax, q.u + r);
    b.vmin = Math.min(b.vmin, q.v - r); b.vmax = Math.max(b.vmax, q.v + r);
  };
  for (const s of scene.spheres) {
    if (s.material.isEmissive) continue;
    if (!isHuge(s)) grow(pr(s.center), s.radius);
    else {
      const c = pr(s.center), d = Math.hypot(eye.u - c.u, eye.v - c.v);
      if (d > s.radius) grow({ u: c.u + ((eye.u - c.u) * s.radius) / d, v: c.v + ((eye.v - c.v) * s.radius) / d });
    }
  }
  for (const o of scene.objects) if (o.min && o.max) { grow(pr(o.min)); grow(pr(o.max)); }
  let size = Math.max(b.umax - b.umin, b.vmax - b.vmin, 2);
  if (record?.hit) {
    const q = pr(record.hit.point);
    // a hit far out on the ground is drawn off the edge, with a note
    if (q.u > b.umin - size && q.u < b.umax + size && q.v > b.vmin - size && q.v < b.vmax + size) grow(q);
  }
  size = Math.max(b.umax - b.umin, b.vmax - b.vmin, 2);
  const near = { umin: b.umin - 0.3 * size, umax: b.umax + 0.3 * size, vmin: b.vmin - 0.3 * size, vmax: b.vmax + 0.3 * size };
  for (const light of scene.lights) {
    const q = pr(light.position), r = light.object?.radius ?? 0;
    if (q.u >= near.umin && q.u <= near.umax && q.v >= near.vmin && q.v <= near.vmax) grow(q, r < 100 ? r : 0);
  }
  // room behind the eye for its label and the angle's
  grow({ u: eye.u - ahead.u * 0.18 * size, v: eye.v - ahead.v * 0.18 * size });
  if (b.umax - b.umin < 2) { b.umin -= 1; b.umax += 1; }
  if (b.vmax - b.vmin < 2) { b.vmin -= 1; b.vmax += 1; }
  return b;
}

/** Where to draw the image plane: 40% of the way to the nearest sphere, within limits. */
function imagePlaneDistance(scene, pr, eye, span) {
  let nearest = Infinity;
  for (const s of scene.spheres) {
    if (isHuge(s) || s.material.isEmissive) continue;
    const c = pr(s.center);
    nearest = Math.min(nearest, Math.hypot(c.u - eye.u, c.v - eye.v) - s.radius);
  }
  const D = Number.isFinite(nearest) && nearest > 0 ? 0.4 * nearest : 0.15 * span;
  return Math.min(0.25 * span, Math.max(0.08 * span, D));
}

/** The point where the segment from (x0, y0) toward (x1, y1) leaves `area` shrunk by `inset`. */
function toEdge(x0, y0, x1, y1, area, inset) {
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

function imagePlane(p, m, top, bottom, cells, selected, color, view) {
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
  const side = view === SIDE;
  const lx = side ? (x0 + x1) / 2 : Math.max(x0, x1) + 12, ly = side ? Math.max(y0, y1) + 18 : (y0 + y1) / 2 - 8;
  const align = side ? 'center' : 'left';
  label(p, `image plane, ${cells} px`, lx, ly, { color: INK, align, size: 13 });
  if (selected !== null) label(p, `${view.cellWord} ${selected}`, lx, ly + 16, { color: RAY, align, size: 13, bold: true });
}

function sphereCircle(p, m, c, r, sphere, selected) {
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
function hugeArc(p, m, c, r, eye, sphere, selected) {
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

function shadowRayLine(p, m, from, to, l) {
  if (!l.facing) {
    line(p, m, from, to, MUTED, 1.5, [2, 5]);
    return;
  }
  line(p, m, from, to, l.inShadow ? SHADOW : LIT, l.inShadow ? 2.5 : 3, l.inShadow ? [8, 6] : []);
}

function angleArc(p, m, eye, view, along, angle) {
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

function eyeGlyph(p, x, y) {
  p.push();
  p.stroke(INK); p.strokeWeight(2); p.fill(PAPER);
  p.ellipse(x, y, 22, 13);
  p.noStroke(); p.fill(INK); p.circle(x, y, 7);
  p.pop();
  label(p, 'eye (Ro)', x, y + 22, { color: INK, bold: true });
}

/** A light as a small sun; on the view's edge (`area` given) its label goes beside it, inside. */
function lightGlyph(p, x, y, name, area) {
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
function lineKey(p, { x, y, w }) {
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

function axesKey(p, area, [across, upward]) {
  label(p, `${across}   ${upward}`, area.x + area.w - 8, area.y + area.h - 12, { color: MUTED, align: 'right', size: 12 });
}

function edgeNote(p, area, text) {
  label(p, text, area.x + area.w - 8, area.y + area.h - 30, { color: RAY, align: 'right', bold: true });
}

/* ========================= geometric construction ========================= */

/**
 * The lesson's geometric route for one ray and one sphere, drawn in the plane
 * that holds the ray and the sphere's centre: Ro, Rd, C, L = C − Ro, tca
 * along the ray, d from C to the ray, thc, r, and the hit points t0, t1, all
 * with their values. A miss (d > r) and a ray starting inside (tca may be
 * negative, t0 behind the eye) are drawn as such.
 * @param {object} p a p5 instance
 * @param {object} o
 * @param {import('../shapes/sphere.js').Sphere} [o.sphere]
 * @param {import('../ray.js').Ray} [o.ray]
 * @param {object} [o.result] intersectGeometric(ray, sphere)'s result (computed when missing)
 * @param {object} [o.record] instead of sphere/ray: an inspectPixel record (its focus sphere is used)
 */
export function drawGeometricConstruction(p, o) {
  let { sphere, ray, result } = o;
  const { x, y, w, h } = o;
  if ((!sphere || !ray) && o.record) {
    const test = focusTest(o.record);
    sphere = test?.sphere; ray = o.record.ray; result = test?.geometric;
  }
  const name = sphere?.name ? ` · ${sphere.name} sphere` : '';
  const content = panel(p, x, y, w, h, 'Geometric route' + name);
  if (!sphere || !ray) {
    placeholder(p, content, 'Click a pixel to see L, tca, d and thc for its ray.');
    return closePanel(p);
  }
  const g = result ?? intersectGeometric(ray, sphere);
  const r = sphere.radius, tca = g.tca, d = Math.sqrt(Math.max(0, g.d2));
  const hit = g.roots > 0, inside = g.d2 + tca * tca < r * r; // |L| < r: the ray starts inside
  const L = g.L ?? { x: sphere.center.x - ray.origin.x, y: sphere.center.y - ray.origin.y, z: sphere.center.z - ray.origin.z };

  // the formulas with this ray's numbers
  const lines = [
    [`L = C − Ro = (${fmt(L.x)}, ${fmt(L.y)}, ${fmt(L.z)})`, INK],
    [`tca = L·Rd = ${fmt(tca)}${tca < 0 ? (inside ? '  (< 0, but Ro is inside: fine)' : '  (< 0: C is behind Ro)') : ''}`, INK],
    [`d² = L·L − tca² = ${fmt(g.d2)},  d = ${fmt(d)},  r = ${fmt(r)}`, INK],
    hit ? [`thc = √(r² − d²) = ${fmt(g.thc)}`, INK] : ['d > r: the ray passes by, no hit', SHADOW],
    hit ? [`t = tca ∓ thc:  t0 = ${fmt(g.t0)},  t1 = ${fmt(g.t1)}  →  ${g.t === null ? 'both behind the eye' : `t = ${fmt(g.t)}`}`, g.t === null ? SHADOW : RAY] : null,
  ].filter(Boolean);
  const lineHeight = 18;
  lines.forEach(([text, color], i) => label(p, text, content.x + 8, content.y + 8 + i * lineHeight, { color, align: 'left', halo: false, size: 13 }));
  const top = content.y + lines.length * lineHeight + 4;
  const area = { x: content.x, y: top, w: content.w, h: content.y + content.h - top };

  // 2D frame: Ro at (0, 0), the ray along +u, C above it at (tca, d).
  const t0 = hit ? g.t0 : null, t1 = hit ? g.t1 : null;
  const m = constructionMapping(tca, d, r, area);
  clip(p, area);
  const Ro = { u: 0, v: 0 }, C = { u: tca, v: d }, P = { u: tca, v: 0 };
  const x0 = m.sx(0), y0 = m.sy(0);

  // the sphere
  const rgb = sphere.material.color.map((v) => Math.min(1, v) * 255);
  p.push();
  p.fill(rgb[0], rgb[1], rgb[2], 90); p.stroke(darker(rgb)); p.strokeWeight(2);
  p.circle(m.sx(C.u), m.sy(C.v), 2 * r * m.s);
  p.pop();

  // the ray: solid ahead of Ro, faint behind it
  p.push();
  p.strokeWeight(2); p.stroke(FAINT); p.drawingContext.setLineDash([5, 5]);
  p.line(area.x, y0, x0, y0);
  p.drawingContext.setLineDash([]);
  p.stroke(RAY); p.strokeWeight(2.5);
  p.line(x0, y0, area.x + area.w, y0);
  p.pop();
  if (m.breakX !== null) breakMark(p, m.breakX, y0);
  // Rd: a unit direction, drawn a fixed 50 px long
  screenArrow(p, x0, y0, x0 + 50, y0, RAY, 3);

  // L = C − Ro
  const cx = m.sx(C.u), cy = m.sy(C.v), px = m.sx(P.u);
  arrow(p, m, Ro, C, CONSTRUCT, 2.5, null);

  // d: from C straight down to the ray, meeting it at P, the closest approach
  line(p, m, C, P, INK, 1.5, [4, 4]);
  if (d * m.s > 14) rightAngle(p, px, y0, tca >= 0 ? -1 : 1);

  // r: from C to the near hit point (the right triangle d, thc, r), or
  // straight toward the ray when it misses
  const rEnd = hit && d > 0.15 * r ? { u: t0, v: 0 } : hit ? { u: tca, v: d + r } : { u: tca, v: d - r };
  line(p, m, C, rEnd, NORMAL, 2.5, []);

  // below the ray: thc (from t0 to P) and tca (from Ro to P) as dimension lines
  if (hit && g.thc > 0) dimension(p, m.sx(t0), px, y0 + 40, null, NORMAL);
  dimension(p, x0, px, y0 + 58, null, CONSTRUCT);
  if (m.breakX !== null) breakMark(p, m.breakX, y0 + 58);

  const roots = !hit ? [] : g.roots === 1 ? [[t0, 't0 = t1']] : [[t0, 't0'], [t1, 't1']];
  for (const [t] of roots) {
    const chosen = g.t !== null && t === g.t;
    dot(p, m.sx(t), y0, chosen ? 6 : 5, t <= 0 ? MUTED : RAY);
    if (chosen) ring(p, m.sx(t), y0, 11, RAY);
  }
  dot(p, x0, y0, 6, INK);
  dot(p, cx, cy, 6, INK);

  // The labels, most important first: each takes the first of its places
  // that is free; L and Rd are left out when no place is (the formulas above say them).
  const labels = labelPlacer(p, area);
  for (const [x, y] of [[x0, y0], [cx, cy]]) labels.keepClear(x - 5, y - 5, 10, 10);
  for (const [t] of roots) labels.keepClear(m.sx(t) - 8, y0 - 8, 16, 16);
  if (m.breakX !== null) { labels.keepClear(m.breakX - 7, y0 - 8, 14, 16); labels.keepClear(m.breakX - 7, y0 + 50, 14, 16); }
  labels.keepClearLine(x0, y0, area.x + area.w, y0);
  labels.keepClearLine(x0, y0, cx, cy);
  labels.keepClearLine(cx, cy, px, y0);
  labels.keepClearLine(cx, cy, m.sx(rEnd.u), m.sy(rEnd.v));
  if (hit && g.thc > 0) labels.put(`thc = ${fmt(g.thc)}`, [[(m.sx(t0) + px) / 2, y0 + 40]], { color: NORMAL, bold: true, box: true });
  labels.put(`tca = ${fmt(tca)}`, [[(x0 + px) / 2, y0 + 72]], { color: CONSTRUCT, bold: true });
  if (!hit) labels.put('d > r: no hit', [[cx, m.sy(d - r) + 16], [cx, y0 + 20], [cx, y0 - 18]], { color: SHADOW, bold: true, size: 15 });
  labels.put('Ro', [[x0 - 8, y0 - 14, 'right'], [x0 - 8, y0 + 16, 'right'], [x0 + 8, y0 + 16, 'left'], [x0, y0 - 18], [x0 + 8, y0 - 14, 'left']], { color: INK, bold: true });
  labels.put('C', [[cx + 10, cy - 12, 'left'], [cx - 10, cy - 12, 'right'], [cx, cy - 18], [cx + 12, cy, 'left'], [cx - 12, cy, 'right'], [cx + 10, cy + 14, 'left'], [cx - 10, cy + 14, 'right']], { color: INK, bold: true });
  for (const [t, name] of roots) {
    const behind = t <= 0, chosen = g.t !== null && t === g.t, tx = m.sx(t);
    const side = name === 't0' ? -1 : 1, align = side < 0 ? 'right' : 'left', other = side < 0 ? 'left' : 'right';
    labels.put(`${name} = ${fmt(t)}${behind ? ' (behind)' : ''}`,
      [[tx + 6 * side, y0 + 18, align], [tx + 14 * side, y0 - 16, align], [tx - 6 * side, y0 + 18, other], [tx - 14 * side, y0 - 16, other]],
      { color: behind ? MUTED : RAY, bold: chosen });
  }
  // r beside its middle, away from the ray first
  const ex = m.sx(rEnd.u) - cx, ey = m.sy(rEnd.v) - cy, len = Math.hypot(ex, ey) || 1;
  let nx = -ey / len, ny = ex / len;
  if (ny > 0) { nx = -nx; ny = -ny; }
  const rAt = (k, f = 0.5) => [cx + ex * f + nx * k, cy + ey * f + ny * k, nx * k < -0.3 * Math.abs(k) ? 'right' : nx * k > 0.3 * Math.abs(k) ? 'left' : 'center'];
  labels.put(`r = ${fmt(r)}`, [rAt(16), rAt(-16), rAt(16, 0.3), rAt(-16, 0.3), rAt(16, 0.7), rAt(-16, 0.7), rAt(30), rAt(-30)], { color: NORMAL, bold: true });
  // d beside the dashed line, or beside C when d is short
  const dy = (cy + y0) / 2;
  labels.put(`d = ${fmt(d)}`, [[px + 8, dy, 'left'], [px - 8, dy, 'right'], [px + 8, dy - 22, 'left'], [px - 8, dy - 22, 'right'],
    [cx + 12, cy - 30, 'left'], [cx - 12, cy - 30, 'right'], [px + 8, y0 + 22, 'left'], [px - 8, y0 + 22, 'right']], { color: INK, bold: true });
  // L beside its arrow, Rd above or below its own
  const along = (f, k) => {
    const ux = cx - x0, uy = cy - y0, ul = Math.hypot(ux, uy) || 1;
    let qx = -uy / ul, qy = ux / ul;
    if (qy > 0) { qx = -qx; qy = -qy; }
    return [x0 + ux * f + qx * k, y0 + uy * f + qy * k];
  };
  labels.put('L', [along(0.3, 14), along(0.5, 14), along(0.7, 14), along(0.3, -14), along(0.5, -14), along(0.15, 14)], { color: CONSTRUCT, bold: true, size: 16 }, { optional: true });
  labels.put('Rd', [[x0 + 34, y0 - 14], [x0 + 34, y0 + 16], [x0 + 20, y0 - 14], [x0 + 20, y0 + 16]], { color: RAY, bold: true }, { optional: true });
  unclip(p);
  closePanel(p);
}

/**
 * Screen mapping of the construction: true scale around the sphere. When Ro
 * is far from the sphere, the empty stretch of ray between them is squeezed
 * into a fixed gap marked with a break (//), so the sphere stays big; lines
 * perpendicular to the ray (d) keep their right angles.
 */
function constructionMapping(tca, d, r, area) {
  const pad = { left: 40, right: 34, top: 18, bottom: 76 };
  const uL = tca - r, uR = tca + r, vmin = Math.min(0, d - r), vmax = d + r;
  const gapPx = 96, h = area.h - pad.top - pad.bottom, w = area.w - pad.left - pad.right;
  const breakLeft = uL > 0.6 * (uR - uL), breakRight = uR < -0.6 * (uR - uL);
  let s, sx, breakX = null;
  if (breakLeft || breakRight) {
    s = Math.min((w - gapPx) / (uR - uL), h / (vmax - vmin));
    const x = area.x + pad.left + (w - gapPx - (uR - uL) * s) / 2; // left end of the drawing
    if (breakLeft) {
      // Ro at x, then the squeezed gap, then the sphere at true scale
      sx = (u) => (u >= uL ? x + gapPx + (u - uL) * s : u >= 0 ? x + (u / uL) * gapPx : x + u * s);
      breakX = x + gapPx * 0.72;
    } else {
      // the sphere (behind the eye) at true scale, the squeezed gap, then Ro
      const xR = x + (uR - uL) * s;
      sx = (u) => (u <= uR ? x + (u - uL) * s : u <= 0 ? xR + ((u - uR) / -uR) * gapPx : xR + gapPx + u * s);
      breakX = xR + gapPx * 0.4;
    }
  } else {
    const umin = Math.min(0, uL), umax = Math.max(0, uR);
    s = Math.min(w / (umax - umin), h / (vmax - vmin));
    const x = area.x + pad.left + (w - (umax - umin) * s) / 2;
    sx = (u) => x + (u - umin) * s;
  }
  const yTop = area.y + pad.top + (h - (vmax - vmin) * s) / 2;
  return { s, sx, sy: (v) => yTop + (vmax - v) * s, breakX };
}

/** "//" across a line at (x, y): this stretch is not to scale. */
function breakMark(p, x, y) {
  p.push();
  p.noStroke(); p.fill(PAPER); p.rect(x - 5, y - 8, 10, 16);
  p.stroke(INK); p.strokeWeight(1.5);
  p.line(x - 7, y + 7, x - 1, y - 7); p.line(x + 1, y + 7, x + 7, y - 7);
  p.pop();
}

/* ========================= the parabola ========================= */

/**
 * f(t) = At² + Bt + C, the lesson's quadratic, over a range around its roots
 * (or its vertex when there are none): the roots marked and labelled, the
 * vertex, and what the discriminant says (no hit, tangent, two hits).
 * @param {object} p a p5 instance
 * @param {object} o `{ A, B, C, t0, t1, x, y, w, h }` (t0, t1 may be null);
 *   or `{ quadratic, … }` with intersectQuadratic's result, or `{ record, … }`
 */
export function drawParabola(p, o) {
  let q = o;
  if (o.quadratic) q = o.quadratic;
  else if (o.A === undefined && o.record) q = focusTest(o.record)?.quadratic ?? {};
  const { x, y, w, h } = o;
  const content = panel(p, x, y, w, h, 'f(t) = At² + Bt + C' + (o.record ? `  ·  pixel ${o.record.x},${o.record.y}` : ''));
  const { A, B, C } = q;
  if (![A, B, C].every(Number.isFinite) || A === 0) {
    placeholder(p, content, 'Click a pixel to see the quadratic of its ray.');
    return closePanel(p);
  }
  const discriminant = B * B - 4 * A * C;
  const roots = q.roots ?? (discriminant > 0 ? 2 : discriminant === 0 ? 1 : 0);
  let t0 = q.t0 ?? null, t1 = q.t1 ?? null;
  if (roots > 0 && (t0 === null || t1 === null)) {
    const s = Math.sqrt(Math.max(0, discriminant));
    t0 = (-B - s) / (2 * A); t1 = (-B + s) / (2 * A);
  }
  const tv = -B / (2 * A), fv = C - (B * B) / (4 * A);
  const f = (t) => (A * t + B) * t + C;

  const meaning = roots === 2 ? ['> 0: two roots, the ray goes in and out', RAY] : roots === 1 ? ['= 0: one root, the ray just touches', LIT] : ['< 0: no real root, no hit', SHADOW];
  const lines = [
    [`f(t) = ${fmt(A, 2)}t² ${sign(B)} ${fmt(Math.abs(B), 2)}t ${sign(C)} ${fmt(Math.abs(C), 2)}`, INK],
    [`B² − 4AC = ${fmt(discriminant)} ${meaning[0]}`, meaning[1]],
  ];
  lines.forEach(([text, color], i) => label(p, text, content.x + 8, content.y + 10 + i * 19, { color, align: 'left', halo: false }));
  const area = { x: content.x + 8, y: content.y + 2 * 19 + 14, w: content.w - 16, h: content.h - 2 * 19 - 14 - 24 };

  // t range: the roots with room either side, else around the vertex
  let lo, hi;
  if (roots === 2) {
    const pad = Math.max((t1 - t0) * 0.6, 1e-3 * Math.max(1, Math.abs(tv)));
    lo = t0 - pad; hi = t1 + pad;
  } else {
    const halfWidth = Math.max(2 * Math.sqrt(Math.abs(fv) / Math.abs(A)), 0.05 * Math.max(1, Math.abs(tv)), 1);
    lo = tv - halfWidth; hi = tv + halfWidth;
  }
  if (lo > 0 && lo < (hi - lo) * 0.5) lo = -(hi - lo) * 0.05; // t = 0 (the eye) is close: show it
  let fmin = Math.min(0, fv), fmax = Math.max(0, f(lo), f(hi));
  if (fmax - fmin === 0) fmax = fmin + 1;
  const padF = (fmax - fmin) * 0.08;
  fmin -= padF; fmax += padF;
  const sx = (t) => area.x + ((t - lo) / (hi - lo)) * area.w;
  const plotH = area.h - 34; // room under the curve for the vertex's label
  const sy = (v) => area.y + plotH - ((v - fmin) / (fmax - fmin)) * plotH;

  clip(p, area);
  // f < 0 between the roots: the part of the ray inside the sphere
  if (roots === 2) {
    p.push(); p.noStroke(); p.fill(194, 24, 91, 28);
    p.rect(sx(t0), sy(0), sx(t1) - sx(t0), Math.max(0, sy(fmin) - sy(0)));
    p.pop();
    label(p, 'f(t) < 0: inside', (sx(t0) + sx(t1)) / 2, sy(0) + 16, { color: RAY, size: 12 });
  }
  // axes
  p.push();
  p.stroke(INK); p.strokeWeight(2);
  p.line(area.x, sy(0), area.x + area.w, sy(0));
  if (lo < 0 && hi > 0) { p.strokeWeight(1.5); p.line(sx(0), area.y, sx(0), area.y + area.h); }
  p.pop();
  if (lo < 0 && hi > 0) label(p, 'eye, t = 0', sx(0) + 6, area.y + 12, { color: MUTED, align: 'left', size: 12 });
  for (const t of niceTicks(lo, hi, 6)) {
    p.push(); p.stroke(INK); p.strokeWeight(1); p.line(sx(t), sy(0) - 4, sx(t), sy(0) + 4); p.pop();
    label(p, fmt(t, Math.abs(hi - lo) < 5 ? 1 : 0), sx(t), sy(0) - 10, { color: MUTED, size: 11 });
  }
  label(p, 't →', area.x + area.w - 6, sy(0) - 12, { color: INK, align: 'right', bold: true });

  // the curve
  p.push();
  p.noFill(); p.stroke(CONSTRUCT); p.strokeWeight(3);
  p.beginShape();
  for (let i = 0; i <= 160; i++) {
    const t = lo + ((hi - lo) * i) / 160;
    p.vertex(sx(t), Math.max(area.y - 10, Math.min(area.y + area.h + 10, sy(f(t)))));
  }
  p.endShape();
  p.pop();

  // vertex and roots
  dot(p, sx(tv), sy(fv), 5, CONSTRUCT);
  label(p, `vertex: t = −B/2A = ${fmt(tv)}, f = ${fmt(fv)}`, sx(tv), sy(fv) + 18, { color: CONSTRUCT, size: 12, bold: true });
  if (roots > 0) {
    const pts = roots === 1 ? [[t0, 't0 = t1']] : [[t0, 't0'], [t1, 't1']];
    for (const [t, name] of pts) {
      dot(p, sx(t), sy(0), 7, t > 0 ? RAY : MUTED);
      label(p, `${name} = ${fmt(t)}${t <= 0 ? ' (behind)' : ''}`, sx(t), sy(0) - 18, { color: t > 0 ? RAY : MUTED, bold: true });
    }
  }
  unclip(p);
  closePanel(p);
}

/* ========================= legends ========================= */

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

/* ========================= which sphere to explain ========================= */

/**
 * The sphere test of a record worth explaining: the sphere the ray hits,
 * else its closest miss (largest discriminant, skipping spheres wholly
 * behind the eye) — the same choice as the discriminant mode. Null when the
 * record has no sphere tests.
 */
export function focusTest(record) {
  const tests = record?.tests ?? [];
  const hit = tests.find((t) => t.sphere === record.hit?.object);
  if (hit) return hit;
  const ahead = tests.filter((t) => t.quadratic.roots === 0);
  const pool = ahead.length ? ahead : tests;
  return pool.reduce((best, t) => (!best || t.quadratic.discriminant > best.quadratic.discriminant ? t : best), null);
}

/* ========================= drawing helpers ========================= */

/** A white card with a title; returns the content box under the title. */
function panel(p, x, y, w, h, title) {
  p.push();
  p.drawingContext.save();
  p.fill(PAPER); p.stroke(FAINT); p.strokeWeight(1);
  p.rect(x + 0.5, y + 0.5, w - 1, h - 1, 6);
  p.noStroke(); p.fill(INK); p.textFont(FONT); p.textStyle(p.BOLD); p.textSize(15);
  p.textAlign(p.LEFT, p.TOP);
  p.text(title, x + 10, y + 8);
  p.textStyle(p.NORMAL);
  return { x: x + 4, y: y + 30, w: w - 8, h: h - 34 };
}

function closePanel(p) {
  p.drawingContext.restore();
  p.pop();
}

function placeholder(p, content, text) {
  message(p, content, text);
}

function message(p, area, text) {
  p.push();
  p.noStroke(); p.fill(255, 255, 255, 200);
  p.rect(area.x + area.w / 2 - 150, area.y + area.h / 2 - 22, 300, 44, 8);
  p.pop();
  label(p, text, area.x + area.w / 2, area.y + area.h / 2, { color: INK, size: 16, bold: true });
}

/** World (u, v) → screen with one scale for both axes (v up), fitted to `area`. */
function mapping(box, area, margin) {
  const bw = box.umax - box.umin || 1, bh = box.vmax - box.vmin || 1;
  const mx = area.w * margin, my = area.h * margin;
  const s = Math.min((area.w - 2 * mx) / bw, (area.h - 2 * my) / bh);
  const ox = area.x + area.w / 2 - ((box.umin + box.umax) / 2) * s;
  const oy = area.y + area.h / 2 + ((box.vmin + box.vmax) / 2) * s;
  return { s, box, area, sx: (u) => ox + u * s, sy: (v) => oy - v * s };
}

function clip(p, a) {
  const ctx = p.drawingContext;
  ctx.save();
  ctx.beginPath(); ctx.rect(a.x, a.y, a.w, a.h); ctx.clip();
}

function unclip(p) {
  p.drawingContext.restore();
}

function line(p, m, a, b, color, weight, dash) {
  p.push();
  p.stroke(color); p.strokeWeight(weight);
  p.drawingContext.setLineDash(dash);
  p.line(m.sx(a.u), m.sy(a.v), m.sx(b.u), m.sy(b.v));
  p.drawingContext.setLineDash([]);
  p.pop();
}

function dashed(p, m, a, b, color, weight, dash) {
  line(p, m, a, b, color, weight, dash);
}

function arrow(p, m, a, b, color, weight, text) {
  screenArrow(p, m.sx(a.u), m.sy(a.v), m.sx(b.u), m.sy(b.v), color, weight);
  if (text) label(p, text, m.sx(b.u) + (m.sx(b.u) >= m.sx(a.u) ? 10 : -10), m.sy(b.v) - 8, { color, bold: true });
}

function screenArrow(p, x0, y0, x1, y1, color, weight) {
  const a = Math.atan2(y1 - y0, x1 - x0), head = 6 + 2 * weight;
  p.push();
  p.stroke(color); p.strokeWeight(weight); p.fill(color);
  p.line(x0, y0, x1 - Math.cos(a) * head * 0.6, y1 - Math.sin(a) * head * 0.6);
  p.noStroke();
  p.triangle(x1, y1, x1 - Math.cos(a - 0.4) * head, y1 - Math.sin(a - 0.4) * head, x1 - Math.cos(a + 0.4) * head, y1 - Math.sin(a + 0.4) * head);
  p.pop();
}

function dot(p, x, y, r, color) {
  p.push(); p.noStroke(); p.fill(color); p.circle(x, y, 2 * r); p.pop();
}

function ring(p, x, y, r, color) {
  p.push(); p.noFill(); p.stroke(color); p.strokeWeight(2); p.circle(x, y, 2 * r); p.pop();
}

function rightAngle(p, x, y, dir) {
  p.push(); p.noFill(); p.stroke(INK); p.strokeWeight(1);
  p.line(x + dir * 9, y, x + dir * 9, y - 9); p.line(x + dir * 9, y - 9, x, y - 9);
  p.pop();
}

/** A measurement line between two x positions at height y, with end bars and its label on it (or below; none when null). */
function dimension(p, xa, xb, y, text, color, below = false) {
  p.push();
  p.stroke(color); p.strokeWeight(1.5);
  p.line(xa, y, xb, y);
  p.line(xa, y - 5, xa, y + 5); p.line(xb, y - 5, xb, y + 5);
  p.pop();
  if (text === null) return;
  if (below) label(p, text, (xa + xb) / 2, y + 14, { color, bold: true });
  else label(p, text, (xa + xb) / 2, y, { color, bold: true, box: true });
}

/**
 * Labels that keep out of each other's way inside `area`: `put` draws a label
 * at the first of its places (x, y, align) where it overlaps no label or mark
 * placed before; when none is free it is drawn at its first place, or left
 * out when optional. Returns whether it was drawn.
 */
function labelPlacer(p, area) {
  const taken = [];
  const overlaps = (a) => taken.some((b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h);
  const inside = (a) => a.x >= area.x && a.y >= area.y && a.x + a.w <= area.x + area.w && a.y + a.h <= area.y + area.h;
  return {
    keepClear(x, y, w, h) { taken.push({ x, y, w, h }); },
    /** A line labels should not sit on, as a row of small squares along it. */
    keepClearLine(xa, ya, xb, yb) {
      const n = Math.ceil(Math.hypot(xb - xa, yb - ya) / 4);
      for (let i = 0; i <= n; i++) taken.push({ x: xa + ((xb - xa) * i) / n - 1.5, y: ya + ((yb - ya) * i) / n - 1.5, w: 3, h: 3 });
    },
    put(text, places, style = {}, { optional = false } = {}) {
      const size = style.size ?? SIZE, ctx = p.drawingContext;
      ctx.save();
      ctx.font = `${style.bold ? 'bold ' : ''}${size}px ${FONT}`;
      const w = ctx.measureText(text).width + 6, h = size * 1.25;
      ctx.restore();
      const box = ([x, y, align = 'center']) => ({ x: align === 'left' ? x - 3 : align === 'right' ? x - w + 3 : x - w / 2, y: y - h / 2, w, h });
      let place = places.find((pl) => { const b = box(pl); return inside(b) && !overlaps(b); });
      if (!place) { if (optional) return false; place = places[0]; }
      taken.push(box(place));
      label(p, text, place[0], place[1], { ...style, align: place[2] ?? 'center' });
      return true;
    },
  };
}

/**
 * Text with a white halo, so a label stays readable over lines and fills.
 * Drawn on the canvas context directly: p5's text() would stroke over the fill.
 */
function label(p, text, x, y, { color = INK, size = SIZE, align = 'center', bold = false, halo = true, box = false } = {}) {
  const ctx = p.drawingContext;
  ctx.save();
  ctx.font = `${bold ? 'bold ' : ''}${size}px ${FONT}`;
  ctx.textAlign = align;
  ctx.textBaseline = 'middle';
  if (box) {
    // a paper patch behind the text, for a label sitting on its own line
    const w = ctx.measureText(text).width + 8;
    const left = align === 'left' ? x - 4 : align === 'right' ? x - w + 4 : x - w / 2;
    ctx.fillStyle = PAPER;
    ctx.fillRect(left, y - size * 0.7, w, size * 1.4);
  } else if (halo) {
    ctx.lineJoin = 'round';
    ctx.lineWidth = 4;
    ctx.strokeStyle = 'rgba(255,255,255,0.9)';
    ctx.strokeText(text, x, y);
  }
  ctx.fillStyle = color;
  ctx.fillText(text, x, y);
  ctx.restore();
}

function darker(rgb) {
  return `rgb(${rgb.map((c) => Math.round(c * 0.6)).join(',')})`;
}

function offset(point, dir, s) {
  return { x: point.x + dir.x * s, y: point.y + dir.y * s, z: point.z + dir.z * s };
}

function norm2(u, v) {
  const len = Math.hypot(u, v) || 1;
  return { u: u / len, v: v / len };
}

function sign(n) {
  return n < 0 ? '−' : '+';
}

/** A number for a label: one decimal (or `digits`), '−' for minus, big ones as a×10ⁿ. */
export function fmt(n, digits = 1) {
  if (n === null || n === undefined || !Number.isFinite(n)) return '—';
  const minus = n < 0 ? '−' : '';
  const a = Math.abs(n);
  if (a >= 1e6) {
    const e = Math.floor(Math.log10(a));
    return `${minus}${(a / 10 ** e).toFixed(2)}×10${[...String(e)].map((d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d]).join('')}`;
  }
  const text = a.toFixed(a >= 1000 ? 0 : digits);
  return Number(text) === 0 ? text : minus + text;
}

function niceTicks(lo, hi, count) {
  const raw = (hi - lo) / count, mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw) ?? 10 * mag;
  const ticks = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi; t += step) ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
  return ticks;
}
