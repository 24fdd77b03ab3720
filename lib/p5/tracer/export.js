/**
 * The tracer view's picture as a PNG file, one pixel per traced pixel: the
 * picture's canvas holds the traced image at its own resolution and nothing
 * else (the grid and the marks are on the overlay), so it is saved as it is.
 */
import { element } from '../dom.js';

/** A canvas's picture as a PNG data URL. */
export function pngDataURL(canvas) {
  return canvas.toDataURL('image/png');
}

/** The name a saved picture gets: its resolution and visual mode, `trace-64x48-shaded.png`. */
export function pngFilename(width, height, mode) {
  return `trace-${width}x${height}-${mode}.png`;
}

/** Lets the browser save a URL's contents as a file named `filename`. */
export function download(url, filename) {
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  a.click();
}

/**
 * The "Save PNG" button under a tracer view (`data-export`).
 * @param {() => void} save what a click does (the view's downloadPNG)
 */
export function createSaveButton(save) {
  const button = element('button', { type: 'button', class: 'rt-button', 'data-export': '', title: 'Download the traced image as a PNG, one pixel per traced pixel' }, 'Save PNG');
  button.addEventListener('click', () => save());
  return button;
}
