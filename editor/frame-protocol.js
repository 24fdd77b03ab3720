/**
 * The messages between a page and the sandboxed frame that runs the code of
 * its editor (code-in-page.js, frame-runtime.js). The frame runs code that
 * may have come in a link, so everything it says is untrusted input: each
 * message is read here, field by field, into a fresh object with known
 * types and sizes, or refused (null). Nothing in it is ever parsed as HTML.
 *
 *   frame → page
 *     { type: 'ready' }                          the frame's document waits for its run
 *     { type: 'alive' }                          every second: the frame's code is not stuck in a loop
 *     { type: 'setup' }                          the sketch's setup() is done: its picture is the one to show
 *     { type: 'render', state }                  'rendering' | 'done' | 'error' (body[data-render] in the frame)
 *     { type: 'error', message, line, column, exact }   a mistake, at a line of the editor's code (or null)
 *     { type: 'select', x, y }                   the pixel selected in the frame's first tracer view
 *     { type: 'check', passed }                  a homework self-check ran on the edited code
 *     { type: 'progress', text }                 the task list's progress, as the kit stores it (lib/lesson/progress.js)
 *     { type: 'size', height }                   the frame's content height in CSS pixels
 *   page → frame
 *     { type: 'run', runtime, code, sourceURL, imports, selected }
 */

/** The longest message text a frame may send (a mistake's message), in characters. */
export const MAX_MESSAGE = 2_000;
/** The longest progress text a frame may send. */
export const MAX_PROGRESS = 4_000;
/** The tallest a frame may ask to be, in CSS pixels. */
export const MAX_HEIGHT = 20_000;
/** The largest traced picture's side a selected pixel may name. */
const MAX_PIXEL = 8_192;

const RENDER_STATES = ['rendering', 'done', 'error'];

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
    case 'check':
      return typeof m.passed === 'boolean' ? { type: 'check', passed: m.passed } : null;
    case 'progress': {
      const progress = text(m.text, MAX_PROGRESS + 1);
      return progress !== null && progress.length <= MAX_PROGRESS ? { type: 'progress', text: progress } : null;
    }
    case 'size':
      return typeof m.height === 'number' && Number.isFinite(m.height) && m.height >= 0 ? { type: 'size', height: Math.min(Math.ceil(m.height), MAX_HEIGHT) } : null;
    default:
      return null;
  }
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
