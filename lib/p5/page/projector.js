/**
 * The "Projector" switch in a sketch page's header: bigger text everywhere
 * (html.projector, see sketches/sketch.css), and with it bigger pictures and
 * diagrams, since their sizes are in rem. Remembered across pages.
 */
import { element } from '../dom.js';

const KEY = 'raytracing-sketchbook:projector';

/** Adds the switch to the page's `<header>` once (no header: nothing), and applies the remembered choice. */
export function addProjectorSwitch() {
  if (typeof document === 'undefined') return;
  const header = document.querySelector('body > header');
  if (!header || header.querySelector('[data-projector]')) return;
  const on = remembered();
  const button = element('button', { type: 'button', class: 'rt-button rt-projector', 'data-projector': '', 'aria-pressed': String(on), title: 'Bigger text, pictures and diagrams, for the back of the room' }, 'Projector');
  button.addEventListener('click', () => setProjector(button.getAttribute('aria-pressed') !== 'true', button));
  header.append(button);
  if (on) setProjector(true, button);
}

function setProjector(on, button) {
  document.documentElement.classList.toggle('projector', on);
  button.setAttribute('aria-pressed', String(on));
  try { localStorage.setItem(KEY, on ? '1' : '0'); } catch { /* storage may be off: the switch still works on this page */ }
  window.dispatchEvent(new Event('resize')); // pictures measure themselves again
}

function remembered() {
  try { return localStorage.getItem(KEY) === '1'; } catch { return false; }
}
