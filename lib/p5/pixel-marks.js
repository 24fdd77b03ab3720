/**
 * Marks on chosen pixels of a tracer view, drawn on a sketch's own p5 canvas
 * laid over the picture: the traced canvas stays exactly as traced.
 *
 *   const marks = createPixelMarks(p, view, 'pink-marks');
 *   p.draw = () => marks.draw(findPixels(view.renderer.buffer, 32, 24, isPink));
 */

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
 * `name` and the attributes `data-<name>` and `data-overlay`.
 * @returns {{ clear: () => void, draw: (pixels: {x: number, y: number}[]) => void }}
 *   clear() sizes the overlay to the picture on screen and empties it; draw() also marks each pixel with a dot
 */
export function createPixelMarks(p, view, name = 'pixel-marks') {
  const { width, height } = view.camera;
  p.createCanvas(width, height).parent(view.canvas.parentElement).class(name).attribute(`data-${name}`, '').attribute('data-overlay', '');
  p.pixelDensity(1);
  const marks = {
    clear() {
      const k = view.scale; // screen pixels per traced pixel: the overlay covers the picture exactly
      if (p.width !== view.camera.width * k || p.height !== view.camera.height * k) p.resizeCanvas(view.camera.width * k, view.camera.height * k);
      p.clear();
    },
    draw(pixels) {
      marks.clear();
      const k = view.scale;
      p.stroke(0);
      p.strokeWeight(2);
      p.fill(255);
      for (const { x, y } of pixels) p.circle((x + 0.5) * k, (y + 0.5) * k, k * 0.4);
    },
  };
  return marks;
}
