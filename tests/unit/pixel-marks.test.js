// Finding the pixels to mark in a traced picture.
import { describe, it, expect } from 'vitest';
import { findPixels } from '../../lib/p5/pixel/marks.js';
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
