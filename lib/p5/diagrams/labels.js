/** Labels: text with a halo, and a placer that keeps labels out of each other's way. */
import { INK, PAPER, FONT, SIZE } from './style.js';

/**
 * Labels that keep out of each other's way inside `area`: `put` draws a label
 * at the first of its places (x, y, align) where it overlaps no label or mark
 * placed before; when none is free it is drawn at its first place, or left
 * out when optional. Returns whether it was drawn.
 */
export function labelPlacer(p, area) {
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
