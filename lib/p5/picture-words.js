/**
 * The tracer view's picture in words: its canvas is an image (`role="img"`)
 * described by what its scene shows through its camera (lib/describe.js),
 * kept current as the scene, camera or mode change; and a "Picture as text"
 * disclosure reads the traced picture row by row in colour names.
 */
import { describeScene, pictureRows } from '../describe.js';
import { MODES } from '../modes.js';
import { element } from './dom.js';

/** A camera that moves every frame re-describes the scene at most this often. */
const DESCRIBE_EVERY_MS = 250;
let ids = 0;

/**
 * Makes `canvas` an image described in words; returns the disclosure and the
 * description (to put under the picture) and `changed()`, `done()` for the view to call.
 * @param {HTMLCanvasElement} canvas
 * @param {{ scene: object, camera: object, mode: string, width: number, height: number, buffer: Uint8ClampedArray }} view
 */
export function createPictureWords(canvas, view) {
  const id = `rt-picture-description-${++ids}`;
  // hidden: read as the picture's description, not a second time as the page's text
  const description = element('p', { id, hidden: '', 'data-picture-description': '' });
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-describedby', id);
  const rows = element('ol', { class: 'rt-picture-rows', 'data-picture-rows': '' });
  const details = element('details', { class: 'rt-picture-text' }, element('summary', {}, 'Picture as text'), rows);
  let last = -Infinity, timer = 0;

  const describe = () => {
    timer = 0;
    last = performance.now();
    const mode = view.mode === 'shaded' ? '' : `${MODES.find((m) => m.name === view.mode)?.label ?? view.mode} map of the scene. `;
    const text = `${view.width} by ${view.height} pixels. ${mode}${describeScene(view.scene, view.camera)}`;
    if (description.textContent !== text) description.textContent = text;
  };
  const readRows = () => {
    rows.replaceChildren(...pictureRows(view.buffer, view.width, view.height).map((line) => element('li', {}, line)));
  };
  details.addEventListener('toggle', () => { if (details.open) readRows(); });

  return {
    details,
    description,
    /** The scene, camera or mode changed: describe it again (in the next task, or later when it changes every frame). */
    changed() {
      if (details.open) rows.replaceChildren(element('li', {}, 'Tracing…'));
      if (timer) return;
      // In a task of its own, never the edit's: it casts rays at every shape (lib/describe.js).
      timer = setTimeout(describe, Math.max(0, last + DESCRIBE_EVERY_MS - performance.now()));
    },
    /** The picture is traced: the rows can be read. */
    done() {
      if (details.open) readRows();
    },
    destroy() { clearTimeout(timer); },
  };
}
