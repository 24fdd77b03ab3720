/**
 * The tracer view's picture in words and by keys, for a student who cannot
 * see it. The canvas is an image (`role="img"`) described by what its scene
 * shows through its camera (lib/lesson/describe.js; a map, by what the map shows:
 * map-words.js), kept current as the scene, camera or mode change. It sits in
 * an `application` (its stage): screen readers in browse mode (NVDA, JAWS) keep
 * the arrow keys for their own cursor unless the focus is in such a widget,
 * and the picture takes the arrow keys. Its keys beside the arrows: a colour's
 * first letters jump to the next pixel of that colour (p: the next pink one;
 * Shift: the one before; while the picture is still traced, once it is done);
 * 3 goes to the page's 3D view. The first Tab into the page lands on the
 * picture (through the "Skip to the picture" link), and a "Picture as text"
 * disclosure reads the traced picture row by row of pixels, in colour names,
 * saying when the rows change.
 */
import { describeScene, pixelNames, pixelRows, nextPixelNamed, COLOR_NAMES } from '../../lesson/describe.js';
import { MODES } from '../../tracing/modes.js';
import { element } from '../dom.js';
import { createAnnouncer } from '../page/announce.js';
import { mapSummary, mapValue } from './map-words.js';

/** A camera that moves every frame re-describes the scene at most this often. */
const DESCRIBE_EVERY_MS = 250;
/** Letters typed within this long of each other spell one colour's name (as in a list box). */
const TYPE_AHEAD_MS = 800;
/** Rows of pixels read out at most: beyond, a row is every n-th pixel row. */
const MAX_ROWS = 240;
let ids = 0;
/** The key on the picture that goes to the page's 3D view (a digit: the letters are colours'). */
const VIEW3D_KEY = '3';
/** The application's name: its keys, by engine. */
const KEYS = {
  cpu: 'Arrow keys: a pixel; p: next pink, or a colour\'s first letter',
  gpu: 'Arrow keys: turn the camera, or move the selected pixel (Escape lets it go); + and −: nearer, farther; p: next pink, or a colour\'s first letter',
};

/**
 * Makes `canvas` an image described in words inside an application that takes
 * the arrow keys and the colour letters; returns the disclosure and the
 * description (to put under the picture), `stage(element)` to make the
 * picture's stage the application, and `changed()`, `done()` for the view to call.
 * @param {HTMLCanvasElement} canvas
 * @param {{ scene: object, camera: object, mode: string, width: number, height: number, buffer: Uint8ClampedArray,
 *   done: boolean, selected: ?{x: number, y: number}, select(x: number, y: number): unknown, on(event: string, fn: Function): Function }} view
 */
export function createPictureWords(canvas, view) {
  const n = ++ids;
  const id = `rt-picture-description-${n}`;
  canvas.id ||= `rt-picture-${n}`;
  const told = pictureDescription(canvas, view, id);
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-describedby', id);
  const voice = createAnnouncer({ name: 'picture', order: 1 });
  const rows = pictureRows(view, voice);
  const colors = colorKeys(view, voice, rows.names);
  let engineNow = 'cpu', stageElement = null;
  addSkipLink(canvas);
  canvas.setAttribute('aria-label', told.name());
  // the 3D view comes after the picture in setup(): the application's name says its key once there is one
  canvas.addEventListener('focus', () => words.engine(engineNow));

  // a map says what the pixel stands for, when the student is on it (the page's inspector says the pixel)
  const unlisten = view.on('select', (s) => {
    if (s && view.mode !== 'shaded' && document.activeElement === canvas) voice.say(mapValue(view.mode, view.scene, view.camera, s.x, s.y));
  });
  listenForKeys(canvas, colors);

  const words = {
    details: rows.details,
    description: told.description,
    /** The scene, camera or mode changed: describe it again (in the next task, or later when it changes every frame). */
    changed() {
      rows.changed();
      told.later();
    },
    /** The picture is traced: the rows can be read, and the colours searched. */
    done() {
      rows.done();
      colors.done();
    },
    /** Makes the picture's stage the application the keys go to (it holds the focusable picture). */
    stage(stage) {
      stageElement = stage;
      stage.setAttribute('role', 'application');
      stage.setAttribute('aria-roledescription', 'picture of pixels');
      this.engine('cpu');
    },
    /** The engine tracing now: on the GPU the arrow keys turn the camera until a pixel is selected (gpu-orbit.js); the name says so. */
    engine(engine) {
      engineNow = engine;
      stageElement?.setAttribute('aria-label', `${KEYS[engine] ?? KEYS.cpu}${sceneView3d() ? `; ${VIEW3D_KEY}: the 3D view` : ''}`);
    },
    destroy() {
      told.destroy();
      unlisten();
      voice.destroy();
    },
  };
  return words;
}


/**
 * The picture's description, what its scene shows through its camera (a map:
 * what the map shows), and its name; `later()` describes it again in a task of
 * its own, at most every DESCRIBE_EVERY_MS.
 */
function pictureDescription(canvas, view, id) {
  // hidden: read as the picture's description, not a second time as the page's text
  const description = element('p', { id, hidden: '', 'data-picture-description': '' });
  let last = -Infinity, timer = 0;
  const caption = () => canvas.closest('figure')?.querySelector('figcaption')?.textContent.trim() || 'Traced picture';
  const modeLabel = () => (view.mode === 'shaded' ? '' : MODES.find((m) => m.name === view.mode)?.label ?? view.mode);
  // a map by its own name (sketch 02's three pictures of one scene are told apart); the size is in the description
  const name = () => {
    const map = modeLabel();
    return `${caption()}${map && !caption().startsWith(map.split(' ')[0]) ? `: ${map} map` : ''}`;
  };
  const describe = () => {
    timer = 0;
    last = performance.now();
    const map = mapSummary(view.mode, view.scene, view.camera);
    const full = `${view.width} by ${view.height} pixels. ${map ? `${map} Of the scene: ` : ''}${describeScene(view.scene, view.camera)}`;
    description.dataset.full = full;
    const twin = earlierTwin(description);
    const text = twin ? `${view.width} by ${view.height} pixels. The same scene as ${twin}, seen from the same eye.` : full;
    if (description.textContent !== text) description.textContent = text;
    canvas.setAttribute('aria-label', name());
  };
  return {
    description,
    name,
    later() {
      if (timer) return;
      // In a task of its own, never the edit's: it casts rays at every shape (lib/lesson/describe.js).
      timer = setTimeout(describe, Math.max(0, last + DESCRIBE_EVERY_MS - performance.now()));
    },
    destroy: () => clearTimeout(timer),
  };
}

/**
 * The "Picture as text" disclosure: the traced picture row by row of pixels,
 * in colour names, read when it is opened and when the picture is done, saying
 * when the rows changed. `names()` is each pixel's colour name, read once per
 * traced picture (the colour keys search it too).
 */
function pictureRows(view, voice) {
  const rows = element('ol', { class: 'rt-picture-rows', 'data-picture-rows': '' });
  const rowsNote = element('p', { class: 'rt-note', 'data-picture-rows-note': '' });
  const details = element('details', { class: 'rt-picture-text' }, element('summary', {}, 'Picture as text'), rowsNote, rows);
  let names = null, shownRows = '';
  const pictureNames = () => (names ??= pixelNames(view.buffer, view.width, view.height));
  const readRows = () => {
    const every = Math.ceil(view.height / MAX_ROWS);
    const lines = pixelRows(pictureNames(), view.width, view.height).filter((_, y) => y % every === 0);
    const text = lines.join('\n');
    const again = shownRows !== '' && text !== shownRows;
    shownRows = text;
    rows.replaceChildren(...lines.map((line) => element('li', {}, line)));
    rowsNote.textContent = `${view.done ? '' : 'Still tracing: '}${view.height} rows of ${view.width} pixels, row 0 at the top, x from 0 at the left${every > 1 ? ` (${everyNth(every)} row)` : ''}.`;
    if (again) voice.say('Picture as text: the picture was traced again, its rows changed.');
  };
  details.addEventListener('toggle', () => { if (details.open) readRows(); });
  return {
    details,
    names: pictureNames,
    changed() {
      names = null;
      if (details.open) rows.replaceChildren(element('li', {}, 'Tracing…'));
    },
    done() {
      names = null;
      if (details.open) readRows();
    },
  };
}

/**
 * The colour keys: a colour's first letters typed on the picture select the
 * next pixel of that colour (`back`: the one before). While the picture is
 * still being traced its coarse blocks are no colours to go by: the key is
 * answered by `done()`, once the picture is.
 */
function colorKeys(view, voice, pictureNames) {
  let typed = '', typedAt = 0, sought = '';
  /** A colour key pressed while the picture was being traced, answered when it is done. */
  let waiting = null;

  /** A letter typed on the picture: true when it was a colour's. */
  function colorKey(letter, back) {
    const now = performance.now();
    typed = now - typedAt < TYPE_AHEAD_MS ? typed + letter : letter;
    typedAt = now;
    if (!COLOR_NAMES.some((c) => c.startsWith(typed)) && !/^(.)\1+$/.test(typed)) typed = letter; // w then g: gray, not "wg" (as a list box)
    // the same letter again: the next pixel of the colour already sought
    const again = /^(.)\1+$/.test(typed) && sought.startsWith(letter);
    if (!again && !COLOR_NAMES.some((c) => c.startsWith(typed))) return false; // not a colour's letter (h, v: the 3D view's fans)
    if (view.done) {
      findColor(typed, again, back);
      return true;
    }
    waiting = { typed, again, back };
    voice.say(`Still tracing: the ${again ? sought : COLOR_NAMES.find((c) => c.startsWith(typed))} pixel is found once the picture is done.`);
    return true;
  }

  /** The next (or, back, the previous) pixel of the colour `typed` begins, in the finished picture. */
  function findColor(letters, again, back) {
    const all = pictureNames();
    const present = COLOR_NAMES.filter((_, i) => all.includes(i));
    const colour = again ? sought : present.find((c) => c.startsWith(letters));
    if (!colour) {
      voice.say(`No ${COLOR_NAMES.find((c) => c.startsWith(letters))} pixel here. This picture has ${present.join(', ')}.`);
      return;
    }
    sought = colour;
    const next = nextPixelNamed(all, view.width, colour, view.selected, back ? -1 : 1);
    if (next) view.select(next.x, next.y); // the inspector (or the activity's verdict) says the pixel
  }

  return {
    key: colorKey,
    done() {
      if (!waiting) return;
      const { typed: letters, again, back } = waiting;
      waiting = null;
      findColor(letters, again, back);
    },
  };
}

/** The picture's own keys: 3 to the page's 3D view, a colour's letters to its pixels. */
function listenForKeys(canvas, colors) {
  canvas.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    if (event.key === VIEW3D_KEY && sceneView3d()) { // one key to the 3D view, not a dozen Tabs past the panels
      event.preventDefault();
      sceneView3d().focus();
      return;
    }
    if (!/^[a-z]$/i.test(event.key)) return;
    const next = colors.key(event.key.toLowerCase(), event.shiftKey);
    if (next) event.preventDefault();
  });
}

/** The page's 3D view of the scene, if it has one. */
const sceneView3d = () => /** @type {HTMLElement|null} */ (document.querySelector('[data-view3d]'));

/** "every other", "every 3rd", "every 4th": which rows a tall picture's text reads. */
const everyNth = (n) => (n === 2 ? 'every other' : `every ${n}${(n % 100 > 10 && n % 100 < 14) ? 'th' : ({ 1: 'st', 2: 'nd', 3: 'rd' })[n % 10] ?? 'th'}`);

/**
 * The caption of a picture before this one on the page whose description is
 * the same (sketch 11's two pictures of one scene): the second says so in a
 * line instead of the whole scene again. Null when there is none.
 */
function earlierTwin(description) {
  for (const other of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('[data-picture-description]'))) {
    if (other === description) return null;
    if (other.dataset.full === description.dataset.full) {
      return other.closest('figure')?.querySelector('figcaption')?.textContent.trim() || 'the picture before';
    }
  }
  return null;
}

/**
 * Once a page: its first link, "Skip to the picture". The first Tab into the
 * page (the focus coming from outside it) goes on through it to the picture,
 * so the picture is one key from the page's start; Shift+Tab back from the
 * header stops on the link itself (no trap), and Enter on it goes to the picture.
 * The page's `<main>`, which holds the picture, is a landmark named for it.
 */
function addSkipLink(canvas) {
  if (document.querySelector('[data-skip-to-picture]')) return;
  const link = element('a', { class: 'rt-skip-link', href: `#${canvas.id}`, 'data-skip-to-picture': '' }, 'Skip to the picture');
  link.addEventListener('focus', (event) => { if (!event.relatedTarget && canvas.isConnected) canvas.focus(); });
  document.body.prepend(link);
  queueMicrotask(() => { // once the view has put its picture on the page
    const main = canvas.closest('main');
    if (!main || main.hasAttribute('aria-label') || main.hasAttribute('aria-labelledby')) return;
    main.setAttribute('aria-label', 'The picture and its panels');
    main.dataset.sketchbookNamed = ''; // the kit's name, kept through a save (hot-swap.js leaves it out of its page check)
  });
}
