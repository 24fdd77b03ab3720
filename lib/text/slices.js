/**
 * Long text built a slice at a time: the lines come from a generator, and
 * every SLICE_MS the work waits for a task of its own, so the page answers
 * between slices. At 10,000 spheres the scene's code (1.4 MB) or a pixel's
 * CSV (1 MB) took a task of 100–300 ms when built at once.
 *
 *   const code = await joinInSlices(sceneCodeLines(scene)); // the same text as sceneToCode(scene)
 */

/** Milliseconds of work between two waits. */
export const SLICE_MS = 10;

/**
 * Resolves in a task of its own (after the browser has had its turn: input, painting).
 * @example
 * nextTask().then(() => 'the page has answered in between');
 */
export function nextTask() {
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/**
 * The lines of `lines` (any iterable of strings, read lazily) joined into one
 * text, waiting for `pause()` whenever a slice has taken `sliceMs`.
 * @param {Iterable<string>} lines
 * @param {{ sliceMs?: number, now?: () => number, pause?: () => Promise<unknown> }} [options]
 * @returns {Promise<string>}
 * @example
 * joinInSlices(sceneCodeLines(classScene())).then((code) => code); // sceneToCode(classScene()), a slice of 10 ms at a time
 */
export async function joinInSlices(lines, { sliceMs = SLICE_MS, now = () => performance.now(), pause = nextTask } = {}) {
  const parts = [];
  let start = now();
  for (const line of lines) {
    parts.push(line);
    if (now() - start >= sliceMs) {
      await pause();
      start = now();
    }
  }
  return parts.join('');
}
