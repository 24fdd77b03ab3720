/**
 * A read-only text box for text the kit writes (a pixel's CSV, a scene's
 * code): it shows the text as it is, with two exceptions.
 *
 * - A CR (a name may hold one) shows as ␍: a text box turns every CR into a
 *   LF, so the box would show a row split in two that the CSV keeps whole.
 * - At most BOX_CHARS characters, cut at a line's end: a text box lays out
 *   all of its text, and 1 MB of it held the page for seconds. The copy and
 *   the download get the whole text.
 */

/** The most characters a box shows (about 30 ms to lay out in Chromium). */
export const BOX_CHARS = 20_000;

/**
 * Puts `text` in `box` as the box can show it; returns '' when the box shows
 * it all, else a note saying how much it shows.
 * @param {HTMLTextAreaElement} box
 * @param {string} text
 * @example
 * note.textContent = showInBox(codeBox, sceneToCode(scene)); // '' or 'The box shows the first 180 of 30,004 lines; …'
 */
export function showInBox(box, text) {
  const visible = text.replaceAll('\r', '␍');
  if (visible.length <= BOX_CHARS) {
    box.value = visible;
    return '';
  }
  const end = visible.lastIndexOf('\n', BOX_CHARS - 1) + 1 || BOX_CHARS;
  box.value = visible.slice(0, end);
  const lines = (text) => text.split('\n').length - (text.endsWith('\n') ? 1 : 0);
  return `The box shows the first ${lines(box.value).toLocaleString('en')} of ${lines(text).toLocaleString('en')} lines; copying or downloading gives them all.`;
}

/**
 * Lets the browser save `text` as a file named `filename`.
 * @example
 * downloadText(sceneToCode(scene), 'scene.js', 'text/javascript');
 */
export function downloadText(text, filename, type = 'text/plain') {
  const url = URL.createObjectURL(new Blob([text], { type: `${type};charset=utf-8` }));
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}
