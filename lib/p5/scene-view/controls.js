/**
 * The 3D view's figure: its caption, the stage the canvas goes on (with a
 * layer for labels over it), and the bar: Shoot rays, Stop, the speed slider,
 * Reset view and the turn / zoom buttons (scene-view-keys.js). The buttons call
 * the view's own methods, passed in.
 */
import { element } from '../dom.js';
import { createOrbitButtons } from './keys.js';
import { orbitChanged } from './words.js';
import { reducedMotion } from '../page/announce.js';

/** Speeds the shoot slider offers, rays per second. */
export const SPEEDS = [1, 2, 4, 8, 15, 30, 60, 120];

/**
 * The controls, to append to the bar: `{ controls, stopButton }`.
 * @param {object} view
 * @param {number} view.raysPerSecond the speed shown at first (one of SPEEDS)
 * @param {() => unknown} view.shoot
 * @param {() => unknown} view.stop
 * @param {(raysPerSecond: number) => unknown} view.setSpeed
 * @param {() => unknown} view.reset
 * @param {Parameters<typeof createOrbitButtons>[0]} view.orbitView what the turn and zoom buttons move
 */
export function createControls({ raysPerSecond, shoot, stop, setSpeed, reset, orbitView }) {
  const resetButton = element('button', { type: 'button', class: 'rt-button', 'data-view3d-reset': '', title: 'Look from the first point of view again' }, 'Reset view');
  resetButton.addEventListener('click', () => { reset(); orbitChanged(orbitView); });
  const shootButton = element('button', { type: 'button', class: 'rt-button', 'data-view3d-shoot': '', title: 'Trace the picture again, one ray at a time, and watch each ray fly' }, 'Shoot rays');
  // reduced motion: no rays fly; the picture is traced again at once (the selected pixel's rays stay drawn)
  shootButton.addEventListener('click', () => (reducedMotion() ? orbitView.view.restart() : shoot()));
  const stopButton = element('button', { type: 'button', class: 'rt-button', 'data-view3d-stop': '', title: 'Stop shooting rays (Esc)', disabled: '' }, 'Stop');
  stopButton.addEventListener('click', () => stop());
  const speedText = element('span', { class: 'rt-view3d-speed-text' }, `${raysPerSecond} rays/s`);
  const speed = element('input', {
    type: 'range', min: '0', max: String(SPEEDS.length - 1), step: '1', value: String(SPEEDS.indexOf(raysPerSecond)),
    'data-view3d-speed': '', 'aria-label': 'Rays per second',
  });
  speed.addEventListener('input', () => {
    const v = SPEEDS[Number(speed.value)];
    speedText.textContent = `${v} rays/s`;
    setSpeed(v);
  });
  const speedLabel = element('label', { class: 'rt-view3d-speed' }, 'Speed ', speed, speedText);
  speedLabel.style.display = 'inline-flex';
  speedLabel.style.alignItems = 'center';
  speedLabel.style.gap = '0.4rem';
  return { controls: [shootButton, stopButton, speedLabel, resetButton, createOrbitButtons(orbitView)], stopButton };
}

/**
 * The figure, empty of canvas: `{ figure, stage, labelLayer, bar }`.
 * @param {{ width: number, height: number, label?: string }} size the canvas's size (CSS px) and the caption
 */
export function createFigure({ width, height, label }) {
  const labelLayer = /** @type {HTMLCanvasElement} */ (element('canvas', { class: 'rt-view3d-labels', 'aria-hidden': 'true', width, height }));
  Object.assign(labelLayer.style, { position: 'absolute', left: '0', top: '0', width: `${width}px`, height: `${height}px`, pointerEvents: 'none' });
  const stage = element('div', { class: 'rt-stage rt-view3d-stage' }, labelLayer);
  stage.style.position = 'relative';
  stage.style.width = `${width}px`;
  stage.style.height = `${height}px`;
  const figure = element('figure', { class: 'rt-view rt-view3d', 'data-scene-view': '' });
  if (label) figure.append(element('figcaption', { class: 'rt-label' }, label));
  figure.append(stage);
  const bar = element('div', { class: 'rt-bar rt-view3d-bar' });
  figure.append(bar);
  return { figure, stage, labelLayer, bar };
}

/** Puts p5's canvas on the stage and marks it for the page contract: `data-view3d`, focusable, described. */
export function dressCanvas(canvas, stage, selected) {
  stage.prepend(canvas);
  canvas.style.display = 'block';
  canvas.style.touchAction = 'none';
  canvas.style.cursor = 'grab';
  canvas.setAttribute('data-view3d', '');
  canvas.setAttribute('tabindex', '0');
  // an application: screen readers in browse mode pass it the arrow keys (scene-view-words.js says where it looks from)
  canvas.setAttribute('role', 'application');
  canvas.setAttribute('aria-roledescription', '3D view');
  canvas.setAttribute('aria-label', 'The scene in 3D: the arrow keys or dragging turn it, + and − or the wheel zoom it, Esc stops shooting rays; click a pixel of the image plane to select it');
  canvas.classList.add('rt-view3d-canvas');
  canvas.setAttribute('data-selected', selected ? `${selected.x},${selected.y}` : '');
}
