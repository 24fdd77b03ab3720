// Finding the pixels to mark in a traced picture.
import { describe, it, expect } from 'vitest';
import { findPixels, createPixelMarks } from '../../lib/p5/pixel/marks.js';
import { classScene, render, Camera, colorName } from '../../lib/index.js';

describe('findPixels', () => {
  it('finds the pixels whose colour passes the test, row by row, and hands the test [r, g, b]', () => {
    const rgba = new Uint8ClampedArray(3 * 2 * 4); // 3 × 2, all black
    rgba.set([255, 0, 0, 255], 4 * 1);     // (1, 0) red
    rgba.set([255, 0, 0, 255], 4 * 3);     // (0, 1) red
    const seen = [];
    const found = findPixels(rgba, 3, 2, (rgb) => { seen.push(rgb); return rgb[0] === 255; });
    expect(found).toEqual([{ x: 1, y: 0 }, { x: 0, y: 1 }]);
    expect(seen).toHaveLength(6);
    expect(seen[1]).toEqual([255, 0, 0]);
  });

  it('finds nothing when nothing passes', () => {
    expect(findPixels(new Uint8ClampedArray(16), 2, 2, () => false)).toEqual([]);
  });

  it('finds the pink pixels of the class scene, each one pink when inspected', () => {
    const camera = new Camera({ width: 32, height: 24, fov: 30 });
    const pink = findPixels(render(classScene(), camera), 32, 24, (rgb) => colorName(rgb) === 'pink');
    expect(pink.length).toBeGreaterThan(10);
    expect(pink.every(({ x, y }) => x >= 0 && x < 32 && y >= 0 && y < 24)).toBe(true);
  });
});

describe('createPixelMarks', () => {
  /** A p5 stand-in that counts what reaches its canvas. */
  function fakeSketch() {
    const calls = [];
    const chain = { parent: () => chain, class: () => chain, attribute: () => chain };
    const p = {
      width: 0, height: 0, calls,
      createCanvas(w, h) { p.width = w; p.height = h; return chain; },
      resizeCanvas(w, h) { calls.push('resize'); p.width = w; p.height = h; },
      pixelDensity() {}, clear: () => calls.push('clear'), stroke() {}, strokeWeight() {}, fill() {},
      circle: () => calls.push('circle'),
    };
    return p;
  }
  const view = { camera: { width: 4, height: 3 }, scale: 2, canvas: { parentElement: {} } };

  it('draws marks once: the same marks at the same size every frame leave the canvas alone', () => {
    const p = fakeSketch();
    const marks = createPixelMarks(p, { view, name: 'test-marks' });
    const pixels = [{ x: 1, y: 1 }, { x: 2, y: 0 }];
    marks.draw(pixels);
    marks.draw(pixels);
    marks.draw(pixels);
    expect(p.calls).toEqual(['resize', 'clear', 'circle', 'circle']);
    marks.draw([{ x: 0, y: 0 }]); // new marks: drawn
    expect(p.calls.slice(4)).toEqual(['clear', 'circle']);
  });

  it('clears once, and again after marks or a new size', () => {
    const p = fakeSketch();
    const marks = createPixelMarks(p, { view: { ...view }, name: 'test-marks' });
    marks.clear();
    marks.clear();
    expect(p.calls).toEqual(['resize', 'clear']);
    const pixels = [{ x: 0, y: 0 }];
    marks.draw(pixels);
    marks.clear();
    marks.clear();
    expect(p.calls.slice(2)).toEqual(['circle', 'clear']); // drawn on the empty overlay, then cleared once
  });

  it("draws the same marks again when the picture's scale on screen changes", () => {
    const p = fakeSketch();
    const shown = { ...view };
    const marks = createPixelMarks(p, { view: shown, name: 'test-marks' });
    const pixels = [{ x: 0, y: 0 }];
    marks.draw(pixels);
    shown.scale = 3;
    marks.draw(pixels);
    expect(p.calls).toEqual(['resize', 'clear', 'circle', 'resize', 'clear', 'circle']);
    expect([p.width, p.height]).toEqual([12, 9]);
  });
});
