/**
 * The student's code of a sketch, kept in this browser (localStorage), one
 * entry per sketch; none while it is the starter. Storage may be off or full:
 * then the code stays in the editor for this visit only.
 */

/** The most code kept per sketch (characters). */
export const MAX_KEPT = 200_000;
const STORE_PREFIX = 'raytracing-sketchbook:code:v1:';

/** The code kept for the sketch `name` (`NN-name`), or null. */
export function keptCode(name) {
  try { return localStorage.getItem(STORE_PREFIX + name); } catch { return null; }
}

/** Keeps `code` for the sketch `name`; the starter itself is not kept (it forgets the old code). */
export function keepCode(name, code, starter) {
  try {
    if (code === starter) localStorage.removeItem(STORE_PREFIX + name);
    else if (code.length <= MAX_KEPT) localStorage.setItem(STORE_PREFIX + name, code);
  } catch { /* storage off or full */ }
}
