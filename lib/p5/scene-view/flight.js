/**
 * Shoot's flight: while the tracer view traces in slow motion, each pixel it
 * traces sends a ray from the eye that grows, leg by leg, along the pixel's
 * story (the primary ray, then at its hit the normal and the shadow rays and
 * the bounce, and so on), then fades. No p5 and no clock of its own: the
 * caller passes the time and draws what `flightFrame` says.
 */
import { clamp } from '../../math/numbers.js';
import { Vec3 } from '../../math/vec3.js';
import { show } from '../../text/check.js';

/** Rays in flight at most: older ones go (they would only overlap). */
export const MAX_FLYING = 60;
/** Of the pixels traced since the last look, only this many last ones fly. */
export const FLY_LAST = 8;

/** A Shoot speed, checked: rays per second, a number greater than 0. */
export function checkSpeed(raysPerSecond) {
  if (!(typeof raysPerSecond === 'number' && raysPerSecond > 0 && Number.isFinite(raysPerSecond))) throw new RangeError(`raysPerSecond must be a number greater than 0, got ${show(raysPerSecond)}`);
  return raysPerSecond;
}

/** Seconds a ray takes for one leg of its flight (eye → hit, hit → light, …) at `raysPerSecond`. */
export function legSeconds(raysPerSecond) {
  return clamp(1.6 / raysPerSecond, 0.06, 0.8);
}

/** When a segment starts to grow, in legs of the flight: a ray of depth d after d legs, the normal and shadow rays at its end. */
export function startOf(s) {
  return s.kind === 'normal' || s.kind === 'shadow' ? s.depth + 1 : s.depth;
}

/**
 * The pixels traced since `last` up to `current`, in scanline order, in a
 * picture `width` wide: `{ count, fly }`, `fly` the last FLY_LAST of them
 * (the others are counted, not drawn). Null when nothing new was traced.
 * @param {{x: number, y: number}|null} last the pixel seen last time (null: none yet)
 * @param {{x: number, y: number}|null} current the pixel traced last
 */
export function tracedSince(last, current, width) {
  if (!current || (last && current.x === last.x && current.y === last.y)) return null;
  const from = last ? last.y * width + last.x + 1 : 0, to = current.y * width + current.x;
  const fly = [];
  for (let i = Math.max(from, to - (FLY_LAST - 1)); i <= to; i++) fly.push({ x: i % width, y: Math.floor(i / width) });
  return { count: to - from + 1, fly };
}

/**
 * One frame of the flight at time `now` (ms), each leg `legMs` long:
 * `{ flying, segments, moving }`: the flights still shown (one that arrived
 * a while ago goes, unless it is the newest), the segments to draw as far as
 * they have grown (a shadow ray shows where it is blocked, and a ray its hit,
 * only once it has arrived), and whether anything still moves.
 * @param {Array<{ segments: object[], t0: number }>} flying
 */
export function flightFrame(flying, now, legMs) {
  let moving = false;
  const segments = [];
  const kept = flying.filter((f, i) => {
    const phase = (now - f.t0) / legMs;
    const last = i === flying.length - 1;
    const end = Math.max(...f.segments.map((s) => startOf(s) + 1));
    if (phase > end + 2 && !last) return false; // arrived a while ago: gone
    if (phase < end) moving = true;
    for (const s of f.segments) {
      const k = clamp(phase - startOf(s), 0, 1);
      if (k <= 0) continue;
      const to = new Vec3(s.from.x + (s.to.x - s.from.x) * k, s.from.y + (s.to.y - s.from.y) * k, s.from.z + (s.to.z - s.from.z) * k);
      segments.push({ ...s, to, blockedAt: k === 1 ? s.blockedAt : null, hit: s.hit && k === 1 });
    }
    return true;
  });
  if (kept.length > 1) moving = true; // old ones still to clear away
  return { flying: kept, segments, moving };
}

/** Adds a flight starting at `t0`, dropping the oldest beyond MAX_FLYING. */
export function launch(flying, segments, t0) {
  flying.push({ segments, t0 });
  if (flying.length > MAX_FLYING) flying.shift();
  return flying;
}

/** One Shoot's flight: the rays in flight, how many rays were sent, and the pixel seen traced last. */
export class Flight {
  /** @type {Array<{ segments: object[], t0: number }>} */
  flying = [];
  shots = 0;
  /** @type {{x: number, y: number}|null} */
  last = null;

  /**
   * The tracer view traced up to `current`: the pixels since the last look
   * are counted, and the last few start flying, each with its story from
   * `storyOf(x, y)`, at the time `now()` says (ms). True when any was new.
   */
  traced(current, width, storyOf, now = () => performance.now()) {
    const traced = tracedSince(this.last, current, width);
    if (!traced) return false;
    for (const { x, y } of traced.fly) launch(this.flying, storyOf(x, y), now());
    this.shots += traced.count;
    this.last = { x: current.x, y: current.y };
    return true;
  }

  /** The flight at time `now` (ms), each leg `legMs` long: `{ segments, moving }` (see flightFrame); arrived rays go. */
  frame(now, legMs) {
    const frame = flightFrame(this.flying, now, legMs);
    this.flying = frame.flying;
    return frame;
  }
}
