// A slider field's reading of its text box and the line under it for a bad value.
import { describe, it, expect } from 'vitest';
import { fieldMessage } from '../../lib/p5/controls/slider-field.js';
import { readNumber } from '../../lib/scene/values.js';
import { Sphere } from '../../lib/index.js';

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

  it('keeps a message that starts with the label as it is (the text box is read by readNumber)', () => {
    let error;
    try { readNumber('abc', 'Centre x (Xc)'); } catch (e) { error = e; }
    expect(fieldMessage('Centre x (Xc)', error)).toBe('Centre x (Xc) must be a number, got "abc". The picture keeps the last good value.');
  });
});
