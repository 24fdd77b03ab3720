/**
 * The tracer view's overlay: a canvas over the picture (never the picture
 * itself, so a screenshot or a saved PNG holds the traced pixels alone) with
 * the pixel grid, the pixel being traced and the selected pixel's crosshair.
 *
 * `k` is overlay pixels per traced pixel. The geometry (where each line goes)
 * is in small pure functions; the painting functions only stroke it.
 */

/** On-screen pixels per traced pixel below which the grid would hide the picture. */
export const GRID_MIN_SCALE = 6;

/** Colours of the marks: the pixel being traced, the selected pixel. */
const TRACING_COLOR = '#ffd400';
const SELECTED_COLOR = '#ffffff';

/**
 * Paints the whole overlay: clears it, then the grid (when on and the pixels
 * are big enough), the pixel being traced, the selected pixel.
 * @param {CanvasRenderingContext2D} g the overlay's context (its canvas is the overlay's size)
 * @param {object} marks
 * @param {number} marks.width the traced image's width in pixels
 * @param {number} marks.height the traced image's height in pixels
 * @param {boolean} marks.grid the grid is on
 * @param {{x: number, y: number}|null} marks.current the pixel being traced, or null
 * @param {{x: number, y: number}|null} marks.selected the selected pixel, or null
 */
export function drawOverlay(g, { width, height, grid, current, selected }) {
  const W = g.canvas.width, H = g.canvas.height;
  const k = W / width;
  g.clearRect(0, 0, W, H);
  if (grid && k >= GRID_MIN_SCALE) drawGrid(g, width, height, k);
  if (current) outlinePixel(g, current.x, current.y, k, TRACING_COLOR, markWidth(k));
  if (selected) drawCrosshair(g, selected.x, selected.y, k, W, H);
}

/** The width of a pixel's outline: thicker on bigger pixels, never under 2. */
export function markWidth(k) {
  return Math.max(2, Math.round(k / 8));
}

/**
 * Where the grid's lines go: between pixels, on whole overlay pixels plus a
 * half (a 1-px line then covers one row of device pixels, crisp). None on the edges.
 * @returns {{ xs: number[], ys: number[] }}
 */
export function gridLines(w, h, k) {
  const xs = [], ys = [];
  for (let x = 1; x < w; x++) xs.push(Math.round(x * k) + 0.5);
  for (let y = 1; y < h; y++) ys.push(Math.round(y * k) + 0.5);
  return { xs, ys };
}

/**
 * The square stroked around pixel (x, y) with a line `lineWidth` wide: just
 * outside the pixel, so the pixel's own colour stays in view.
 * @returns {{ left: number, top: number, size: number }} strokeRect's arguments
 */
export function pixelSquare(x, y, k, lineWidth) {
  const X = Math.round(x * k), Y = Math.round(y * k), K = Math.max(1, Math.round(k));
  return { left: X - lineWidth / 2 - 0.5, top: Y - lineWidth / 2 - 0.5, size: K + lineWidth + 1 };
}

/**
 * The crosshair's four hair lines, `[x0, y0, x1, y1]` each: from the overlay's
 * edges (W × H) toward the centre of pixel (x, y), stopping short of it so the
 * pixel and its outline stay clear.
 * @returns {number[][]}
 */
export function crosshairArms(x, y, k, W, H) {
  const cx = (x + 0.5) * k, cy = (y + 0.5) * k, gap = k / 2 + Math.max(6, k * 0.6);
  return [
    [0, cy, cx - gap, cy],
    [cx + gap, cy, W, cy],
    [cx, 0, cx, cy - gap],
    [cx, cy + gap, cx, H],
  ];
}

function drawGrid(g, w, h, k) {
  const { xs, ys } = gridLines(w, h, k);
  g.save();
  g.beginPath();
  for (const X of xs) { g.moveTo(X, 0); g.lineTo(X, h * k); }
  for (const Y of ys) { g.moveTo(0, Y); g.lineTo(w * k, Y); }
  g.strokeStyle = 'rgba(0, 0, 0, 0.22)';
  g.lineWidth = 1;
  g.stroke();
  g.restore();
}

/** A square around pixel (x, y): a dark and a light stroke, visible on any colour. */
function outlinePixel(g, x, y, k, color, width) {
  const { left, top, size } = pixelSquare(x, y, k, width);
  g.save();
  g.lineWidth = width + 2;
  g.strokeStyle = 'rgba(0, 0, 0, 0.85)';
  g.strokeRect(left, top, size, size);
  g.lineWidth = width;
  g.strokeStyle = color;
  g.strokeRect(left, top, size, size);
  g.restore();
}

/** Hair lines from the edges toward the selected pixel, stopping short of it, and a box around it. */
function drawCrosshair(g, x, y, k, W, H) {
  g.save();
  g.beginPath();
  for (const [x0, y0, x1, y1] of crosshairArms(x, y, k, W, H)) { g.moveTo(x0, y0); g.lineTo(x1, y1); }
  g.lineWidth = 3;
  g.strokeStyle = 'rgba(0, 0, 0, 0.45)';
  g.stroke();
  g.lineWidth = 1;
  g.strokeStyle = 'rgba(255, 255, 255, 0.9)';
  g.stroke();
  g.restore();
  outlinePixel(g, x, y, k, SELECTED_COLOR, markWidth(k));
}
