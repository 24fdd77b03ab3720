/**
 * The tracer view's size on screen: how many screen pixels each traced pixel
 * gets, and the picture and its overlay sized to match. Whole numbers keep
 * every traced pixel the same size, so "pixel 10,12" is a square a class can
 * point at.
 */
import { show } from '../../text/check.js';

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
 * On a big screen (text larger than 16 px: a window wider than 1455 px, or
 * Projector) a numeric scale grows until the picture takes this share of the
 * window's width or of its height, whichever comes first.
 */
const GROW_WIDTH_SHARE = 0.35;
const GROW_HEIGHT_SHARE = 0.5;
/** A picture shrunk to its room keeps whole screen pixels per traced pixel from this scale up. */
const MIN_WHOLE_SCALE = 2;

/**
 * A numeric scale in the room it has: `fixedScale`, grown on a big screen (see
 * GROW_WIDTH_SHARE), then shrunk to the room's width so that the page never
 * scrolls sideways (a phone, a zoomed page): whole numbers while at least 1 fits.
 * @param {number} scale screen pixels per traced pixel with 16 px text
 * @param {number} width the traced image's width
 * @param {number} height the traced image's height
 * @param {{ rem: number, width: number, windowWidth: number, windowHeight: number }} room
 *   the root font size, the width the picture may take, the window's size, in px
 */
export function cappedScale(scale, width, height, room) {
  let s = fixedScale(scale, room.rem);
  if (room.rem > BASE_REM) s = Math.max(s, grownScale(width, height, room));
  return Math.min(s, widthScale(width, room.width));
}

/** The smallest whole scale that reaches the big screen's share, at most what fits the room and 70% of the window's height. */
function grownScale(width, height, { width: roomWidth, windowWidth, windowHeight }) {
  const wanted = Math.ceil(Math.min((windowWidth * GROW_WIDTH_SHARE) / width, (windowHeight * GROW_HEIGHT_SHARE) / height));
  const most = Math.floor(Math.min(roomWidth / width, (windowHeight * AUTO_MAX_HEIGHT_SHARE) / height));
  return Math.min(wanted, most);
}

/**
 * The largest scale whose picture fits `roomWidth`: a whole number from 2 up;
 * below 2, the picture fills the room (160 px wide in 288 px: 1.8, not 1).
 */
function widthScale(width, roomWidth) {
  const fit = roomWidth / width;
  return fit >= MIN_WHOLE_SCALE ? Math.floor(fit) : fit;
}

/**
 * The room a view's picture has: its parent's content width, and never more
 * than the page's width right of the picture (less a margin as wide as the
 * one on its left, at most 1.5rem), so that a parent sized by its content
 * cannot push the page wider than the window.
 * @param {HTMLElement} figure the view's element
 */
export function roomFor(figure) {
  const rem = rootFontSize();
  const left = Math.max(0, figure.getBoundingClientRect().left + window.scrollX);
  const pageRoom = document.documentElement.clientWidth - left - Math.min(left, 1.5 * rem);
  const parentRoom = contentWidth(figure.parentElement);
  return { rem, width: Math.max(1, parentRoom ? Math.min(parentRoom, pageRoom) : pageRoom), windowWidth: window.innerWidth, windowHeight: window.innerHeight };
}

/** An element's width inside its padding; 0 when it has no box (display: contents). */
function contentWidth(el) {
  if (!el || !el.clientWidth) return 0;
  const style = getComputedStyle(el);
  return el.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
}

/**
 * Screen pixels per traced pixel for a view's `scale` on this page right now.
 * @param {'auto'|number} scale
 * @param {number} width the traced image's width
 * @param {number} height the traced image's height
 * @param {HTMLElement} figure the view's element, whose parent gives the room
 */
export function pictureScale(scale, width, height, figure) {
  const room = roomFor(figure);
  if (scale !== 'auto') return cappedScale(scale, width, height, room);
  return fitScale(width, height, { ...room, parentWidth: room.width });
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

/**
 * Calls `onChange` when the room of a view may have changed: the window's
 * size, or its parent's width (the columns beside it filled in, the page
 * reflowed). One call per frame at most, after layout, so that a picture
 * that changes its parent's width does not loop. Returns a function that stops.
 * @param {HTMLElement} figure the view's element
 * @param {() => void} onChange
 */
export function watchRoom(figure, onChange) {
  let frame = 0, lastWidth = -1;
  const later = () => { if (!frame) frame = requestAnimationFrame(() => { frame = 0; onChange(); }); };
  const parent = figure.parentElement;
  const observer = typeof ResizeObserver === 'function' && parent ? new ResizeObserver(() => {
    const w = parent.clientWidth;
    if (w !== lastWidth) { lastWidth = w; later(); }
  }) : null;
  observer?.observe(parent);
  window.addEventListener('resize', onChange);
  return () => {
    observer?.disconnect();
    window.removeEventListener('resize', onChange);
    cancelAnimationFrame(frame);
  };
}

/** The root element's font size in px (1rem). */
function rootFontSize() {
  return parseFloat(getComputedStyle(document.documentElement).fontSize) || BASE_REM;
}
