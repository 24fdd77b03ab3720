/**
 * Saves that keep your place. Saving a sketch file reloads its page (the
 * dev server's live reload), and a reload used to lose the selected pixel,
 * the visual mode, the values typed in the page's boxes and the scroll
 * position, so after every edit the teacher clicked the same pixel again.
 *
 * When the page goes away (pagehide: a live reload, or F5), its place is
 * written to sessionStorage; when it comes back by a reload, the place is
 * restored right after setup() (p5's postsetup), before the first picture
 * is done. A plain visit (a link, the address bar) starts fresh.
 *
 * The code wins over the place: a box or a view's mode is restored only if
 * the page had changed it from what setup() made, and setup() still makes
 * the same; so editing the camera's yaw in the sketch shows the new yaw, not
 * the old typed one. A page whose setup() failed (a mistake on the page)
 * keeps the place saved before it, for the reload that fixes it.
 */
import { registerAddon } from '../register.js';
import { pageViews } from './page-state.js';

const KEY = 'sketchbook:place:';
/** Inputs whose value is a place on the page (not buttons, files or secrets). */
const SKIPPED_TYPES = new Set(['button', 'submit', 'reset', 'image', 'file', 'password', 'hidden']);

/** What setup() made: each box's value and each view's mode, to tell a change on the page from a change in the code. */
let made = null;
/** The place saved before this reload, restored once setup() is done; null on a plain visit. */
let saved = null;
/** Ends the scrolling back under way, if any. */
let stopScrolling = () => {};

/** The page's place now: views (selection, mode), boxes, scroll. */
export function currentPlace() {
  return {
    views: pageViews().filter(isTracerView).map((view) => ({ selected: view.selected, mode: view.mode })),
    boxes: boxes().map(({ key, element }) => ({ key, value: valueOf(element) })),
    scroll: { x: window.scrollX, y: window.scrollY },
  };
}

/**
 * Puts the page back in `place`: values in boxes the page had changed (the
 * sketch hears them as `input` and `change` events, as if typed), the view's
 * modes it had changed, the selected pixels, the scroll position.
 * @param {ReturnType<typeof currentPlace> & { made?: object }} place
 */
export function restorePlace(place, now = madeNow()) {
  const before = place.made ?? { boxes: {}, modes: [] };
  for (const { key, value } of place.boxes ?? []) {
    const box = boxes().find((b) => b.key === key);
    if (!box || before.boxes[key] === undefined || before.boxes[key] === value) continue; // unchanged on the page
    if (now.boxes[key] !== before.boxes[key]) continue; // the code changed it: the code wins
    if (valueOf(box.element) === value) continue;
    setValue(box.element, value);
    box.element.dispatchEvent(new Event('input', { bubbles: true }));
    box.element.dispatchEvent(new Event('change', { bubbles: true }));
  }
  const views = pageViews().filter(isTracerView);
  (place.views ?? []).forEach((was, i) => {
    const view = views[i];
    if (!view) return;
    if (was.mode !== before.modes[i] && now.modes[i] === before.modes[i] && view.mode !== was.mode) {
      try { view.setMode(was.mode); } catch { /* a mode this kit no longer has */ }
    }
    const s = was.selected;
    if (s && s.x < view.width && s.y < view.height && (view.selected?.x !== s.x || view.selected?.y !== s.y)) view.select(s.x, s.y);
  });
  if (place.scroll) scrollBack(place.scroll);
}

/**
 * A save is swapping the sketch in place (hot-swap.js): the place now is
 * restored after the new setup(), as after a reload, and written for the
 * reload that follows if the swap fails. A page whose setup() had failed
 * keeps the place from before its mistake.
 */
export function keepPlaceForSwap() {
  stopScrolling(); // the new sketch scrolls back again
  if (made) {
    saved = { ...currentPlace(), made };
    try { sessionStorage.setItem(storageKey(), JSON.stringify(saved)); } catch { /* storage full or off */ }
  }
  made = null; // until the new setup() is done: the pagehide of a failed swap keeps this place
}

/** Each view's mode and each box's value as setup() left them. */
function madeNow() {
  const boxesMade = {};
  for (const { key, element } of boxes()) boxesMade[key] = valueOf(element);
  return { boxes: boxesMade, modes: pageViews().filter(isTracerView).map((view) => view.mode) };
}

/** The page's boxes, each with a key that finds it again after a reload: its id, else its name and place in the page. */
function boxes() {
  const counts = new Map();
  return [.../** @type {NodeListOf<HTMLInputElement>} */ (document.querySelectorAll('input, select, textarea'))]
    .filter((element) => !SKIPPED_TYPES.has(element.type) && !element.closest('[data-error]'))
    .map((element) => {
      let key = element.id ? `#${element.id}` : `${element.tagName}:${element.name}:${element.type}`;
      if (!element.id) {
        const n = counts.get(key) ?? 0;
        counts.set(key, n + 1);
        key += `:${n}`;
      }
      return { key, element };
    });
}

function valueOf(element) {
  return element.type === 'checkbox' || element.type === 'radio' ? element.checked : element.value;
}

function setValue(element, value) {
  if (element.type === 'checkbox' || element.type === 'radio') element.checked = Boolean(value);
  else element.value = String(value);
}

function isTracerView(view) {
  return typeof view?.select === 'function' && typeof view.setMode === 'function';
}

/** Scrolls back now and once the page has grown (pictures and panels laid out), unless the reader scrolled first. */
function scrollBack({ x, y }) {
  window.scrollTo(x, y);
  let tries = 0;
  const reader = new AbortController(); // its listeners go once the scrolling is over: a swap (hot-swap.js) restores again and again
  const again = () => {
    if ((window.scrollY === y && window.scrollX === x) || tries === Infinity) return reader.abort();
    window.scrollTo(x, y);
    if (++tries < 30) requestAnimationFrame(again);
    else reader.abort();
    return undefined;
  };
  requestAnimationFrame(again);
  const stop = () => { tries = Infinity; reader.abort(); };
  stopScrolling = stop;
  window.addEventListener('wheel', stop, { once: true, passive: true, signal: reader.signal });
  window.addEventListener('keydown', stop, { once: true, signal: reader.signal });
}

/** Was this page load a reload (F5, or the dev server's live reload)? */
export function isReload() {
  const navigation = /** @type {PerformanceNavigationTiming|undefined} */ (performance.getEntriesByType?.('navigation')[0]);
  return navigation?.type === 'reload';
}

function storageKey() {
  return KEY + location.pathname + location.search;
}

function install() {
  const flags = /** @type {any} */ (globalThis);
  if (typeof window === 'undefined' || typeof sessionStorage === 'undefined' || flags.__sketchbookKeepPlace) return;
  flags.__sketchbookKeepPlace = true;
  if (isReload()) {
    try { saved = JSON.parse(sessionStorage.getItem(storageKey()) ?? 'null'); } catch { saved = null; }
  }
  window.addEventListener('pagehide', () => {
    if (!made) return; // setup() never finished: keep the place saved before, for the reload that fixes it
    try {
      sessionStorage.setItem(storageKey(), JSON.stringify({ ...currentPlace(), made }));
    } catch { /* storage full or off: the next load starts fresh */ }
  });
  registerAddon((p5Class, fn, lifecycles) => {
    lifecycles.postsetup = function () {
      const now = madeNow();
      if (saved) {
        restorePlace(saved, now);
        saved = null;
      }
      made = now;
    };
  });
}

install();
