/**
 * The 3D view by keyboard and by buttons, not by dragging only: the arrow
 * keys turn it (Shift: further), + and − zoom it, Esc stops a Shoot; the same
 * moves as buttons beside it, for a pointer that cannot drag.
 */
import { element } from '../dom.js';
import { orbitChanged } from './words.js';

/** Degrees one arrow press turns the view (Shift: three times as far). */
export const TURN_STEP = 10;
/** How much nearer one + press brings the view (− as much further). */
export const ZOOM_STEP = 1.25;

/**
 * What a key does to the view: `{ yaw, pitch }` degrees to turn by, or
 * `{ zoom }` a factor for the distance (< 1: nearer), or `{ stop: true }`;
 * null for a key it does not use.
 * @param {string} key a keyboard event's `key`
 * @param {boolean} [shift]
 */
export function orbitKey(key, shift = false) {
  const step = shift ? 3 * TURN_STEP : TURN_STEP;
  switch (key) {
    case 'ArrowLeft': return { yaw: step, pitch: 0 };
    case 'ArrowRight': return { yaw: -step, pitch: 0 };
    case 'ArrowUp': return { yaw: 0, pitch: -step };
    case 'ArrowDown': return { yaw: 0, pitch: step };
    case '+': case '=': return { zoom: 1 / ZOOM_STEP };
    case '-': case '_': return { zoom: ZOOM_STEP };
    case 'Escape': return { stop: true };
    default: return null;
  }
}

/**
 * Does what `orbitKey` says to the view; true when the key was used.
 * @param {{ turn(yaw: number, pitch: number): unknown, zoom(factor: number): unknown, stop(): unknown, shooting: boolean, canvas?: HTMLCanvasElement | null }} view
 */
export function applyOrbitKey(view, key, shift) {
  const move = orbitKey(key, shift);
  if (!move) return false;
  if (move.stop) {
    if (!view.shooting) return false;
    view.stop();
  } else if (move.zoom) {
    view.zoom(move.zoom);
  } else {
    view.turn(move.yaw, move.pitch);
    orbitChanged(view); // its name says where it looks from now, and the page says it once it rests
  }
  return true;
}

/** The arrow keys, + and − on the 3D canvas; Esc anywhere in its figure stops a Shoot. */
export function listenForOrbitKeys(canvas, figure, view) {
  canvas.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || e.key === 'Escape') return;
    if (applyOrbitKey(view, e.key, e.shiftKey)) e.preventDefault(); // the page must not scroll
  });
  figure.addEventListener('keydown', (e) => {
    if (e.key === 'Escape' && applyOrbitKey(view, e.key, false)) e.preventDefault();
  });
  canvas.addEventListener('pointerup', () => orbitChanged(view)); // after a drag
  queueMicrotask(() => orbitChanged(view, false)); // once the view has drawn its first orbit: the name says where from
}

/** Buttons that turn and zoom the view, each named in words: `{ element }`. */
export function createOrbitButtons(view) {
  const button = (text, label, key, action) => {
    const b = element('button', { type: 'button', class: 'rt-button rt-orbit-button', 'data-view3d-turn': key, 'aria-label': label, title: label }, text);
    b.addEventListener('click', action);
    return b;
  };
  const group = element('span', { class: 'rt-orbit-buttons', role: 'group', 'aria-label': 'Turn and zoom the 3D view' },
    button('◀', 'Turn left', 'left', () => applyOrbitKey(view, 'ArrowLeft')),
    button('▶', 'Turn right', 'right', () => applyOrbitKey(view, 'ArrowRight')),
    button('▲', 'Look from higher', 'up', () => applyOrbitKey(view, 'ArrowDown')),
    button('▼', 'Look from lower', 'down', () => applyOrbitKey(view, 'ArrowUp')),
    button('+', 'Zoom in', 'in', () => applyOrbitKey(view, '+')),
    button('−', 'Zoom out', 'out', () => applyOrbitKey(view, '-')));
  return group;
}
