/**
 * Small DOM helpers shared by the tracer view, the inspector panel and the
 * controls: the stylesheet, elements built from text, where a part goes, the clipboard.
 */
import { show } from '../check.js';

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
 * would not (no permission, the page not focused or not secure, no clipboard
 * at all), and the person has to select the text and copy it themselves.
 * @example
 * if (!(await copyText(line))) status.textContent = 'Select the text and press Ctrl+C (⌘C).';
 */
export async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    return false;
  }
}
