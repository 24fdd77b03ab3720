/** Labels: text with a halo, and a placer that keeps labels out of each other's way. */
import { INK, PAPER, FONT, SIZE } from './style.js';

/**
 * What it costs a label to sit on a mark: on a label or a glyph (the eye, a
 * light, a dot) it is unreadable, across a thick line (the ray, a shadow
 * ray) hard to read, inside a shape (a sphere) it seems to name the shape,
 * across a thin line (the frustum, an outline) it is a pity.
 */
export const ON_LABEL = 1000;
export const ON_THICK = 30;
export const ON_FILL = 10;
export const ON_THIN = 1;
const LATER = 1; // what each place down a label's list costs (unless put says): a later place must be clearly better
const OUTSIDE = 1e6; // cut by the edge of the area

/**
 * Labels that keep out of each other's way inside `area`. Marks are
 * registered first (`keepClear…`, each with what sitting on it costs), then
 * `put` draws a label at the cheapest of its places, in list order: the
 * first free place when there is one, else a later one only when it costs
 * clearly less (`later`: what one step down the list costs; small for
 * places all as good as each other). A place is
 * [x, y, align = 'center', valign = 'middle'], the anchor of the label's
 * box as for canvas text. A label put is itself a mark (ON_LABEL), with
 * `spacing` px kept free left and right of it, so that two labels side by
 * side never read as one. An optional label is left out when every place
 * would cover a label or leave the area. `put` returns the box it took, or
 * null; `find` and `take` do the same for any box (a card).
 */
export function labelPlacer(p, area, { spacing = 0 } = {}) {
  const marks = [];
  const inside = (a) => a.x >= area.x && a.y >= area.y && a.x + a.w <= area.x + area.w && a.y + a.h <= area.y + area.h;
  // what a box costs, counted only up to `limit` (a cheaper place is known)
  const cost = (a, limit = Infinity) => {
    let sum = inside(a) ? 0 : OUTSIDE;
    for (let i = 0; i < marks.length && sum < limit; i++) if (marks[i].hits(a)) sum += marks[i].weight;
    return sum;
  };
  const placer = {
    keepClear(x, y, w, h, weight = ON_LABEL) {
      marks.push({ weight, hits: (a) => overlaps(a, { x, y, w, h }) });
    },
    /** A line labels should not sit on, `pad` px either side of it. */
    keepClearLine(xa, ya, xb, yb, weight = ON_LABEL, pad = 1.5) {
      marks.push({ weight, hits: (a) => segmentNearBox(xa, ya, xb, yb, a, pad) });
    },
    /** A polyline ([[x, y], …]), as one mark; only its stretches near the area count. */
    keepClearPath(points, weight = ON_LABEL, pad = 1.5) {
      const near = { x: area.x - pad, y: area.y - pad, w: area.w + 2 * pad, h: area.h + 2 * pad };
      const segments = [];
      for (let i = 1; i < points.length; i++) {
        const [xa, ya] = points[i - 1], [xb, yb] = points[i];
        if (segmentHitsBox(xa, ya, xb, yb, near)) segments.push([xa, ya, xb, yb]);
      }
      if (segments.length) marks.push({ weight, hits: (a) => segments.some(([xa, ya, xb, yb]) => segmentNearBox(xa, ya, xb, yb, a, pad)) });
    },
    /** A circle's outline (a ring `pad` px either side), or with `disc` the whole disc. */
    keepClearCircle(cx, cy, r, weight = ON_LABEL, { disc = false, pad = 1.5 } = {}) {
      marks.push({ weight, hits: (a) => circleHitsBox(cx, cy, r, a, disc, pad) });
    },
    /** The best box of size w × h at `places`, with its cost, or null when there are no places. */
    find(w, h, places, later = LATER) {
      let best = null, bestCost = Infinity;
      places.forEach((place, i) => {
        const b = boxAt(place, w, h), c = cost(b, bestCost - i * later) + i * later;
        if (c < bestCost) { best = b; bestCost = c; }
      });
      return best && { box: best, cost: bestCost };
    },
    /** Marks `box` as taken, as a label's is (with `spacing` beside it). */
    take(box) {
      const room = { x: box.x - spacing, y: box.y, w: box.w + 2 * spacing, h: box.h };
      marks.push({ weight: ON_LABEL, hits: (a) => overlaps(a, room) });
    },
    put(text, places, style = {}, { optional = false, later = LATER } = {}) {
      const { w, h, rows } = measure(p, text, style);
      const found = placer.find(w, h, places, later);
      if (!found || (optional && found.cost >= ON_LABEL)) return null;
      placer.take(found.box);
      drawRows(p, rows, found.box, style);
      return found.box;
    },
  };
  return placer;
}

/**
 * Places beside a round mark of radius `r` at (x, y), `gap` px off it, in
 * the order asked: 'above', 'below', 'left', 'right', 'above left',
 * 'above right', 'below left', 'below right'.
 */
export function around(x, y, r, gap, sides) {
  const d = r + gap, k = d * Math.SQRT1_2, m = 3; // m: a box reaches 3 px past its anchor on the aligned side
  const at = {
    above: [x, y - d, 'center', 'bottom'], below: [x, y + d, 'center', 'top'],
    left: [x - d - m, y, 'right', 'middle'], right: [x + d + m, y, 'left', 'middle'],
    'above left': [x - k - m, y - k, 'right', 'bottom'], 'above right': [x + k + m, y - k, 'left', 'bottom'],
    'below left': [x - k - m, y + k, 'right', 'top'], 'below right': [x + k + m, y + k, 'left', 'top'],
  };
  return sides.map((side) => at[side]);
}

/** All eight sides of `around`, those facing (dx, dy) first. */
export function sidesToward(dx, dy) {
  const dirs = { above: [0, -1], below: [0, 1], left: [-1, 0], right: [1, 0], 'above left': [-1, -1], 'above right': [1, -1], 'below left': [-1, 1], 'below right': [1, 1] };
  const score = ([u, v]) => (u * dx + v * dy) / Math.hypot(u, v);
  return Object.keys(dirs).sort((a, b) => score(dirs[b]) - score(dirs[a]));
}

/**
 * A label's rows and size: `text` is a string, or rows [[text, style], …]
 * drawn one under the other (each row's style over the label's).
 */
function measure(p, text, style) {
  const rows = (Array.isArray(text) ? text : [[text, {}]]).map(([t, s]) => ({ text: t, style: { ...style, ...s }, w: 0, h: 0 }));
  const ctx = p.drawingContext;
  ctx.save();
  for (const row of rows) {
    const size = row.style.size ?? SIZE;
    ctx.font = `${row.style.bold ? 'bold ' : ''}${size}px ${FONT}`;
    row.w = ctx.measureText(row.text).width + 6;
    row.h = size * 1.25;
  }
  ctx.restore();
  return { rows, w: Math.max(...rows.map((r) => r.w)), h: rows.reduce((s, r) => s + r.h, 0) };
}

function boxAt([x, y, align = 'center', valign = 'middle'], w, h) {
  return {
    x: align === 'left' ? x - 3 : align === 'right' ? x - w + 3 : x - w / 2,
    y: valign === 'top' ? y : valign === 'bottom' ? y - h : y - h / 2,
    w, h, align,
  };
}

function drawRows(p, rows, box, style) {
  const x = box.align === 'left' ? box.x + 3 : box.align === 'right' ? box.x + box.w - 3 : box.x + box.w / 2;
  let y = box.y;
  for (const row of rows) {
    label(p, row.text, x, y + row.h / 2, { ...style, ...row.style, align: box.align });
    y += row.h;
  }
}

function overlaps(a, b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

/** Whether the segment passes closer than `pad` to the box. */
function segmentNearBox(xa, ya, xb, yb, b, pad) {
  if (Math.max(xa, xb) <= b.x - pad || Math.min(xa, xb) >= b.x + b.w + pad || Math.max(ya, yb) <= b.y - pad || Math.min(ya, yb) >= b.y + b.h + pad) return false;
  if (segmentHitsBox(xa, ya, xb, yb, b)) return true;
  const corners = [[b.x, b.y], [b.x + b.w, b.y], [b.x, b.y + b.h], [b.x + b.w, b.y + b.h]];
  return pointToBox(xa, ya, b) < pad || pointToBox(xb, yb, b) < pad || corners.some(([x, y]) => pointToSegment(x, y, xa, ya, xb, yb) < pad);
}

/** Whether the segment crosses the box (Liang–Barsky clipping). */
function segmentHitsBox(xa, ya, xb, yb, b) {
  const dx = xb - xa, dy = yb - ya;
  let t0 = 0, t1 = 1;
  for (const [q, r] of [[-dx, xa - b.x], [dx, b.x + b.w - xa], [-dy, ya - b.y], [dy, b.y + b.h - ya]]) {
    if (q === 0) { if (r < 0) return false; continue; }
    const t = r / q;
    if (q < 0) t0 = Math.max(t0, t); else t1 = Math.min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

function pointToBox(x, y, b) {
  return Math.hypot(Math.max(b.x - x, 0, x - b.x - b.w), Math.max(b.y - y, 0, y - b.y - b.h));
}

function pointToSegment(x, y, xa, ya, xb, yb) {
  const dx = xb - xa, dy = yb - ya, len2 = dx * dx + dy * dy;
  const t = len2 ? Math.max(0, Math.min(1, ((x - xa) * dx + (y - ya) * dy) / len2)) : 0;
  return Math.hypot(x - xa - t * dx, y - ya - t * dy);
}

function circleHitsBox(cx, cy, r, b, disc, pad) {
  const nx = Math.max(b.x, Math.min(cx, b.x + b.w)) - cx, ny = Math.max(b.y, Math.min(cy, b.y + b.h)) - cy;
  if (disc) return Math.hypot(nx, ny) < r;
  if (Math.hypot(nx, ny) >= r + pad) return false; // wholly outside the ring
  const fx = Math.max(Math.abs(b.x - cx), Math.abs(b.x + b.w - cx)), fy = Math.max(Math.abs(b.y - cy), Math.abs(b.y + b.h - cy));
  return Math.hypot(fx, fy) > r - pad; // not wholly inside the ring
}

/**
 * Text with a white halo, so a label stays readable over lines and fills.
 * Drawn on the canvas context directly: p5's text() would stroke over the fill.
 */
export function label(p, text, x, y, { color = INK, size = SIZE, align = 'center', bold = false, halo = true, box = false } = {}) {
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
