/**
 * The 3D view in words: where it looks from, in its name and said once it
 * rests, so that turning it by keys or buttons is heard, not only seen. Every
 * burst of keys is said, with the view's yaw and pitch (a turn that stays in
 * one sector of words, or one against the pitch's limit, is heard too).
 * Yaw 0 looks from behind the eye the way the eye looks; yaw < 0 from its
 * right; pitch > 0 from above (lib/lesson/rays3d.js orbitCamera).
 */
import { createAnnouncer } from '../page/announce.js';

/** The keys of the 3D view, said in its name after where it looks from. */
const KEYS = 'arrow keys turn it, + and − zoom, Esc stops Shoot';

/**
 * Where the view looks from, in words: `'from behind the eye and to its right, from above'`.
 * @param {{ yaw: number, pitch: number }} orbit degrees
 */
export function orbitWords({ yaw, pitch }) {
  const y = ((((-yaw + 180) % 360) + 360) % 360) - 180; // > 0: to the eye's right
  const a = Math.abs(y), side = y > 0 ? 'right' : 'left';
  const around = a <= 15 ? 'from behind the eye' : a < 75 ? `from behind the eye and to its ${side}`
    : a <= 105 ? `from the eye's ${side}` : a < 165 ? `from in front of the eye, to its ${side}` : 'from in front, facing the eye';
  const height = Math.abs(pitch) < 10 ? 'at the eye\'s height' : pitch >= 60 ? 'from high above' : pitch > 0 ? 'from above' : 'from below';
  return `${around}, ${height}`;
}

/** Each 3D view's words, made on its first turn. */
const words = new WeakMap();

/**
 * Keeps a 3D view's canvas named by where it looks from, and says it once it
 * rests after a turn (keys, buttons, a drag). Call it after the view turned;
 * `speak = false` only names it (as the canvas comes).
 * @param {{ canvas?: HTMLCanvasElement | null }} view its canvas's data-yaw and data-pitch say where it looks from
 */
export function orbitChanged(view, speak = true) {
  if (!words.has(view)) words.set(view, createOrbitWords(view));
  words.get(view)(speak);
}

function createOrbitWords(view) {
  let voice = null; // made with the first orbit there is to say: a view without a canvas (yet) says nothing
  return (speak) => {
    const c = view.canvas;
    const orbit = c && c.dataset.yaw !== undefined ? { yaw: Number(c.dataset.yaw), pitch: Number(c.dataset.pitch) } : null;
    if (!orbit) return;
    const where = orbitWords(orbit);
    c.setAttribute('aria-label', `The scene in 3D, seen ${where}: ${KEYS}`);
    voice ??= createAnnouncer({ name: 'view3d' });
    if (speak) voice.say(`Seen ${where}: yaw ${Math.round(orbit.yaw)}°, pitch ${Math.round(orbit.pitch)}°.`);
  };
}
