/**
 * Small DOM helpers shared by the tracer view and the inspector panel.
 */

const STYLE_URL = new URL('./style.css', import.meta.url).href;

/**
 * Adds the sketchbook's stylesheet (lib/p5/style.css) to the page once,
 * unless the page already links it.
 */
export function useStyle() {
  if (typeof document === 'undefined') return;
  const linked = [...document.querySelectorAll('link[rel="stylesheet"]')].some((l) => l.href === STYLE_URL || l.dataset.sketchbook !== undefined);
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
