/**
 * One short spoken line for screen readers: an atomic status (role="status")
 * that says only the last of quick changes. While an arrow key repeats, the
 * selected pixel changes every 30 ms; the status waits until it rests.
 */
import { element } from './dom.js';

/** How long the news must rest before it is said, ms. */
export const ANNOUNCE_DELAY_MS = 200;
/** The most words one announcement may have. */
export const MAX_WORDS = 40;

/**
 * @param {object} [options]
 * @param {string} [options.name] the `data-announce` value (what it announces), for tests
 * @param {number} [options.delay=ANNOUNCE_DELAY_MS]
 * @returns {{ element: HTMLElement, say: (text: string) => void, destroy: () => void }}
 */
export function createAnnouncer({ name = '', delay = ANNOUNCE_DELAY_MS } = {}) {
  const status = element('p', { class: 'rt-visually-hidden', role: 'status', 'aria-atomic': 'true', 'data-announce': name });
  let timer = 0;
  return {
    element: status,
    say(text) {
      clearTimeout(timer);
      timer = setTimeout(() => { status.textContent = limitWords(text); }, delay);
    },
    destroy() { clearTimeout(timer); },
  };
}

/** At most MAX_WORDS words of `text` (a long name a student typed must not fill a screen reader). */
export function limitWords(text, max = MAX_WORDS) {
  const words = String(text).trim().split(/\s+/);
  return words.length <= max ? words.join(' ') : `${words.slice(0, max - 1).join(' ')} …`;
}
