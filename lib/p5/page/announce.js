/**
 * The page's one voice for screen readers: one atomic status (role="status")
 * that says only the last of quick changes, and says together what happened
 * together. While an arrow key repeats, the selected pixel changes every
 * 30 ms; the status waits until it rests. One arrow press on sketch 04 moves
 * the pixel, judges the answer and may tick a task off: the three come as one
 * message (pixel, then verdict, then task), not three that interrupt each other.
 * What the sketch's setup() selects is on the page, not news: the voice speaks
 * once the student has done something (a key, a press, a typed value), so a
 * message made while the page loads is not said at some later moment, as if
 * the student's first key had caused it. While a message waits to be said the
 * status carries `data-pending` (a walk by keys waits for the page's voice).
 */
import { element } from '../dom.js';

/** What the student does: the page's voice speaks after the first of them. */
const STUDENT_EVENTS = ['keydown', 'pointerdown', 'input', 'change'];
/** How long the news must rest before it is said, ms. */
export const ANNOUNCE_DELAY_MS = 200;
/** The most words one part (the pixel, a verdict, a task) may have. */
export const MAX_WORDS = 40;
/** The most words one message of the page may have, all its parts together. */
export const MAX_MESSAGE_WORDS = 60;

/**
 * The page's voice: its status element (made on first use, at the end of the
 * body), the parts said since it last spoke, and the parts that no longer speak
 * because another speaks for them (sketch 04's verdict says the pixel as the
 * line to type, so the inspector's line of the ray's own angles is not said).
 */
let voice = null;

function pageVoice() {
  if (voice?.status.isConnected) return voice;
  const status = element('p', { class: 'rt-visually-hidden', role: 'status', 'aria-atomic': 'true', 'data-announce': 'page' });
  document.body.append(status);
  voice = { status, parts: new Map(), silenced: new Map(), timer: 0, delay: ANNOUNCE_DELAY_MS };
  return voice;
}

/**
 * Has the student done anything on this page yet? Heard from the first part
 * of the voice on (made as the page's views are made, before any key: a voice
 * made on the first key must say what that key did), capturing (a handler
 * that stops an event does not hide it). Not at import: importing the kit
 * touches no page.
 */
let studentActed = typeof document === 'undefined', listening = false;
function listenForTheStudent() {
  if (studentActed || listening) return;
  listening = true;
  const acted = () => {
    studentActed = true;
    for (const type of STUDENT_EVENTS) document.removeEventListener(type, acted, true);
  };
  for (const type of STUDENT_EVENTS) document.addEventListener(type, acted, true);
}

/** Says the parts heard since the last message, in their order, as one message. */
function speak(v) {
  v.timer = 0;
  delete v.status.dataset.pending;
  const parts = [...v.parts.entries()].filter(([name]) => !v.silenced.get(name)).map(([, part]) => part).sort((a, b) => a.order - b.order);
  v.parts.clear();
  if (parts.length === 0) return;
  let text = limitWords(parts.map((p) => p.text).join(' '), MAX_MESSAGE_WORDS);
  // the same words again (a second press that found the same): a status that does not change says nothing
  if (v.status.textContent === text) text += '\u00a0';
  v.status.textContent = text;
}

/**
 * One part of the page's voice.
 * @param {object} [options]
 * @param {string} [options.name] what it announces ('pixel', 'verdict', 'task', …): its `data-announce`, for tests
 * @param {number} [options.order=0] where it comes in a message said together with others (smaller first)
 * @param {string} [options.speaksFor] the name of a part this one says instead (that part is no longer said)
 * @param {number} [options.delay=ANNOUNCE_DELAY_MS]
 * @returns {{ element: HTMLElement, say: (text: string) => void, destroy: () => void }} `element` holds the
 *   part's last words for whoever reads the page's text (hidden: the page's status says them)
 * @example
 * const voice = createAnnouncer({ name: 'explain', order: 1 }); // after the pixel, in the same message
 * view.onSelect(() => voice.say('d > r: the ray passes the sphere by.'));
 */
export function createAnnouncer({ name = '', order = 0, speaksFor = '', delay = ANNOUNCE_DELAY_MS } = {}) {
  listenForTheStudent();
  const last = element('p', { hidden: '', 'data-announce': name });
  const v = pageVoice();
  v.status.before(last); // on the page beside the voice, unless its part puts it in its own place
  const key = name || `part-${v.parts.size}-${Math.random()}`;
  if (speaksFor) v.silenced.set(speaksFor, (v.silenced.get(speaksFor) ?? 0) + 1);
  return {
    element: last,
    say(text) {
      const words = limitWords(text);
      last.textContent = words;
      const now = pageVoice();
      if (!studentActed) return; // the page as it opens: read with the page, not said
      now.parts.set(key, { text: words, order });
      now.status.dataset.pending = '';
      clearTimeout(now.timer);
      now.timer = setTimeout(() => speak(now), delay);
    },
    destroy() {
      last.remove(); // its part is gone: a sketch swapped in place makes its own again
      voice?.parts.delete(key);
      if (speaksFor && voice) voice.silenced.set(speaksFor, Math.max(0, (voice.silenced.get(speaksFor) ?? 1) - 1));
    },
  };
}

/** At most MAX_WORDS words of `text` (a long name a student typed must not fill a screen reader). */
export function limitWords(text, max = MAX_WORDS) {
  const words = String(text).trim().split(/\s+/);
  return words.length <= max ? words.join(' ') : `${words.slice(0, max - 1).join(' ')} …`;
}

/** True when the student asked for less motion (the system's "reduce motion"). */
export function reducedMotion() {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}
