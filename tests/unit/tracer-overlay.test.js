// The tracer view's overlay: where the grid, the pixel outlines and the
// crosshair go, and what is painted when (into a context that records calls).
import { describe, it, expect } from 'vitest';
import { drawOverlay, gridLines, pixelSquare, crosshairArms, markWidth, GRID_MIN_SCALE } from '../../lib/p5/tracer/overlay.js';

/** A 2D context standing in for the overlay's: it records the calls that draw something. */
function recordingContext(width, height) {
  const calls = [];
  const g = { canvas: { width, height }, strokeStyle: '', lineWidth: 1 };
  for (const name of ['clearRect', 'strokeRect', 'moveTo', 'lineTo', 'beginPath', 'save', 'restore']) g[name] = (...args) => calls.push([name, ...args]);
  g.stroke = () => calls.push(['stroke', g.strokeStyle, g.lineWidth]);
  g.strokeRect = (...args) => calls.push(['strokeRect', g.strokeStyle, ...args]);
  return { g, calls, named: (name) => calls.filter((c) => c[0] === name) };
}

describe('overlay geometry', () => {
  it('puts grid lines between pixels, half a pixel into the overlay pixel, none on the edges', () => {
    expect(gridLines(3, 2, 10)).toEqual({ xs: [10.5, 20.5], ys: [10.5] });
    expect(gridLines(1, 1, 10)).toEqual({ xs: [], ys: [] });
  });

  it('rounds grid lines to whole overlay pixels when a traced pixel is not a whole number of them', () => {
    const { xs } = gridLines(4, 1, 7.5);
    expect(xs).toEqual([8.5, 15.5, 23.5]);
  });

  it('strokes a pixel square just outside the pixel, so its colour stays in view', () => {
    const k = 10, w = 2;
    const { left, top, size } = pixelSquare(3, 4, k, w);
    expect(left + w / 2).toBeLessThanOrEqual(3 * k);         // the stroke's inner edge is left of the pixel
    expect(top + w / 2).toBeLessThanOrEqual(4 * k);
    expect(left + size - w / 2).toBeGreaterThanOrEqual(4 * k); // and right of it
    expect(pixelSquare(3, 4, k, w)).toEqual({ left: 28.5, top: 38.5, size: 13 });
  });

  it('keeps a pixel square at least one overlay pixel wide when the picture is shown smaller than its pixels', () => {
    expect(pixelSquare(0, 0, 0.25, 2).size).toBe(1 + 2 + 1);
  });

  it('draws the crosshair from the four edges toward the pixel, stopping short of its outline', () => {
    const k = 20, W = 200, H = 100;
    const arms = crosshairArms(4, 2, k, W, H);
    const cx = 4.5 * k, cy = 2.5 * k;
    expect(arms).toHaveLength(4);
    const [left, right, up, down] = arms;
    expect(left.slice(0, 2)).toEqual([0, cy]);
    expect(right.slice(2)).toEqual([W, cy]);
    expect(up.slice(0, 2)).toEqual([cx, 0]);
    expect(down.slice(2)).toEqual([cx, H]);
    const square = pixelSquare(4, 2, k, markWidth(k));
    expect(left[2]).toBeLessThan(square.left);
    expect(right[0]).toBeGreaterThan(square.left + square.size);
    expect(up[3]).toBeLessThan(square.top);
    expect(down[1]).toBeGreaterThan(square.top + square.size);
  });

  it('keeps the crosshair clear of a small pixel too (a gap of at least 6 overlay pixels)', () => {
    const [left] = crosshairArms(10, 10, 2, 100, 100);
    expect((10.5 * 2) - left[2]).toBeGreaterThanOrEqual(6);
  });

  it('makes outlines thicker on bigger pixels, never thinner than 2', () => {
    expect(markWidth(1)).toBe(2);
    expect(markWidth(16)).toBe(2);
    expect(markWidth(40)).toBe(5);
  });
});

describe('drawOverlay', () => {
  const marks = { width: 4, height: 3, grid: false, current: null, selected: null };

  it('clears the whole overlay and draws nothing when there is nothing to mark', () => {
    const { g, calls } = recordingContext(40, 30);
    drawOverlay(g, marks);
    expect(calls).toEqual([['clearRect', 0, 0, 40, 30]]);
  });

  it('draws the grid only when it is on and the pixels are big enough to keep it from hiding the picture', () => {
    const big = recordingContext(4 * GRID_MIN_SCALE, 3 * GRID_MIN_SCALE);
    drawOverlay(big.g, { ...marks, grid: true });
    expect(big.named('moveTo')).toHaveLength(3 + 2);
    const small = recordingContext(4 * (GRID_MIN_SCALE - 1), 3 * (GRID_MIN_SCALE - 1));
    drawOverlay(small.g, { ...marks, grid: true });
    expect(small.named('moveTo')).toHaveLength(0);
  });

  it('outlines the pixel being traced in yellow and the selected one in white, each over a dark stroke', () => {
    const { g, named } = recordingContext(40, 30);
    drawOverlay(g, { ...marks, current: { x: 1, y: 1 }, selected: { x: 2, y: 0 } });
    const rects = named('strokeRect');
    expect(rects.map((r) => r[1])).toEqual(['rgba(0, 0, 0, 0.85)', '#ffd400', 'rgba(0, 0, 0, 0.85)', '#ffffff']);
    const { left, top, size } = pixelSquare(1, 1, 10, markWidth(10));
    expect(rects[1].slice(2)).toEqual([left, top, size, size]);
    expect(named('lineTo')).toHaveLength(4); // the crosshair's arms
  });
});
