/**
 * Saves swapped in place. The dev server (scripts/vite-live-coding.js,
 * swapSketchesInPlace) serves a page's own script with Vite's HMR hooks
 * calling swapOut() and swappedIn(); on a save the page then removes the
 * p5 instances the old version made (p.remove(): p5's elements, loop and
 * listeners; the kit's parts by their destroy()), checks that the page is
 * back to what it was before the sketch ran, and imports the new version,
 * which makes its own instance. No reload: the first coarse preview comes
 * within 100 ms of the save instead of 0.3–0.7 s.
 *
 * The place (selected pixels, modes, boxes, scroll) comes back as after a
 * reload (keep-place.js); a picture of the last good frame stays until the
 * new sketch has set up, and under the mistake panel if it cannot. Anything
 * that cannot be undone here reloads the page instead, as before: a sketch
 * in global mode, a page changed outside p5 (its body, head or title differ
 * from before the sketch ran), a new version that fails to load.
 *
 * Only imported by the dev server's hooks: a built site never loads it.
 */
import p5 from 'p5';
import { clearMistakes, sketchFrame } from './error-panel.js';
import { keepPlaceForSwap } from './keep-place.js';

/** The p5 instances on the page: the sketch's (its script imports nothing else that could make one). */
const instances = new Set();
/** Pictures of the last good frame, over the page while a swap is under way. */
let ghosts = [];
/** The page before the sketch ran, which every swap comes back to. */
let before = null;
/** Swaps so far: tests tell a swap from a reload by it. */
let swaps = 0;
/** Listeners added since the sketch began to the window, the document or the page's own elements, still there. */
const lasting = new Set();

/**
 * The page as the sketch can change it: body, head and title, less what the
 * kit adds once per page and keeps (its stylesheet, the Projector switch,
 * the mistake panel, body[data-render]).
 */
function pageNow() {
  const markup = new XMLSerializer(); // reads the page as text, parses nothing
  const body = /** @type {HTMLElement} */ (document.body.cloneNode(true));
  body.removeAttribute('data-render');
  body.querySelectorAll('[data-error], [data-sketchbook-ghost], [data-projector]').forEach((e) => e.remove());
  const copies = body.querySelectorAll('[data-sketchbook-held]'); // the widths holdRoom holds, as they were
  held.forEach((parent, i) => { if (copies[i]) restoreStyle(copies[i], heldStyles[i]); });
  const head = [...document.head.children]
    .filter((e) => !e.matches('link[data-sketchbook], style#p5-loading-style, style[data-vite-dev-id]'))
    .map((e) => markup.serializeToString(e));
  return JSON.stringify([document.title, head, markup.serializeToString(body)]);
}

/** Why the page cannot be swapped, or '' when it can. */
function whyNot() {
  if ([...instances].some((p) => /** @type {any} */ (p)._isGlobal)) return 'a sketch in global mode';
  return '';
}

/**
 * Watches listeners the sketch itself adds (its own line calls
 * addEventListener) to what a swap leaves in place: the window, the
 * document, the page's own elements. One still there after the swap would
 * call the old sketch, so the page reloads. A listener on an element the
 * swap removes goes with it; p5's and the kit's are theirs to take off.
 */
function watchListeners() {
  const stays = new Set(/** @type {EventTarget[]} */ ([window, document, ...document.querySelectorAll('*')]));
  const target = EventTarget.prototype, add = target.addEventListener, remove = target.removeEventListener;
  const captures = (options) => (typeof options === 'boolean' ? options : Boolean(options?.capture));
  target.addEventListener = function (type, listener, options) {
    add.call(this, type, listener, options);
    if (!listener || !stays.has(this) || !sketchFrame(String(new Error().stack).split('\n')[2], location.origin)) return;
    const entry = { on: this, type, listener, capture: captures(options) };
    lasting.add(entry);
    const forget = () => lasting.delete(entry);
    if (typeof options === 'object' && options?.signal) add.call(options.signal, 'abort', forget, { once: true });
    if (typeof options === 'object' && options?.once) add.call(this, type, forget, { once: true, capture: entry.capture });
  };
  target.removeEventListener = function (type, listener, options) {
    remove.call(this, type, listener, options);
    const capture = captures(options);
    for (const e of lasting) if (e.on === this && e.type === type && e.listener === listener && e.capture === capture) lasting.delete(e);
  };
}

/**
 * Vite's dispose hook of the old version: keeps the place, removes the
 * sketch and checks the page is as it was; else reloads it.
 */
export function swapOut() {
  keepPlaceForSwap();
  const why = whyNot();
  if (why) return reload(why);
  // Ghosts still up: the version going out never set up, and its canvases (if any) are no good picture; the last good one stays.
  const pictures = ghosts.length > 0 ? ghosts : [...document.querySelectorAll('canvas[data-tracer]')].map(ghostOf);
  if (ghosts.length === 0) holdRoom();
  for (const p of [...instances]) p.remove(); // its `remove` hook takes it out of the set
  clearMistakes();
  for (const ghost of pictures) ghost.remove(); // out of the page while it is compared with before
  delete document.body.dataset.render;
  if (lasting.size > 0) return reload(`the sketch still listens for ${[...lasting].map((e) => e.type).join(', ')} on the page`);
  if (pageNow() !== before) return reload('the sketch changed the page outside p5');
  ghosts = pictures;
  document.body.append(...ghosts);
  return undefined;
}

/**
 * Vite's accept hook: `next` is the new version's module, undefined when it
 * failed to load (an error at its top level, a missing import): the reload
 * then shows the mistake on the page, as before.
 * @param {object|undefined} next
 */
export function swappedIn(next) {
  if (!next) return reload('the new version did not load');
  swaps += 1;
  /** @type {any} */ (globalThis).__sketchbookSwaps = swaps;
  return undefined;
}

function reload(why) {
  console.info(`Reloading the page: ${why}.`);
  location.reload();
}

/** A copy of a traced canvas where it is on the page, to show until the new one is there. */
function ghostOf(canvas) {
  const ghost = document.createElement('canvas');
  ghost.width = canvas.width;
  ghost.height = canvas.height;
  ghost.getContext('2d').drawImage(canvas, 0, 0);
  const r = canvas.getBoundingClientRect();
  ghost.dataset.sketchbookGhost = '';
  ghost.setAttribute('aria-hidden', 'true');
  Object.assign(ghost.style, {
    position: 'absolute', left: `${r.left + window.scrollX}px`, top: `${r.top + window.scrollY}px`,
    width: `${r.width}px`, height: `${r.height}px`, imageRendering: getComputedStyle(canvas).imageRendering, pointerEvents: 'none',
  });
  return ghost;
}

function removeGhosts() {
  for (const ghost of ghosts) ghost.remove();
  ghosts = [];
}

/** Elements given a minimum width by holdRoom, to be given back, and their style attributes before (null: none). */
let held = [], heldStyles = [];

/**
 * While the sketch is away the page keeps its height (the scroll position
 * does not jump to the top) and each tracer view's parent keeps its size: a
 * parent sized by what it holds (a column of a flex row) would shrink to
 * nothing, the text after it would move up under the copy of the last
 * picture, and the new view, measuring its room there ('auto' scale), would
 * come back smaller than the picture it replaces.
 */
function holdRoom() {
  document.documentElement.style.minHeight = `${document.documentElement.scrollHeight}px`;
  held = [...new Set([...document.querySelectorAll('[data-tracer-view]')].map((figure) => figure.parentElement).filter(Boolean))];
  heldStyles = held.map((parent) => parent.getAttribute('style'));
  const sizes = held.map((parent) => {
    const box = parent.getBoundingClientRect(), style = getComputedStyle(parent);
    const sum = (...sides) => (style.boxSizing === 'border-box' ? 0 : sides.reduce((total, side) => total + parseFloat(style[side]), 0));
    // min-width and min-height are of the content box, unless border-box: the same outer size either way
    return [box.width - sum('paddingLeft', 'paddingRight', 'borderLeftWidth', 'borderRightWidth'),
      box.height - sum('paddingTop', 'paddingBottom', 'borderTopWidth', 'borderBottomWidth')];
  });
  held.forEach((parent, i) => {
    parent.dataset.sketchbookHeld = '';
    Object.assign(parent.style, { minWidth: `${sizes[i][0]}px`, minHeight: `${sizes[i][1]}px` });
  });
}

/** Gives an element held by holdRoom its style attribute back. */
function restoreStyle(e, style) {
  delete e.dataset.sketchbookHeld;
  if (style === null) e.removeAttribute('style');
  else e.setAttribute('style', style);
}

/** The new sketch has set up (its place restored by keep-place.js): the page may take its own height and widths again. */
function settle() {
  document.documentElement.style.minHeight = '';
  held.forEach((parent, i) => restoreStyle(parent, heldStyles[i]));
  held = [];
  heldStyles = [];
  if (ghosts.length > 0) requestAnimationFrame(() => requestAnimationFrame(removeGhosts)); // after its first preview
}

function install() {
  const flags = /** @type {any} */ (globalThis);
  if (typeof document === 'undefined' || flags.__sketchbookHotSwap) return;
  flags.__sketchbookHotSwap = true;
  before = pageNow(); // this module is the sketch's last import: the sketch itself has not run yet
  watchListeners();
  p5.registerAddon((p5Class, fn, lifecycles) => {
    lifecycles.presetup = function () { instances.add(this); };
    lifecycles.postsetup = settle;
    lifecycles.remove = function () { instances.delete(this); };
  });
}

install();
