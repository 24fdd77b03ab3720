/** The lesson's quadratic f(t) = At² + Bt + C as a curve, with its roots and vertex. */
import { INK, MUTED, RAY, LIT, SHADOW, CONSTRUCT } from './style.js';
import { label } from './labels.js';
import { formatLabel, sign } from '../../text/format.js';
import { niceTicks } from '../../math/numbers.js';
import { panel, closePanel, placeholder, clip, unclip, dot } from './draw.js';
import { focusTest } from './focus.js';
import { nameDiagram } from './aria.js';

/**
 * f(t) = At² + Bt + C, the lesson's quadratic, over a range around its roots
 * (or its vertex when there are none): the roots marked and labelled, the
 * vertex, and what the discriminant says (no hit, tangent, two hits).
 * @param {object} p a p5 instance
 * @param {object} o `{ A, B, C, t0, t1, x, y, w, h }` (t0, t1 may be null);
 *   or `{ quadratic, … }` with intersectQuadratic's result, or `{ record, … }`
 * @example
 * p.drawParabola({ A: 1, B: -40, C: 384, t0: 16, t1: 24, x: 0, y: 0, w: 400, h: 240 }); // two roots: two hits
 */
export function drawParabola(p, o) {
  let q = o;
  if (o.quadratic) q = o.quadratic;
  else if (o.A === undefined && o.record) q = focusTest(o.record)?.quadratic ?? {};
  const { x, y, w, h } = o;
  const content = panel(p, x, y, w, h, 'f(t) = At² + Bt + C' + (o.record ? `  ·  pixel ${o.record.x},${o.record.y}` : ''));
  const { A, B, C } = q;
  if (![A, B, C].every(Number.isFinite) || A === 0) {
    nameDiagram(p, o, 'The parabola f(t) = At² + Bt + C: click a pixel to see the quadratic of its ray.');
    placeholder(p, content, 'Click a pixel to see the quadratic of its ray.');
    return closePanel(p);
  }
  const curve = quadratic(q, A, B, C);
  const lines = formulaLines(curve);
  const roots = curve.roots === 2 ? `roots t0 = ${formatLabel(curve.t0)} and t1 = ${formatLabel(curve.t1)}` : curve.roots === 1 ? `one root t = ${formatLabel(curve.t0)}` : 'no root: the curve stays above the t axis';
  nameDiagram(p, o, `The parabola${o.record ? ` of pixel ${o.record.x},${o.record.y}` : ''}: ${lines.map(([text]) => text).join('; ')}; ${roots}.`);
  const area = drawFormulas(p, content, lines);
  const m = plotMapping(curve, area);
  clip(p, area);
  drawAxes(p, m, area, curve);
  drawCurve(p, m, area, curve);
  drawVertexAndRoots(p, m, curve);
  unclip(p);
  closePanel(p);
}

/** The quadratic's numbers: discriminant, roots (given, else solved), vertex (tv, fv) and f itself. */
function quadratic(q, A, B, C) {
  const discriminant = B * B - 4 * A * C;
  const roots = q.roots ?? (discriminant > 0 ? 2 : discriminant === 0 ? 1 : 0);
  let t0 = q.t0 ?? null, t1 = q.t1 ?? null;
  if (roots > 0 && (t0 === null || t1 === null)) {
    const s = Math.sqrt(Math.max(0, discriminant));
    t0 = (-B - s) / (2 * A); t1 = (-B + s) / (2 * A);
  }
  const tv = -B / (2 * A), fv = C - (B * B) / (4 * A);
  const f = (t) => (A * t + B) * t + C;
  return { A, B, C, discriminant, roots, t0, t1, tv, fv, f };
}

/** f(t) and B² − 4AC with what it means: `[text, color]` lines. */
function formulaLines({ A, B, C, discriminant, roots }) {
  const meaning = roots === 2 ? ['> 0: two roots, the ray goes in and out', RAY] : roots === 1 ? ['= 0: one root, the ray just touches', LIT] : ['< 0: no real root, no hit', SHADOW];
  return [
    [`f(t) = ${formatLabel(A, 2)}t² ${sign(B)} ${formatLabel(Math.abs(B), 2)}t ${sign(C)} ${formatLabel(Math.abs(C), 2)}`, INK],
    [`B² − 4AC = ${formatLabel(discriminant)} ${meaning[0]}`, meaning[1]],
  ];
}

/** The formula lines at the top of `content`; returns the plot's area under them. */
function drawFormulas(p, content, lines) {
  lines.forEach(([text, color], i) => label(p, text, content.x + 8, content.y + 10 + i * 19, { color, align: 'left', halo: false }));
  return { x: content.x + 8, y: content.y + 2 * 19 + 14, w: content.w - 16, h: content.h - 2 * 19 - 14 - 24 };
}

/** The t range (the roots with room either side, else around the vertex) and f's, mapped onto `area`. */
function plotMapping({ A, roots, t0, t1, tv, fv, f }, area) {
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
  return { lo, hi, fmin, sx, sy };
}

/** The shaded stretch inside the sphere (f < 0), the t axis with its ticks, and the eye at t = 0. */
function drawAxes(p, { lo, hi, fmin, sx, sy }, area, { roots, t0, t1 }) {
  // f < 0 between the roots: the part of the ray inside the sphere
  if (roots === 2) {
    p.push(); p.noStroke(); p.fill(194, 24, 91, 28);
    p.rect(sx(t0), sy(0), sx(t1) - sx(t0), Math.max(0, sy(fmin) - sy(0)));
    p.pop();
    label(p, 'f(t) < 0: inside', (sx(t0) + sx(t1)) / 2, sy(0) + 16, { color: RAY, size: 12 });
  }
  p.push();
  p.stroke(INK); p.strokeWeight(2);
  p.line(area.x, sy(0), area.x + area.w, sy(0));
  if (lo < 0 && hi > 0) { p.strokeWeight(1.5); p.line(sx(0), area.y, sx(0), area.y + area.h); }
  p.pop();
  if (lo < 0 && hi > 0) label(p, 'eye, t = 0', sx(0) + 6, area.y + 12, { color: MUTED, align: 'left', size: 12 });
  for (const t of niceTicks(lo, hi, 6)) {
    p.push(); p.stroke(INK); p.strokeWeight(1); p.line(sx(t), sy(0) - 4, sx(t), sy(0) + 4); p.pop();
    label(p, formatLabel(t, Math.abs(hi - lo) < 5 ? 1 : 0), sx(t), sy(0) - 10, { color: MUTED, size: 11 });
  }
  label(p, 't →', area.x + area.w - 6, sy(0) - 12, { color: INK, align: 'right', bold: true });
}

/** The parabola itself, 160 segments, held just outside the plot. */
function drawCurve(p, { lo, hi, sx, sy }, area, { f }) {
  p.push();
  p.noFill(); p.stroke(CONSTRUCT); p.strokeWeight(3);
  p.beginShape();
  for (let i = 0; i <= 160; i++) {
    const t = lo + ((hi - lo) * i) / 160;
    p.vertex(sx(t), Math.max(area.y - 10, Math.min(area.y + area.h + 10, sy(f(t)))));
  }
  p.endShape();
  p.pop();
}

/** The vertex and the roots, marked and labelled; a root at t ≤ 0 is behind the eye. */
function drawVertexAndRoots(p, { sx, sy }, { roots, t0, t1, tv, fv }) {
  dot(p, sx(tv), sy(fv), 5, CONSTRUCT);
  label(p, `vertex: t = −B/2A = ${formatLabel(tv)}, f = ${formatLabel(fv)}`, sx(tv), sy(fv) + 18, { color: CONSTRUCT, size: 12, bold: true });
  if (roots > 0) {
    const pts = roots === 1 ? [[t0, 't0 = t1']] : [[t0, 't0'], [t1, 't1']];
    for (const [t, name] of pts) {
      dot(p, sx(t), sy(0), 7, t > 0 ? RAY : MUTED);
      label(p, `${name} = ${formatLabel(t)}${t <= 0 ? ' (behind)' : ''}`, sx(t), sy(0) - 18, { color: t > 0 ? RAY : MUTED, bold: true });
    }
  }
}
