/**
 * The tracer view's size on screen: how many screen pixels each traced pixel
 * gets, and the picture and its overlay sized to match. Whole numbers keep
 * every traced pixel the same size, so "pixel 10,12" is a square a class can
 * point at.
 */
import { show } from '../check.js';

/**
 * 'auto' scale: the picture fits its parent's width, 40rem, 70% of the
 * window's height, and leaves 34rem of the window's width for a panel beside
 * it (so that at 1024×768 the inspector still sits next to the picture).
 * Sizes are in rem so that the picture grows with the page's text on a big
 * screen (sketch.css sets the root font size from the window's width).
 */
const AUTO_MAX_WIDTH_REM = 40;
const AUTO_PANEL_ROOM_REM = 34;
const AUTO_MAX_HEIGHT_SHARE = 0.7;
/** Below this much room beside the panel (in rem), the panel goes below the picture instead. */
const AUTO_MIN_BESIDE_REM = 20;
/** The size of text a numeric `scale` is given for: the browser's default rem. */
export const BASE_REM = 16;

/** A tracer view's `scale` option: 'auto' or a number greater than 0, else a RangeError. */
export function checkScale(scale) {
  if (scale === 'auto') return scale;
  if (typeof scale !== 'number' || !Number.isFinite(scale) || scale <= 0) {
    throw new RangeError(`scale must be 'auto' or a number greater than 0, got ${show(scale)}`);
  }
  return scale;
}

/**
 * A numeric scale on the page: it is for 16 px text; larger text (a projector)
 * makes the pixels larger, in whole steps when the scale is a whole number.
 * @param {number} scale screen pixels per traced pixel with 16 px text
 * @param {number} rem the page's root font size in px
 */
export function fixedScale(scale, rem) {
  const s = scale * (rem / BASE_REM);
  return Number.isInteger(scale) ? Math.max(1, Math.round(s)) : s;
}

/**
 * The 'auto' scale: the largest whole number of screen pixels per traced
 * pixel that fits the room (a fraction when even 1 does not fit).
 * @param {number} width the traced image's width
 * @param {number} height the traced image's height
 * @param {{ rem: number, parentWidth?: number, windowWidth: number, windowHeight: number }} room
 *   the root font size, the width of the view's parent (0 or none: unknown), the window's size, in px
 */
export function fitScale(width, height, { rem, parentWidth, windowWidth, windowHeight }) {
  const available = parentWidth || AUTO_MAX_WIDTH_REM * rem;
  const besidePanel = windowWidth - AUTO_PANEL_ROOM_REM * rem; // on a narrow screen the panel goes below instead
  const maxW = Math.min(available, AUTO_MAX_WIDTH_REM * rem, besidePanel >= AUTO_MIN_BESIDE_REM * rem ? besidePanel : Infinity);
  const maxH = windowHeight * AUTO_MAX_HEIGHT_SHARE;
  const fit = Math.min(maxW / width, maxH / height);
  return fit >= 1 ? Math.floor(fit) : fit; // whole numbers keep every pixel the same size
}

/**
 * Screen pixels per traced pixel for a view's `scale` on this page right now
 * (the page is measured only for 'auto').
 * @param {'auto'|number} scale
 * @param {number} width the traced image's width
 * @param {number} height the traced image's height
 * @param {HTMLElement} figure the view's element, whose parent gives the room
 */
export function pictureScale(scale, width, height, figure) {
  const rem = rootFontSize();
  if (scale !== 'auto') return fixedScale(scale, rem);
  return fitScale(width, height, { rem, parentWidth: figure.parentElement?.clientWidth, windowWidth: window.innerWidth, windowHeight: window.innerHeight });
}

/**
 * Sizes the picture on screen (`s` screen pixels per traced pixel) and the
 * overlay to match, with as many canvas pixels as the screen has device
 * pixels there, so its lines are crisp.
 * @param {{ canvas: HTMLCanvasElement, overlay: HTMLCanvasElement, figure: HTMLElement }} parts
 * @param {number} width the traced image's width
 * @param {number} height the traced image's height
 * @param {number} s
 */
export function sizePicture({ canvas, overlay, figure }, width, height, s) {
  const cssW = width * s, cssH = height * s;
  canvas.style.width = `${cssW}px`;
  canvas.style.height = `${cssH}px`;
  const dpr = window.devicePixelRatio || 1;
  overlay.style.width = `${cssW}px`;
  overlay.style.height = `${cssH}px`;
  overlay.width = Math.round(cssW * dpr);
  overlay.height = Math.round(cssH * dpr);
  figure.style.setProperty('--rt-picture-width', `${cssW}px`);
}

/** The root element's font size in px (1rem). */
function rootFontSize() {
  return parseFloat(getComputedStyle(document.documentElement).fontSize) || BASE_REM;
}
