/**
 * Small DOM helpers shared by the tracer view, the inspector panel and the
 * controls: the stylesheet, elements built from text, where a part goes, the clipboard.
 */
import { show } from '../text/check.js';

const STYLE_URL = new URL('./style.css', import.meta.url).href;

/**
 * Adds the sketchbook's stylesheet (lib/p5/style.css) to the page once,
 * unless the page already links it.
 */
export function useStyle() {
  if (typeof document === 'undefined') return;
  const linked = [.../** @type {NodeListOf<HTMLLinkElement>} */ (document.querySelectorAll('link[rel="stylesheet"]'))].some((l) => l.href === STYLE_URL || l.dataset.sketchbook !== undefined);
  if (linked) return;
  const link = document.createElement('link');
  link.rel = 'stylesheet';
  link.href = STYLE_URL;
  link.dataset.sketchbook = '';
  document.head.append(link);
}

/**
 * `element('div', { class: 'x', 'data-field': 'A' }, child, 'text', …)`:
 * an element with attributes (values as strings) and children (nodes or text;
 * null and false are skipped).
 */
export function element(tag, attributes = {}, ...children) {
  const el = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value !== undefined && value !== null && value !== false) el.setAttribute(name, String(value));
  }
  for (const child of children) {
    if (child === null || child === undefined || child === false) continue;
    el.append(child instanceof Node ? child : String(child));
  }
  return el;
}

/** A name from a scene is shown cut past this many characters: a 100,000-character name made page 05 a million pixels wide. */
export const NAME_SHOWN = 40;

/**
 * A name as the page shows it: whole up to `max` characters, else cut with
 * an ellipsis (the title, the JSON, the CSV and the code keep it whole).
 * @example
 * shownName('x'.repeat(100_000)); // 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx…' (40 characters)
 */
export function shownName(name, max = NAME_SHOWN) {
  const text = String(name);
  if (text.length <= max) return text;
  let cut = text.slice(0, max - 1);
  if (/[\uD800-\uDBFF]$/.test(cut)) cut = cut.slice(0, -1); // not half of a character
  return `${cut}…`;
}

/** An element's attributes for a name it shows: the whole name as its title when shownName cuts it. */
export function nameTitle(name, max = NAME_SHOWN) {
  return String(name).length > max ? { title: String(name) } : {};
}

/**
 * Sets a p5.Element's (or an element's) text, never parsed as HTML: p5's
 * createP/createDiv/createElement(tag, text) and .html() set innerHTML.
 */
export function withText(el, text) {
  (el.elt ?? el).textContent = String(text);
  return el;
}

/**
 * The element a factory's `parent` option names: an element, a p5.Element, an
 * element id or a CSS selector; `fallback` (an element) when it is left out.
 */
export function resolveParent(parent, fallback) {
  if (parent == null) return fallback;
  if (typeof parent === 'string') {
    const found = document.getElementById(parent) ?? document.querySelector(parent);
    if (!found) throw new TypeError(`parent: no element with id or selector ${show(parent)}`);
    return found;
  }
  if (parent.elt instanceof HTMLElement) return parent.elt; // a p5.Element
  if (parent instanceof HTMLElement) return parent;
  throw new TypeError(`parent must be an element, its id or a p5.Element, got ${show(parent)}`);
}

/**
 * The node a sketch was started in (`new p5(sketch, node)`), where its parts go
 * by default; the page's <main> (or body) for a global-mode sketch. p5 keeps
 * that node in a field of its own and has no public getter for it: this is the
 * one place the kit reads it.
 */
export function sketchNode(p) {
  const node = p?._userNode;
  if (node instanceof HTMLElement) return node;
  if (typeof node === 'string' && document.getElementById(node)) return document.getElementById(node);
  return document.querySelector('main') ?? document.body;
}

/**
 * Puts `text` on the clipboard: true when the browser took it, false when it
 * would not, and the person has to select the text and copy it themselves.
 * A student's page on the teacher's plain-http address is not a secure
 * context and has no `navigator.clipboard`: there the text is copied as a
 * selection is (`execCommand('copy')`, still honoured within a click).
 * @example
 * if (!(await copyText(line))) status.textContent = 'Select the text and press Ctrl+C (⌘C).';
 */
export async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    return copyBySelection(text);
  }
}

/** Copies `text` through a hidden text box, as Ctrl+C copies a selection; the focus goes back where it was. */
function copyBySelection(text) {
  if (typeof document === 'undefined' || typeof document.execCommand !== 'function') return false;
  const box = element('textarea', { readonly: '', 'aria-hidden': 'true', tabindex: '-1', style: 'position:fixed;top:0;left:0;width:1px;height:1px;opacity:0' });
  box.value = text;
  const before = document.activeElement;
  document.body.append(box);
  box.select();
  let copied = false;
  try { copied = document.execCommand('copy'); } catch { /* refused: the caller says how to copy */ }
  box.remove();
  if (before instanceof HTMLElement) before.focus({ preventScroll: true });
  return copied;
}
