import { describe, it, expect } from 'vitest';
import { clamp, niceTicks } from '../../lib/math/numbers.js';

describe('clamp', () => {
  it('holds a value within lo and hi, and leaves one inside alone', () => {
    expect(clamp(-3, 0, 10)).toBe(0);
    expect(clamp(12, 0, 10)).toBe(10);
    expect(clamp(4.5, 0, 10)).toBe(4.5);
  });
});

describe('niceTicks', () => {
  it('gives round values in steps of 1, 2 or 5 × 10ⁿ, with 0 exactly 0', () => {
    expect(niceTicks(0, 10, 5)).toEqual([0, 2, 4, 6, 8, 10]);
    expect(niceTicks(-3, 12, 6)).toEqual([0, 5, 10]); // a step of 2.5 is not round: 5
    expect(Object.is(niceTicks(-3, 12, 6)[0], 0)).toBe(true); // not −0, whose label would read '−0'
    expect(niceTicks(-1, 1, 4)).toEqual([-1, -0.5, 0, 0.5, 1]);
  });
});
