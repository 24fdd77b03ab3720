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
 * new sketch has set up, and under the mistake panel if it cannot (last-picture.js). Anything
 * that cannot be undone here reloads the page instead, as before: a sketch
 * in global mode, a page changed outside p5 (its body, head or title differ
 * from before the sketch ran), a new version that fails to load.
 *
 * Only imported by the dev server's hooks: a built site never loads it.
 */
import p5 from 'p5';
import { clearMistakes, sketchFrame } from './error-panel.js';
import { keepPlaceForSwap } from './keep-place.js';
import { keepPictures, showPictures, withoutHolds } from './last-picture.js';

/** The p5 instances on the page: the sketch's (its script imports nothing else that could make one). */
const instances = new Set();
/** The page before the sketch ran, which every swap comes back to. */
let before = null;
/** Swaps so far: tests tell a swap from a reload by it. */
let swaps = 0;
/** Listeners added since the sketch began to the window, the document or the page's own elements, still there. */
const lasting = new Set();

/**
 * The page as the sketch can change it: body, head and title, less what the
 * kit adds once per page and keeps (its stylesheet, the Projector switch,
 * the mistake panel, body[data-render]; the code editor, whose text the student changes;
 * the page's one voice for screen readers, its "Skip to the picture" link, the name it
 * gives the page's <main> and the class board's bar, made once and kept).
 */
function pageNow() {
  const markup = new XMLSerializer(); // reads the page as text, parses nothing
  // Child by child, less Vite's error overlay: cloning that element runs its constructor without an error, which throws.
  const body = /** @type {HTMLElement} */ (document.body.cloneNode(false));
  for (const child of document.body.childNodes) if (child.nodeName !== 'VITE-ERROR-OVERLAY') body.append(child.cloneNode(true));
  body.removeAttribute('data-render');
  body.querySelectorAll('[data-error], [data-sketchbook-ghost], [data-projector], [data-code-panel], [data-code-frames], [data-announce="page"], [data-skip-to-picture], [data-class-bar]').forEach((e) => e.remove());
  body.querySelectorAll('[data-sketchbook-named]').forEach((e) => { e.removeAttribute('aria-label'); e.removeAttribute('data-sketchbook-named'); });
  withoutHolds(body); // the sizes last-picture.js holds while the sketch is away
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
  keepPictures(); // copies of the last good pictures (last-picture.js), shown until the new version has set up
  holdHeight();
  for (const p of [...instances]) p.remove(); // its `remove` hook takes it out of the set
  clearMistakes();
  delete document.body.dataset.render;
  if (lasting.size > 0) return reload(`the sketch still listens for ${[...lasting].map((e) => e.type).join(', ')} on the page`);
  if (pageNow() !== before) return reload('the sketch changed the page outside p5');
  showPictures();
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

/** The page keeps its height while the sketch is away, so the scroll position does not jump to the top. */
function holdHeight() {
  document.documentElement.style.minHeight = `${document.documentElement.scrollHeight}px`;
}

/** The new sketch has set up (its place restored by keep-place.js, its pictures by last-picture.js): the page may take its own height again. */
function settle() {
  document.documentElement.style.minHeight = '';
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
