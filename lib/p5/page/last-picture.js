/**
 * The last good picture stays under the mistake panel, where it was, at its
 * size, whatever mistakes come next, until a version of the sketch sets up.
 *
 * A save swapped in place (hot-swap.js) takes copies of the traced canvases
 * before it removes the sketch; a save that reloads the page (a sketch that
 * cannot be swapped, a version that fails to load) writes them to
 * sessionStorage when the page goes away, and the reloaded page shows them
 * again if a mistake comes before its pictures. The copies are plain canvases
 * over the page (`data-sketchbook-ghost`), and the place each view had keeps
 * its size meanwhile (`data-sketchbook-held`): a parent sized by what it
 * holds (a column of a flex row) would shrink to nothing, the text after it
 * would move up under the copy, and a new view measuring its room there
 * ('auto' scale) would come back smaller than the picture it replaces.
 */
import { onMistake } from './error-panel.js';
import { isReload } from './keep-place.js';
import { registerAddon } from '../register.js';

const KEY = 'sketchbook:picture:';
/** The copies over the page (in it or not, during a swap). */
let ghosts = [];
/** Elements holding their size, with their style attribute before (null: none). */
let held = [];
/** A version of the sketch has set up on this page: its canvases are good pictures. */
let setUp = false;

/**
 * Copies of the last good pictures, to show while the sketch is away: the
 * copies already up when the version going out never set up (its canvases,
 * if any, are no good picture), else new copies of the traced canvases, the
 * room of each view held. Not yet in the page: showPictures puts them there.
 * @returns {HTMLCanvasElement[]}
 */
export function keepPictures() {
  if (ghosts.length === 0) {
    const canvases = [.../** @type {NodeListOf<HTMLCanvasElement>} */ (document.querySelectorAll('canvas[data-tracer]'))];
    ghosts = canvases.map((canvas) => ghost(box(canvas), getComputedStyle(canvas).imageRendering, canvas));
    holdRoom(canvases.map((canvas) => canvas.closest('[data-tracer-view]')?.parentElement));
  }
  setUp = false;
  ghosts.forEach((g) => g.remove());
  return ghosts;
}

/** Puts the copies over the page. */
export function showPictures() {
  document.body.append(...ghosts);
}

/** A version has set up: the page takes its own sizes again, and the copies go after its first preview. */
function settled() {
  setUp = true;
  try { sessionStorage.removeItem(storageKey()); } catch { /* storage off */ }
  releaseRoom();
  const going = ghosts;
  ghosts = [];
  if (going.length > 0) requestAnimationFrame(() => requestAnimationFrame(() => going.forEach((g) => g.remove())));
}

/**
 * `body` (a copy of the page's body) as it would be without the held sizes:
 * hot-swap.js compares the page with how it was before the sketch ran.
 * @param {HTMLElement} body
 */
export function withoutHolds(body) {
  const copies = body.querySelectorAll('[data-sketchbook-held]');
  held.filter(({ element }) => element.isConnected).forEach(({ style }, i) => { if (copies[i]) restoreStyle(copies[i], style); });
}

/* ---------------- the room ---------------- */

function holdRoom(parents, sizes = null) {
  releaseRoom();
  [...new Set(parents.filter(Boolean))].forEach((element, i) => {
    const size = sizes?.[i] ?? contentSize(element);
    held.push({ element, style: element.getAttribute('style') });
    element.dataset.sketchbookHeld = '';
    Object.assign(element.style, { minWidth: `${size[0]}px`, minHeight: `${size[1]}px` });
  });
}

/** The size min-width and min-height give an element its outer size now (of its content box, unless border-box). */
function contentSize(element) {
  const r = element.getBoundingClientRect(), style = getComputedStyle(element);
  const sum = (...sides) => (style.boxSizing === 'border-box' ? 0 : sides.reduce((total, side) => total + parseFloat(style[side]), 0));
  return [r.width - sum('paddingLeft', 'paddingRight', 'borderLeftWidth', 'borderRightWidth'),
    r.height - sum('paddingTop', 'paddingBottom', 'borderTopWidth', 'borderBottomWidth')];
}

function releaseRoom() {
  for (const { element, style } of held) restoreStyle(element, style);
  held = [];
}

function restoreStyle(element, style) {
  delete element.dataset.sketchbookHeld;
  if (style === null) element.removeAttribute('style');
  else element.setAttribute('style', style);
}

/* ---------------- the copies ---------------- */

/** The box of an element in the page (CSS px, from the page's top left). */
function box(element) {
  const r = element.getBoundingClientRect();
  return { left: r.left + window.scrollX, top: r.top + window.scrollY, width: r.width, height: r.height };
}

/** Where each copy is (its style says it too, but rounded). */
const places = new WeakMap();

/** A copy of `source` (a canvas or an image; none: drawn later) at `at` on the page. */
function ghost(at, imageRendering, source = null) {
  const copy = document.createElement('canvas');
  places.set(copy, at);
  if (source) draw(copy, source);
  copy.dataset.sketchbookGhost = '';
  copy.setAttribute('aria-hidden', 'true');
  Object.assign(copy.style, {
    position: 'absolute', left: `${at.left}px`, top: `${at.top}px`, width: `${at.width}px`, height: `${at.height}px`,
    imageRendering, pointerEvents: 'none',
  });
  return copy;
}

function draw(copy, source) {
  copy.width = source.width;
  copy.height = source.height;
  copy.getContext('2d').drawImage(source, 0, 0);
}

/* ---------------- across a reload ---------------- */

/** An element found again after a reload: by its id, else by its place among its parents' children. */
function pathOf(element) {
  const path = [];
  for (let e = element; e && e !== document.body; e = e.parentElement) {
    if (e.id) return { id: e.id, path };
    path.unshift([...e.parentElement.children].indexOf(e));
  }
  return { id: null, path };
}

/** The element pathOf found, on this page (null when the page has changed there). */
function findPath({ id, path }) {
  /** @type {Element|null} */
  let e = id ? document.getElementById(id) : document.body;
  for (const i of path) e = e?.children[i] ?? null;
  return /** @type {HTMLElement|null} */ (e);
}

/** The most a page's stored pictures may take in sessionStorage (characters of their data URLs). */
const STORED_MAX = 2_000_000;

/** When the page goes away: the pictures to show if the next load begins with a mistake. */
function storePictures() {
  const shown = ghosts.length > 0 ? ghosts : setUp ? [...document.querySelectorAll('canvas[data-tracer]')] : [];
  if (shown.length === 0) return; // no good picture on this page: the one stored before stays
  const at = (c) => places.get(c) ?? box(c);
  const pictures = shown.map((c) => ({ image: c.toDataURL(), at: at(c), rendering: getComputedStyle(c).imageRendering || c.style.imageRendering }));
  const parents = held.length > 0 ? held.map(({ element }) => element)
    : shown.map((c) => c.closest('[data-tracer-view]')?.parentElement).filter(Boolean);
  const room = parents.map((element) => ({ where: pathOf(element), size: contentSize(element) }));
  if (pictures.reduce((sum, { image }) => sum + image.length, 0) > STORED_MAX) return;
  try {
    sessionStorage.setItem(storageKey(), JSON.stringify({ pictures, room }));
  } catch { /* storage full or off: the next load shows no picture under its mistake */ }
}

/** After a reload, a mistake before any picture: the pictures of the page before, where they were. */
function showStoredPictures() {
  if (setUp || ghosts.length > 0 || document.querySelector('canvas[data-tracer]')) return;
  let stored;
  try { stored = JSON.parse(sessionStorage.getItem(storageKey()) ?? 'null'); } catch { stored = null; }
  if (!stored?.pictures?.length) return;
  const places = stored.room.map(({ where }) => findPath(where));
  holdRoom(places, stored.room.map(({ size }) => size));
  ghosts = stored.pictures.map(({ at, rendering, image }) => {
    const copy = ghost(at, rendering), img = new Image();
    img.onload = () => draw(copy, img);
    img.src = image; // a data: URL this page wrote: nothing from outside
    return copy;
  });
  showPictures();
}

function storageKey() {
  return KEY + location.pathname + location.search;
}

function install() {
  const flags = /** @type {any} */ (globalThis);
  if (typeof window === 'undefined' || typeof sessionStorage === 'undefined' || flags.__sketchbookLastPicture) return;
  flags.__sketchbookLastPicture = true;
  if (!isReload()) {
    try { sessionStorage.removeItem(storageKey()); } catch { /* storage off */ }
  }
  // Only the dev server reloads a page on a save (a built site's page is never live-coded): only there is it worth
  // storing. Its pages say so (scripts/vite-live-coding.js's classic script).
  if (flags.__sketchbookDevServer) window.addEventListener('pagehide', storePictures);
  onMistake(showStoredPictures);
  registerAddon((p5Class, fn, lifecycles) => { // p5 2.x or 1.x alike
    lifecycles.postsetup = settled;
  });
}

install();
