// Reading what a student types in a box (every bad value named) and showing colours so they read back the same.
import { describe, it, expect } from 'vitest';
import { readNumber, readColor, colorText } from '../../lib/scene/values.js';

describe('readNumber', () => {
  it('reads numbers as people type them', () => {
    expect(readNumber('4', 'radius')).toBe(4);
    expect(readNumber('  -5.5 ', 'x')).toBe(-5.5);
    expect(readNumber('.5', 'x')).toBe(0.5);
    expect(readNumber('1e3', 'x')).toBe(1000);
    expect(readNumber('−3', 'x')).toBe(-3); // a typographic minus
    expect(readNumber(12, 'x')).toBe(12);
  });

  it('names the box when it is empty or not a number', () => {
    expect(() => readNumber('', 'Pixel x')).toThrow(TypeError);
    expect(() => readNumber('   ', 'Pixel x')).toThrow(/^Pixel x is empty/);
    expect(() => readNumber('abc', 'radius')).toThrow(/^radius must be a number, got "abc"/);
    expect(() => readNumber('4px', 'radius')).toThrow(/^radius must be a number/);
    expect(() => readNumber('1,5', 'radius')).toThrow(/^radius must be a number/);
    expect(() => readNumber('NaN', 'radius')).toThrow(/^radius must be a number/);
    expect(() => readNumber('Infinity', 'radius')).toThrow(/^radius must be a number/);
    expect(() => readNumber('1e999', 'radius')).toThrow(RangeError);
  });

  it('says to write decimals with a point when a comma stands for one (2,5), and one number to a whole-number box', () => {
    expect(() => readNumber('2,5', 'Camera H')).toThrow(/^Camera H must be a number, got "2,5": write decimals with a point, 2\.5$/);
    expect(() => readNumber('-0,25', 'Camera V')).toThrow(/write decimals with a point, -0\.25$/);
    expect(() => readNumber('2,5', 'Pixel x', { integer: true })).toThrow(/^Pixel x must be a whole number, got "2,5": one number to a box$/);
    expect(() => readNumber('1,2,3', 'radius')).toThrow(/^radius must be a number, got "1,2,3"$/); // no point would help
  });

  it('checks whole numbers and ranges, with the range in the message', () => {
    const rule = { min: 0, max: 31, integer: true };
    expect(readNumber('31', 'Pixel x', rule)).toBe(31);
    expect(() => readNumber('32', 'Pixel x', rule)).toThrow(/^Pixel x must be from 0 to 31, got 32$/);
    expect(() => readNumber('-1', 'Pixel x', rule)).toThrow(RangeError);
    expect(() => readNumber('2.5', 'Pixel x', rule)).toThrow(/^Pixel x must be a whole number, got 2.5$/);
    expect(() => readNumber('', 'Pixel x', rule)).toThrow(/whole number from 0 to 31/);
    expect(() => readNumber('120', 'Camera V', { min: -90, max: 90 })).toThrow(/^Camera V must be from -90 to 90, got 120$/);
    expect(() => readNumber('-1', 'intensity', { min: 0 })).toThrow(/^intensity must be at least 0, got -1$/);
  });

  it('can exclude the bound: a radius must be greater than 0', () => {
    expect(readNumber('0.001', 'radius', { above: 0 })).toBe(0.001);
    expect(() => readNumber('0', 'radius', { above: 0 })).toThrow(/^radius must be greater than 0, got 0$/);
    expect(() => readNumber('-1', 'radius', { above: 0 })).toThrow(/^radius must be greater than 0, got -1$/);
  });
});

describe('readColor and colorText', () => {
  it('reads hex, names, rgb(), three numbers and one number (a grey)', () => {
    expect(readColor('#ff0000', 'colour')).toEqual([1, 0, 0]);
    expect(readColor('pink', 'colour')).toEqual([1, 192 / 255, 203 / 255]);
    expect(readColor('rgb(0, 255, 0)', 'colour')).toEqual([0, 1, 0]);
    expect(readColor('1, 0.32, 0.36', 'colour')).toEqual([1, 0.32, 0.36]);
    expect(readColor('[1 0.5 0]', 'colour')).toEqual([1, 0.5, 0]);
    expect(readColor('1.2', 'emission')).toEqual([1.2, 1.2, 1.2]);
  });

  it('names the box for a bad colour', () => {
    expect(() => readColor('', 'Sphere 1 colour')).toThrow(/^Sphere 1 colour is empty/);
    expect(() => readColor('pinkish', 'Sphere 1 colour')).toThrow(/^Sphere 1 colour must be a colour like/);
    expect(() => readColor('-1', 'emission')).toThrow(RangeError);
    expect(() => readColor('-1', 'emission')).toThrow(/^emission/);
    expect(() => readColor('1, 2', 'colour')).toThrow(/^colour/);
  });

  it('shows colours the way a box can read them back', () => {
    expect(colorText([1, 0, 0])).toBe('#ff0000');
    expect(colorText([2, 2, 2])).toBe('2');
    expect(colorText([1.2, 1.2, 1.2], { grey: true })).toBe('1.2');
    expect(colorText([0, 0, 0], { grey: true })).toBe('0');
    expect(colorText([0, 0, 0])).toBe('#000000');
    expect(colorText([2, 1, 0])).toBe('2, 1, 0');
    for (const rgb of [[2, 2, 2], [2, 1, 0], [0.2, 0.4, 1]]) expect(readColor(colorText(rgb), 'c')).toEqual(rgb);
  });
});

describe('long typed text', () => {
  it('tests a number in time proportional to its length (60,000 digits then a letter took 3 s)', async () => {
    const { PLAIN_NUMBER } = await import('../../lib/scene/values.js');
    const { timeRatio } = await import('./linear-time.js');
    const test = (text) => PLAIN_NUMBER.test(text);
    expect(timeRatio(test, (n) => `${'1'.repeat(n)}x`)).toBeLessThan(400);
    expect(timeRatio(test, (n) => `${'1'.repeat(n / 2)}.${'1'.repeat(n / 2)}x`)).toBeLessThan(400);
  });

  it('refuses text past the cap at once, naming the box, without repeating the text', async () => {
    const { TYPED_MAX } = await import('../../lib/scene/values.js');
    const long = `${'1'.repeat(60000)}x`;
    expect(() => readNumber(long, 'Camera H')).toThrow(new RangeError(`Camera H is too long: 60,001 characters, at most ${TYPED_MAX}`));
    expect(() => readColor(` ${'1, '.repeat(50)} `, 'color')).toThrow(/^color is too long: 149 characters, at most 100$/);
    expect(readNumber(`  ${'1'.repeat(TYPED_MAX - 1)}  `, 'x')).toBe(Number('1'.repeat(TYPED_MAX - 1))); // trimmed first
  });

  it('cuts a too-big number in its message', () => {
    const typed = `${'9'.repeat(90)}e999`;
    let message = '';
    try { readNumber(typed, 'x'); } catch (error) { message = error.message; }
    expect(message).toMatch(/^x is too big, got "9+…$/);
    expect(message).not.toContain(typed);
  });
});
