/**
 * A diagram's words for a screen reader: the canvas it is drawn on becomes an
 * image (`role="img"`) named by what each diagram on it shows, kept current as
 * they are drawn again. An attribute, never HTML (p5's describe() writes its
 * text as innerHTML, and a sphere's name is the student's).
 */

/** Each canvas's diagrams' words, by the box each is drawn in. */
const said = new WeakMap();

/**
 * Names the diagram drawn in `box` on p's canvas; several diagrams on one
 * canvas (the side and top views) are read one after the other, top first.
 * @param {object} p a p5 instance (anything without a canvas is left alone)
 * @param {{ x: number, y: number }} box
 * @param {string} text
 */
export function nameDiagram(p, box, text) {
  const canvas = p?.canvas ?? p?.drawingContext?.canvas;
  if (!canvas?.setAttribute) return;
  let parts = said.get(canvas);
  if (!parts) said.set(canvas, parts = new Map());
  parts.set(`${box.y},${box.x}`, text);
  const label = [...parts.entries()].sort(([a], [b]) => a.localeCompare(b, 'en', { numeric: true })).map(([, t]) => t).join(' ');
  if (canvas.getAttribute('role') !== 'img') canvas.setAttribute('role', 'img');
  if (canvas.getAttribute('aria-label') !== label) canvas.setAttribute('aria-label', label);
}
