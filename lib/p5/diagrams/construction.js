/** The geometric route: L, tca, d, thc, r and t0, t1 for one ray and one sphere. */
import { intersectGeometric } from '../../shapes/sphere.js';
import { INK, MUTED, FAINT, PAPER, RAY, NORMAL, SHADOW, CONSTRUCT } from './style.js';
import { label, labelPlacer } from './labels.js';
import { formatLabel } from '../../text/format.js';
import { panel, closePanel, placeholder, clip, unclip, line, arrow, screenArrow, dot, ring, rightAngle, dimension, darker } from './draw.js';
import { focusTest } from './focus.js';
import { nameDiagram } from './aria.js';

/**
 * The lesson's geometric route for one ray and one sphere, drawn in the plane
 * that holds the ray and the sphere's centre: Ro, Rd, C, L = C − Ro, tca
 * along the ray, d from C to the ray, thc, r, and the hit points t0, t1, all
 * with their values. A miss (d > r) and a ray starting inside (tca may be
 * negative, t0 behind the eye) are drawn as such.
 * @param {object} p a p5 instance
 * @param {object} o
 * @param {import('../../shapes/sphere.js').Sphere} [o.sphere]
 * @param {import('../../math/ray.js').Ray} [o.ray]
 * @param {object} [o.result] intersectGeometric(ray, sphere)'s result (computed when missing)
 * @param {object} [o.record] instead of sphere/ray: an inspectPixel record (its focus sphere is used)
 * @param {number} o.x the box it is drawn in: left
 * @param {number} o.y top
 * @param {number} o.w width
 * @param {number} o.h height
 * @example
 * p.drawGeometricConstruction({ record: view.selected, x: 0, y: 0, w: 480, h: 320 }); // L, tca, d, thc, r of the clicked ray
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
    nameDiagram(p, o, 'Geometric route: click a pixel to see L, tca, d and thc for its ray.');
    placeholder(p, content, 'Click a pixel to see L, tca, d and thc for its ray.');
    return closePanel(p);
  }
  const f = construction(result ?? intersectGeometric(ray, sphere), sphere, ray);
  const lines = formulaLines(f);
  nameDiagram(p, o, `Geometric route${sphere.name ? ` for the ${sphere.name} sphere` : ''}: ${lines.map(([text]) => text).join('; ')}.`);
  const area = drawFormulas(p, content, lines);
  const m = constructionMapping(f.tca, f.d, f.r, area);
  clip(p, area);
  const marks = drawFigure(p, m, area, sphere, f);
  placeLabels(p, m, area, f, marks);
  unclip(p);
  closePanel(p);
}

/** The numbers of the construction: the route's result, d, whether the ray hits, starts inside, and its roots to mark. */
function construction(g, sphere, ray) {
  const r = sphere.radius, tca = g.tca, d = Math.sqrt(Math.max(0, g.d2));
  const hit = g.roots > 0, inside = g.d2 + tca * tca < r * r; // |L| < r: the ray starts inside
  const L = g.L ?? { x: sphere.center.x - ray.origin.x, y: sphere.center.y - ray.origin.y, z: sphere.center.z - ray.origin.z };
  const t0 = hit ? g.t0 : null, t1 = hit ? g.t1 : null;
  const roots = !hit ? [] : g.roots === 1 ? [[t0, 't0 = t1']] : [[t0, 't0'], [t1, 't1']];
  return { g, r, tca, d, hit, inside, L, t0, t1, roots };
}

/** The formulas with this ray's numbers, one a line: `[text, color]`. */
function formulaLines({ g, r, tca, d, hit, inside, L }) {
  return [
    [`L = C − Ro = (${formatLabel(L.x)}, ${formatLabel(L.y)}, ${formatLabel(L.z)})`, INK],
    [`tca = L·Rd = ${formatLabel(tca)}${tca < 0 ? (inside ? '  (< 0, but Ro is inside: fine)' : '  (< 0: C is behind Ro)') : ''}`, INK],
    [`d² = L·L − tca² = ${formatLabel(g.d2)},  d = ${formatLabel(d)},  r = ${formatLabel(r)}`, INK],
    hit ? [`thc = √(r² − d²) = ${formatLabel(g.thc)}`, INK] : ['d > r: the ray passes by, no hit', SHADOW],
    hit ? [`t = tca ∓ thc:  t0 = ${formatLabel(g.t0)},  t1 = ${formatLabel(g.t1)}  →  ${g.t === null ? 'both behind the eye' : `t = ${formatLabel(g.t)}`}`, g.t === null ? SHADOW : RAY] : null,
  ].filter(Boolean);
}

/** The formula lines at the top of `content`; returns the area left under them. */
function drawFormulas(p, content, lines) {
  const lineHeight = 18;
  lines.forEach(([text, color], i) => label(p, text, content.x + 8, content.y + 8 + i * lineHeight, { color, align: 'left', halo: false, size: 13 }));
  const top = content.y + lines.length * lineHeight + 4;
  return { x: content.x, y: top, w: content.w, h: content.y + content.h - top };
}

/**
 * The figure, in a 2D frame with Ro at (0, 0), the ray along +u and C above it
 * at (tca, d): the sphere, the ray and Rd, L, d, r, thc and tca, the roots.
 * Returns the screen points the labels go around.
 */
function drawFigure(p, m, area, sphere, { g, r, tca, d, hit, t0, roots }) {
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

  for (const [t] of roots) {
    const chosen = g.t !== null && t === g.t;
    dot(p, m.sx(t), y0, chosen ? 6 : 5, t <= 0 ? MUTED : RAY);
    if (chosen) ring(p, m.sx(t), y0, 11, RAY);
  }
  dot(p, x0, y0, 6, INK);
  dot(p, cx, cy, 6, INK);
  return { x0, y0, cx, cy, px, rEnd };
}

/**
 * The figure's labels, most important first: each takes the first of its
 * places that is free; L and Rd are left out when no place is (the formulas
 * above say them).
 */
function placeLabels(p, m, area, { g, r, tca, d, hit, t0, roots }, { x0, y0, cx, cy, px, rEnd }) {
  const labels = labelPlacer(p, area);
  for (const [x, y] of [[x0, y0], [cx, cy]]) labels.keepClear(x - 5, y - 5, 10, 10);
  for (const [t] of roots) labels.keepClear(m.sx(t) - 8, y0 - 8, 16, 16);
  if (m.breakX !== null) { labels.keepClear(m.breakX - 7, y0 - 8, 14, 16); labels.keepClear(m.breakX - 7, y0 + 50, 14, 16); }
  labels.keepClearLine(x0, y0, area.x + area.w, y0);
  labels.keepClearLine(x0, y0, cx, cy);
  labels.keepClearLine(cx, cy, px, y0);
  labels.keepClearLine(cx, cy, m.sx(rEnd.u), m.sy(rEnd.v));
  if (hit && g.thc > 0) labels.put(`thc = ${formatLabel(g.thc)}`, [[(m.sx(t0) + px) / 2, y0 + 40]], { color: NORMAL, bold: true, box: true });
  labels.put(`tca = ${formatLabel(tca)}`, [[(x0 + px) / 2, y0 + 72]], { color: CONSTRUCT, bold: true });
  if (!hit) labels.put('d > r: no hit', [[cx, m.sy(d - r) + 16], [cx, y0 + 20], [cx, y0 - 18]], { color: SHADOW, bold: true, size: 15 });
  labels.put('Ro', [[x0 - 8, y0 - 14, 'right'], [x0 - 8, y0 + 16, 'right'], [x0 + 8, y0 + 16, 'left'], [x0, y0 - 18], [x0 + 8, y0 - 14, 'left']], { color: INK, bold: true });
  labels.put('C', [[cx + 10, cy - 12, 'left'], [cx - 10, cy - 12, 'right'], [cx, cy - 18], [cx + 12, cy, 'left'], [cx - 12, cy, 'right'], [cx + 10, cy + 14, 'left'], [cx - 10, cy + 14, 'right']], { color: INK, bold: true });
  for (const [t, name] of roots) {
    const behind = t <= 0, chosen = g.t !== null && t === g.t, tx = m.sx(t);
    const side = name === 't0' ? -1 : 1, align = side < 0 ? 'right' : 'left', other = side < 0 ? 'left' : 'right';
    labels.put(`${name} = ${formatLabel(t)}${behind ? ' (behind)' : ''}`,
      [[tx + 6 * side, y0 + 18, align], [tx + 14 * side, y0 - 16, align], [tx - 6 * side, y0 + 18, other], [tx - 14 * side, y0 - 16, other]],
      { color: behind ? MUTED : RAY, bold: chosen });
  }
  // r beside its middle, away from the ray first
  const ex = m.sx(rEnd.u) - cx, ey = m.sy(rEnd.v) - cy, len = Math.hypot(ex, ey) || 1;
  let nx = -ey / len, ny = ex / len;
  if (ny > 0) { nx = -nx; ny = -ny; }
  const rAt = (k, f = 0.5) => [cx + ex * f + nx * k, cy + ey * f + ny * k, nx * k < -0.3 * Math.abs(k) ? 'right' : nx * k > 0.3 * Math.abs(k) ? 'left' : 'center'];
  labels.put(`r = ${formatLabel(r)}`, [rAt(16), rAt(-16), rAt(16, 0.3), rAt(-16, 0.3), rAt(16, 0.7), rAt(-16, 0.7), rAt(30), rAt(-30)], { color: NORMAL, bold: true });
  // d beside the dashed line, or beside C when d is short
  const dy = (cy + y0) / 2;
  labels.put(`d = ${formatLabel(d)}`, [[px + 8, dy, 'left'], [px - 8, dy, 'right'], [px + 8, dy - 22, 'left'], [px - 8, dy - 22, 'right'],
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
