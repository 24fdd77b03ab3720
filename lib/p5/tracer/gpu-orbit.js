/**
 * Moving the camera of a view on the GPU engine, where a whole frame follows
 * every move: dragging the picture orbits the camera about the point it looks
 * at, the arrow keys turn it too (while no pixel is selected: they move a
 * selected pixel, as on every view; Escape lets the pixel go), + and − move
 * it closer and farther. A press without a drag still selects its pixel.
 * A move by keys or a drag is said once it rests, in the lesson's angles
 * (the camera's H and V), so that a student who cannot see it hears it.
 */
import { Camera } from '../../math/camera.js';
import { formatAngle, formatNumber } from '../../text/format.js';
import { createAnnouncer } from '../page/announce.js';

/** Degrees per screen pixel dragged, per arrow press; the share + and − move the camera by. */
const DRAG = 0.4, TURN = 5, ZOOM = 0.9;
/** How far ahead of the camera the point it orbits lies, when nothing is nearer. */
const AHEAD = 20;
const ARROWS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };

/** Listens on the view's canvas; acts only while `view.engine` is 'gpu'. */
export function listenForOrbit(canvas, view) {
  let press = null, voice = null;
  const say = (text) => (voice ??= createAnnouncer({ name: 'camera', order: 1 })).say(text);
  canvas.addEventListener('pointerdown', (event) => {
    press = view.engine === 'gpu' ? { x: event.clientX, y: event.clientY, dragging: false } : null;
  }, { capture: true });
  canvas.addEventListener('pointermove', (event) => {
    if (!press || !event.buttons) return;
    const dx = event.clientX - press.x, dy = event.clientY - press.y;
    if (!press.dragging && Math.hypot(dx, dy) < 4) return;
    press.dragging = true;
    event.stopImmediatePropagation(); // a drag orbits; it does not drag the selection
    press.x = event.clientX; press.y = event.clientY;
    orbit(view, dx * DRAG, -dy * DRAG, 1);
  }, { capture: true });
  canvas.addEventListener('pointerup', () => {
    if (press?.dragging) say(cameraWords(view));
    press = null;
  }, { capture: true });
  canvas.addEventListener('keydown', (event) => {
    if (view.engine !== 'gpu') return;
    const arrow = ARROWS[event.key];
    if (event.key === 'Escape' && view.selected) { view.select(null); say('No pixel selected: the arrow keys turn the camera.'); return stop(event); }
    if (event.key === '+' || event.key === '=') orbit(view, 0, 0, ZOOM);
    else if (event.key === '-' || event.key === '_') orbit(view, 0, 0, 1 / ZOOM);
    else if (arrow && !view.selected) orbit(view, arrow[0] * TURN, arrow[1] * TURN, 1);
    else return;
    say(cameraWords(view));
    stop(event);
  }, { capture: true });
}

function stop(event) {
  event.preventDefault();
  event.stopImmediatePropagation();
}

/** Where the camera looks now, in the answer line's angles: `Camera: H: 5; V: -8; 26 from the point it turns about.` */
export function cameraWords(view) {
  const c = view.camera;
  return `Camera: H: ${formatAngle(c.yaw)}; V: ${formatAngle(c.pitch)}; ${formatNumber(view.orbitDistance ?? AHEAD)} from the point it turns about.`;
}

/** Turns the view's camera by yaw and pitch degrees about the point it looks at, its distance times `scale`. */
export function orbit(view, yaw, pitch, scale) {
  const c = view.camera, f = c.forward, p = c.position;
  const distance = view.orbitDistance ?? AHEAD;
  const centre = [p.x + f.x * distance, p.y + f.y * distance, p.z + f.z * distance];
  const next = { yaw: c.yaw + yaw, pitch: Math.max(-89, Math.min(89, c.pitch + pitch)), distance: distance * scale };
  view.orbitDistance = next.distance;
  const r = Math.PI / 180, cp = Math.cos(next.pitch * r);
  const ahead = [Math.sin(next.yaw * r) * cp, Math.sin(next.pitch * r), -Math.cos(next.yaw * r) * cp]; // Camera's forward
  const position = centre.map((v, i) => v - ahead[i] * next.distance);
  view.setCamera(new Camera({ width: c.width, height: c.height, fov: c.fov, samples: c.samples, position, yaw: next.yaw, pitch: next.pitch }));
}
