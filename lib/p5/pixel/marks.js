/**
 * Marks on chosen pixels of a tracer view, drawn on a sketch's own p5 canvas
 * laid over the picture: the traced canvas stays exactly as traced.
 *
 *   const marks = createPixelMarks(p, view, 'pink-marks');
 *   p.draw = () => marks.draw(findPixels(view.buffer, 32, 24, isPink));
 *
 * Or all of it behind a tick box under the picture, with a count:
 *
 *   const pinkOnes = createPixelHighlight(p, view, { name: 'pink', label: 'Highlight every pink pixel', test: isPink, describe });
 *   p.draw = () => pinkOnes.draw();
 */
import { element } from '../dom.js';
import { checkOptions } from '../../text/check.js';

/**
 * Every pixel `{ x, y }` of an RGBA buffer whose `[r, g, b]` (0–255) passes
 * the test, row by row from the top-left.
 */
export function findPixels(rgba, width, height, test) {
  const found = [];
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      if (test([rgba[i], rgba[i + 1], rgba[i + 2]])) found.push({ x, y });
    }
  }
  return found;
}

/**
 * Makes the sketch's canvas an overlay on the view's picture, with the class
 * `name` and the attributes `data-<name>` and `data-overlay`:
 * `p.createPixelMarks({ view, name })`.
 * @returns {{ clear: () => void, draw: (pixels: {x: number, y: number}[]) => void }}
 *   clear() sizes the overlay to the picture on screen and empties it; draw() also marks each pixel with a dot.
 *   Both do nothing when the overlay already shows that: pass a new array to draw() for new marks.
 */
export function createPixelMarks(p, options) {
  const { view, name = 'pixel-marks' } = checkOptions(options, ['view', 'name'], 'createPixelMarks');
  const { width, height } = view.camera;
  // aria-hidden: the marks repeat what the picture and the count say
  p.createCanvas(width, height).parent(view.canvas.parentElement).class(name).attribute(`data-${name}`, '').attribute('data-overlay', '').attribute('aria-hidden', 'true');
  p.pixelDensity(1);
  // What the overlay shows now: the same marks at the same size are not drawn again, so a sketch
  // calling draw() every frame leaves the page still (no repaint each frame on a phone's battery).
  let shown = { pixels: null, k: 0 };
  const sized = (k) => p.width === view.camera.width * k && p.height === view.camera.height * k;
  const marks = {
    clear() {
      const k = view.scale; // screen pixels per traced pixel: the overlay covers the picture exactly
      if (shown.pixels === null && sized(k)) return;
      if (!sized(k)) p.resizeCanvas(view.camera.width * k, view.camera.height * k);
      p.clear();
      shown = { pixels: null, k };
    },
    draw(pixels) {
      const k = view.scale;
      if (pixels === shown.pixels && k === shown.k && sized(k)) return;
      marks.clear();
      p.stroke(0);
      p.strokeWeight(2);
      p.fill(255);
      for (const { x, y } of pixels) p.circle((x + 0.5) * k, (y + 0.5) * k, k * 0.4);
      shown = { pixels, k };
    },
  };
  return marks;
}

/**
 * A tick box under a view's picture that marks every pixel of the finished
 * picture passing `test`, and a line saying how many. The marks are found once
 * per picture: again after the scene or the camera changes.
 * @param {import('p5').default} p the sketch: its canvas becomes the marks' overlay (see createPixelMarks)
 * @param {object} options
 * @param {import('../tracer/view.js').TracerView} options.view
 * @param {string} options.name names the parts: the box has `data-show-<name>`, the line
 *   `data-<name>-count` (set to the count), the overlay the class `<name>-marks`
 * @param {string} options.label the words beside the box
 * @param {(rgb: number[]) => boolean} options.test which pixels to mark (`[r, g, b]`, 0–255)
 * @param {(count: number, total: number) => string} options.describe the line, from the count and the number of pixels
 * @returns {{ draw: () => void, destroy: () => void }} call draw() from the sketch's draw(); destroy() (p.remove() calls it) takes the box away
 * @example
 * p.createPixelHighlight({
 *   view, name: 'pink', label: 'Show the pink pixels',
 *   test: ([r, g, b]) => colorName([r, g, b]) === 'pink',
 *   describe: (count, total) => `${count} of ${total} pixels are pink`,
 * });
 */
export function createPixelHighlight(p, options) {
  const { view, name, label, test, describe } = checkOptions(options, ['view', 'name', 'label', 'test', 'describe'], 'createPixelHighlight');
  const marks = createPixelMarks(p, { view, name: `${name}-marks` });
  const box = element('input', { type: 'checkbox', [`data-show-${name}`]: '' });
  const count = element('span', { [`data-${name}-count`]: '', role: 'status', 'aria-atomic': 'true' }); // the count is said when it changes
  const controls = element('div', { class: 'controls' }, element('label', {}, box, label), count);
  view.figure.after(controls);
  let found = null, foundIn = null; // the marked pixels, and the { scene, camera } of their picture

  return {
    draw() {
      if (!box.checked) {
        marks.clear();
        found = null;
        count.textContent = '';
        return;
      }
      if (!view.done) return marks.clear();
      if (!found || foundIn.scene !== view.scene || foundIn.camera !== view.camera) {
        found = findPixels(view.buffer, view.width, view.height, test);
        foundIn = { scene: view.scene, camera: view.camera };
        count.textContent = describe(found.length, view.width * view.height);
        count.setAttribute(`data-${name}-count`, String(found.length));
      }
      marks.draw(found);
    },
    destroy() { controls.remove(); },
  };
}
