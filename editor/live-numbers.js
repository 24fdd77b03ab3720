/**
 * The page's side of a scrubbed number (number-scrub.js): whether the new
 * value can go to the frame as a value of the scene (live, coarse to fine,
 * no new run) or the code must run again, as after typing.
 *
 * The first step of a literal runs the code at once: the scene the frame
 * reports then, beside the one before, says which fields the literal writes
 * (live-values.js). From then on, while the code differs from the code on
 * show only inside that literal (more steps, a drag, Undo, Redo), the page
 * sends the frame the literal's value, read from the page's own code, for
 * those fields. Nothing the frame says becomes code.
 */
import { fieldsOfLiteral, valueInPlace, fieldWords } from './live-values.js';

/**
 * @param {{ send: (message: object) => boolean }} host the frames (frame-host.js)
 * @returns {{
 *   ran: (code: string) => void, setUp: () => void, failed: () => void, gone: () => void,
 *   scene: (message: { scene: string|null, camera: string|null }) => boolean,
 *   changed: (code: string, scrub?: { from: number, to: number, was: string, now: string }) => { run: 'now'|'later'|null, words: string|null }
 * }}
 */
export function liveNumbers(host) {
  /** The code of the picture on show, and the scene and camera its frame last reported (plain data). */
  let shownCode = null, shownData = null, ranCode = null;
  /** The literal whose fields are known: the code around it and the fields' paths (null: it is no field of the scene). */
  let binding = null;
  /** A literal's first step, running: the code around it, its two values, the scene before. */
  let probe = null;

  /** Sends the literal's value in `code` to the frame when only the bound literal differs from the code on show. */
  function sendInPlace(code) {
    if (!binding?.fields || shownCode === null || valueInPlace(binding, shownCode) === null) return null;
    const value = valueInPlace(binding, code);
    if (value === null || !host.send({ type: 'values', changes: binding.fields.map((path) => ({ path, value })) })) return null;
    shownCode = code;
    const names = [...new Set(binding.fields.map(fieldWords))];
    return `${names.join(' and ')} ${value}`;
  }

  return {
    /** A run of `code` starts (a new frame): a probe is only its own run's. */
    ran(code) {
      ranCode = code;
      if (probe && probe.code !== code) probe = null;
    },
    /** The run's frame is on show. */
    setUp() {
      shownCode = ranCode;
      shownData = null;
    },
    /** The run stopped at a mistake before its picture: the literal's fields stay unknown. */
    failed() { probe = null; },
    /** The frames are gone (stopped in a loop): no picture is on show, whatever code comes next runs. */
    gone() {
      shownCode = shownData = probe = null;
    },
    /** The frame's report of its scene; true when it taught the page a literal's fields (then the code is followed again). */
    scene(message) {
      const data = readReport(message);
      const taught = probe !== null && shownCode === probe.code;
      if (taught) {
        const fields = data && fieldsOfLiteral(probe.before, data, probe.was, probe.now);
        binding = { prefix: probe.prefix, suffix: probe.suffix, fields }; // fields null: no field of the scene
        probe = null;
      }
      shownData = data;
      return taught;
    },
    /**
     * The editor's code changed (by a scrub, if `scrub`): what to do.
     * @returns {{ run: 'now'|'later'|null, words: string|null }} run the code now, after the pause, or not; what to say
     */
    changed(code, scrub) {
      if (code === shownCode) return { run: null, words: null };
      const words = sendInPlace(code);
      if (words !== null) return { run: null, words };
      if (probe && valueInPlace(probe, code) !== null) return { run: null, words: null }; // its first step is running
      if (scrub && binding?.fields === null && valueInPlace(binding, code) !== null) return { run: 'later', words: `${scrub.now}: your code runs again` };
      const prefix = code.slice(0, scrub?.from), suffix = shownCode?.slice(scrub?.to) ?? '';
      if (scrub && shownData && shownCode === `${prefix}${scrub.was}${suffix}` && code.endsWith(suffix)) {
        probe = { prefix, suffix, was: Number(scrub.was), now: Number(scrub.now), before: shownData, code };
        return { run: 'now', words: null };
      }
      return { run: 'later', words: scrub ? `${scrub.now}: your code runs again` : null };
    },
  };
}

/** The frame's scene and camera as plain data; null when it sent none or text that is not JSON (the frame is not trusted). */
function readReport({ scene, camera }) {
  if (scene === null || camera === null) return null;
  try {
    return { scene: JSON.parse(scene), camera: JSON.parse(camera) };
  } catch {
    return null;
  }
}
