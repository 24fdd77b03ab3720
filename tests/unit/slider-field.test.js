// A slider field's reading of its text box and the line under it for a bad value.
import { describe, it, expect } from 'vitest';
import { readTypedNumber, fieldMessage } from '../../lib/p5/slider-field.js';
import { Sphere } from '../../lib/index.js';

describe('readTypedNumber', () => {
  it('reads numbers as typed, spaces around them too', () => {
    expect(readTypedNumber('6')).toBe(6);
    expect(readTypedNumber(' -2.5 ')).toBe(-2.5);
    expect(readTypedNumber('1e1')).toBe(10);
  });

  it('takes no empty box, word or infinity for a number', () => {
    for (const text of ['', '  ', 'abc', '4,5', 'Infinity']) expect(() => readTypedNumber(text)).toThrow(new TypeError(`must be a number, got "${text}"`));
  });
});

describe('fieldMessage', () => {
  it('puts the label before what is wrong, and says the picture stays', () => {
    expect(fieldMessage('Centre x (Xc)', new TypeError('must be a number, got "abc"')))
      .toBe('Centre x (Xc): must be a number, got "abc". The picture keeps the last good value.');
  });

  it('drops the field name the library starts its message with: the label says it', () => {
    let error;
    try { new Sphere([0, 0, -20], -2); } catch (e) { error = e; }
    expect(error.message).toMatch(/^radius must/);
    expect(fieldMessage('Radius r', error)).toBe('Radius r: must be greater than 0, got -2. The picture keeps the last good value.');
  });
});
