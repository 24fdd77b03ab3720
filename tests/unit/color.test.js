import { describe, it, expect } from 'vitest';
import { toColor, toHex, colorName } from '../../lib/index.js';
import { colorToHex } from '../../lib/math/color.js';

const close = (actual, expected) => expected.forEach((c, i) => expect(actual[i]).toBeCloseTo(c, 12));

describe('toColor', () => {
  it('keeps [r, g, b] arrays (0–1, above 1 allowed for lights)', () => {
    expect(toColor([1, 0.32, 0.36])).toEqual([1, 0.32, 0.36]);
    expect(toColor([2, 2, 2])).toEqual([2, 2, 2]);
    expect(toColor(new Float32Array([0.5, 0.25, 0]))).toEqual([0.5, 0.25, 0]);
  });

  it('a single number is a grey', () => {
    expect(toColor(1.2)).toEqual([1.2, 1.2, 1.2]);
    expect(toColor(0)).toEqual([0, 0, 0]);
  });

  it('parses #rrggbb, #rgb, rgb(…) and names', () => {
    close(toColor('#ff5160'), [1, 0x51 / 255, 0x60 / 255]);
    close(toColor('#FF5160'), [1, 0x51 / 255, 0x60 / 255]);
    close(toColor('#f56'), [1, 0x55 / 255, 0x66 / 255]);
    close(toColor('rgb(255, 81, 96)'), [1, 81 / 255, 96 / 255]);
    close(toColor('rgb(0,0,0)'), [0, 0, 0]);
    close(toColor('pink'), [1, 0xc0 / 255, 0xcb / 255]);
    close(toColor('  Pink '), [1, 0xc0 / 255, 0xcb / 255]);
    close(toColor('red'), [1, 0, 0]);
    close(toColor('white'), [1, 1, 1]);
  });

  it('rejects bad strings with a TypeError naming the field', () => {
    for (const bad of ['', 'pinkish', '#ff51', '#ggg', '#ff516', 'rgb(256, 0, 0)', 'rgb(1, 2)', 'rgba(1,2,3,1)', 'hsl(0, 50%, 50%)']) {
      expect(() => toColor(bad, 'background'), bad).toThrow(TypeError);
      expect(() => toColor(bad, 'background'), bad).toThrow(/background/);
    }
  });

  it('rejects bad arrays and values naming the field (and channel)', () => {
    expect(() => toColor([1, 0], 'color')).toThrow(TypeError);
    expect(() => toColor([1, 0, 0, 1], 'color')).toThrow(/color/);
    expect(() => toColor([1, NaN, 0], 'color')).toThrow(/color\[1\]/);
    expect(() => toColor([1, '0', 0], 'color')).toThrow(TypeError);
    expect(() => toColor([1, 0, -0.5], 'emission')).toThrow(RangeError);
    expect(() => toColor([1, 0, -0.5], 'emission')).toThrow(/emission\[2\]/);
    expect(() => toColor(-1, 'emission')).toThrow(RangeError);
    expect(() => toColor(null, 'color')).toThrow(TypeError);
    expect(() => toColor({ r: 1, g: 0, b: 0 }, 'color')).toThrow(/color/);
    expect(() => toColor(true, 'color')).toThrow(TypeError);
  });
});

describe('hex', () => {
  it('toHex of 0–255 channels, colorToHex of 0–1 channels (clamped)', () => {
    expect(toHex([255, 81, 96])).toBe('#ff5160');
    expect(toHex([0, 0, 0])).toBe('#000000');
    expect(toHex([300, -5, 127.6])).toBe('#ff0080'); // out of range: clamped, still six digits
    expect(colorToHex([1, 0, 0])).toBe('#ff0000');
    expect(colorToHex([2, -1, 0.5])).toBe('#ff0080');
    expect(colorToHex(toColor('#ff5160'))).toBe('#ff5160');
  });
});

describe('colorName: the nearest simple colour', () => {
  it("calls the lesson's pink sphere's lit pixels pink", () => {
    expect(colorName([255, 82, 92])).toBe('pink');
    expect(colorName([255, 81, 96])).toBe('pink');
    expect(colorName([255, 192, 203])).toBe('pink');
    expect(colorName([255, 105, 180])).toBe('pink');
  });

  it('names the simple colours', () => {
    const cases = {
      red: [[255, 0, 0], [200, 20, 20]],
      yellow: [[255, 255, 0], [230, 220, 40]],
      green: [[0, 128, 0], [0, 255, 0], [40, 200, 60]],
      blue: [[0, 0, 255], [30, 60, 220]],
      white: [[255, 255, 255], [250, 250, 250]],
      black: [[0, 0, 0], [10, 12, 8]],
      gray: [[128, 128, 128], [51, 51, 51], [100, 105, 100]],
      orange: [[255, 165, 0]],
      cyan: [[0, 255, 255]],
      purple: [[128, 0, 128]],
    };
    for (const [name, colours] of Object.entries(cases)) {
      for (const rgb of colours) expect(colorName(rgb), `${rgb}`).toBe(name);
    }
  });

  it('a dark red is red, not pink', () => {
    expect(colorName([150, 30, 35])).toBe('red');
  });
});

describe('pink through the shading', () => {
  it('the pink sphere half lit is still pink; dim, it is red; a pure red stays red', () => {
    expect(colorName([201, 64, 72])).toBe('pink'); // pink sphere, cos θ ≈ 0.79
    expect(colorName([185, 59, 66])).toBe('pink'); // cos θ ≈ 0.72
    expect(colorName([160, 51, 58])).toBe('red'); // cos θ ≈ 0.63: darker, crimson
    expect(colorName([110, 35, 40])).toBe('red'); // too dark to look pink
    expect(colorName([230, 10, 10])).toBe('red');
  });
});

describe('a misspelt colour name', () => {
  it('names the nearest colour name, and none when nothing is near', async () => {
    const { toColor } = await import('../../lib/math/color.js');
    expect(() => toColor('pinkk')).toThrow(`color must be a colour like '#ff5160', 'rgb(255, 81, 96)' or 'pink', got "pinkk" (did you mean 'pink'?)`);
    expect(() => toColor('Yelow', 'material.color')).toThrow(/^material\.color must be .* got "yelow" \(did you mean 'yellow'\?\)$/);
    expect(() => toColor('pinkish')).toThrow(/got "pinkish"$/);
    expect(() => toColor('#ff51')).toThrow(/got "#ff51"$/); // not a name: no guess
  });
});
