// The answer form's reading of its boxes: every box read (so each bad one says why), all values or none.
import { describe, it, expect } from 'vitest';
import { readBoxes } from '../../lib/p5/controls/answer-form.js';

const box = (value) => ({ reads: 0, read() { this.reads++; return value; } });

describe('readBoxes', () => {
  it('gives every value by name when all are good', () => {
    expect(readBoxes({ x: box(10), y: box(12), h: box(0), v: box(-8.5) })).toEqual({ x: 10, y: 12, h: 0, v: -8.5 });
  });

  it('gives undefined when any box is bad, having read every box', () => {
    const boxes = { x: box(undefined), y: box(12), h: box(undefined), v: box(0) };
    expect(readBoxes(boxes)).toBeUndefined();
    expect(Object.values(boxes).map((b) => b.reads)).toEqual([1, 1, 1, 1]);
  });
});
