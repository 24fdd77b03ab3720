/**
 * The mistake on the page. In class nobody sees the browser console, so any
 * error a sketch raises (in setup — p5 2.x runs it async, so it arrives as an
 * unhandled rejection —, draw, an event handler, a promise, a library
 * TypeError/RangeError, a ReferenceError) is shown in a panel marked
 * `data-error`: the message in large type, the sketch's own file and line
 * (from the stack, skipping frames in node_modules and lib/) and, when the
 * file can be fetched from the page's own origin, the line itself.
 *
 * Importing lib/p5 installs it; the sketch does nothing. The console keeps
 * the error (no preventDefault). The panel sits over the page, so the last
 * good picture stays under it; the next save (a reload or a swap) starts without it.
 * Text goes in with textContent only: a message may quote anything.
 *
 * body[data-render]: a mistake can stop a view before its picture is done,
 * and "rendering" would then never end; so when the panel appears while the
 * page is not "done", the page says "error". A view that still finishes
 * afterwards sets "done" as usual, and one that restarts sets "rendering".
 */
import { useStyle, element } from '../dom.js';

/** Errors already shown, by message and place: a draw() error repeats every frame. */
const shown = new Map();
/** Called for each new mistake shown (last-picture.js puts the last good picture back under it). */
const mistakeListeners = [];
/** Characters of a source line shown at most. */
const SHOWN_CHARS = 120;
let panel = null;

/**
 * Listens for uncaught errors and unhandled rejections on `win` (once per
 * window, however often the module is loaded).
 * @param {Window & { __sketchbookErrorPanel?: boolean }} [win]
 */
export function installErrorPanel(win = globalThis.window) {
  const flags = /** @type {any} */ (win);
  if (!win?.addEventListener || flags.__sketchbookErrorPanel) return;
  flags.__sketchbookErrorPanel = true;
  win.addEventListener('error', (event) => {
    showError(event.error ?? event.message, { url: event.filename, line: event.lineno, column: event.colno });
  });
  win.addEventListener('unhandledrejection', (event) => showError(event.reason));
}

/**
 * Shows `error` (an Error or any thrown value) in the page's error panel.
 * @param {any} error
 * @param {{ url?: string, line?: number, column?: number }} [fallback] where the browser says it happened
 * @returns {HTMLElement|null} the panel (null outside a page)
 */
export function showError(error, fallback = {}) {
  if (typeof document === 'undefined' || !document.body) return null;
  const origin = location.origin;
  const stack = /** @type {any} */ (error)?.stack;
  const frame = sketchFrame(typeof stack === 'string' ? stack : '', origin)
    ?? (fallback.url && fallback.line ? sketchFrame(`at ${fallback.url}:${fallback.line}:${fallback.column || 1}`, origin) : null);
  return showMistake(errorMessage(error), frame);
}

/**
 * Shows a mistake in the page's error panel: its message, and where it is
 * (the line itself is fetched from `url` unless `source` gives it).
 * @param {string} message
 * @param {{ url?: string, file: string, line: number, column: number, source?: string, exact?: boolean, suggestion?: string }|null} [where]
 *   `exact`: the column is the mistake's own (a syntax error), so it is shown too;
 *   `suggestion`: what was probably meant ("did you mean Sphere?"), else one is looked for (mistake-hints.js)
 * @returns {HTMLElement|null} the panel (null outside a page)
 */
export function showMistake(message, where = null) {
  if (typeof document === 'undefined' || !document.body) return null;
  const key = `${message}\n${where?.file}:${where?.line}`;
  const seen = shown.get(key);
  if (seen) {
    seen.count += 1;
    seen.countElement.textContent = `×${seen.count}`;
    return panel;
  }

  useStyle();
  document.querySelectorAll('.loading-indicator').forEach((spinner) => spinner.remove()); // p5's setup spinner would spin for ever
  if (!panel || !panel.isConnected) panel = buildPanel();
  const entry = element('section', { class: 'rt-error-entry' });
  const countElement = element('span', { class: 'rt-error-count', 'data-error-count': '' });
  entry.append(element('p', { class: 'rt-error-message', 'data-error-message': '' }, message, ' ', countElement));
  if (where) {
    const place = `${where.file}:${where.line}${where.exact ? `:${where.column}` : ''}`;
    entry.append(element('p', { class: 'rt-error-where', 'data-error-where': '' }, place));
    if (typeof where.source === 'string') showLine(entry, where, where.source);
    else showSourceLine(entry, where);
  }
  if (where?.suggestion) showSuggestion(entry, where.suggestion);
  else if (mayHaveHint(message)) import('./mistake-hints.js').then((hints) => hints.hintFor(message, where?.url ?? location.href)).then((hint) => showSuggestion(entry, hint), () => {});
  panel.querySelector('.rt-error-list').append(entry);
  shown.set(key, { count: 1, countElement });
  if (document.body.dataset.render !== 'done') document.body.dataset.render = 'error';
  for (const listener of mistakeListeners) listener();
  return panel;
}

/** Calls `listener` each time a new mistake is shown. */
export function onMistake(listener) {
  mistakeListeners.push(listener);
}

/**
 * A module the page could not load, heard by the dev server's classic script
 * (scripts/vite-live-coding.js) because none of the page's modules ran: an
 * import the module does not export (a SyntaxError at the import's line), or
 * a script that could not be fetched.
 * @param {ErrorEvent|Event} event the window's `error` event
 * @param {string} script the `src` of the script element that failed, if it was one
 */
export function showModuleFailure(event, script) {
  const e = /** @type {ErrorEvent} */ (event);
  if (e.error) return showError(e.error, { url: e.filename, line: e.lineno, column: e.colno });
  const file = script ? decodeURIComponent(new URL(script).pathname.replace(/^\//, '')) : 'the page\'s script';
  return showMistake(`${file} did not load: it, or a file it imports, is missing or cannot be fetched (the browser console names it)`);
}

/** Messages mistake-hints.js may know a "did you mean" for: a name that is not there. */
function mayHaveHint(message) {
  return /does not provide an export named|is not a function|is not defined|Can't find variable/.test(message);
}

/** A line under the message saying what was probably meant. */
function showSuggestion(entry, text) {
  if (text) entry.querySelector('[data-error-message]').after(element('p', { class: 'rt-error-suggestion', 'data-error-suggestion': '' }, text));
}

/** Takes the panel away: a save swapped in a new version of the sketch (hot-swap.js), as a reload would. */
export function clearMistakes() {
  shown.clear();
  panel?.remove();
  panel = null;
}

/** "TypeError: radius must be …" for an Error, the value itself for anything else thrown. */
export function errorMessage(error) {
  if (error instanceof Error || (error && typeof error.message === 'string')) {
    return error.name && error.name !== 'Error' ? `${error.name}: ${error.message}` : error.message || String(error.name);
  }
  if (typeof error === 'string') return error;
  try { return JSON.stringify(error) ?? String(error); } catch { return String(error); }
}

/**
 * The first stack frame in the sketch's own files: same origin, not in
 * node_modules, Vite's own modules or the library (a lib/ folder).
 * @param {string} stack an Error's stack (Chromium `at f (url:line:col)`, Firefox/Safari `f@url:line:col`)
 * @param {string} origin the page's origin, e.g. "http://localhost:5173"
 * @returns {{ url: string, file: string, line: number, column: number }|null}
 *   `file` the path from the site's root, like "sketches/11-my-sketch.js";
 *   `url` without Vite's query (?t=…)
 */
export function sketchFrame(stack, origin) {
  for (const text of String(stack).split('\n')) {
    const m = /((?:https?|file):\/\/[^\s()]+?):(\d+):(\d+)\)?\s*$/.exec(text);
    if (!m) continue;
    let url;
    try { url = new URL(m[1]); } catch { continue; }
    if (url.origin !== origin) continue;
    const path = url.pathname;
    if (/\/(node_modules|lib)\//.test(path) || path.startsWith('/@')) continue; // p5, Vite's client, the library
    if (!/\.[cm]?[jt]sx?$/.test(path)) continue;
    const file = decodeURIComponent(path.replace(/^\//, ''));
    return { url: url.origin + url.pathname, file, line: Number(m[2]), column: Number(m[3]) };
  }
  return null;
}

/** Fetches the sketch file (same origin only) and shows the offending line. */
async function showSourceLine(entry, frame) {
  try {
    const response = await fetch(frame.url, { cache: 'no-store' });
    if (!response.ok) return;
    showLine(entry, frame, (await response.text()).split(/\r?\n/)[frame.line - 1]);
  } catch {
    // The file cannot be had (offline, another origin): the file and line are enough.
  }
}

/** The offending line, with a caret under the column (1-based). */
function showLine(entry, frame, line) {
  if (line === undefined || !line.trim()) return;
  const indent = line.length - line.trimStart().length;
  let code = line.trim(), at = Math.max(0, Math.min(code.length - 1, frame.column - 1 - indent));
  if (code.length > SHOWN_CHARS) { // a long (built, minified) line: the part around the column
    const from = Math.max(0, Math.min(at - SHOWN_CHARS / 2, code.length - SHOWN_CHARS));
    code = (from > 0 ? '…' : '') + code.slice(from, from + SHOWN_CHARS) + (from + SHOWN_CHARS < code.length ? '…' : '');
    at = at - from + (from > 0 ? 1 : 0);
  }
  const caret = ' '.repeat(at) + '^';
  const number = `${frame.line} │ `;
  entry.append(element('pre', { class: 'rt-error-source', 'data-error-source': '' }, number + code, '\n', ' '.repeat(number.length) + caret));
}

function buildPanel() {
  const hide = element('button', { type: 'button', class: 'rt-error-hide' }, 'Hide');
  const box = element('aside', { class: 'rt-error', 'data-error': '', role: 'alert', 'aria-live': 'assertive' },
    element('div', { class: 'rt-error-head' }, element('strong', {}, 'Mistake in the sketch'), hide),
    element('div', { class: 'rt-error-list' }),
    element('p', { class: 'rt-error-hint' }, 'Fix it and save: the panel goes. The browser console (F12) has the whole story.'));
  hide.addEventListener('click', () => { box.hidden = true; });
  document.body.append(box);
  return box;
}

installErrorPanel();
