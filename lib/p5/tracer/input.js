/**
 * The tracer view's input: press on the picture (or press and drag, to scrub
 * across pixels and watch the numbers change) to select a pixel; the arrow
 * keys move the selection, Shift+arrow ten pixels at a time. Pixel
 * coordinates are the traced image's, whatever the canvas's on-screen size.
 */
import { clamp } from '../../math/numbers.js';

/** Each arrow key's step, [dx, dy] in traced pixels (y grows downward). */
const ARROWS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
/** Pixels one Shift+arrow moves. */
const SHIFT_STEP = 10;

/**
 * The traced-image pixel under a point on screen, whatever the canvas's
 * on-screen size: client coordinates → share of the canvas's box → pixel.
 * Points outside the canvas give its nearest edge pixel.
 * @param {{ getBoundingClientRect(): { left: number, top: number, width: number, height: number } }} canvas
 */
export function pixelAt(canvas, clientX, clientY, width, height) {
  const box = canvas.getBoundingClientRect();
  const x = Math.floor(((clientX - box.left) / box.width) * width);
  const y = Math.floor(((clientY - box.top) / box.height) * height);
  return { x: clamp(x, 0, width - 1), y: clamp(y, 0, height - 1) };
}

/**
 * Where a key moves the selection in a width × height picture: one pixel per
 * arrow (ten with Shift), stopping at the edges; from nothing selected, the
 * first press selects the middle pixel. Null for a key that is no arrow.
 * @param {string} key a keyboard event's `key`
 * @param {boolean} shift Shift is held
 * @param {{x: number, y: number}|null} selected
 * @returns {{x: number, y: number}|null}
 */
export function arrowMove(key, shift, selected, width, height) {
  const step = ARROWS[key];
  if (!step) return null;
  const n = shift ? SHIFT_STEP : 1;
  const s = selected ?? { x: Math.floor(width / 2) - step[0] * n, y: Math.floor(height / 2) - step[1] * n };
  return { x: clamp(s.x + step[0] * n, 0, width - 1), y: clamp(s.y + step[1] * n, 0, height - 1) };
}

/**
 * Listens on a tracer view's canvas for presses, drags and arrow keys, and
 * selects the pixel they point at with `view.select(x, y)`.
 * @param {HTMLCanvasElement} canvas the picture (focusable: tabindex)
 * @param {{ width: number, height: number, selected: {x: number, y: number}|null, select(x: number, y: number): unknown }} view
 */
export function listenForPixels(canvas, view) {
  let pointer = { x: NaN, y: NaN }; // where the pointer last picked, in client coordinates
  const pick = (event) => {
    pointer = { x: event.clientX, y: event.clientY };
    const { x, y } = pixelAt(canvas, event.clientX, event.clientY, view.width, view.height);
    const s = view.selected;
    if (x !== s?.x || y !== s?.y) view.select(x, y);
  };
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return; // the browser focuses the canvas itself (tabindex), for the arrow keys
    canvas.setPointerCapture?.(event.pointerId);
    pick(event);
  });
  canvas.addEventListener('pointermove', (event) => {
    // Chromium also sends a move when the page reflows under a still pointer (the
    // panel filling in beside the picture): that is no drag, and must not re-pick.
    const moved = event.clientX !== pointer.x || event.clientY !== pointer.y;
    if (moved && event.buttons & 1 && canvas.hasPointerCapture?.(event.pointerId)) pick(event);
  });
  canvas.addEventListener('keydown', (event) => {
    const next = arrowMove(event.key, event.shiftKey, view.selected, view.width, view.height);
    if (!next) return;
    event.preventDefault(); // the page must not scroll
    view.select(next.x, next.y);
  });
}
