import { describe, it, expect } from 'vitest';
import { clamp } from '../../lib/numbers.js';

describe('clamp', () => {
  it('holds a value within lo and hi, and leaves one inside alone', () => {
    expect(clamp(-3, 0, 10)).toBe(0);
    expect(clamp(12, 0, 10)).toBe(10);
    expect(clamp(4.5, 0, 10)).toBe(4.5);
  });
});
