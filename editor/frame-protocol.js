/**
 * The messages between a page and the sandboxed frame that runs the code of
 * its editor (code-in-page.js, frame-runtime.js). The frame runs code that
 * may have come in a link, so everything it says is untrusted input: each
 * message is read here, field by field, into a fresh object with known
 * types and sizes, or refused (null). Nothing in it is ever parsed as HTML.
 * The frame reports; it never judges: a message claiming a verdict, a task
 * done or progress is no message the page knows. The page judges the
 * homework itself from the scene the code built (editor/page-judge.js).
 *
 *   frame → page
 *     { type: 'ready' }                          the frame's document waits for its run
 *     { type: 'alive' }                          every second: the frame's code is not stuck in a loop
 *     { type: 'setup' }                          the sketch's setup() is done: its picture is the one to show
 *     { type: 'render', state }                  'rendering' | 'done' | 'error' (body[data-render] in the frame)
 *     { type: 'error', message, line, column, exact }   a mistake, at a line of the editor's code (or null)
 *     { type: 'select', x, y }                   the pixel selected in the frame's first tracer view
 *     { type: 'scene', scene, camera, mode, order, problem }   what the code built, as the library's JSON text
 *                                                (lib/scene/json.js), read again by the page; or null and the
 *                                                problem, in words, when it could not be written
 *     { type: 'size', height }                   the frame's content height in CSS pixels (the page clamps it: frameHeight)
 *   page → frame
 *     { type: 'run', runtime, code, sourceURL, imports, selected }
 *     { type: 'values', changes: [{ path, value }] }   new values of scene or camera fields, each found by the
 *                                                page from its own parse of the code (editor/live-values.js):
 *                                                the frame sets them and traces again, coarse to fine
 *
 * Nothing the frame says can change the editor's code: the page writes the
 * code only from the student's keys and pointer, and from values it computed.
 */

/** The longest message text a frame may send (a mistake's message), in characters. */
export const MAX_MESSAGE = 2_000;
/** The longest scene JSON a frame may send (characters): 10,000 objects, or sketch 13's bunny, with room to spare. */
export const MAX_SCENE_TEXT = 4_000_000;
/** The longest camera JSON a frame may send (characters): a camera is about 100. */
const MAX_CAMERA_TEXT = 1_000;
/** The shortest a frame is made, in CSS pixels, whatever it asks. */
export const MIN_HEIGHT = 160;
/** The tallest a frame is made, in CSS pixels, unless the window is taller: past it, the frame scrolls. */
export const MAX_HEIGHT = 2_000;
/** The largest traced picture's side a selected pixel may name. */
const MAX_PIXEL = 8_192;

const RENDER_STATES = ['rendering', 'done', 'error'];
const ORDERS = ['coarse', 'scanline', 'slow'];

const isWhole = (n, min, max) => Number.isInteger(n) && n >= min && n <= max;
const text = (s, max) => (typeof s === 'string' ? s.slice(0, max) : null);

/**
 * A frame's message, checked: a new object holding only the known fields of
 * its type, or null when it is not one the page knows or a field is wrong.
 * @param {unknown} data `event.data` of a `message` event from the frame
 * @returns {object|null}
 */
export function readFrameMessage(data) {
  if (data === null || typeof data !== 'object' || Array.isArray(data)) return null;
  const m = /** @type {Record<string, unknown>} */ (data);
  switch (m.type) {
    case 'ready':
    case 'alive':
    case 'setup':
      return { type: m.type };
    case 'render':
      return RENDER_STATES.includes(/** @type {string} */ (m.state)) ? { type: 'render', state: m.state } : null;
    case 'error': {
      const message = text(m.message, MAX_MESSAGE);
      if (message === null) return null;
      const line = isWhole(m.line, 1, 1_000_000) ? m.line : null;
      const column = line !== null && isWhole(m.column, 1, 1_000_000) ? m.column : null;
      return { type: 'error', message, line, column, exact: m.exact === true };
    }
    case 'select':
      if (m.x === null && m.y === null) return { type: 'select', x: null, y: null };
      return isWhole(m.x, 0, MAX_PIXEL) && isWhole(m.y, 0, MAX_PIXEL) ? { type: 'select', x: m.x, y: m.y } : null;
    case 'scene':
      return readScene(m);
    case 'size':
      return typeof m.height === 'number' && Number.isFinite(m.height) && m.height >= 0 ? { type: 'size', height: m.height } : null;
    default:
      return null;
  }
}

/** A scene message's fields: whole texts within their limits (a cut scene would be another scene), or null. */
function readScene(m) {
  const within = (s, max) => s === null || (typeof s === 'string' && s.length <= max);
  if (!within(m.scene, MAX_SCENE_TEXT) || !within(m.camera, MAX_CAMERA_TEXT)) return null;
  if ((m.scene === null) !== (m.camera === null)) return null;
  const mode = typeof m.mode === 'string' && /^[a-z]{1,20}$/.test(m.mode) ? m.mode : 'shaded';
  const order = ORDERS.includes(/** @type {string} */ (m.order)) ? m.order : 'coarse';
  const problem = m.scene === null ? text(m.problem, MAX_MESSAGE) ?? 'the scene could not be written as JSON' : null;
  return { type: 'scene', scene: m.scene, camera: m.camera, mode, order, problem };
}

/** The most fields one literal may write (a literal shared by a whole row of shapes). */
const MAX_CHANGES = 256;
const isKey = (k) => typeof k === 'string' && /^(scene|camera|[A-Za-z]{1,40}|\d{1,6})$/.test(k);

/**
 * A values message, checked in the frame: its changes, each a path of field
 * names and indices and a finite number, or null.
 * @param {unknown} data
 * @returns {{ path: string[], value: number }[]|null}
 */
export function readValues(data) {
  const m = /** @type {any} */ (data);
  if (m === null || typeof m !== 'object' || m.type !== 'values' || !Array.isArray(m.changes) || m.changes.length > MAX_CHANGES) return null;
  const changes = [];
  for (const c of m.changes) {
    const path = c?.path;
    if (!Array.isArray(path) || path.length < 2 || path.length > 8 || !['scene', 'camera'].includes(path[0]) || !path.every(isKey)) return null;
    if (typeof c.value !== 'number' || !Number.isFinite(c.value)) return null;
    changes.push({ path: [...path], value: c.value });
  }
  return changes;
}

/**
 * The frame's height on the page for the height it asked for: at least
 * MIN_HEIGHT, at most MAX_HEIGHT or the window's height, whichever is more.
 * @param {number} asked the frame's content height (a checked size message's)
 * @param {number} windowHeight the page's window (innerHeight)
 */
export function frameHeight(asked, windowHeight) {
  const most = Math.max(MAX_HEIGHT, Number.isFinite(windowHeight) ? windowHeight : 0);
  return Math.min(Math.max(Math.ceil(asked), MIN_HEIGHT), most);
}

/**
 * Where in the editor's code a mistake is: the first stack frame in the
 * code's own script (named by its `//# sourceURL`), else the place the
 * browser gave when it is the code's script (a syntax error, a missing
 * export: the frame's document or the sourceURL itself).
 * @param {string} stack an Error's stack ('' when none)
 * @param {{ filename?: string, lineno?: number, colno?: number }} event the error event's place, if any
 * @param {string} sourceURL the name the code's script runs under
 * @returns {{ line: number, column: number }|null}
 */
export function codePlace(stack, event, sourceURL) {
  const name = sourceURL.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  const m = new RegExp(`(?:^|[\\s(@])${name}:(\\d+):(\\d+)`, 'm').exec(String(stack ?? ''));
  if (m) return { line: Number(m[1]), column: Number(m[2]) };
  const file = event?.filename ?? '';
  if ([sourceURL, 'about:srcdoc', ''].includes(file) && isWhole(event?.lineno, 1, 1_000_000)) {
    return { line: /** @type {number} */ (event.lineno), column: isWhole(event?.colno, 1, 1_000_000) ? /** @type {number} */ (event.colno) : 1 };
  }
  return null;
}
