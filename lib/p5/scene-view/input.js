/**
 * The 3D view by pointer: drag to turn it, the wheel to zoom, a click (a
 * press and release that hardly moved) on the image plane to select a pixel;
 * h / v, on either view, show every ray of the selected pixel's row / column.
 * The arrow keys and the buttons are scene-view-keys.js. The orbit's maths
 * (how far a drag turns, how near the wheel may come) is here, with no page.
 */
import { clamp } from '../../math/numbers.js';
import { show, checkOptions } from '../../text/check.js';
import { screenRay, pickImagePlane } from '../../lesson/rays3d.js';
import { listenForOrbitKeys } from './keys.js';

/** Mouse travel (px) under which a press and release is a click, not a turn. */
export const CLICK_SLOP = 4;
/** Degrees a drag turns the view per px of travel. */
export const DRAG_DEGREES = 0.4;

/** The pitch the view may look from, degrees: never straight down or up (the orbit would flip). */
export function clampPitch(pitch) {
  return clamp(pitch, -89, 89);
}

/** Where a drag of (dx, dy) px turns the view from `start` `{ yaw, pitch }`: right turns it left, down looks from higher. */
export function dragOrbit(start, dx, dy) {
  return { yaw: start.yaw - dx * DRAG_DEGREES, pitch: start.pitch + dy * DRAG_DEGREES };
}

/** True once a press has moved far enough to be a drag. */
export function isDrag(dx, dy) {
  return Math.hypot(dx, dy) >= CLICK_SLOP;
}

/** The view's distance times `factor`, kept from 0.3 to 8 times the scene's radius `r`. */
export function zoomDistance(distance, factor, r) {
  return clamp(distance * factor, r * 0.3, r * 8);
}

/** The factor one wheel event (its deltaY) zooms by: down (positive) goes further. */
export function wheelFactor(deltaY) {
  return Math.exp(deltaY * 0.0015);
}

/**
 * The traced pixel `{ x, y, point, t }` under a point of the 3D canvas (lib/lesson/rays3d.js pickImagePlane), or null off the
 * image plane: the ray from the orbit's eye through that point, met with the plane.
 * @param {{ left: number, top: number, width: number, height: number }} box the canvas's box on screen
 * @param {number} clientX @param {number} clientY the point, in client coordinates
 * @param {{ eye: object, camera: object, planeDistance: number, width: number, height: number, fovy: number }} view
 *   the orbit camera (lib/lesson/rays3d.js orbitCamera), the traced camera, the plane's distance, the canvas's size and field
 */
export function pixelUnder(box, clientX, clientY, { eye, camera, planeDistance, width, height, fovy }) {
  const px = ((clientX - box.left) / box.width) * width, py = ((clientY - box.top) / box.height) * height;
  const { origin, direction } = screenRay(eye, px, py, width, height, fovy);
  return pickImagePlane(camera, planeDistance, origin, direction);
}

/** What the h and v keys show: 'row', 'column', or null for any other key (or with Ctrl, Alt or Meta). */
export function fanKey(event) {
  if (event.ctrlKey || event.metaKey || event.altKey) return null;
  return { h: 'row', v: 'column' }[event.key.toLowerCase()] ?? null;
}

/** An orbit's given parts `{ yaw?, pitch?, distance? }`, checked: degrees, and a distance > 0. */
export function checkOrbit(orbit) {
  const own = checkOptions(orbit, ['yaw', 'pitch', 'distance'], 'orbit');
  const out = {};
  for (const key of Object.keys(own)) {
    const v = orbit[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || (key === 'distance' && v <= 0)) throw new RangeError(`orbit.${key} must be a ${key === 'distance' ? 'distance greater than 0' : 'number of degrees'}, got ${show(v)}`);
    out[key] = v;
  }
  return out;
}

/**
 * Listens on the 3D canvas (and, for h / v, on the tracer view's canvas too).
 * @param {HTMLCanvasElement} canvas the 3D canvas
 * @param {object} input what the listeners need of the view
 * @param {HTMLElement} input.figure the 3D view's figure (Esc anywhere in it stops a Shoot)
 * @param {HTMLElement} input.tracerCanvas the tracer view's canvas
 * @param {{ orbit: {yaw: number, pitch: number, distance: number}, fan: string|null, setOrbit(o: object): unknown, showFan(kind: string|null): unknown, turn(yaw: number, pitch: number): unknown, zoom(f: number): unknown, stop(): unknown, shooting: boolean }} input.view
 * @param {() => number} input.radius the scene's radius now (the wheel's limits)
 * @param {(clientX: number, clientY: number) => void} input.pick a click at a point of the screen
 */
export function listenForInput(canvas, { figure, tracerCanvas, view, radius, pick }) {
  const keys = (e) => {
    const kind = fanKey(e);
    if (kind) view.showFan(view.fan === kind ? null : kind);
  };
  canvas.addEventListener('keydown', keys);
  tracerCanvas.addEventListener('keydown', keys);
  listenForOrbitKeys(canvas, figure, view);
  let drag = null;
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    canvas.setPointerCapture?.(e.pointerId);
    const { yaw, pitch } = view.orbit;
    drag = { x: e.clientX, y: e.clientY, yaw, pitch, moved: false };
    canvas.style.cursor = 'grabbing';
  });
  canvas.addEventListener('pointermove', (e) => {
    const d = drag;
    if (!d || !(e.buttons & 1)) return;
    const dx = e.clientX - d.x, dy = e.clientY - d.y;
    if (!d.moved && !isDrag(dx, dy)) return;
    d.moved = true;
    view.setOrbit(dragOrbit(d, dx, dy));
  });
  const release = (e) => {
    const d = drag;
    drag = null;
    canvas.style.cursor = 'grab';
    if (d && !d.moved && e.type === 'pointerup') pick(e.clientX, e.clientY);
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault(); // zoom the view, not scroll the page
    view.setOrbit({ distance: zoomDistance(view.orbit.distance, wheelFactor(e.deltaY), radius()) });
  }, { passive: false });
}
